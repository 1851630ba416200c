/// `shortest_fewest_turns`: the cheapest (fewest / cheapest stops and turns) of all shortest
/// paths. Hand-worked energies under the `mei2006` preset (1 per cell length, stop 0.5, turns
/// 0.4/0.6/0.8/1.0 for 45..180 degrees), an exhaustive check against every shortest path on
/// small random maps, and the ordering dijkstra >= shortest_fewest_turns >= lattice on energy.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "core/config_error.hpp"
#include "planner_test_utils.hpp"
#include "planners/grid_planner.hpp"
#include "planners/lattice_planner.hpp"
#include "planners/registry.hpp"
#include "planners/shortest_fewest_turns.hpp"
#include "world/energy_model.hpp"
#include "world/motion.hpp"

namespace fsweep {
namespace {

using testing::expect_valid_path;
using testing::known_from_ascii;
using testing::mei_request;

TEST(ShortestFewestTurns, OneTurnFromHeadingEast) {
  // Open 10x8 room, (0,4) -> (8,0): every shortest path has 4 east and 4 north-east steps
  // (length 4 + 4 sqrt(2)). From heading east the cheapest is E,E,E,E then NE,NE,NE,NE: one stop
  // and one 45-degree turn, energy 4 + 4 sqrt(2) + 0.5 + 0.4 (starting north-east would need a
  // turn at the start and another back). (Dijkstra, with exact octile costs, finds a one-turn
  // path here too: its old staircase came from rounding in summed costs.)
  const auto m = known_from_ascii({
      "........G.",
      "..........",
      "..........",
      "..........",
      "S.........",
      "..........",
      "..........",
      "..........",
  });
  const PlanRequest req = mei_request(m.start, m.goal, 0);
  ShortestFewestTurnsPlanner sft;
  const PlanResult r = sft.plan(m.known, req);
  expect_valid_path(m.known, req, r);
  const double length = 4.0 + 4.0 * kSqrt2;
  EXPECT_NEAR(r.length_m, length, 1e-9);
  EXPECT_EQ(r.stops, 1);
  EXPECT_EQ(r.turns, 1);
  EXPECT_NEAR(r.energy, length + 0.5 + 0.4, 1e-9);
  const std::vector<Cell> expected{{0, 4}, {1, 4}, {2, 4}, {3, 4}, {4, 4}, {5, 3}, {6, 2}, {7, 1}, {8, 0}};
  EXPECT_EQ(r.path, expected);
}

TEST(ShortestFewestTurns, FewerTurnsWhereDijkstraTurnsMore) {
  // Two obstacles; (6,5) -> (1,2) from heading east. Every shortest path has the same length;
  // Dijkstra's tie-breaking (smaller f, larger g, smaller cell index) picks one with more turns
  // than the cheapest in energy, which shortest_fewest_turns finds.
  const auto m = known_from_ascii({
      "........",
      "....#...",
      ".G......",
      "........",
      "........",
      "...#..S.",
  });
  const PlanRequest req = mei_request(m.start, m.goal, 0);
  ShortestFewestTurnsPlanner sft;
  const PlanResult r = sft.plan(m.known, req);
  expect_valid_path(m.known, req, r);
  GridPlanner dijkstra(GridSearchKind::Dijkstra);
  const PlanResult d = dijkstra.plan(m.known, req);
  expect_valid_path(m.known, req, d);
  EXPECT_EQ(r.length_m, d.length_m);  // exact lengths: equal, not merely close
  EXPECT_LT(r.turns, d.turns);
  EXPECT_LT(r.energy, d.energy);
}

TEST(ShortestFewestTurns, StartHeadingCounts) {
  // Same room, start heading south-east (1): SE,SE,SE first, then E,E,E is again one 45-degree
  // turn; from heading north (6) the best first move is east (90 degrees) or south-east (135
  // degrees), so the cheapest is turn 90 to east, then 45 to south-east: 2 stops, 0.6 + 0.4.
  const auto m = known_from_ascii({
      "S.......",
      "........",
      "........",
      "......G.",
      "........",
  });
  ShortestFewestTurnsPlanner sft;
  const double length = 3.0 + 3.0 * kSqrt2;
  const PlanResult se = sft.plan(m.known, mei_request(m.start, m.goal, 1));
  EXPECT_NEAR(se.energy, length + 0.5 + 0.4, 1e-9);
  EXPECT_EQ(se.path[1], (Cell{1, 1}));
  const PlanResult north = sft.plan(m.known, mei_request(m.start, m.goal, 6));
  EXPECT_NEAR(north.energy, length + 2 * 0.5 + 0.6 + 0.4, 1e-9);
  EXPECT_EQ(north.stops, 2);
}

TEST(ShortestFewestTurns, NeverTakesTheLongerCheaperPath) {
  // A winding map (the only route: east along row 0, down column 8, back west through the
  // gap at x = 5): the planner keeps dijkstra's length, and its energy lies between dijkstra's
  // and the lattice's optimum over all paths.
  const auto m = known_from_ascii({
      "S........",
      ".#######.",
      "....#....",
      "###.#.###",
      "....#...G",
  });
  const PlanRequest req = mei_request(m.start, m.goal, 0);
  ShortestFewestTurnsPlanner sft;
  GridPlanner dijkstra(GridSearchKind::Dijkstra);
  LatticePlanner lattice(LatticeSearchKind::Dijkstra);
  const PlanResult s = sft.plan(m.known, req);
  const PlanResult d = dijkstra.plan(m.known, req);
  const PlanResult l = lattice.plan(m.known, req);
  expect_valid_path(m.known, req, s);
  EXPECT_NEAR(s.length_m, d.length_m, 1e-9);
  EXPECT_LE(s.energy, d.energy + 1e-9);
  EXPECT_GE(s.energy, l.energy - 1e-9);
}

/// Least energy over every shortest path start -> goal, by exhaustive depth-first enumeration
/// (prunes a branch once its length plus the octile distance left exceeds `shortest`).
double brute_force_min_energy(const KnownMap& known, const PlanRequest& req, double shortest) {
  double best = std::numeric_limits<double>::infinity();
  std::vector<Cell> path{req.start};
  std::function<void(double)> dfs = [&](double length) {
    const Cell c = path.back();
    if (c == req.goal) {
      if (std::abs(length - shortest) < 1e-9) {
        best = std::min(best, measure_path(path, req.start_heading, req.energy, known.resolution_m()).energy);
      }
      return;
    }
    for (int h = 0; h < 8; ++h) {
      const Cell n{c.x + kDirections[static_cast<std::size_t>(h)].x,
                   c.y + kDirections[static_cast<std::size_t>(h)].y};
      if (!octile_step_allowed(known, c, n, req.allow_corner_cutting)) continue;
      const double next = length + step_length(h);
      if (next + octile_distance(n, req.goal) > shortest + 1e-9) continue;
      path.push_back(n);
      dfs(next);
      path.pop_back();
    }
  };
  dfs(0.0);
  return best;
}

TEST(ShortestFewestTurns, MatchesExhaustiveSearchOnSmallRandomMaps) {
  // 12 random 8x7 maps with 20% obstacles, 12 queries each, random start headings, a third
  // with corner cutting: the energy equals the minimum over every shortest path.
  ShortestFewestTurnsPlanner sft;
  GridPlanner dijkstra(GridSearchKind::Dijkstra);
  int checked = 0;
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    const KnownMap known = testing::random_known_map(8, 7, 0.2, seed);
    Rng rng = make_rng(seed, "sft_exhaustive");
    for (int q = 0; q < 12; ++q) {
      PlanRequest req =
          mei_request(testing::random_free_cell(known, rng), testing::random_free_cell(known, rng),
                      static_cast<int>(uniform_below(rng, 8)));
      req.allow_corner_cutting = q % 3 == 2;
      const PlanResult d = dijkstra.plan(known, req);
      const PlanResult s = sft.plan(known, req);
      ASSERT_EQ(s.status, d.status);
      if (d.status != PlanStatus::Success) continue;
      expect_valid_path(known, req, s);
      EXPECT_NEAR(s.length_m, d.length_m, 1e-9);
      EXPECT_NEAR(s.energy, brute_force_min_energy(known, req, d.length_m), 1e-9)
          << "seed " << seed << " query " << q;
      ++checked;
    }
  }
  EXPECT_GT(checked, 60);
}

TEST(ShortestFewestTurns, BetweenDijkstraAndLatticeOnRandomMaps) {
  // On random 40x40 maps with 20% obstacles: same length as dijkstra, energy no more than
  // dijkstra's (same length, cheapest turns) and no less than the lattice's (its optimum over
  // all paths).
  ShortestFewestTurnsPlanner sft;
  GridPlanner dijkstra(GridSearchKind::Dijkstra);
  LatticePlanner lattice(LatticeSearchKind::AStar);
  int solved = 0;
  int strictly_cheaper = 0;
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    const KnownMap known = testing::random_known_map(40, 40, 0.2, seed);
    Rng rng = make_rng(seed, "sft_random");
    for (int q = 0; q < 60; ++q) {
      PlanRequest req =
          mei_request(testing::random_free_cell(known, rng), testing::random_free_cell(known, rng),
                      static_cast<int>(uniform_below(rng, 8)));
      req.allow_corner_cutting = q % 5 == 4;
      const PlanResult d = dijkstra.plan(known, req);
      const PlanResult s = sft.plan(known, req);
      const PlanResult l = lattice.plan(known, req);
      ASSERT_EQ(s.status, d.status);
      if (d.status != PlanStatus::Success) continue;
      expect_valid_path(known, req, s);
      EXPECT_NEAR(s.length_m, d.length_m, 1e-9);
      EXPECT_LE(s.energy, d.energy + 1e-9);
      EXPECT_GE(s.energy, l.energy - 1e-9);
      strictly_cheaper += s.energy < d.energy - 1e-9 ? 1 : 0;
      ++solved;
    }
  }
  EXPECT_GT(solved, 150);
  EXPECT_GT(strictly_cheaper, solved / 4);  // the tie-breaking of dijkstra is often not the cheapest
}

TEST(ShortestFewestTurns, StatusesAndStartEqualsGoal) {
  const auto m = known_from_ascii({
      "S.#..",
      "..#.G",
      "..#..",
  });
  ShortestFewestTurnsPlanner sft;
  EXPECT_EQ(sft.plan(m.known, mei_request(m.start, m.goal)).status, PlanStatus::NoPath);
  EXPECT_EQ(sft.plan(m.known, mei_request(Cell{2, 0}, m.goal)).status, PlanStatus::StartInvalid);
  EXPECT_EQ(sft.plan(m.known, mei_request(m.start, Cell{9, 9})).status, PlanStatus::GoalInvalid);
  const PlanResult same = sft.plan(m.known, mei_request(m.start, m.start));
  ASSERT_EQ(same.status, PlanStatus::Success);
  EXPECT_EQ(same.path.size(), 1U);
  EXPECT_DOUBLE_EQ(same.energy, 0.0);
  EXPECT_THROW((void)sft.plan(m.known, mei_request(m.start, m.goal, 8)), std::invalid_argument);
}

TEST(ShortestFewestTurns, BothSearchesShareOneExpansionBudget) {
  // The distance field settles d cells, the lattice search l states: a budget of d + l - 1
  // times out in the lattice search, d - 1 in the distance field, d + l succeeds.
  const auto m = known_from_ascii({"S.........", "########.#", "G........."});
  const PlanRequest req = mei_request(m.start, m.goal);
  const PlanResult full = ShortestFewestTurnsPlanner().plan(m.known, req);
  ASSERT_EQ(full.status, PlanStatus::Success);
  for (const long budget : {full.expansions - 1, 5L}) {
    ShortestFewestTurnsParams p;
    p.max_expansions = budget;
    const PlanResult r = ShortestFewestTurnsPlanner(p).plan(m.known, req);
    EXPECT_EQ(r.status, PlanStatus::Timeout) << budget;
    EXPECT_EQ(r.expansions, budget);
    EXPECT_TRUE(r.path.empty());
  }
  ShortestFewestTurnsParams exact;
  exact.max_expansions = full.expansions;
  const PlanResult e = ShortestFewestTurnsPlanner(exact).plan(m.known, req);
  EXPECT_EQ(e.status, PlanStatus::Success);
  EXPECT_EQ(e.path, full.path);
  ShortestFewestTurnsParams tiny_time;
  tiny_time.time_limit_s = 1e-9;
  EXPECT_EQ(ShortestFewestTurnsPlanner(tiny_time).plan(m.known, req).status, PlanStatus::Timeout);
}

TEST(ShortestFewestTurns, ParamsRejectUnknownKeys) {
  EXPECT_NO_THROW((void)configure_planner("shortest_fewest_turns", nlohmann::json(), "p"));
  EXPECT_NO_THROW((void)configure_planner("shortest_fewest_turns", nlohmann::json::object(), "p"));
  EXPECT_THROW((void)configure_planner("shortest_fewest_turns", nlohmann::json{{"weight", 1}}, "p"),
               ConfigError);
}

}  // namespace
}  // namespace fsweep
