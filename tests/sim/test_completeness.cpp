// Map completeness (RunMetrics::completeness): the observable set, a hand-worked value, and
// full exploration.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "sim/simulation.hpp"
#include "world/ascii_world.hpp"
#include "world/map_spec.hpp"

namespace fsweep {
namespace {

/// Brute force: every cell that Sensor::visible (range and ray rules, any heading) reports
/// from some reachable free cell.
Grid<std::uint8_t> visible_from_reachable(const WorldMap& map, double range_m) {
  SensorParams params;
  params.range_m = range_m;
  const Sensor sensor(params, map.resolution_m);
  const Grid<std::uint8_t> reachable = reachable_free(map, map.start);
  Grid<std::uint8_t> seen(map.width(), map.height(), 0);
  const int r = static_cast<int>(sensor.range_cells()) + 1;
  for (int i = 0; i < reachable.size(); ++i) {
    if (reachable[i] == 0) continue;
    const Cell p = reachable.cell(i);
    for (int y = p.y - r; y <= p.y + r; ++y) {
      for (int x = p.x - r; x <= p.x + r; ++x) {
        const Cell c{x, y};
        if (seen.in_bounds(c) && seen.at(c) == 0 && sensor.visible(map, p, c)) seen.at(c) = 1;
      }
    }
  }
  return seen;
}

TEST(Completeness, ObservableCellsAreWhatTheSensorCanSee) {
  for (const char* spec : {"random:w=24,h=18,p=0.3,seed=1", "random:w=24,h=18,p=0.45,seed=2",
                           "rooms:w=30,h=24,door=2,seed=3", "office:w=40,h=36,seed=4"}) {
    const WorldMap map = load_map_spec(spec);
    const Grid<std::uint8_t> observable = observable_cells(map, reachable_free(map, map.start));
    for (const double range : {1.5, 2.5, 6.0}) {
      EXPECT_EQ(observable.data(), visible_from_reachable(map, range).data()) << spec << " range " << range;
    }
  }
}

TEST(Completeness, HandWorkedCorridorAfterTheFirstScan) {
  // Observable: the 4 free cells, the 4 + 4 wall cells above and below them and the two end
  // walls = 14 (the corners are not: both cells beside the diagonal are walls). From (2, 1)
  // with range 1.5 the robot sees its 8 neighbours and itself: 3 free cells and 6 walls
  // (the diagonal walls through a corner with one free side). Completeness 9 / 14; coverage
  // 3 / 4.
  RunSpec spec;
  spec.map = std::make_shared<const WorldMap>(test::ascii_world({
      "######",
      "#.S..#",
      "######",
  }));
  spec.robot.sensor.range_m = 1.5;
  const RunResult r = Simulation(spec).result();
  EXPECT_DOUBLE_EQ(r.metrics.completeness, 9.0 / 14.0);
  EXPECT_DOUBLE_EQ(r.metrics.coverage, 3.0 / 4.0);
}

TEST(Completeness, FullExplorationIsComplete) {
  RunSpec spec;
  spec.map = std::make_shared<const WorldMap>(load_map_spec("rooms:w=40,h=30,door=3,seed=1"));
  spec.robot.sensor.range_m = 6.0;
  const RunResult r = simulate(spec);
  ASSERT_EQ(r.end, EndReason::Complete) << r.end_detail;
  EXPECT_DOUBLE_EQ(r.metrics.coverage, 1.0);
  EXPECT_DOUBLE_EQ(r.metrics.completeness, 1.0);
}

TEST(Completeness, StoppedEarlyIsBelowOne) {
  RunSpec spec;
  spec.map = std::make_shared<const WorldMap>(load_map_spec("rooms:w=40,h=30,door=3,seed=1"));
  spec.robot.sensor.range_m = 6.0;
  spec.sim.max_steps = 20;
  const RunResult r = simulate(spec);
  EXPECT_EQ(r.end, EndReason::StepLimit);
  EXPECT_GT(r.metrics.completeness, 0.0);
  EXPECT_LT(r.metrics.completeness, 1.0);
  // Every known cell is observable, so completeness = known cells / observable cells.
  const Grid<std::uint8_t> observable =
      observable_cells(*spec.map, reachable_free(*spec.map, spec.map->start));
  int observable_count = 0;
  for (const auto v : observable.data()) observable_count += v;
  EXPECT_DOUBLE_EQ(r.metrics.completeness,
                   static_cast<double>(r.final_known.known_count()) / observable_count);
}

}  // namespace
}  // namespace fsweep
