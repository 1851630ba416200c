// End-to-end runs on small maps: end reasons, coverage, energy accounting, determinism.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/config_error.hpp"
#include "sim/simulation.hpp"
#include "world/ascii_world.hpp"
#include "world/map_loaders.hpp"
#include "world/map_spec.hpp"

namespace fsweep {
namespace {

RunSpec spec_for(const std::string& map_spec, const std::string& strategy, nlohmann::json params = nullptr) {
  RunSpec s;
  s.map = std::make_shared<const WorldMap>(load_map_spec(map_spec));
  s.strategy = configure_strategy(strategy, std::move(params));
  s.robot.sensor.range_m = 6.0;
  s.seed = 7;
  return s;
}

const nlohmann::json kEaFree = {{"w1", 10}, {"w2", 0}, {"w3", 9}, {"w4", 20}};

TEST(Simulation, ClosestFrontierCompletesRoomsWithFullCoverage) {
  for (const char* map : {"rooms:w=40,h=30,door=3,seed=1", "rooms:w=60,h=40,door=2,seed=9",
                          "random:w=40,h=40,p=0.2,seed=3", "free:w=30,h=20"}) {
    const RunResult r = simulate(spec_for(map, "closest_frontier"));
    EXPECT_EQ(r.end, EndReason::Complete) << map << " " << r.end_detail;
    EXPECT_DOUBLE_EQ(r.metrics.coverage, 1.0) << map;
    EXPECT_DOUBLE_EQ(r.metrics.residual_unknown_m2, 0.0) << map;
    EXPECT_GT(r.metrics.distance_m, 0.0) << map;
  }
}

TEST(Simulation, EnergyAwareUnlimitedCompletesWithFullCoverage) {
  const RunResult r = simulate(spec_for("rooms:w=40,h=30,door=3,seed=2", "energy_aware", kEaFree));
  EXPECT_EQ(r.end, EndReason::Complete) << r.end_detail;
  EXPECT_DOUBLE_EQ(r.metrics.coverage, 1.0);
}

TEST(Simulation, ClosestFrontierEqualsEnergyAwareWeights1000) {
  // Unlimited battery: closest_frontier takes its early-stop fast path, energy_aware (1,0,0,0)
  // the full candidate list; with a battery both use the full list. All must agree.
  for (const bool battery : {false, true}) {
    auto cf = spec_for("rooms:w=50,h=40,door=3,seed=5", "closest_frontier");
    auto ea = spec_for("rooms:w=50,h=40,door=3,seed=5", "energy_aware",
                       nlohmann::json{{"w1", 1}, {"w2", 0}, {"w3", 0}, {"w4", 0}});
    if (battery) cf.robot.battery_capacity = ea.robot.battery_capacity = 400.0;
    const RunResult a = simulate(cf);
    const RunResult b = simulate(ea);
    EXPECT_EQ(a.trajectory, b.trajectory) << "battery " << battery;
    EXPECT_EQ(a.end, b.end);
  }
}

TEST(Simulation, BatteryLimitedRunRechargesAndNeverStrands) {
  auto s = spec_for("free:w=81,h=81", "energy_aware", kEaFree);
  s.robot.battery_capacity = 60.0;  // metres per charge: reach 30 m from the dock
  const RunResult r = simulate(s);
  EXPECT_EQ(r.end, EndReason::RangeLimited) << r.end_detail;
  EXPECT_GT(r.metrics.recharges, 1);
  EXPECT_LT(r.metrics.coverage, 1.0);
  // Every cell of the trajectory stays within half the range of the dock (the start).
  for (const Cell c : r.trajectory) EXPECT_LE(octile_distance(c, r.dock), 30.0 + 1e-9);
}

TEST(Simulation, Mei2006EnergyIsTravelPlusStopsPlusTurns) {
  auto s = spec_for("rooms:w=40,h=30,door=3,seed=1", "closest_frontier");
  s.robot.energy = energy_preset("mei2006");
  const RunResult r = simulate(s);
  const RunMetrics& m = r.metrics;
  // Turn costs 0.4/0.6/0.8/1.0 for k = 1..4 eighth turns are 0.2 + 0.2 k.
  const double expected = m.distance_m / 1.0 + 0.5 * m.stops + 0.2 * m.turns + 0.2 * (m.turned_deg / 45.0);
  EXPECT_NEAR(m.energy, expected, 1e-6);
  EXPECT_EQ(m.stops, m.turns);
}

TEST(Simulation, DeterministicForASeedAndCopyableMidRun) {
  const auto spec = spec_for("rooms:w=40,h=30,door=3,seed=3", "energy_aware", kEaFree);
  const RunResult a = simulate(spec);
  Simulation sim(spec);
  for (int i = 0; i < 5; ++i) ASSERT_TRUE(sim.step());
  Simulation fork = sim;  // clone the whole state, strategy and planner included
  const RunResult b = sim.run();
  const RunResult c = fork.run();
  EXPECT_EQ(a.trajectory, b.trajectory);
  EXPECT_EQ(b.trajectory, c.trajectory);
  EXPECT_EQ(a.metrics.energy, c.metrics.energy);
}

TEST(Simulation, ProgressCurveIsMonotoneAndSampledOnAGrid) {
  auto s = spec_for("rooms:w=40,h=30,door=3,seed=1", "closest_frontier");
  s.sim.progress_step_m = 5.0;
  const RunResult r = simulate(s);
  ASSERT_GE(r.progress.size(), 3U);
  EXPECT_DOUBLE_EQ(r.progress[0].distance_m, 0.0);
  EXPECT_DOUBLE_EQ(r.progress[1].distance_m, 5.0);
  for (std::size_t i = 1; i < r.progress.size(); ++i) {
    EXPECT_GE(r.progress[i].explored_area_m2, r.progress[i - 1].explored_area_m2);
    EXPECT_GT(r.progress[i].distance_m, r.progress[i - 1].distance_m);
  }
  EXPECT_DOUBLE_EQ(r.progress.back().distance_m, r.metrics.distance_m);
  EXPECT_DOUBLE_EQ(r.progress.back().coverage, 1.0);
}

TEST(Simulation, StepCapEndsTheRun) {
  auto s = spec_for("rooms:w=40,h=30,door=3,seed=1", "closest_frontier");
  s.sim.max_steps = 25;
  const RunResult r = simulate(s);
  EXPECT_EQ(r.end, EndReason::StepLimit);
  EXPECT_EQ(r.metrics.steps, 25);
}

TEST(Simulation, DockUnreachableOrBlockedIsAConfigError) {
  auto s = spec_for("free:w=20,h=20", "closest_frontier");
  s.robot.dock = Cell{0, 0};  // the border is occupied
  try {
    (void)simulate(s);
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("(0, 0)"), std::string::npos) << e.what();
  }
}

TEST(Simulation, SensorRangeBeyondTheSupportedCellsIsAConfigError) {
  auto s = spec_for("free:w=20,h=20,res=0.01", "closest_frontier");
  s.robot.sensor.range_m = 30.0;  // 3000 cells
  try {
    (void)simulate(s);
    FAIL();
  } catch (const ConfigError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("robot/sensor/range_m"), std::string::npos) << what;
    EXPECT_NE(what.find("at most 2000 cells"), std::string::npos) << what;
  }
}

TEST(Simulation, NoFrontierLeftInAClosedBoxEndsComplete) {
  RunSpec s;
  s.map = std::make_shared<const WorldMap>(parse_ascii_map("#####\n#S..#\n#####\n"));
  s.robot.sensor.range_m = 5.0;
  const RunResult r = simulate(s);
  EXPECT_EQ(r.end, EndReason::Complete);
  EXPECT_EQ(r.metrics.distance_m, 0.0);
  EXPECT_DOUBLE_EQ(r.metrics.coverage, 1.0);
}

TEST(Simulation, UnreachablePocketDoesNotCountAgainstCoverage) {
  RunSpec s;
  s.map =
      std::make_shared<const WorldMap>(parse_ascii_map("#########\n"
                                                       "#S..#...#\n"
                                                       "#...#...#\n"
                                                       "#########\n"));
  s.robot.sensor.range_m = 10.0;
  const RunResult r = simulate(s);
  EXPECT_EQ(r.end, EndReason::Complete);
  EXPECT_DOUBLE_EQ(r.metrics.reachable_area_m2, 6.0);
  EXPECT_DOUBLE_EQ(r.metrics.coverage, 1.0);
}

TEST(Simulation, ATargetMarginKeepsGoalsAwayFromWallsAndLeavesANarrowAlcoveUnseen) {
  // A room and a dead-end alcove one cell wide below it. sim.target_margin_m 0.6 on 1 m cells
  // leaves out of the goals every cell whose centre is closer than 0.6 to a known wall's square,
  // i.e. the 4-neighbours of known walls: every alcove cell. With a 1.5 m sensor the alcove's
  // far end is seen only from inside it, so it stays unknown.
  RunSpec spec;
  spec.map = std::make_shared<const WorldMap>(test::ascii_world({
      "##########",  //
      "#........#",  //
      "#...S....#",  //
      "#........#",  //
      "#####.####",  //
      "#####.####",  //
      "#####.####",  //
      "#####.####",  //
      "##########",  //
  }));
  spec.strategy = configure_strategy("closest_frontier", nullptr);
  spec.robot.sensor.range_m = 1.5;
  spec.seed = 7;
  const RunResult plain = simulate(spec);
  EXPECT_EQ(plain.end, EndReason::Complete);
  EXPECT_DOUBLE_EQ(plain.metrics.completeness, 1.0);
  EXPECT_DOUBLE_EQ(plain.metrics.coverage, 1.0);
  spec.sim.target_margin_m = 0.6;
  const RunResult margin = simulate(spec);
  EXPECT_EQ(margin.end, EndReason::Complete) << margin.end_detail;  // no goal the robot may take
  EXPECT_LT(margin.metrics.coverage, 1.0);
  EXPECT_LT(margin.metrics.completeness, 1.0);
  // The robot never enters the alcove below its first cell (5,4), which it sees from the room.
  for (const Cell c : margin.trajectory) EXPECT_LT(c.y, 5) << c.x << ";" << c.y;
  EXPECT_EQ(margin.metrics.dropped_goals, 0);  // excluded, not dropped
  // Recorded only when set.
  EXPECT_FALSE(nlohmann::json(SimParams{}).contains("target_margin_m"));
  EXPECT_EQ(nlohmann::json(spec.sim)["target_margin_m"], 0.6);
}

}  // namespace
}  // namespace fsweep
