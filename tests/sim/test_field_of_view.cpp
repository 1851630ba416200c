// A sensor with a field of view (SensorParams::fov_deg < 360, facing the robot's heading), and
// the beam lidar model, work with every registered strategy; a robot with a narrow view looks
// around at its goals (Simulation::look_around).
#include <gtest/gtest.h>

#include <memory>
#include <nlohmann/json.hpp>
#include <utility>
#include <vector>

#include "sim/simulation.hpp"
#include "strategies/registry.hpp"
#include "world/energy_model.hpp"
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

TEST(FieldOfView, EveryStrategyExploresWithANarrowViewWhicheverWayItStarts) {
  // 60 degrees, starting toward each side: on this map heading 0 faces a wall at the start, where
  // the robot used to see only its own cell and end at once, "complete".
  const auto map = std::make_shared<const WorldMap>(load_map_spec("rooms:w=40,h=30,door=3,seed=2"));
  for (const auto& name : strategy_names()) {
    for (const int heading : {0, 2, 4, 6}) {
      RunSpec s;
      s.map = map;
      s.strategy = configure_strategy(name, nullptr);
      s.robot.sensor.range_m = 5.0;
      s.robot.sensor.fov_deg = 60.0;
      s.robot.start_heading = heading;
      s.seed = 5;
      const RunResult r = simulate(s);
      EXPECT_EQ(r.end, EndReason::Complete) << name << " heading " << heading << " " << r.end_detail;
      EXPECT_GT(r.metrics.coverage, 0.99) << name << " heading " << heading;
    }
  }
}

/// A corridor of 5 free cells, one high, the robot at its west end.
RunSpec corridor_run(double fov_deg, int start_heading) {
  WorldMap map;
  map.occupied = Grid<std::uint8_t>(5, 1, 0);
  map.source = "test corridor";
  RunSpec s;
  s.map = std::make_shared<const WorldMap>(std::move(map));
  s.strategy = configure_strategy("closest_frontier", nullptr);
  s.robot.sensor.range_m = 10.0;
  s.robot.sensor.fov_deg = fov_deg;
  s.robot.start_heading = start_heading;
  s.robot.energy = energy_preset("mei2006");
  return s;
}

TEST(FieldOfView, ARobotFacingTheMapsEdgeTurnsRoundAndPaysForTheTurn) {
  // Facing west, off the map: it sees its own cell, decides to look from where it stands, turns
  // 180 degrees (one stop, one turn) toward its only unknown neighbour, and sees the corridor.
  const RunResult r = simulate(corridor_run(90.0, 4));
  EXPECT_EQ(r.end, EndReason::Complete) << r.end_detail;
  EXPECT_DOUBLE_EQ(r.metrics.coverage, 1.0);
  EXPECT_DOUBLE_EQ(r.metrics.distance_m, 0.0);
  EXPECT_EQ(r.metrics.turns, 1);
  EXPECT_EQ(r.metrics.stops, 1);
  EXPECT_DOUBLE_EQ(r.metrics.turned_deg, 180.0);
  EXPECT_DOUBLE_EQ(r.metrics.energy, energy_preset("mei2006").turn(4));
  // The progress curve ends with what the turn revealed, at the same distance.
  ASSERT_FALSE(r.progress.empty());
  EXPECT_DOUBLE_EQ(r.progress.back().distance_m, 0.0);
  EXPECT_DOUBLE_EQ(r.progress.back().coverage, 1.0);
  EXPECT_DOUBLE_EQ(r.progress.back().energy, energy_preset("mei2006").turn(4));
}

TEST(FieldOfView, ARobotThatSeesAllAroundNeverTurnsInPlace) {
  for (const double fov : {360.0, 90.0}) {
    // Facing east, the corridor is in view at once; all around, it is whichever way it faces.
    for (const int heading : fov == 360.0 ? std::vector<int>{4, 0} : std::vector<int>{0}) {
      const RunResult r = simulate(corridor_run(fov, heading));
      EXPECT_DOUBLE_EQ(r.metrics.coverage, 1.0) << fov << " " << heading;
      EXPECT_EQ(r.metrics.turns, 0) << fov << " " << heading;
      EXPECT_DOUBLE_EQ(r.metrics.energy, 0.0) << fov << " " << heading;
    }
  }
}

TEST(FieldOfView, ARobotDoesNotLookAroundAtItsNavigationTarget) {
  // Three rows, the robot in the middle one facing east along it with a one-degree view: it sees
  // the row, goes straight to the stop cell at its end and stops there without turning, though
  // unknown cells lie beside it.
  WorldMap map;
  map.occupied = Grid<std::uint8_t>(5, 3, 0);
  map.start = Cell{0, 1};
  map.source = "test three rows";
  RunSpec s;
  s.map = std::make_shared<const WorldMap>(std::move(map));
  s.strategy = configure_strategy("closest_frontier", nullptr);
  s.robot.sensor.range_m = 10.0;
  s.robot.sensor.fov_deg = 1.0;
  s.sim.stop_at_cell = Cell{4, 1};
  const RunResult r = simulate(s);
  EXPECT_EQ(r.end, EndReason::TargetReached) << r.end_detail;
  EXPECT_EQ(r.metrics.turns, 0);
  EXPECT_DOUBLE_EQ(r.metrics.distance_m, 4.0);
}

TEST(FieldOfView, ARobotDoesNotLookAroundAtTheDockItReturnsTo) {
  // A battery that forces returns and a 90-degree view: a step that ends with a recharge (a
  // return to the dock) turns where its path changes direction, and at most once more (toward its
  // first move), but never in place at the dock, though on this map the dock has unknown
  // neighbours at some of the returns.
  RunSpec s;
  s.map = std::make_shared<const WorldMap>(load_map_spec("random:w=30,h=30,p=0.2,seed=3"));
  s.strategy = configure_strategy("closest_frontier", nullptr);
  s.robot.sensor.range_m = 5.0;
  s.robot.sensor.fov_deg = 90.0;
  s.robot.battery_capacity = 60.0;
  Simulation sim(s);
  int returns = 0;
  int returns_beside_unknown = 0;
  while (!sim.ended()) {
    const RunMetrics before = sim.metrics_so_far();
    const std::size_t moved_before = sim.result().trajectory.size();
    (void)sim.step();
    const RunMetrics& after = sim.metrics_so_far();
    if (after.recharges == before.recharges) continue;
    const std::vector<Cell> trajectory = sim.result().trajectory;
    ASSERT_GE(moved_before, 1U);
    int direction_changes = 0;
    for (std::size_t i = moved_before + 1; i < trajectory.size(); ++i) {
      const Cell a{trajectory[i - 1].x - trajectory[i - 2].x, trajectory[i - 1].y - trajectory[i - 2].y};
      const Cell b{trajectory[i].x - trajectory[i - 1].x, trajectory[i].y - trajectory[i - 1].y};
      if (a != b) ++direction_changes;
    }
    ++returns;
    EXPECT_LE(after.turns - before.turns, direction_changes + 1) << "return " << returns;
    const Cell dock = sim.robot();
    for (const Cell d : kDirections) {
      const Cell n{dock.x + d.x, dock.y + d.y};
      if (sim.known().in_bounds(n) && sim.known().state(n) == CellState::Unknown) {
        ++returns_beside_unknown;
        break;
      }
    }
  }
  EXPECT_GT(returns, 0);
  EXPECT_GT(returns_beside_unknown, 0);  // where a look around would have turned
}

}  // namespace
}  // namespace fsweep
