/// The heading-lattice planners (Mei et al. 2006, section IV-C): hand-worked energies under the
/// `mei2006` preset (1 per cell length, stop 0.5, turns 0.4/0.6/0.8/1.0 for 45..180 degrees),
/// the paper's Figure 2 effect, and Dijkstra == A* on random maps.

#include <gtest/gtest.h>

#include <cstdint>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "core/config_error.hpp"
#include "planner_test_utils.hpp"
#include "planners/grid_planner.hpp"
#include "planners/lattice_planner.hpp"
#include "planners/registry.hpp"
#include "world/energy_model.hpp"
#include "world/motion.hpp"

namespace fsweep {
namespace {

using testing::expect_valid_path;
using testing::known_from_ascii;
using testing::mei_request;

class LatticePlannerBoth : public ::testing::TestWithParam<LatticeSearchKind> {};

TEST_P(LatticePlannerBoth, StraightCorridorHasNoTurns) {
  // Start heading 0 is east, along the corridor: 4 cells of travel, nothing else.
  const auto m = known_from_ascii({"#####", "S...G", "#####"});
  LatticePlanner planner(GetParam());
  const PlanRequest req = mei_request(m.start, m.goal);
  const PlanResult r = planner.plan(m.known, req);
  expect_valid_path(m.known, req, r);
  EXPECT_EQ(r.path.size(), 5U);
  EXPECT_DOUBLE_EQ(r.length_m, 4.0);
  EXPECT_EQ(r.stops, 0);
  EXPECT_EQ(r.turns, 0);
  EXPECT_DOUBLE_EQ(r.energy, 4.0);
  EXPECT_GT(r.expansions, 0);
  EXPECT_GE(r.time_s, 0.0);
}

TEST_P(LatticePlannerBoth, LCorridorHasOneNinetyDegreeTurn) {
  // East 3 cells, then south 3 cells: one stop and one 90-degree turn at the corner.
  const auto m = known_from_ascii({
      "S...",
      "###.",
      "###.",
      "###G",
  });
  LatticePlanner planner(GetParam());
  const PlanRequest req = mei_request(m.start, m.goal);
  const PlanResult r = planner.plan(m.known, req);
  expect_valid_path(m.known, req, r);
  EXPECT_DOUBLE_EQ(r.length_m, 6.0);
  EXPECT_EQ(r.stops, 1);
  EXPECT_EQ(r.turns, 1);
  EXPECT_DOUBLE_EQ(r.energy, 6.0 + 0.5 + 0.6);  // cells + stop + 90-degree turn
}

TEST_P(LatticePlannerBoth, StartHeadingFacingAwayCostsAHalfTurn) {
  // Facing west (heading 4) in an east-going corridor: one stop and a 180-degree turn first.
  const auto m = known_from_ascii({"#####", "S...G", "#####"});
  LatticePlanner planner(GetParam());
  const PlanRequest req = mei_request(m.start, m.goal, 4);
  const PlanResult r = planner.plan(m.known, req);
  expect_valid_path(m.known, req, r);
  EXPECT_EQ(r.stops, 1);
  EXPECT_EQ(r.turns, 1);
  EXPECT_DOUBLE_EQ(r.energy, 4.0 + 0.5 + 1.0);
}

TEST_P(LatticePlannerBoth, GoalHasNoFinalStop) {
  // Arriving heading east on a goal where a different heading would be free costs nothing more.
  const auto m = known_from_ascii({"S.G", "..."});
  LatticePlanner planner(GetParam());
  const PlanRequest req = mei_request(m.start, m.goal);
  const PlanResult r = planner.plan(m.known, req);
  expect_valid_path(m.known, req, r);
  EXPECT_DOUBLE_EQ(r.energy, 2.0);
  EXPECT_EQ(r.stops, 0);
}

/// Paper Figure 2 on a grid: R1, a 1-cell staircase corridor from S to G, is the shortest route
/// but stops at every cell; R2 runs along row 0 and column 7, longer but with four stops.
testing::AsciiKnownMap figure2_map() {
  return known_from_ascii({
      "........",
      "#S.####.",
      "##..###.",
      "###..##.",
      "####..#.",
      "#####...",
      "######G.",
  });
}

TEST_P(LatticePlannerBoth, LongerButCheaperThanShortestPath) {
  const auto m = figure2_map();
  GridPlanner astar(GridSearchKind::AStar);
  LatticePlanner lattice(GetParam());
  const PlanRequest req = mei_request(m.start, m.goal);  // start heading east
  const PlanResult shortest = astar.plan(m.known, req);
  const PlanResult cheapest = lattice.plan(m.known, req);
  expect_valid_path(m.known, req, shortest);
  expect_valid_path(m.known, req, cheapest);
  // R1 (hand count): the only path of length 10 (every diagonal in the staircase is blocked by
  // the corner rule): E,S,E,S,...,S = 10 cells and 9 stops with 90-degree turns: 10 + 9 * 1.1.
  EXPECT_DOUBLE_EQ(shortest.length_m, 10.0);
  EXPECT_EQ(shortest.stops, 9);
  EXPECT_NEAR(shortest.energy, 19.9, 1e-9);
  // R2 (hand count, stop + turn in brackets): NE to (2,0) [45 degrees: 0.9], E to (7,0) [45: 0.9],
  // S to (7,5) [90: 1.1], SW to G [45: 0.9]: length 10 + 2 sqrt(2), 4 stops, energy that + 3.8.
  // (N then E at the start costs 1 + 2.2 > sqrt(2) + 1.8; S to (7,6) then W costs 1 + 1.1 more
  // than SW's sqrt(2) + 0.9, so both corners are cut diagonally.)
  EXPECT_GT(cheapest.length_m, shortest.length_m);
  EXPECT_NEAR(cheapest.length_m, 10.0 + 2.0 * kSqrt2, 1e-9);
  EXPECT_EQ(cheapest.stops, 4);
  EXPECT_NEAR(cheapest.energy, 13.8 + 2.0 * kSqrt2, 1e-9);
  EXPECT_LT(cheapest.energy, shortest.energy);
}

TEST_P(LatticePlannerBoth, WithSectionIVAsCornerRuleTheStaircaseIsOneDiagonal) {
  // Mei 2006 section IV-A: a move needs only its two cells free, so a diagonal may pass a
  // blocked corner. On the Figure 2 map every staircase step (1,1) -> (2,2) -> ... -> (6,6) then
  // is one diagonal: 5 sqrt(2) cells, one stop with a 45-degree turn from the start heading
  // east (0.5 + 0.4). Without the rule the same planner pays 10 cells and 9 turns or goes round.
  const auto m = figure2_map();
  LatticePlanner lattice(GetParam());
  PlanRequest req = mei_request(m.start, m.goal);
  req.allow_corner_cutting = true;
  const PlanResult cut = lattice.plan(m.known, req);
  expect_valid_path(m.known, req, cut);
  EXPECT_NEAR(cut.length_m, 5.0 * kSqrt2, 1e-9);
  EXPECT_EQ(cut.path.size(), 6U);
  EXPECT_EQ(cut.stops, 1);
  EXPECT_NEAR(cut.energy, 5.0 * kSqrt2 + 0.9, 1e-9);
  req.allow_corner_cutting = false;
  const PlanResult uncut = lattice.plan(m.known, req);
  expect_valid_path(m.known, req, uncut);
  EXPECT_NEAR(uncut.energy, 13.8 + 2.0 * kSqrt2, 1e-9);  // R2, as above
}

TEST_P(LatticePlannerBoth, NeverMoreEnergyThanShortestPath) {
  // On random maps the lattice energy is a lower bound on the measured energy of astar's path.
  GridPlanner astar(GridSearchKind::AStar);
  LatticePlanner lattice(GetParam());
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const KnownMap known = testing::random_known_map(25, 25, 0.25, seed);
    Rng rng = make_rng(seed, "queries");
    for (int q = 0; q < 10; ++q) {
      PlanRequest req =
          mei_request(testing::random_free_cell(known, rng), testing::random_free_cell(known, rng),
                      static_cast<int>(uniform_below(rng, 8)));
      const PlanResult a = astar.plan(known, req);
      const PlanResult l = lattice.plan(known, req);
      ASSERT_EQ(a.status, l.status);
      if (l.status != PlanStatus::Success) continue;
      expect_valid_path(known, req, l);
      EXPECT_LE(l.energy, a.energy + 1e-9);
      EXPECT_GE(l.length_m + 1e-9, a.length_m);
    }
  }
}

TEST_P(LatticePlannerBoth, GoalInvalid) {
  const auto m = known_from_ascii({"S..", ".#?", "..."});
  LatticePlanner planner(GetParam());
  for (const Cell goal : {Cell{1, 1}, Cell{2, 1}, Cell{3, 0}, Cell{0, -1}}) {
    const PlanResult r = planner.plan(m.known, mei_request(m.start, goal));
    EXPECT_EQ(r.status, PlanStatus::GoalInvalid) << goal.x << "," << goal.y;
    EXPECT_TRUE(r.path.empty());
    EXPECT_EQ(r.energy, 0.0);
  }
}

TEST_P(LatticePlannerBoth, StartEqualsGoalCostsNothing) {
  const auto m = known_from_ascii({"...", ".S.", "..."});
  LatticePlanner planner(GetParam());
  const PlanResult r = planner.plan(m.known, mei_request(m.start, m.start, 5));
  ASSERT_EQ(r.status, PlanStatus::Success);
  ASSERT_EQ(r.path.size(), 1U);
  EXPECT_EQ(r.energy, 0.0);
  EXPECT_EQ(r.stops, 0);
}

TEST_P(LatticePlannerBoth, RejectsStartHeadingOutOfRange) {
  const auto m = known_from_ascii({"S.G"});
  LatticePlanner planner(GetParam());
  EXPECT_THROW((void)planner.plan(m.known, mei_request(m.start, m.goal, 8)), std::invalid_argument);
  EXPECT_THROW((void)planner.plan(m.known, mei_request(m.start, m.goal, -1)), std::invalid_argument);
}

TEST_P(LatticePlannerBoth, ExpansionBudgetIsExact) {
  // A corridor query that settles `needed` (cell, heading) states: a budget one short times out
  // having settled exactly the budget; a budget of exactly `needed` finds the same path.
  const auto m = known_from_ascii({"S.........", "########.#", "G........."});
  const PlanRequest req = mei_request(m.start, m.goal);
  LatticePlanner unbounded(GetParam());
  const PlanResult full = unbounded.plan(m.known, req);
  ASSERT_EQ(full.status, PlanStatus::Success);
  const long needed = full.expansions;
  ASSERT_GT(needed, 10);

  LatticePlannerParams short_one;
  short_one.max_expansions = needed - 1;
  const PlanResult r = LatticePlanner(GetParam(), short_one).plan(m.known, req);
  EXPECT_EQ(r.status, PlanStatus::Timeout);
  EXPECT_EQ(r.expansions, needed - 1);
  EXPECT_TRUE(r.path.empty());
  EXPECT_EQ(r.energy, 0.0);

  LatticePlannerParams exact;
  exact.max_expansions = needed;
  const PlanResult e = LatticePlanner(GetParam(), exact).plan(m.known, req);
  EXPECT_EQ(e.status, PlanStatus::Success);
  EXPECT_EQ(e.path, full.path);
  EXPECT_EQ(e.energy, full.energy);
}

TEST_P(LatticePlannerBoth, TinyTimeLimitTimesOut) {
  // Corner to corner on an open 60x60 map settles far more than StopCondition::kClockInterval
  // states, so the clock is read during the search, and 1 ns has passed by the first read.
  const KnownMap open = testing::random_known_map(60, 60, 0.0, 1);
  const PlanRequest req = mei_request(Cell{0, 0}, Cell{59, 59});
  LatticePlannerParams tiny;
  tiny.time_limit_s = 1e-9;
  const PlanResult r = LatticePlanner(GetParam(), tiny).plan(open, req);
  EXPECT_EQ(r.status, PlanStatus::Timeout);
  EXPECT_TRUE(r.path.empty());
  EXPECT_LT(r.expansions, StopCondition::kClockInterval + 1);
  LatticePlannerParams generous;
  generous.time_limit_s = 60.0;
  const PlanResult g = LatticePlanner(GetParam(), generous).plan(open, req);
  const PlanResult u = LatticePlanner(GetParam()).plan(open, req);
  EXPECT_EQ(g.status, PlanStatus::Success);
  EXPECT_EQ(g.path, u.path);
  EXPECT_EQ(g.expansions, u.expansions);
}

INSTANTIATE_TEST_SUITE_P(Kinds, LatticePlannerBoth,
                         ::testing::Values(LatticeSearchKind::Dijkstra, LatticeSearchKind::AStar),
                         [](const ::testing::TestParamInfo<LatticeSearchKind>& info) {
                           return info.param == LatticeSearchKind::AStar ? "AStar" : "Dijkstra";
                         });

TEST(LatticePlanner, DijkstraAndAStarReturnEqualEnergy) {
  // ~20 random 30x30 maps at 25% obstacles, random headings, both corner rules; A* must keep
  // optimality (admissible, consistent heuristic) and expand no more states than Dijkstra.
  LatticePlanner dijkstra(LatticeSearchKind::Dijkstra);
  LatticePlanner astar(LatticeSearchKind::AStar);
  int successes = 0;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const KnownMap known = testing::random_known_map(30, 30, 0.25, seed);
    Rng rng = make_rng(seed, "lattice_queries");
    for (int q = 0; q < 5; ++q) {
      PlanRequest req =
          mei_request(testing::random_free_cell(known, rng), testing::random_free_cell(known, rng),
                      static_cast<int>(uniform_below(rng, 8)));
      req.allow_corner_cutting = q % 2 == 1;
      const PlanResult d = dijkstra.plan(known, req);
      const PlanResult a = astar.plan(known, req);
      ASSERT_EQ(d.status, a.status) << "seed " << seed << " query " << q;
      if (d.status != PlanStatus::Success) continue;
      ++successes;
      expect_valid_path(known, req, d);
      expect_valid_path(known, req, a);
      EXPECT_NEAR(d.energy, a.energy, 1e-9) << "seed " << seed << " query " << q;
      EXPECT_LE(a.expansions, d.expansions);
    }
  }
  EXPECT_GT(successes, 40);
}

TEST(LatticePlanner, UsesTheRequestEnergyModel) {
  // Under the `distance` preset turns are free, so the lattice returns a shortest path.
  const auto m = figure2_map();
  PlanRequest req = mei_request(m.start, m.goal);
  req.energy = energy_preset("distance");
  GridPlanner astar(GridSearchKind::AStar);
  LatticePlanner lattice(LatticeSearchKind::Dijkstra);
  const PlanResult shortest = astar.plan(m.known, req);
  const PlanResult l = lattice.plan(m.known, req);
  expect_valid_path(m.known, req, l);
  EXPECT_NEAR(l.length_m, shortest.length_m, 1e-9);
  EXPECT_NEAR(l.energy, shortest.energy, 1e-9);
}

TEST(LatticePlanner, ParamsRejectUnknownKeys) {
  EXPECT_NO_THROW((void)configure_planner("lattice", nlohmann::json(), "/planners/0"));
  EXPECT_NO_THROW((void)configure_planner("lattice", nlohmann::json::object(), "/planners/0"));
  EXPECT_THROW((void)configure_planner("lattice", nlohmann::json{{"heuristic", 1}}, "/planners/0"),
               ConfigError);
}

TEST(LatticePlanner, BudgetParams) {
  const PlannerConfig c =
      configure_planner("lattice_astar", nlohmann::json{{"time_limit_s", 0.5}, {"max_expansions", 64}}, "p");
  EXPECT_EQ(c.params, nlohmann::json({{"time_limit_s", 0.5}, {"max_expansions", 64}}));
  EXPECT_EQ(c.make()->budget().time_limit_s, 0.5);
  EXPECT_EQ(c.make()->budget().max_expansions, 64);
  try {
    (void)configure_planner("lattice", nlohmann::json{{"max_expansions", -3}}, "/planners/0");
    FAIL() << "no ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.where(), "/planners/0/params/max_expansions");
    EXPECT_NE(std::string(e.what()).find(">= 0"), std::string::npos) << e.what();
  }
  EXPECT_THROW((void)configure_planner("lattice", nlohmann::json{{"time_limit_s", 0.0}}, "p"), ConfigError);
}

TEST(LatticePlanner, NamesAndClone) {
  EXPECT_EQ(LatticePlanner(LatticeSearchKind::Dijkstra).name(), "lattice");
  EXPECT_EQ(LatticePlanner(LatticeSearchKind::AStar).name(), "lattice_astar");
  EXPECT_EQ(LatticePlanner(LatticeSearchKind::AStar).clone()->name(), "lattice_astar");
}

}  // namespace
}  // namespace fsweep
