// A sensor with a field of view (SensorParams::fov_deg < 360, facing the robot's heading), and
// the beam lidar model, work with every registered strategy.
#include <gtest/gtest.h>

#include <memory>
#include <nlohmann/json.hpp>

#include "sim/simulation.hpp"
#include "strategies/registry.hpp"
#include "world/map_spec.hpp"

namespace fsweep {
namespace {

/// Every registered strategy explores a small building completely with `sensor`, and takes
/// another path with `other` (the sensor setting under test matters).
void expect_every_strategy_explores(const SensorParams& sensor, const SensorParams& other) {
  const auto map = std::make_shared<const WorldMap>(load_map_spec("rooms:w=40,h=30,door=3,seed=2"));
  for (const auto& name : strategy_names()) {
    RunSpec s;
    s.map = map;
    s.strategy = configure_strategy(name, nullptr);
    s.robot.sensor = sensor;
    s.seed = 5;
    const RunResult r = simulate(s);
    EXPECT_EQ(r.end, EndReason::Complete) << name << " " << r.end_detail;
    EXPECT_GT(r.metrics.coverage, 0.99) << name;
    EXPECT_GT(r.metrics.completeness, 0.95) << name;
    s.robot.sensor = other;
    EXPECT_NE(simulate(s).trajectory, r.trajectory) << name;
  }
}

TEST(FieldOfView, EveryStrategyExploresWith180Degrees) {
  // The same run with an omnidirectional sensor differs: the heading matters.
  SensorParams half;
  half.range_m = 5.0;
  half.fov_deg = 180.0;
  SensorParams full = half;
  full.fov_deg = 360.0;
  expect_every_strategy_explores(half, full);
}

TEST(FieldOfView, EveryStrategyExploresWithABeamLidar) {
  // 31 beams over 180 degrees, 6 degrees apart: gbl and holz estimate their gains and
  // target_seeking its objective with the same beams. The grid model with the same field of
  // view differs: the model matters.
  SensorParams grid;
  grid.range_m = 5.0;
  grid.fov_deg = 180.0;
  SensorParams beams = grid;
  beams.model = SensorModel::Beams;
  beams.beams = 31;
  expect_every_strategy_explores(beams, grid);
}

}  // namespace
}  // namespace fsweep
