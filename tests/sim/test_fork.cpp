// Forking a run (copying a Simulation, as a search over weight vectors does at every decision):
// a fork run to the end gives exactly the result of the run it was forked from, for every
// strategy (some keep state: random streams, the previous goal) and heuristic, and a fork shares
// no mutable state with its original.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "planners/registry.hpp"
#include "sim/effort_free.hpp"
#include "sim/heuristics.hpp"
#include "sim/simulation.hpp"
#include "strategies/registry.hpp"
#include "world/map_spec.hpp"

namespace fsweep {
namespace {

using nlohmann::json;

/// A run with every source of state in play: a battery (recharges, dock distances), a sensor
/// that misses cells (the "sensor" stream), the strategy's own seed.
RunSpec fork_spec(const std::string& strategy, json heuristics) {
  static const auto kMap = std::make_shared<const WorldMap>(load_map_spec("office:w=50,h=40,seed=2"));
  RunSpec s;
  s.map = kMap;
  s.strategy = configure_strategy(strategy, nullptr);
  s.heuristics = heuristics_from_json(heuristics, "heuristics");
  s.robot.sensor.range_m = 5.0;
  s.robot.sensor.miss_probability = 0.05;
  s.robot.battery_capacity = 250.0;
  s.seed = 11;
  return s;
}

using test::without_timing;

/// Every field of the two results equal (RunResult's operator==), timings aside; the parts
/// are checked one by one so that a failure says which.
void expect_same_result(const RunResult& expected, const RunResult& actual, const std::string& what) {
  const RunResult a = without_timing(expected);
  const RunResult b = without_timing(actual);
  EXPECT_EQ(a.end, b.end) << what;
  EXPECT_EQ(a.end_detail, b.end_detail) << what;
  EXPECT_TRUE(a.metrics == b.metrics) << what << ": metrics differ";
  EXPECT_TRUE(a.progress == b.progress) << what << ": progress differs";
  EXPECT_TRUE(a.trajectory == b.trajectory) << what << ": trajectory differs";
  EXPECT_EQ(a.recharge_steps, b.recharge_steps) << what;
  EXPECT_TRUE(a.final_known == b.final_known) << what << ": final map differs";
  EXPECT_EQ(a.final_frontiers, b.final_frontiers) << what;
  EXPECT_TRUE(a == b) << what;
}

TEST(Fork, AForkRunToTheEndGivesTheOriginalsResultForEveryStrategyAndHeuristic) {
  const std::vector<int> fork_at{0, 1, 2, 5, 13, 40};  // decisions made before the fork
  for (const std::string& name : strategy_names()) {
    for (const json& h : {json::array(), json({"rr", "seg"})}) {
      const std::string what = name + " " + h.dump();
      const RunSpec spec = fork_spec(name, h);
      const RunResult reference = simulate(spec);
      Simulation sim(spec);
      std::vector<std::pair<int, Simulation>> forks;
      for (int decisions = 0; !sim.ended(); ++decisions) {
        if (std::find(fork_at.begin(), fork_at.end(), decisions) != fork_at.end()) {
          forks.emplace_back(decisions, sim);
        }
        sim.step();
      }
      forks.emplace_back(-1, sim);  // forked after the end
      ASSERT_GE(forks.size(), 4U) << what << ": the run is too short to fork at several decisions";
      expect_same_result(reference, sim.result(), what + ", the original after forking");
      for (auto& [at, fork] : forks) {
        expect_same_result(reference, fork.run(),
                           what + ", forked after " + std::to_string(at) + " decisions");
      }
    }
  }
}

TEST(Fork, AdvancingAForkLeavesTheOriginalAsItWas) {
  for (const char* name : {"energy_aware", "random_frontier"}) {  // dock distances; a random stream
    const RunSpec spec = fork_spec(name, json({"rr", "seg"}));
    const RunResult reference = simulate(spec);
    Simulation sim(spec);
    for (int i = 0; i < 8; ++i) ASSERT_TRUE(sim.step()) << name;
    const RunResult before = sim.result();
    const KnownMap known_before = sim.known();
    const Cell robot_before = sim.robot();

    Simulation fork = sim;
    for (int i = 0; i < 10 && fork.step(); ++i) {
    }
    EXPECT_NE(fork.known().known_count(), known_before.known_count()) << name << ": the fork did not move on";
    EXPECT_TRUE(sim.known() == known_before) << name;
    EXPECT_EQ(sim.robot(), robot_before) << name;
    expect_same_result(before, sim.result(), std::string(name) + ", the original while the fork advanced");

    // The other way round: the original runs to its end, then the fork still finishes as the
    // original did (both from where they were).
    expect_same_result(reference, sim.run(), std::string(name) + ", the original run after the fork");
    expect_same_result(reference, fork.run(), std::string(name) + ", the fork run after the original");
  }
}

TEST(Fork, ForksRunOnSeveralThreadsAtOnceGiveTheOriginalsResult) {
  // The forks share the run's immutable setup and, until they update it, the dock's distance
  // field (copy-on-write): each must still finish as the original does.
  const RunSpec spec = fork_spec("energy_aware", json::array());
  const RunResult reference = simulate(spec);
  Simulation sim(spec);
  for (int i = 0; i < 4; ++i) ASSERT_TRUE(sim.step());
  std::vector<Simulation> forks(4, sim);
  std::vector<RunResult> results(forks.size());
  std::vector<std::thread> threads;
  for (std::size_t i = 0; i < forks.size(); ++i) {
    threads.emplace_back([&, i] { results[i] = forks[i].run(); });
  }
  for (auto& t : threads) t.join();
  for (const RunResult& r : results) expect_same_result(reference, r, "a fork on its own thread");
  expect_same_result(reference, sim.run(), "the original after its forks");
}

TEST(Fork, RunsKeepingWhatEachCellSeesGiveTheSameResults) {
  // Simulation::keep_sight(): a run and its forks, on several threads, fill and read one
  // SightTable of the map; each finishes as a run without one (every strategy; a sensor that
  // misses cells, and one with a field of view of 120 degrees that looks around).
  for (const double fov : {360.0, 120.0}) {
    for (const std::string& name : strategy_names()) {
      RunSpec spec = fork_spec(name, json::array());
      spec.robot.sensor.fov_deg = fov;
      const std::string what = name + " fov " + std::to_string(fov);
      const RunResult reference = simulate(spec);
      Simulation sim(spec);
      sim.keep_sight();
      for (int i = 0; i < 3 && sim.step(); ++i) {
      }
      std::vector<Simulation> forks(3, sim);
      std::vector<RunResult> results(forks.size());
      std::vector<std::thread> threads;
      for (std::size_t i = 0; i < forks.size(); ++i) {
        threads.emplace_back([&, i] { results[i] = forks[i].run(); });
      }
      expect_same_result(reference, sim.run(), what + ", the run keeping what it sees");
      for (auto& t : threads) t.join();
      for (const RunResult& r : results)
        expect_same_result(reference, r, what + ", a fork on its own thread");
      // The table was made and filled (a grid sensor of 5 cells on a 50 x 40 map).
      ASSERT_NE(sim.setup().sight(), nullptr) << what;
      int filled = 0;
      for (int i = 0; i < 50 * 40; ++i) filled += sim.setup().sight()->filled(i) ? 1 : 0;
      EXPECT_GT(filled, 10) << what;
    }
  }
}

TEST(Fork, AJourneyOnTheProbesPathIsTheJourneyAstarPlans) {
  // A journey to a goal whose length a probe measured takes the probe's path
  // (PlanRequest::searched); `astar` with an expansion budget searches for itself. Both runs, and
  // a fork of each taken mid-run, must be the same, planner expansions included.
  for (const std::string& name : {std::string("energy_aware"), std::string("closest_frontier")}) {
    RunSpec own = fork_spec(name, json::array());
    own.planner = configure_planner("astar", json{{"max_expansions", 1000000000}});
    const RunResult reference = simulate(own);
    const RunSpec spec = fork_spec(name, json::array());
    Simulation sim(spec);
    for (int i = 0; i < 6 && sim.step(); ++i) {
    }
    Simulation fork = sim;
    Simulation assigned(spec);
    assigned = sim;  // assignment drops the paths the target's own probes found
    expect_same_result(reference, sim.run(), name + ", probes' paths");
    expect_same_result(reference, fork.run(), name + ", a fork");
    expect_same_result(reference, assigned.run(), name + ", an assigned copy");
  }
}

TEST(Fork, CopyAssignmentAndMoveCarryTheWholeRun) {
  const RunSpec spec = fork_spec("random_frontier", json::array());
  const RunResult reference = simulate(spec);
  Simulation sim(spec);
  for (int i = 0; i < 6; ++i) ASSERT_TRUE(sim.step());
  Simulation assigned(fork_spec("closest_frontier", json({"seg"})));  // another run, overwritten
  ASSERT_TRUE(assigned.step());
  assigned = sim;
  Simulation moved = std::move(sim);
  expect_same_result(reference, assigned.run(), "copy-assigned");
  expect_same_result(reference, moved.run(), "moved");
}

}  // namespace
}  // namespace fsweep
