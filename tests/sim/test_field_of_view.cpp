// A sensor with a field of view (SensorParams::fov_deg < 360, facing the robot's heading) works
// with every registered strategy.
#include <gtest/gtest.h>

#include <memory>
#include <nlohmann/json.hpp>

#include "sim/simulation.hpp"
#include "strategies/registry.hpp"
#include "world/map_spec.hpp"

namespace fsweep {
namespace {

TEST(FieldOfView, EveryStrategyExploresWith180Degrees) {
  const auto map = std::make_shared<const WorldMap>(load_map_spec("rooms:w=40,h=30,door=3,seed=2"));
  for (const auto& name : strategy_names()) {
    RunSpec s;
    s.map = map;
    s.strategy = configure_strategy(name, nullptr);
    s.robot.sensor.range_m = 5.0;
    s.robot.sensor.fov_deg = 180.0;
    s.seed = 5;
    const RunResult r = simulate(s);
    EXPECT_EQ(r.end, EndReason::Complete) << name << " " << r.end_detail;
    EXPECT_GT(r.metrics.coverage, 0.99) << name;
    EXPECT_GT(r.metrics.completeness, 0.95) << name;
    // The same run with an omnidirectional sensor differs: the heading matters.
    s.robot.sensor.fov_deg = 360.0;
    EXPECT_NE(simulate(s).trajectory, r.trajectory) << name;
  }
}

}  // namespace
}  // namespace fsweep
