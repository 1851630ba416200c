/// The offline optimum's bounds: exact against an exhaustive search written independently of the
/// solver, never above a complete online run, and routes that reveal everything when replayed.

#include <gtest/gtest.h>

#include <cstdint>
#include <initializer_list>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <queue>
#include <set>

#include "core/config_error.hpp"
#include "optimum/optimum.hpp"
#include "search/octile_grid.hpp"
#include "sim/simulation.hpp"
#include "world/ascii_world.hpp"
#include "world/map_spec.hpp"
#include "world/sensor.hpp"

namespace fsweep {
namespace {

RunSpec spec_of(WorldMap map, double range_m) {
  RunSpec spec;
  spec.map = std::make_shared<const WorldMap>(std::move(map));
  spec.robot.sensor.range_m = range_m;
  return spec;
}

/// The optimum by exhaustive search over (cell, set of revealed cells), written from the problem
/// statement only: what a scan from each reachable cell reveals (the simulation's Sensor on an
/// empty map), the targets as the union of those, Dijkstra over the states with the planners'
/// moves. Returns +infinity when no route reveals every target.
double brute_force_optimum(const RunSpec& spec) {
  const WorldMap& map = *spec.map;
  KnownMap truth(map.width(), map.height(), map.resolution_m);
  for (int i = 0; i < map.width() * map.height(); ++i) truth.reveal(i, !map.is_free(i));
  const Grid<std::uint8_t> reachable = reachable_free(map, map.start, spec.robot.allow_corner_cutting);
  Sensor sensor(spec.robot.sensor, map.resolution_m);
  Rng rng(1);
  std::map<int, std::set<int>> sees;  // cell -> revealed cells
  std::map<int, int> bit;             // target cell -> bit
  for (int i = 0; i < map.width() * map.height(); ++i) {
    if (reachable[i] == 0) continue;
    KnownMap empty(map.width(), map.height(), map.resolution_m);
    for (const int c : sensor.scan(map, empty, truth.cell(i), 0.0, rng)) {
      sees[i].insert(c);
      bit.emplace(c, 0);
    }
  }
  int next = 0;
  for (auto& [cell, b] : bit) b = next++;
  EXPECT_LE(next, 64) << "too many targets for the brute force";
  const std::uint64_t full = next == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << next) - 1;
  const auto mask_of = [&](int cell) {
    std::uint64_t m = 0;
    for (const int c : sees[cell]) m |= std::uint64_t{1} << bit[c];
    return m;
  };
  using Item = std::tuple<double, int, std::uint64_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  std::map<std::pair<int, std::uint64_t>, double> best;
  const int start = truth.index(map.start);
  open.emplace(0.0, start, mask_of(start));
  best[{start, mask_of(start)}] = 0.0;
  while (!open.empty()) {
    const auto [g, cell, mask] = open.top();
    open.pop();
    if (g > best[{cell, mask}]) continue;
    if (mask == full) return g;
    const Cell a = truth.cell(cell);
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const Cell b{a.x + dx, a.y + dy};
        if (!octile_step_allowed(truth, a, b, spec.robot.allow_corner_cutting)) continue;
        const int nb = truth.index(b);
        const double ng = g + (dx != 0 && dy != 0 ? kSqrt2 : 1.0) * map.resolution_m;
        const std::uint64_t nm = mask | mask_of(nb);
        const auto it = best.find({nb, nm});
        if (it != best.end() && it->second <= ng) continue;
        best[{nb, nm}] = ng;
        open.emplace(ng, nb, nm);
      }
    }
  }
  return std::numeric_limits<double>::infinity();
}

const std::vector<std::vector<std::string>>& small_maps() {
  static const std::vector<std::vector<std::string>> maps{
      {"#######", "#S....#", "#######"},
      {"#######", "#S.#..#", "#.....#", "#..#..#", "#######"},
      {"########", "#S.....#", "####.###", "#......#", "########"},
      {"#######", "#..#..#", "#.S...#", "#..#..#", "#######"},
      {"#########", "#S#.....#", "#.#.###.#", "#...#...#", "#########"},
      {"######", "#S...#", "#.##.#", "#....#", "######"},
  };
  return maps;
}

TEST(Optimum, ExactOnSmallMapsEqualsAnExhaustiveSearch) {
  for (const double range : {1.5, 2.0, 3.0}) {
    for (const auto& rows : small_maps()) {
      const RunSpec spec = spec_of(test::ascii_world(rows), range);
      const double truth = brute_force_optimum(spec);
      const OptimumResult r = solve_optimum(spec);
      SCOPED_TRACE(rows[1] + " range " + std::to_string(range));
      EXPECT_TRUE(r.exact);
      EXPECT_NEAR(r.lower_m, truth, 1e-9);
      EXPECT_NEAR(r.upper_m, truth, 1e-9);
      EXPECT_LT(r.time_s, 5.0);
    }
  }
}

TEST(Optimum, GeneratedSmallMapsAreExactAndAgreeWithTheExhaustiveSearch) {
  for (int seed = 1; seed <= 6; ++seed) {
    RunMap m = load_run_map_spec("rooms:w=9,h=7,door=1,min_room=3,seed=" + std::to_string(seed));
    const RunSpec spec = spec_of(std::move(m.map), 2.0);
    const OptimumResult r = solve_optimum(spec);
    SCOPED_TRACE("seed " + std::to_string(seed) + " targets " + std::to_string(r.targets));
    if (r.targets > 40) continue;
    const double truth = brute_force_optimum(spec);
    EXPECT_TRUE(r.exact);
    EXPECT_NEAR(r.lower_m, truth, 1e-9);
  }
}

/// The solver as the short tests run it: 250 of the witness search's 1,000 trials and 4 of the
/// route's 64 covers (both only tighten a bound, and every test still checks the bounds it gets).
/// The long test and the benchmarks run the defaults.
OptimumOptions short_test_options() {
  OptimumOptions o;
  o.lower.witness_swaps = 250;
  o.route.restarts = 4;
  return o;
}

/// The options check_runs_above_lower_bound() solves with (the long test sets the defaults).
OptimumOptions& check_options() {
  static OptimumOptions options = short_test_options();
  return options;
}

/// Runs `spec` with each strategy and seeds 1..seeds; every run that ends complete with
/// completeness 1 is checked to be at or above `lower_m`. Returns how many were checked.
int check_complete_runs(RunSpec spec, double lower_m, std::initializer_list<const char*> strategies,
                        int seeds) {
  int checked = 0;
  for (const char* strategy : strategies) {
    for (int seed = 1; seed <= seeds; ++seed) {
      spec.strategy = configure_strategy(strategy, nullptr);
      spec.seed = static_cast<std::uint64_t>(seed);
      const RunResult run = simulate(spec);
      if (run.end != EndReason::Complete || run.metrics.completeness < 1.0) continue;
      ++checked;
      EXPECT_GE(run.metrics.distance_to_final_coverage_m, lower_m) << strategy << " seed " << seed;
    }
  }
  return checked;
}

/// Bounds, and every complete online run (completeness 1) at or above the lower bound.
int check_runs_above_lower_bound(const std::string& map_spec, double range_m, int seeds,
                                 double battery = std::numeric_limits<double>::infinity(),
                                 double miss_probability = 0.0) {
  RunMap m = load_run_map_spec(map_spec);
  RunSpec spec = spec_of(std::move(m.map), range_m);
  spec.robot.battery_capacity = battery;
  spec.robot.sensor.miss_probability = miss_probability;
  const OptimumResult r = solve_optimum(spec, check_options());
  SCOPED_TRACE(map_spec);
  EXPECT_LE(r.lower_m, r.upper_m);
  EXPECT_LT(r.upper_m, std::numeric_limits<double>::infinity());
  const CoverageInstance in = build_coverage_instance(spec);
  const RouteReplay replay = replay_route(in, spec, r.route);
  EXPECT_TRUE(replay.covers());
  EXPECT_DOUBLE_EQ(replay.distance_to_final_coverage_m, r.upper_m);
  return check_complete_runs(spec, r.lower_m,
                             {"closest_frontier", "energy_aware", "random_frontier", "widest_frontier",
                              "orientation", "gbl", "mcdm"},
                             seeds);
}

TEST(Optimum, CompleteRunsAreNeverBelowTheLowerBound) {
  EXPECT_GT(check_runs_above_lower_bound("rooms:w=30,h=24,door=2,seed=3", 4.0, 2), 0);
  EXPECT_GT(check_runs_above_lower_bound("office:w=40,h=32,seed=2", 5.0, 1), 0);
  EXPECT_GT(check_runs_above_lower_bound("random:w=24,h=24,p=0.2,seed=5", 3.0, 2), 0);
  EXPECT_GT(check_runs_above_lower_bound("oldtown:w=48,h=48,seed=1", 4.0, 1), 0);
}

TEST(Optimum, WithABatteryTheRouteIsSplitIntoTripsThatReplayWithinEachCharge) {
  RunMap m = load_run_map_spec("rooms:w=40,h=30,door=2,seed=4");
  RunSpec spec = spec_of(std::move(m.map), 4.0);
  spec.robot.battery_capacity = 150.0;
  const OptimumResult r = solve_optimum(spec, short_test_options());
  ASSERT_LT(r.upper_m, std::numeric_limits<double>::infinity());
  EXPECT_GT(r.trips, 1);
  const CoverageInstance in = build_coverage_instance(spec);
  EXPECT_EQ(in.out_of_reach, 0);
  const RouteReplay replay = replay_route(in, spec, r.route);
  EXPECT_TRUE(replay.covers());
  EXPECT_EQ(replay.trips, r.trips);
  // Without the battery the optimum can only be shorter: the same lower bound holds.
  RunSpec unlimited = spec;
  unlimited.robot.battery_capacity = std::numeric_limits<double>::infinity();
  EXPECT_LE(solve_optimum(unlimited, short_test_options()).lower_m, r.upper_m);
  EXPECT_GT(check_runs_above_lower_bound("rooms:w=40,h=30,door=2,seed=4", 4.0, 1, 150.0), 0);
}

TEST(Optimum, TheWitnessSearchTheViewpointMovesAndTheRestartsOnlyTightenTheBounds) {
  // Each improvement is kept only when it tightens its bound, so with it the bounds are at
  // least as tight as without it, and on some of these maps strictly tighter; the routes replay.
  // (The restarts include the plain cover; the moves are compared on that one cover.)
  int raised = 0;
  int shortened = 0;
  int restarts_helped = 0;
  for (const char* map :
       {"rooms:w=30,h=24,door=2,seed=3", "oldtown:w=48,h=48,seed=1", "office:w=40,h=32,seed=2"}) {
    SCOPED_TRACE(map);
    RunMap m = load_run_map_spec(map);
    const RunSpec spec = spec_of(std::move(m.map), 4.0);
    const CoverageInstance in = build_coverage_instance(spec);
    LowerBoundOptions without_search;
    without_search.witness_swaps = 0;
    const double plain = CoverageLowerBound(in, without_search).at_start();
    const double searched = CoverageLowerBound(in, short_test_options().lower).at_start();
    EXPECT_GE(searched, plain);
    raised += searched > plain ? 1 : 0;
    RouteOptions one_cover;
    one_cover.restarts = 1;
    RouteOptions without_moves = one_cover;
    without_moves.max_relocations = 0;
    const double unmoved =
        replay_route(in, spec, cover_route(in, spec, without_moves).cells).distance_to_final_coverage_m;
    const RouteReplay moved = replay_route(in, spec, cover_route(in, spec, one_cover).cells);
    const RouteReplay restarted =
        replay_route(in, spec, cover_route(in, spec, short_test_options().route).cells);
    ASSERT_TRUE(moved.covers());
    ASSERT_TRUE(restarted.covers());
    EXPECT_LE(moved.distance_to_final_coverage_m, unmoved);
    EXPECT_LE(restarted.distance_to_final_coverage_m, moved.distance_to_final_coverage_m);
    shortened += moved.distance_to_final_coverage_m < unmoved ? 1 : 0;
    restarts_helped += restarted.distance_to_final_coverage_m < moved.distance_to_final_coverage_m ? 1 : 0;
  }
  EXPECT_GT(raised, 0);
  EXPECT_GT(shortened, 0);
  EXPECT_GT(restarts_helped, 0);
}

TEST(Optimum, NoRestartBeginsOnceTheWorkBudgetIsSpent) {
  // A budget the first route spends: the route of the plain cover alone, whatever `restarts` says.
  RunMap m = load_run_map_spec("rooms:w=30,h=24,door=2,seed=3");
  const RunSpec spec = spec_of(std::move(m.map), 4.0);
  const CoverageInstance in = build_coverage_instance(spec);
  RouteOptions spent;
  spent.restart_work = 0;
  RouteOptions one;
  one.restarts = 1;
  const std::vector<int> plain = cover_route(in, spec, one).cells;
  EXPECT_EQ(cover_route(in, spec, spent).cells, plain);
  EXPECT_NE(cover_route(in, spec, RouteOptions{}).cells, plain);  // so the budget mattered
}

TEST(Optimum, TheSweepBoundHoldsWithAndWithoutABattery) {
  // In free space the sweep bound is the larger one; no complete run is below it.
  RunMap m = load_run_map_spec("free:w=25,h=25");
  RunSpec spec = spec_of(std::move(m.map), 2.0);
  spec.robot.battery_capacity = 50.0;
  const CoverageInstance in = build_coverage_instance(spec);
  const CoverageLowerBound bound(in, short_test_options().lower);
  EXPECT_GT(sweep_bound(in), 0.0);
  EXPECT_EQ(bound.start_sweep_bound(), sweep_bound(in));
  EXPECT_GE(bound.at_start(), bound.start_sweep_bound());
  EXPECT_EQ(solve_optimum(spec, short_test_options()).lower_method, "sweep bound");
  EXPECT_GT(check_runs_above_lower_bound("free:w=25,h=25", 2.0, 1, 50.0), 0);
  EXPECT_GT(check_runs_above_lower_bound("free:w=25,h=25", 2.0, 1), 0);
}

TEST(Optimum, TheTripBoundHoldsOnBatteryLimitedMaps) {
  // Never above a replayed route, nor above a complete run; on the Manhattan map with a short
  // charge it is the bound reported.
  for (const auto& [map, battery] :
       std::vector<std::pair<std::string, double>>{{"manhattan:w=48,h=48,seed=1", 60.0},
                                                   {"manhattan:w=48,h=48,seed=1", 100.0},
                                                   {"rooms:w=40,h=30,door=2,seed=4", 150.0},
                                                   {"oldtown:w=48,h=48,seed=1", 60.0}}) {
    SCOPED_TRACE(map + " battery " + std::to_string(battery));
    RunMap m = load_run_map_spec(map);
    RunSpec spec = spec_of(std::move(m.map), 4.0);
    spec.robot.battery_capacity = battery;
    const CoverageInstance in = build_coverage_instance(spec);
    const double trips = trip_bound(in);
    const OptimumResult r = solve_optimum(in, spec, short_test_options());
    ASSERT_LT(r.upper_m, std::numeric_limits<double>::infinity());
    EXPECT_LE(trips, r.upper_m);
    EXPECT_GE(r.lower_m, trips);
    if (battery == 60.0 && map.starts_with("manhattan")) {
      EXPECT_GT(trips, 0.0);
      EXPECT_EQ(r.lower_method, "trip bound");
    }
  }
  RunSpec unlimited = spec_of(load_run_map_spec("manhattan:w=48,h=48,seed=1").map, 4.0);
  EXPECT_EQ(trip_bound(build_coverage_instance(unlimited)), 0.0);  // no battery, no trips
  EXPECT_GT(check_runs_above_lower_bound("manhattan:w=48,h=48,seed=1", 4.0, 1, 100.0), 0);
}

TEST(Optimum, TheLowerBoundFromAStateIsNeverAboveTheRestOfACompleteRun) {
  // From every 25th step of complete runs: the bound from that state is at most what the run
  // still walked to its final coverage.
  RunMap m = load_run_map_spec("rooms:w=30,h=24,door=2,seed=3");
  RunSpec spec = spec_of(std::move(m.map), 4.0);
  const CoverageInstance in = build_coverage_instance(spec);
  const CoverageLowerBound bound(in, LowerBoundOptions{});
  for (const char* strategy : {"closest_frontier", "energy_aware"}) {
    spec.strategy = configure_strategy(strategy, nullptr);
    const RunResult run = simulate(spec);
    ASSERT_EQ(run.end, EndReason::Complete);
    // Replay the run's trajectory to recover its states.
    KnownMap known(in.width, in.height, in.resolution_m);
    Sensor sensor(spec.robot.sensor, in.resolution_m);
    Rng rng(0);
    double walked = 0.0;
    (void)sensor.scan(*spec.map, known, run.trajectory.front(), 0.0, rng);
    for (std::size_t i = 1; i < run.trajectory.size(); ++i) {
      const Cell a = run.trajectory[i - 1];
      const Cell b = run.trajectory[i];
      walked += (a.x != b.x && a.y != b.y ? kSqrt2 : 1.0) * in.resolution_m;
      (void)sensor.scan(*spec.map, known, b, 0.0, rng);
      if (i % 25 != 0 || walked >= run.metrics.distance_to_final_coverage_m) continue;
      EXPECT_LE(bound.from_state(b, known), run.metrics.distance_to_final_coverage_m - walked + 1e-9)
          << strategy << " step " << i;
    }
  }
}

TEST(Optimum, CellsOutOfTheBatterysReachAreCountedAndTheBoundsAreForTheRest) {
  RunMap m = load_run_map_spec("rooms:w=40,h=30,door=2,seed=4");
  RunSpec spec = spec_of(std::move(m.map), 4.0);
  spec.robot.battery_capacity = 40.0;  // 20 m out and back: the far rooms are out of reach
  const CoverageInstance in = build_coverage_instance(spec);
  ASSERT_GT(in.out_of_reach, 0);
  EXPECT_EQ(in.explorable_count(), in.targets() - in.out_of_reach);
  for (int t = 0; t < in.targets(); ++t) {  // out of reach: seen from no node within half a charge
    if (in.is_explorable(t)) continue;
    for (const int n : in.seen_from.row(t)) EXPECT_EQ(in.node_usable[static_cast<std::size_t>(n)], 0);
  }
  const OptimumResult r = solve_optimum(in, spec, OptimumOptions{});
  EXPECT_EQ(r.out_of_reach, in.out_of_reach);
  EXPECT_LE(r.lower_m, r.upper_m);
  ASSERT_LT(r.upper_m, std::numeric_limits<double>::infinity());
  const RouteReplay replay = replay_route(in, spec, r.route);
  EXPECT_TRUE(replay.covers());
  EXPECT_EQ(replay.explorable, in.explorable_count());
}

TEST(Optimum, RefusesTheBeamSensorAndInstancesAboveTheSizeLimit) {
  RunMap m = load_run_map_spec("rooms:w=30,h=24,door=2,seed=3");
  RunSpec spec = spec_of(std::move(m.map), 4.0);
  const auto path_of = [&](const RunSpec& s, std::size_t limit) {
    try {
      (void)build_coverage_instance(s, limit);
    } catch (const ConfigError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  RunSpec beams = spec;
  beams.robot.sensor.model = SensorModel::Beams;
  EXPECT_NE(path_of(beams, kMaxVisibilityPairs).find("robot/sensor/model"), std::string::npos);
  const std::string big = path_of(spec, 1000);
  EXPECT_NE(big.find("map: too large for the offline optimum"), std::string::npos) << big;
  EXPECT_NE(big.find("above the limit of 1000"), std::string::npos) << big;
  EXPECT_EQ(path_of(spec, kMaxVisibilityPairs), "no error");
}

TEST(Optimum, NoRouteIsBuiltAboveTheDistanceFieldLimitAndTheLowerBoundStands) {
  RunMap m = load_run_map_spec("rooms:w=30,h=24,door=2,seed=3");
  const RunSpec spec = spec_of(std::move(m.map), 4.0);
  OptimumOptions options = short_test_options();
  const OptimumResult full = solve_optimum(spec, options);
  options.route.max_field_cells = 1000;  // fewer than one field of this map's 596 cells per viewpoint
  const OptimumResult r = solve_optimum(spec, options);
  EXPECT_EQ(r.upper_m, std::numeric_limits<double>::infinity());
  EXPECT_TRUE(r.route.empty());
  EXPECT_TRUE(r.upper_method.starts_with("none: the covering route's distance fields (")) << r.upper_method;
  EXPECT_NE(r.upper_method.find(" x 596 cells, "), std::string::npos) << r.upper_method;
  EXPECT_NE(r.upper_method.find("above the limit of 0.008 MB"), std::string::npos) << r.upper_method;
  EXPECT_EQ(r.lower_m, full.lower_m);
  EXPECT_FALSE(r.exact);
}

TEST(Optimum, ANarrowFieldOfViewHasTheWideOnesLowerBoundAndARouteThatLooksAround) {
  // The tables are the 360-degree sensor's (a relaxation), so the lower bound is the same; the
  // route turns round on its viewpoints and its replay with the narrow sensor reveals every cell;
  // no complete run of the narrow sensor is below the bound.
  for (const double fov : {180.0, 90.0}) {
    SCOPED_TRACE("fov " + std::to_string(fov));
    RunMap m = load_run_map_spec("rooms:w=30,h=24,door=2,seed=3");
    RunSpec spec = spec_of(std::move(m.map), 4.0);
    const OptimumResult wide = solve_optimum(spec, short_test_options());
    spec.robot.sensor.fov_deg = fov;
    const CoverageInstance in = build_coverage_instance(spec);
    const OptimumResult r = solve_optimum(in, spec, short_test_options());
    EXPECT_EQ(r.lower_m, wide.lower_m);
    ASSERT_LT(r.upper_m, std::numeric_limits<double>::infinity());
    EXPECT_GT(r.upper_m, wide.upper_m);  // the turns cost distance
    const RouteReplay replay = replay_route(in, spec, r.route);
    EXPECT_TRUE(replay.covers());
    const int checked =
        check_complete_runs(spec, r.lower_m, {"closest_frontier", "energy_aware", "random_frontier"}, 2);
    // (With 90 degrees the online robot facing a wall at the start sees no frontier and its runs
    // end at once, complete with completeness below 1: they are not checked.)
    if (fov == 180.0) {
      EXPECT_GT(checked, 0);
    }
  }
  // With a battery the look-around steps count in the trips' split, so the trips fit a charge.
  RunMap m = load_run_map_spec("rooms:w=30,h=24,door=2,seed=3");
  RunSpec spec = spec_of(std::move(m.map), 4.0);
  spec.robot.sensor.fov_deg = 90.0;
  spec.robot.battery_capacity = 120.0;
  const CoverageInstance in = build_coverage_instance(spec);
  const OptimumResult r = solve_optimum(in, spec, short_test_options());
  ASSERT_LT(r.upper_m, std::numeric_limits<double>::infinity());
  EXPECT_GT(r.trips, 1);
  EXPECT_TRUE(replay_route(in, spec, r.route).covers());
}

/// The long version (ctest label long, make test-long, the nightly job): many maps, all
/// strategies, sensor misses and a battery.
TEST(OptimumLong, DISABLED_CompleteRunsAreNeverBelowTheLowerBoundOnManyMaps) {
  check_options() = OptimumOptions{};  // the defaults (this test runs alone, under its label)
  int checked = 0;
  for (int seed = 1; seed <= 12; ++seed) {
    const std::string s = std::to_string(seed);
    checked += check_runs_above_lower_bound("rooms:w=40,h=30,door=2,seed=" + s, 4.0, 3);
    checked += check_runs_above_lower_bound("office:w=48,h=36,seed=" + s, 5.0, 2);
    checked += check_runs_above_lower_bound("random:w=30,h=30,p=0.15,seed=" + s, 3.0, 2);
    checked += check_runs_above_lower_bound("manhattan:w=48,h=48,seed=" + s, 4.0, 2);
    checked += check_runs_above_lower_bound("oldtown:w=48,h=48,seed=" + s, 4.0, 2);
    // Sensor misses and a battery: fewer runs reveal every observable cell, those that do count.
    checked += check_runs_above_lower_bound("rooms:w=40,h=30,door=2,seed=" + s, 4.0, 3, 150.0, 0.05);
    checked += check_runs_above_lower_bound("manhattan:w=48,h=48,seed=" + s, 4.0, 2, 100.0);  // trip bound
  }
  checked += check_runs_above_lower_bound(std::string(FSWEEP_TEST_DATA) + "/room-64-64-8.map", 4.0, 2);
  checked += check_runs_above_lower_bound(
      std::string(FSWEEP_TEST_DATA) + "/houseexpo/house_expo_room_1451.json:res=0.2", 3.0, 2);
  EXPECT_GT(checked, 500);
  std::cout << "complete runs checked against the lower bound: " << checked << "\n";
}

}  // namespace
}  // namespace fsweep
