// A coverage target (sim.stop_at_coverage) ends a run `target_reached` at the scan that reaches
// the share: the run is the run without a target up to that scan. The lower bound the weight
// search prunes by (Simulation::coverage_target_bound_m) never exceeds the distance it bounds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "core/config_error.hpp"
#include "sim/simulation.hpp"
#include "strategies/registry.hpp"
#include "world/ascii_world.hpp"
#include "world/energy_model.hpp"
#include "world/map_spec.hpp"

namespace fsweep {
namespace {

using nlohmann::json;

RunSpec rooms_run(const std::string& strategy) {
  RunSpec spec;
  spec.map = std::make_shared<const WorldMap>(load_map_spec("rooms:w=30,h=24,door=3,seed=5"));
  spec.strategy = configure_strategy(strategy, nullptr);
  spec.robot.sensor.range_m = 3.0;
  spec.seed = 7;
  return spec;
}

TEST(CoverageTarget, EndsTheRunAtTheScanThatReachesTheShare) {
  RunSpec spec = rooms_run("closest_frontier");
  const RunResult full = simulate(spec);
  ASSERT_EQ(full.end, EndReason::Complete);
  EXPECT_FALSE(full.metrics.distance_to_coverage_target_m.has_value());
  double previous = 0.0;
  for (const double share : {0.25, 0.5, 0.9, 1.0}) {
    spec.sim.stop_at_coverage = share;
    const RunResult r = simulate(spec);
    ASSERT_EQ(r.end, EndReason::TargetReached) << share << ": " << r.end_detail;
    EXPECT_NE(r.end_detail.find("coverage target"), std::string::npos) << r.end_detail;
    EXPECT_GE(r.metrics.coverage, share);
    ASSERT_TRUE(r.metrics.distance_to_coverage_target_m.has_value());
    EXPECT_EQ(*r.metrics.distance_to_coverage_target_m, r.metrics.distance_m);
    EXPECT_EQ(r.metrics.distance_to_final_coverage_m, r.metrics.distance_m);
    // The same run as without the target, up to where it stopped.
    ASSERT_LE(r.trajectory.size(), full.trajectory.size());
    EXPECT_TRUE(std::equal(r.trajectory.begin(), r.trajectory.end(), full.trajectory.begin())) << share;
    EXPECT_GE(r.metrics.distance_m, previous);
    previous = r.metrics.distance_m;
  }
  // The whole reachable area is known at the full run's last reveal at the latest (walls may
  // be revealed after it).
  EXPECT_LE(previous, full.metrics.distance_to_final_coverage_m);
  EXPECT_LT(previous, full.metrics.distance_m) << "the full run travels on after its last reveal";
}

TEST(CoverageTarget, ARunThatNeverReachesItHasNoDistanceToIt) {
  // A battery too small to see the far rooms: the run ends range_limited below the share.
  RunSpec spec = rooms_run("closest_frontier");
  spec.robot.battery_capacity = 20.0;
  spec.sim.stop_at_coverage = 0.95;
  const RunResult r = simulate(spec);
  ASSERT_NE(r.end, EndReason::TargetReached) << r.end_detail;
  EXPECT_LT(r.metrics.coverage, 0.95);
  EXPECT_FALSE(r.metrics.distance_to_coverage_target_m.has_value());
}

TEST(CoverageTarget, TheSearchsBoundNeverExceedsTheDistanceToTheTarget) {
  for (const std::string strategy : {"closest_frontier", "energy_aware"}) {
    RunSpec spec = rooms_run(strategy);
    spec.sim.stop_at_coverage = 0.9;
    Simulation sim(spec);
    std::vector<double> bounds{sim.coverage_target_bound_m()};
    while (sim.step()) bounds.push_back(sim.coverage_target_bound_m());
    bounds.push_back(sim.coverage_target_bound_m());
    const RunResult r = sim.result();
    ASSERT_TRUE(r.metrics.distance_to_coverage_target_m.has_value()) << strategy;
    const double reached = *r.metrics.distance_to_coverage_target_m;
    for (std::size_t i = 0; i < bounds.size(); ++i)
      EXPECT_LE(bounds[i], reached) << strategy << " step " << i;
    EXPECT_EQ(bounds.back(), reached);
    // At the start, far more cells are needed than one sensor disc holds: the bound says so.
    EXPECT_GT(bounds.front(), 0.0) << strategy;
  }
}

// Rappaport's Manhattan class: the runs spend most of their distance going back to the dock, which
// the bound counts (reveal_bound.hpp). Every step, several weights, a dock away from the start and
// an energy model with turn costs (whose battery holds fewer metres than its charge).
TEST(CoverageTarget, TheBatteryAwareBoundNeverExceedsTheDistanceOnStreetGrids) {
  struct Case {
    int map_seed;
    json weights;
    std::string energy;
    std::optional<Cell> dock;
    double over_tube;  // the bound at the start over the tube's alone, at least
  };
  // mei2006's battery of 300 holds 1,500 m (1 per 5 m cell) against 1,200 m: fewer trips.
  const std::vector<Case> cases{
      {1, json{{"w1", 4}, {"w2", 0}, {"w3", 3}, {"w4", 7}}, "distance", std::nullopt, 1.15},
      {2, json{{"w1", 0}, {"w2", 1}, {"w3", 0}, {"w4", 0}}, "distance", std::nullopt, 1.15},
      {3, json{{"w1", 220}, {"w2", 21}, {"w3", 104}, {"w4", 100}}, "mei2006", Cell{116, 120}, 1.02}};
  for (const Case& c : cases) {
    RunSpec spec;
    spec.map = std::make_shared<const WorldMap>(
        load_map_spec("manhattan:w=241,h=241,res=5,block=16,street=4,seed=" + std::to_string(c.map_seed)));
    spec.strategy = configure_strategy("energy_aware", c.weights);
    spec.robot.sensor.range_m = 30.0;
    spec.robot.battery_capacity = c.energy == "distance" ? 1200.0 : 300.0;
    spec.robot.energy = energy_preset(c.energy);
    spec.robot.dock = c.dock;
    spec.sim.stop_at_coverage = 0.5;
    Simulation sim(spec);
    // The tube alone at the start: the travel within R of which the needed cells fit.
    const double reach = 30.0 + 5.0 * std::sqrt(0.5);
    const double needed_m2 = 0.5 * sim.metrics_so_far().reachable_area_m2 - sim.known().free_count() * 25.0;
    const double tube = (needed_m2 - std::numbers::pi * reach * reach) / (2.0 * reach);
    std::vector<double> bounds{sim.coverage_target_bound_m()};
    while (sim.step()) bounds.push_back(sim.coverage_target_bound_m());
    const RunResult r = sim.result();
    ASSERT_TRUE(r.metrics.distance_to_coverage_target_m.has_value()) << c.map_seed << ": " << r.end_detail;
    const double reached = *r.metrics.distance_to_coverage_target_m;
    for (std::size_t i = 0; i < bounds.size(); ++i)
      ASSERT_LE(bounds[i], reached) << c.map_seed << " step " << i;
    EXPECT_GT(bounds.front(), c.over_tube * tube) << c.map_seed << ": the trips to the far streets count";
  }
}

TEST(CoverageTarget, TheBoundDependsOnTheStateAloneNotOnWhenItWasAskedFor) {
  // A run asked at every step (its counts kept up to date scan by scan, its last value kept)
  // against fresh runs asked once at the same step, and a fork asked only after moving on.
  RunSpec spec = rooms_run("energy_aware");
  spec.robot.battery_capacity = 60.0;
  spec.sim.stop_at_coverage = 0.9;
  Simulation every(spec);
  std::vector<double> bounds{every.coverage_target_bound_m()};
  while (every.step()) bounds.push_back(every.coverage_target_bound_m());
  ASSERT_GT(bounds.size(), 10U);
  for (std::size_t n = 0; n < bounds.size(); n += 3) {
    Simulation once(spec);
    for (std::size_t k = 0; k < n; ++k) ASSERT_TRUE(once.step());
    EXPECT_EQ(once.coverage_target_bound_m(), bounds[n]) << "step " << n;
  }
  Simulation asked(spec);
  (void)asked.coverage_target_bound_m();
  Simulation fork = asked;
  for (int k = 0; k < 5; ++k) ASSERT_TRUE(fork.step());
  EXPECT_EQ(fork.coverage_target_bound_m(), bounds[5]);
  EXPECT_EQ(asked.coverage_target_bound_m(), bounds[0]);
}

TEST(CoverageTarget, ADockTheStartCannotReachLeavesTheTubeAlone) {
  // The dock is free but walled off from the start: no trips to it are counted (every cell's
  // bin is -1), and every scan's reveals still keep the counts right.
  RunSpec spec;
  spec.map = std::make_shared<const WorldMap>(test::ascii_world({
      "S.......#...",
      "........#...",
      "........#...",
      "........#...",
      "........#...",
  }));
  spec.strategy = configure_strategy("closest_frontier", nullptr);
  spec.robot.sensor.range_m = 2.0;
  spec.robot.dock = Cell{10, 2};
  spec.sim.stop_at_coverage = 0.9;
  Simulation sim(spec);
  std::vector<double> bounds{sim.coverage_target_bound_m()};
  while (sim.step()) bounds.push_back(sim.coverage_target_bound_m());
  const RunResult r = sim.result();
  ASSERT_TRUE(r.metrics.distance_to_coverage_target_m.has_value()) << r.end_detail;
  for (const double b : bounds) EXPECT_LE(b, *r.metrics.distance_to_coverage_target_m);
  EXPECT_GT(bounds.front(), 0.0);
}

TEST(CoverageTarget, IsReadAndWrittenOnlyWhenSet) {
  EXPECT_FALSE(json(SimParams{}).contains("stop_at_coverage")) << "run keys without a target unchanged";
  EXPECT_EQ(json(sim_params_from_json(json{{"stop_at_coverage", 0.9}}, "sim")).at("stop_at_coverage"), 0.9);
  for (const json& bad : {json{{"stop_at_coverage", -0.1}}, json{{"stop_at_coverage", 1.5}},
                          json{{"stop_at_coverage", "most"}}}) {
    try {
      (void)sim_params_from_json(bad, "sim");
      ADD_FAILURE() << bad.dump();
    } catch (const ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find("sim/stop_at_coverage"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace fsweep
