// End-to-end runs of Mei 2006's target selection rules (orientation, widest_frontier) with
// the paper's sensing radius of 10 cells.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "sim/simulation.hpp"
#include "world/energy_model.hpp"
#include "world/map_loaders.hpp"
#include "world/map_spec.hpp"

namespace fsweep {
namespace {

RunSpec mei_spec(const std::string& map_spec, const std::string& strategy, const std::string& planner) {
  RunSpec s;
  s.map = std::make_shared<const WorldMap>(load_map_spec(map_spec));
  s.strategy = configure_strategy(strategy, nullptr);
  s.planner = configure_planner(planner, nullptr);
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

// Mei 2006 section V-C (Figures 8, 9): on structured maps whose rooms are large against the
// sensing radius (rooms >= 30 cells, d_s = 10), orientation's route is much shorter and cheaper
// than widest frontier's. The maps of sweeps/paper/mei2006_structured.json, seeds 1-3, with the
// paper's planner, energy model and move rule (diagonals may pass a blocked corner, section
// IV-A); measured: 858.9 vs 1232.5, 799.8 vs 1124.7, 718.8 vs 1036.6 (all 50 seeds of that sweep:
// orientation shorter in 49, median 23.4%).
TEST(MeiExploration, OrientationBeatsWidestFrontierInLargeRooms) {
  for (const int seed : {1, 2, 3}) {
    const std::string map = "rooms:w=100,h=80,door=3,min_room=30,start=1;1,seed=" + std::to_string(seed);
    RunSpec o = mei_spec(map, "orientation", "lattice");
    RunSpec w = mei_spec(map, "widest_frontier", "lattice");
    o.robot.energy = energy_preset("mei2006");
    w.robot.energy = energy_preset("mei2006");
    o.robot.allow_corner_cutting = true;
    w.robot.allow_corner_cutting = true;
    const RunResult ro = simulate(o);
    const RunResult rw = simulate(w);
    ASSERT_EQ(ro.end, EndReason::Complete) << map;
    ASSERT_EQ(rw.end, EndReason::Complete) << map;
    EXPECT_LT(ro.metrics.distance_m, 0.9 * rw.metrics.distance_m) << map;
    EXPECT_LT(ro.metrics.energy, 0.9 * rw.metrics.energy) << map;
  }
}

}  // namespace
}  // namespace fsweep
