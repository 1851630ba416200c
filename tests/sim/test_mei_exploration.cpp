// End-to-end runs of Mei 2006's target selection rules (orientation, widest_frontier) with
// the paper's sensing radius of 10 cells.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "engine/sim/simulation.hpp"
#include "engine/world/map_loaders.hpp"
#include "engine/world/map_spec.hpp"

namespace fsweep {
namespace {

RunSpec mei_spec(const std::string& map_spec, const std::string& strategy, const std::string& planner) {
  RunSpec s;
  s.map = std::make_shared<const WorldMap>(load_map_spec(map_spec));
  s.strategy = strategy;
  s.planner = planner;
  s.robot.sensor.range_m = 10.0;  // d_s = 10 cells at resolution 1 (section V-A)
  s.seed = 1;
  return s;
}

TEST(MeiExploration, OrientationAndWidestFrontierCompleteRooms) {
  for (const char* strategy : {"orientation", "widest_frontier"}) {
    for (const char* map : {"rooms:w=60,h=40,door=3,seed=1", "random:w=40,h=40,p=0.2,seed=3"}) {
      const RunResult r = simulate(mei_spec(map, strategy, "astar"));
      EXPECT_EQ(r.end, EndReason::Complete) << strategy << " " << map << " " << r.end_detail;
      EXPECT_DOUBLE_EQ(r.metrics.coverage, 1.0) << strategy << " " << map;
      EXPECT_GT(r.metrics.distance_m, 0.0) << strategy << " " << map;
    }
  }
}

}  // namespace
}  // namespace fsweep
