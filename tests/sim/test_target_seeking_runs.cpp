// target_seeking runs (src/strategies/target_seeking.hpp) through the simulation loop: the target
// is reached, an unreachable target ends the run with a reason, decisions are taken after
// every step, and without a target the strategy explores completely.
#include <gtest/gtest.h>

#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/config_error.hpp"
#include "planners/registry.hpp"
#include "sim/simulation.hpp"
#include "strategies/registry.hpp"
#include "world/ascii_world.hpp"
#include "world/map_spec.hpp"

namespace fsweep {
namespace {

using nlohmann::json;

// A wall splits the room; the only way round is the gap at x = 7..8.
const std::vector<std::string> kSplitRoom = {
    "##########",  //
    "#S.......#",  //
    "#........#",  //
    "#######..#",  //
    "#........#",  //
    "#........#",  //
    "##########",  //
};

RunSpec spec_for(const WorldMap& map, const json& params, double range_m) {
  RunSpec spec;
  spec.map = std::make_shared<const WorldMap>(map);
  spec.strategy = configure_strategy("target_seeking", params);
  spec.robot.sensor.range_m = range_m;
  spec.seed = 3;
  return spec;
}

TEST(TargetSeekingRuns, ReachesATargetBehindAWall) {
  const RunResult r = simulate(spec_for(test::ascii_world(kSplitRoom), json{{"target", {1, 5}}}, 2.0));
  ASSERT_EQ(r.end, EndReason::TargetReached) << r.end_detail;
  EXPECT_EQ(r.trajectory.back(), (Cell{1, 5}));
  // Any way round passes a gap cell, (7,3) or (8,3); the octile lower bound through (7,3),
  // the nearer: (4 + 2 sqrt2) + (4 + 2 sqrt2).
  const double via_gap = octile_distance(Cell{1, 1}, Cell{7, 3}) + octile_distance(Cell{7, 3}, Cell{1, 5});
  EXPECT_GE(r.metrics.distance_m, via_gap - 1e-9);
  // Metrics: without corner cutting the diagonals into and out of the gap are closed, so the
  // shortest path on the known map is (1,1) -> (7,2) [5 + sqrt2], (7,3), (7,4) [2], -> (1,5)
  // [5 + sqrt2].
  EXPECT_NEAR(r.metrics.target_shortest_m, 12.0 + 2.0 * kSqrt2, 1e-9);
  EXPECT_DOUBLE_EQ(r.metrics.target_path_m, r.metrics.distance_m);
  EXPECT_DOUBLE_EQ(r.metrics.target_path_ratio, r.metrics.distance_m / r.metrics.target_shortest_m);
  EXPECT_GE(r.metrics.target_path_ratio, 1.0);
  // Decided after every step while exploring: at least one decision per step until the target
  // was seen, and the run is deterministic.
  EXPECT_GT(r.metrics.decisions, 5);
  EXPECT_EQ(simulate(spec_for(test::ascii_world(kSplitRoom), json{{"target", {1, 5}}}, 2.0)).trajectory,
            r.trajectory);
}

TEST(TargetSeekingRuns, GradientMotionReachesTargets) {
  const RunResult split = simulate(
      spec_for(test::ascii_world(kSplitRoom), json{{"target", {1, 5}}, {"motion", "gradient"}}, 2.0));
  ASSERT_EQ(split.end, EndReason::TargetReached) << split.end_detail;
  EXPECT_EQ(split.trajectory.back(), (Cell{1, 5}));
  const WorldMap office = load_map_spec("office:w=50,h=40,seed=2");
  const Cell far{office.start.x < 25 ? 47 : 2, office.start.y < 20 ? 37 : 2};
  const Grid<std::uint8_t> reachable = reachable_free(office, office.start, false);
  // The reachable cell nearest to the far corner (row-major scan, first of the smallest).
  Cell target = office.start;
  double best = 1e300;
  for (int i = 0; i < reachable.size(); ++i) {
    if (reachable[i] != 0 && euclidean_distance(reachable.cell(i), far) < best) {
      best = euclidean_distance(reachable.cell(i), far);
      target = reachable.cell(i);
    }
  }
  const json params{{"target", {target.x, target.y}}, {"motion", "gradient"}};
  const RunResult r = simulate(spec_for(office, params, 4.0));
  EXPECT_EQ(r.end, EndReason::TargetReached) << r.end_detail;
  EXPECT_EQ(r.trajectory.back(), target);
  // Not the same walk as shortest_path motion.
  const RunResult sp = simulate(spec_for(office, json{{"target", {target.x, target.y}}}, 4.0));
  EXPECT_EQ(sp.end, EndReason::TargetReached) << sp.end_detail;
  EXPECT_NE(sp.trajectory, r.trajectory);
}

TEST(TargetSeekingRuns, AVisibleTargetIsReachedByTheShortestPath) {
  const std::vector<std::string> open = {
      "#######",  //
      "#S....#",  //
      "#.....#",  //
      "#######",  //
  };
  const RunResult r = simulate(spec_for(test::ascii_world(open), json{{"target", {5, 2}}}, 10.0));
  ASSERT_EQ(r.end, EndReason::TargetReached) << r.end_detail;
  EXPECT_DOUBLE_EQ(r.metrics.distance_m, 3.0 + kSqrt2);  // octile (1,1) -> (5,2)
  EXPECT_EQ(r.metrics.decisions, 2);                     // go to the target; finish there
  EXPECT_DOUBLE_EQ(r.metrics.target_shortest_m, 3.0 + kSqrt2);
  EXPECT_DOUBLE_EQ(r.metrics.target_path_ratio, 1.0);
}

TEST(TargetSeekingRuns, UnreachableTargetsEndWithAReason) {
  // (5,5) is free but walled in; (8,1) is a wall cell; (20,1) is off the map.
  const std::vector<std::string> pocket = {
      "##########",  //
      "#S.......#",  //
      "#........#",  //
      "#...###..#",  //
      "#...#.#..#",  //
      "#...###..#",  //
      "##########",  //
  };
  const WorldMap map = test::ascii_world(pocket);
  const RunResult walled = simulate(spec_for(map, json{{"target", {5, 4}}}, 2.0));
  EXPECT_EQ(walled.end, EndReason::TargetUnreachable);
  EXPECT_NE(walled.end_detail.find("no reachable frontier borders the unknown region of target (5, 4)"),
            std::string::npos)
      << walled.end_detail;
  const RunResult wall = simulate(spec_for(map, json{{"target", {4, 4}}}, 2.0));
  EXPECT_EQ(wall.end, EndReason::TargetUnreachable);
  EXPECT_NE(wall.end_detail.find("occupied"), std::string::npos) << wall.end_detail;
  const RunResult off = simulate(spec_for(map, json{{"target", {20, 1}}}, 2.0));
  EXPECT_EQ(off.end, EndReason::TargetUnreachable);
  EXPECT_NE(off.end_detail.find("outside the 10x7 map"), std::string::npos) << off.end_detail;
  EXPECT_EQ(off.metrics.distance_m, 0.0);
  // Not reached: no path length or ratio; the walled-in cell has no shortest path either.
  EXPECT_EQ(walled.metrics.target_path_m, 0.0);
  EXPECT_EQ(walled.metrics.target_path_ratio, 0.0);
  EXPECT_EQ(walled.metrics.target_shortest_m, 0.0);
  EXPECT_EQ(off.metrics.target_shortest_m, 0.0);
  EXPECT_EQ(to_string(EndReason::TargetUnreachable), "target_unreachable");
  EXPECT_EQ(to_string(EndReason::TargetReached), "target_reached");
}

TEST(TargetSeekingRuns, WithoutTargetExploresCompletelyWithEveryGridPlanner) {
  for (const char* map_text : {"rooms:w=24,h=18,door=3,seed=4", "random:w=24,h=24,p=0.2,seed=3"}) {
    const WorldMap map = load_map_spec(map_text);
    for (const char* planner : {"astar", "dijkstra"}) {
      RunSpec spec = spec_for(map, nullptr, 5.0);
      spec.planner = configure_planner(planner, nullptr);
      const RunResult r = simulate(spec);
      EXPECT_EQ(r.end, EndReason::Complete) << map_text << " " << planner << ": " << r.end_detail;
      EXPECT_DOUBLE_EQ(r.metrics.coverage, 1.0) << map_text << " " << planner;
      EXPECT_EQ(r.metrics.target_shortest_m, 0.0);  // no target: no navigation metrics
    }
  }
}

TEST(TargetSeekingRuns, ReachesRandomReachableTargetsOnGeneratedMaps) {
  const WorldMap map = load_map_spec("office:w=50,h=40,seed=2");
  const Grid<std::uint8_t> reachable = reachable_free(map, map.start, false);
  int tried = 0;
  for (int i = reachable.size() - 1; i >= 0 && tried < 4; i -= 397) {
    if (reachable[i] == 0) continue;
    ++tried;
    const Cell t = reachable.cell(i);
    const RunResult r = simulate(spec_for(map, json{{"target", {t.x, t.y}}}, 4.0));
    EXPECT_EQ(r.end, EndReason::TargetReached) << t.x << "," << t.y << " " << r.end_detail;
    EXPECT_EQ(r.trajectory.back(), t);
  }
  EXPECT_EQ(tried, 4);
}

TEST(TargetSeekingRuns, RandomTargetIsDrawnPerSeedAmongReachableFreeCells) {
  const WorldMap map = load_map_spec("rooms:w=30,h=24,door=3,seed=5");
  const Grid<std::uint8_t> reachable = reachable_free(map, map.start, false);
  const json params{{"target", "random"}, {"w1", 1}, {"w2", 0.9}, {"w3", 0.4}};
  std::vector<Cell> targets;
  for (const std::uint64_t seed : {1U, 2U, 3U, 4U}) {
    RunSpec spec = spec_for(map, params, 3.0);
    spec.seed = seed;
    const RunResult r = simulate(spec);
    const Cell t{r.metrics.target_x, r.metrics.target_y};
    ASSERT_TRUE(map.occupied.in_bounds(t)) << seed;
    EXPECT_TRUE(map.is_free(t)) << seed;
    EXPECT_NE(reachable.at(t), 0) << seed;
    EXPECT_NE(t, map.start) << seed;
    // Reachable targets are reached, the run's metrics are about the drawn cell.
    EXPECT_EQ(r.end, EndReason::TargetReached) << seed << " " << r.end_detail;
    EXPECT_EQ(r.trajectory.back(), t) << seed;
    EXPECT_GT(r.metrics.target_shortest_m, 0.0) << seed;
    // The same seed draws the same target (and runs the same way).
    const RunResult again = simulate(spec);
    EXPECT_EQ(again.metrics.target_x, t.x);
    EXPECT_EQ(again.metrics.target_y, t.y);
    EXPECT_EQ(again.trajectory, r.trajectory);
    // The drawn cell is resolve_random_target's, which depends only on the stream "target".
    const json resolved = resolve_random_target(params, reachable, map.start, seed);
    EXPECT_EQ(resolved.at("target"), (json{t.x, t.y}));
    EXPECT_EQ(resolved.at("w2"), params.at("w2"));
    targets.push_back(t);
  }
  // Different seeds, different targets (hundreds of candidate cells).
  for (std::size_t i = 0; i < targets.size(); ++i) {
    for (std::size_t j = i + 1; j < targets.size(); ++j) EXPECT_NE(targets[i], targets[j]) << i << " " << j;
  }
  // A given target is recorded as given; no target records -1.
  EXPECT_EQ(simulate(spec_for(test::ascii_world(kSplitRoom), json{{"target", {1, 5}}}, 2.0)).metrics.target_y,
            5);
  RunSpec none = spec_for(test::ascii_world(kSplitRoom), nullptr, 2.0);
  EXPECT_EQ(simulate(none).metrics.target_x, -1);
  // Params without "random" come back unchanged; the only candidate is taken; none is an error.
  EXPECT_EQ(resolve_random_target(json{{"target", {2, 3}}}, reachable, map.start, 1),
            (json{{"target", {2, 3}}}));
  Grid<std::uint8_t> two(3, 1, 0);
  two.at(Cell{0, 0}) = 1;
  two.at(Cell{2, 0}) = 1;
  EXPECT_EQ(resolve_random_target(json{{"target", "random"}}, two, Cell{0, 0}, 9).at("target"), (json{2, 0}));
  Grid<std::uint8_t> alone(3, 1, 0);
  alone.at(Cell{0, 0}) = 1;
  EXPECT_THROW((void)resolve_random_target(json{{"target", "random"}}, alone, Cell{0, 0}, 9), ConfigError);
  // The strategy accepts "random" (sweep validation builds it) but knows no cell before the
  // simulation resolves it; the parameter is recorded as "random" (same run configuration for
  // every drawn target).
  EXPECT_FALSE(make_strategy("target_seeking", json{{"target", "random"}}, 1)->target().has_value());
  EXPECT_EQ(configure_strategy("target_seeking", params).params.at("target"), "random");
}

TEST(TargetSeekingRuns, StopAtCellTurnsClosestFrontierIntoANavigationBaseline) {
  // Fixed cell: closest_frontier explores until (1, 5) is known free and reachable, then goes
  // there by the shortest path and the run ends target_reached on it.
  RunSpec spec = spec_for(test::ascii_world(kSplitRoom), nullptr, 2.0);
  spec.strategy = configure_strategy("closest_frontier", nullptr);
  spec.sim = sim_params_from_json(json{{"stop_at_cell", {1, 5}}}, "sim");
  const RunResult r = simulate(spec);
  ASSERT_EQ(r.end, EndReason::TargetReached) << r.end_detail;
  EXPECT_EQ(r.trajectory.back(), (Cell{1, 5}));
  EXPECT_EQ(r.metrics.target_x, 1);
  EXPECT_EQ(r.metrics.target_y, 5);
  EXPECT_NEAR(r.metrics.target_shortest_m, 12.0 + 2.0 * kSqrt2, 1e-9);  // as ReachesATargetBehindAWall
  EXPECT_DOUBLE_EQ(r.metrics.target_path_m, r.metrics.distance_m);
  EXPECT_DOUBLE_EQ(r.metrics.target_path_ratio, r.metrics.distance_m / r.metrics.target_shortest_m);
  // Without the stop cell the same run explores the whole room, farther.
  RunSpec plain = spec;
  plain.sim = SimParams{};
  const RunResult full = simulate(plain);
  EXPECT_EQ(full.end, EndReason::Complete);
  EXPECT_GT(full.metrics.distance_m, r.metrics.distance_m);
  EXPECT_EQ(full.metrics.target_x, -1);

  // "random": the same cell as target_seeking's "target": "random" with the same seed.
  const WorldMap map = load_map_spec("rooms:w=30,h=24,door=3,seed=5");
  RunSpec ts = spec_for(map, json{{"target", "random"}}, 3.0);
  RunSpec cf = spec_for(map, nullptr, 3.0);
  cf.strategy = configure_strategy("closest_frontier", nullptr);
  cf.sim = sim_params_from_json(json{{"stop_at_cell", "random"}}, "sim");
  for (const std::uint64_t seed : {7U, 8U}) {
    ts.seed = seed;
    cf.seed = seed;
    const RunResult a = simulate(ts);
    const RunResult b = simulate(cf);
    EXPECT_EQ(b.end, EndReason::TargetReached) << b.end_detail;
    EXPECT_EQ(a.metrics.target_x, b.metrics.target_x);
    EXPECT_EQ(a.metrics.target_y, b.metrics.target_y);
    EXPECT_EQ(b.trajectory.back(), (Cell{b.metrics.target_x, b.metrics.target_y}));
    EXPECT_DOUBLE_EQ(a.metrics.target_shortest_m, b.metrics.target_shortest_m);
  }

  // JSON: absent -> left out of to_json (run keys unchanged); given -> written back; bad -> error.
  EXPECT_FALSE(json(SimParams{}).contains("stop_at_cell"));
  EXPECT_EQ(json(sim_params_from_json(json{{"stop_at_cell", {3, 4}}}, "sim")).at("stop_at_cell"),
            (json{3, 4}));
  EXPECT_EQ(json(sim_params_from_json(json{{"stop_at_cell", "random"}}, "sim")).at("stop_at_cell"), "random");
  for (const json& bad :
       {json{{"stop_at_cell", {-1, 2}}}, json{{"stop_at_cell", "near"}}, json{{"stop_at_cell", 3}}}) {
    try {
      (void)sim_params_from_json(bad, "sim");
      ADD_FAILURE() << bad.dump();
    } catch (const ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find("sim/stop_at_cell"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace fsweep
