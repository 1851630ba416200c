#include <gtest/gtest.h>

#include <limits>
#include <nlohmann/json.hpp>

#include "core/config_error.hpp"
#include "planner_test_utils.hpp"
#include "planners/grid_planner.hpp"
#include "planners/registry.hpp"
#include "search/distance_field.hpp"

namespace fsweep {
namespace {

using testing::expect_valid_path;
using testing::known_from_ascii;
using testing::request_for;

class GridPlannerBoth : public ::testing::TestWithParam<GridSearchKind> {};

TEST_P(GridPlannerBoth, StraightLine) {
  // 4 orthogonal steps of 0.5 m.
  const auto m = known_from_ascii({"S...G"}, 0.5);
  GridPlanner planner(GetParam());
  const PlanRequest req = request_for(m.start, m.goal);
  const PlanResult r = planner.plan(m.known, req);
  expect_valid_path(m.known, req, r);
  EXPECT_EQ(r.path.size(), 5U);
  EXPECT_DOUBLE_EQ(r.length_m, 2.0);
  EXPECT_EQ(r.turns, 0);  // start heading 0 is east, along the corridor
  EXPECT_GT(r.expansions, 0);
  EXPECT_GE(r.time_s, 0.0);
}

TEST_P(GridPlannerBoth, DiagonalOnOpenMap) {
  const auto m = known_from_ascii({"S....", ".....", ".....", ".....", "....G"});
  GridPlanner planner(GetParam());
  const PlanResult r = planner.plan(m.known, request_for(m.start, m.goal));
  expect_valid_path(m.known, request_for(m.start, m.goal), r);
  EXPECT_NEAR(r.length_m, 4 * kSqrt2, 1e-12);
}

TEST_P(GridPlannerBoth, StartEqualsGoalIsOneCellPath) {
  const auto m = known_from_ascii({"...", ".S.", "..."});
  GridPlanner planner(GetParam());
  const PlanResult r = planner.plan(m.known, request_for(m.start, m.start));
  ASSERT_EQ(r.status, PlanStatus::Success);
  ASSERT_EQ(r.path.size(), 1U);
  EXPECT_EQ(r.path[0], m.start);
  EXPECT_EQ(r.length_m, 0.0);
  EXPECT_EQ(r.energy, 0.0);
  EXPECT_EQ(r.turns, 0);
}

TEST_P(GridPlannerBoth, GoalInsideObstacle) {
  const auto m = known_from_ascii({"S..", ".#.", "..."});
  GridPlanner planner(GetParam());
  const PlanResult r = planner.plan(m.known, request_for(m.start, Cell{1, 1}));
  EXPECT_EQ(r.status, PlanStatus::GoalInvalid);
  EXPECT_TRUE(r.path.empty());
  EXPECT_EQ(r.length_m, 0.0);
}

TEST_P(GridPlannerBoth, GoalOutsideGridOrUnknown) {
  const auto m = known_from_ascii({"S.?", "..."});
  GridPlanner planner(GetParam());
  EXPECT_EQ(planner.plan(m.known, request_for(m.start, Cell{3, 0})).status, PlanStatus::GoalInvalid);
  EXPECT_EQ(planner.plan(m.known, request_for(m.start, Cell{0, -1})).status, PlanStatus::GoalInvalid);
  EXPECT_EQ(planner.plan(m.known, request_for(m.start, Cell{2, 0})).status, PlanStatus::GoalInvalid);
}

TEST_P(GridPlannerBoth, UnknownCellsBlock) {
  // The direct row is unknown in the middle: the path goes around through row 1.
  const auto m = known_from_ascii({"S.?.G", "....."});
  GridPlanner planner(GetParam());
  const PlanRequest req = request_for(m.start, m.goal);
  const PlanResult r = planner.plan(m.known, req);
  expect_valid_path(m.known, req, r);
  // Hand calculation: (0,0) -diag-> (1,1) -> (2,1) -> (3,1) -diag-> (4,0). The diagonals past
  // the unknown cell (2,0) are blocked without corner cutting, so 2 + 2 sqrt(2).
  EXPECT_NEAR(r.length_m, 2.0 + 2.0 * kSqrt2, 1e-12);
  const Cell unknown{2, 0};
  for (const Cell c : r.path) EXPECT_FALSE(c == unknown);
}

TEST_P(GridPlannerBoth, CornerCuttingChangesLength) {
  // (0,0) -> (1,1) past the blocked corner (0,1): 2 without cutting, sqrt(2) with it.
  const auto m = known_from_ascii({"S.", "#G"});
  GridPlanner planner(GetParam());
  const PlanResult strict = planner.plan(m.known, request_for(m.start, m.goal, false));
  expect_valid_path(m.known, request_for(m.start, m.goal, false), strict);
  EXPECT_DOUBLE_EQ(strict.length_m, 2.0);
  const PlanResult cut = planner.plan(m.known, request_for(m.start, m.goal, true));
  expect_valid_path(m.known, request_for(m.start, m.goal, true), cut);
  EXPECT_DOUBLE_EQ(cut.length_m, kSqrt2);
}

TEST_P(GridPlannerBoth, DiagonalGapNeedsCornerCutting) {
  const auto m = known_from_ascii({"S#", "#G"});
  GridPlanner planner(GetParam());
  EXPECT_EQ(planner.plan(m.known, request_for(m.start, m.goal, false)).status, PlanStatus::NoPath);
  EXPECT_EQ(planner.plan(m.known, request_for(m.start, m.goal, true)).status, PlanStatus::Success);
}

TEST_P(GridPlannerBoth, EnergyStopsAndTurnsFromMeasurePath) {
  // The only path: east, east, south, south. One 90-degree turn from start heading east.
  const auto m = known_from_ascii({"S..", "##.", "##G"});
  GridPlanner planner(GetParam());
  PlanRequest req = request_for(m.start, m.goal);
  req.energy.per_metre = 1.0;
  req.energy.per_stop = 0.5;
  req.energy.per_turn = {0.4, 0.6, 0.8, 1.0};
  const PlanResult r = planner.plan(m.known, req);
  expect_valid_path(m.known, req, r);
  EXPECT_DOUBLE_EQ(r.length_m, 4.0);
  EXPECT_EQ(r.stops, 1);
  EXPECT_EQ(r.turns, 1);
  EXPECT_DOUBLE_EQ(r.energy, 4.0 + 0.5 + 0.6);  // travel + stop + 90-degree turn
}

TEST_P(GridPlannerBoth, DeterministicAndReusable) {
  // The same planner answers queries on maps of different sizes; results equal a fresh
  // planner's (search arrays are reset by generation stamp, not cleared).
  GridPlanner reused(GetParam());
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const KnownMap known = testing::random_known_map(20 + static_cast<int>(seed) * 7, 25, 0.25, seed);
    Rng rng = make_rng(seed, "queries");
    for (int q = 0; q < 20; ++q) {
      const PlanRequest req =
          request_for(testing::random_free_cell(known, rng), testing::random_free_cell(known, rng));
      GridPlanner fresh(GetParam());
      const PlanResult a = reused.plan(known, req);
      const PlanResult b = fresh.plan(known, req);
      ASSERT_EQ(a.status, b.status);
      EXPECT_EQ(a.path, b.path);
      EXPECT_EQ(a.expansions, b.expansions);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Kinds, GridPlannerBoth,
                         ::testing::Values(GridSearchKind::Dijkstra, GridSearchKind::AStar),
                         [](const ::testing::TestParamInfo<GridSearchKind>& info) {
                           return info.param == GridSearchKind::AStar ? std::string("AStar")
                                                                      : std::string("Dijkstra");
                         });

TEST(GridPlanner, DijkstraAndAStarAgreeOnRandomMaps) {
  GridPlanner dijkstra(GridSearchKind::Dijkstra);
  GridPlanner astar(GridSearchKind::AStar);
  long dijkstra_expansions = 0;
  long astar_expansions = 0;
  int successes = 0;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const KnownMap known = testing::random_known_map(40, 30, 0.3, seed);
    Rng rng = make_rng(seed, "queries");
    for (int q = 0; q < 30; ++q) {
      const PlanRequest req = request_for(testing::random_free_cell(known, rng),
                                          testing::random_free_cell(known, rng), q % 2 == 1);
      const PlanResult d = dijkstra.plan(known, req);
      const PlanResult a = astar.plan(known, req);
      ASSERT_EQ(d.status, a.status) << "seed " << seed << " query " << q;
      if (d.status != PlanStatus::Success) continue;
      ++successes;
      expect_valid_path(known, req, d);
      expect_valid_path(known, req, a);
      EXPECT_NEAR(d.length_m, a.length_m, 1e-9) << "seed " << seed << " query " << q;
      dijkstra_expansions += d.expansions;
      astar_expansions += a.expansions;
    }
  }
  EXPECT_GT(successes, 50);
  EXPECT_LT(astar_expansions, dijkstra_expansions);
}

TEST_P(GridPlannerBoth, ExpansionBudgetIsExact) {
  // A corridor query that settles `needed` cells: a budget one short times out having settled
  // exactly the budget; a budget of exactly `needed` finds the same path as no budget.
  const auto m = known_from_ascii({"S.........", "########.#", "G........."});
  const PlanRequest req = request_for(m.start, m.goal);
  GridPlanner unbounded(GetParam());
  const PlanResult full = unbounded.plan(m.known, req);
  ASSERT_EQ(full.status, PlanStatus::Success);
  const long needed = full.expansions;
  ASSERT_GT(needed, 10);

  GridPlannerParams short_one;
  short_one.max_expansions = needed - 1;
  GridPlanner tight(GetParam(), short_one);
  const PlanResult r = tight.plan(m.known, req);
  EXPECT_EQ(r.status, PlanStatus::Timeout);
  EXPECT_EQ(r.expansions, needed - 1);
  EXPECT_TRUE(r.path.empty());
  EXPECT_EQ(r.length_m, 0.0);

  GridPlannerParams exact;
  exact.max_expansions = needed;
  GridPlanner enough(GetParam(), exact);
  const PlanResult e = enough.plan(m.known, req);
  EXPECT_EQ(e.status, PlanStatus::Success);
  EXPECT_EQ(e.path, full.path);
  EXPECT_EQ(e.expansions, needed);
}

TEST_P(GridPlannerBoth, TinyTimeLimitTimesOut) {
  // An open 100x100 map corner to corner settles far more than StopCondition::kClockInterval
  // cells, so the clock is read during the search, and 1 ns has passed by the first read.
  const KnownMap open = testing::random_known_map(100, 100, 0.0, 1);
  const PlanRequest req = request_for(Cell{0, 0}, Cell{99, 99});
  GridPlannerParams tiny;
  tiny.time_limit_s = 1e-9;
  GridPlanner planner(GetParam(), tiny);
  const PlanResult r = planner.plan(open, req);
  EXPECT_EQ(r.status, PlanStatus::Timeout);
  EXPECT_TRUE(r.path.empty());
  EXPECT_LT(r.expansions, StopCondition::kClockInterval + 1);
  // A generous limit changes nothing.
  GridPlannerParams generous;
  generous.time_limit_s = 60.0;
  const PlanResult g = GridPlanner(GetParam(), generous).plan(open, req);
  const PlanResult u = GridPlanner(GetParam()).plan(open, req);
  EXPECT_EQ(g.status, PlanStatus::Success);
  EXPECT_EQ(g.path, u.path);
  EXPECT_EQ(g.expansions, u.expansions);
}

TEST(GridPlanner, BudgetParams) {
  const PlannerConfig none = configure_planner("astar", nlohmann::json::object(), "p");
  EXPECT_EQ(none.params, nlohmann::json({{"time_limit_s", nullptr}, {"max_expansions", 0}}));
  EXPECT_EQ(none.make()->budget().time_limit_s, std::numeric_limits<double>::infinity());
  EXPECT_EQ(none.make()->budget().max_expansions, 0);
  const PlannerConfig both =
      configure_planner("dijkstra", nlohmann::json{{"time_limit_s", 0.25}, {"max_expansions", 1000}}, "p");
  EXPECT_EQ(both.params, nlohmann::json({{"time_limit_s", 0.25}, {"max_expansions", 1000}}));
  EXPECT_EQ(both.make()->budget().time_limit_s, 0.25);
  EXPECT_EQ(both.make()->budget().max_expansions, 1000);
  EXPECT_EQ(make_planner("astar", nlohmann::json{{"time_limit_s", 2}})->budget().time_limit_s, 2.0);
  EXPECT_EQ(make_planner("astar", nlohmann::json{{"time_limit_s", nullptr}})->budget().time_limit_s,
            std::numeric_limits<double>::infinity());
  for (const nlohmann::json& bad :
       {nlohmann::json{{"time_limit_s", 0}}, nlohmann::json{{"time_limit_s", -1.0}},
        nlohmann::json{{"time_limit_s", "1"}}, nlohmann::json{{"max_expansions", -1}},
        nlohmann::json{{"max_expansions", 1.5}}, nlohmann::json{{"tie_break", 1}}}) {
    EXPECT_THROW((void)configure_planner("astar", bad, "p"), ConfigError) << bad.dump();
  }
  try {  // every problem at once, each at its own path
    (void)configure_planner("astar", nlohmann::json{{"time_limit_s", 0}, {"max_expansions", -2}},
                            "/planners/0");
    FAIL() << "no ConfigError";
  } catch (const ConfigError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("/planners/0/params/time_limit_s"), std::string::npos) << msg;
    EXPECT_NE(msg.find("/planners/0/params/max_expansions"), std::string::npos) << msg;
  }
}

TEST(GridPlanner, APathProbeFindsAstarsPathWhateverItsBoundAndBudget) {
  // PathProbe (search/distance_field.hpp) runs astar's A* with the parents kept: when it reaches
  // the goal, under any bound at least the length and any budget it does not run out of, its
  // path and its settled cells are astar's, and its length is DistanceField::compute_to's bit
  // for bit. Seeded maps of random walls, both corner rules.
  int reached = 0;
  int cut = 0;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    const KnownMap known = testing::random_known_map(30 + static_cast<int>(seed) * 5, 28, 0.3, seed);
    Rng rng = make_rng(seed, "probe-queries");
    for (int q = 0; q < 40; ++q) {
      PlanRequest req =
          request_for(testing::random_free_cell(known, rng), testing::random_free_cell(known, rng));
      req.allow_corner_cutting = q % 2 == 1;
      GridPlanner astar(GridSearchKind::AStar);
      const PlanResult planned = astar.plan(known, req);
      DistanceQuery query;
      query.allow_corner_cutting = req.allow_corner_cutting;
      DistanceField field;
      const std::optional<double> length = field.compute_to(known, req.start, req.goal, query);
      ASSERT_TRUE(length.has_value());
      for (const double bound : {std::numeric_limits<double>::infinity(), *length, *length * 1.5 + 1.0}) {
        for (const long budget : {0L, planned.expansions, planned.expansions - 1}) {
          query.max_distance_m = bound;
          query.stop = StopCondition(SearchBudget{std::numeric_limits<double>::infinity(), budget},
                                     StopCondition::Clock::time_point{});
          PathProbe probe;
          const std::optional<double> d = probe.compute_to(known, req.start, req.goal, query);
          const std::string what = "seed " + std::to_string(seed) + " query " + std::to_string(q) +
                                   " bound " + std::to_string(bound) + " budget " + std::to_string(budget);
          if (planned.status != PlanStatus::Success) {
            ASSERT_FALSE(probe.reached_goal()) << what;
            continue;
          }
          if (budget > 0 && budget < planned.expansions) {  // ran out one cell short of the goal
            ASSERT_FALSE(d.has_value()) << what;
            ASSERT_FALSE(probe.reached_goal()) << what;
            ++cut;
            continue;
          }
          ASSERT_TRUE(probe.reached_goal()) << what;
          ASSERT_EQ(*d, *length) << what;
          std::vector<Cell> path;
          for (const int i : probe.path()) path.push_back(known.cell(i));
          ASSERT_EQ(path, planned.path) << what;
          ASSERT_EQ(probe.expansions(), planned.expansions) << what;
          ++reached;
        }
      }
      // Below the length the probe does not reach the goal (nor keep a path).
      if (planned.status == PlanStatus::Success && *length > 0.0) {
        query.max_distance_m = *length * 0.999;
        query.stop = StopCondition{};
        PathProbe probe;
        EXPECT_EQ(probe.compute_to(known, req.start, req.goal, query),
                  std::numeric_limits<double>::infinity());
        EXPECT_FALSE(probe.reached_goal());
        EXPECT_TRUE(probe.path().empty());
      }
    }
  }
  EXPECT_GT(reached, 1500);
  EXPECT_GT(cut, 150);
}

TEST(GridPlanner, AstarTakesTheSearchedPathOnlyWithoutABudget) {
  // PlanRequest::searched: astar returns it as its own search's result (an expansion count no
  // search gives shows it);
  // with a budget, and for dijkstra, it searches.
  const auto m = known_from_ascii({"S....", ".###.", "....G"});
  PlanRequest req = request_for(m.start, m.goal);
  SearchResult given;
  given.status = PlanStatus::Success;
  given.path = {m.start, Cell{1, 0}, Cell{2, 0}, Cell{3, 0}, Cell{4, 0}, Cell{4, 1}, m.goal};
  given.expansions = 77;
  req.searched = &given;
  const PlanResult taken = GridPlanner(GridSearchKind::AStar).plan(m.known, req);
  EXPECT_EQ(taken.path, given.path);
  EXPECT_EQ(taken.expansions, 77);
  const PlanResult own = GridPlanner(GridSearchKind::AStar).plan(m.known, request_for(m.start, m.goal));
  for (const PlanResult& searched :
       {GridPlanner(GridSearchKind::AStar, GridPlannerParams{1.0e9, 0}).plan(m.known, req),
        GridPlanner(GridSearchKind::AStar,
                    GridPlannerParams{std::numeric_limits<double>::infinity(), 1000000})
            .plan(m.known, req)}) {
    EXPECT_EQ(searched.path, own.path);
    EXPECT_EQ(searched.expansions, own.expansions);
  }
  EXPECT_NE(GridPlanner(GridSearchKind::Dijkstra).plan(m.known, req).expansions, 77);
}

TEST(GridPlanner, NamesAndClone) {
  EXPECT_EQ(GridPlanner(GridSearchKind::Dijkstra).name(), "dijkstra");
  EXPECT_EQ(GridPlanner(GridSearchKind::AStar).name(), "astar");
  const auto clone = GridPlanner(GridSearchKind::AStar).clone();
  EXPECT_EQ(clone->name(), "astar");
}

TEST(GridPlanner, ToStringNamesEveryStatus) {
  EXPECT_EQ(to_string(PlanStatus::Success), "Success");
  EXPECT_EQ(to_string(PlanStatus::StartInvalid), "StartInvalid");
  EXPECT_EQ(to_string(PlanStatus::GoalInvalid), "GoalInvalid");
  EXPECT_EQ(to_string(PlanStatus::NoPath), "NoPath");
  EXPECT_EQ(to_string(PlanStatus::Timeout), "Timeout");
}

}  // namespace
}  // namespace fsweep
