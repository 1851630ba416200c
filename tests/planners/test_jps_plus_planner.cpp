/// `jps+` against `astar`: the same shortest lengths (the same numbers of straight and diagonal
/// steps) on every query of the MovingAI scenarios in tests/data and on seeded random maps under
/// both corner rules; its jump table rebuilt exactly when the map changed (a wall appears or goes,
/// cells are revealed, another map takes the old one's place) and reused otherwise; jumps longer
/// than a table entry holds; the expansion budget.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "core/config_error.hpp"
#include "planner_test_utils.hpp"
#include "planners/grid_planner.hpp"
#include "planners/jps_plus_planner.hpp"
#include "planners/registry.hpp"
#include "world/energy_model.hpp"
#include "world/known_map.hpp"
#include "world/map_loaders.hpp"

namespace fsweep {
namespace test_jps_plus_planner {  // not anonymous: unity builds put it beside other test files' helpers

using testing::expect_valid_path;
using testing::known_from_ascii;
using testing::request_for;

/// (straight, diagonal) steps of a cell chain: equal pairs are equal exact lengths.
std::pair<int, int> straight_and_diagonal_steps(const std::vector<Cell>& path) {
  std::pair<int, int> steps{0, 0};
  for (std::size_t i = 1; i < path.size(); ++i) {
    ++(path[i].x != path[i - 1].x && path[i].y != path[i - 1].y ? steps.second : steps.first);
  }
  return steps;
}

std::string text(Cell c) { return "(" + std::to_string(c.x) + "," + std::to_string(c.y) + ")"; }

/// Plans `req` with jps+ and with astar: the same status and, on Success, a valid path with
/// astar's numbers of straight and diagonal steps. Returns astar's status.
PlanStatus expect_astar_answer(Planner& jps_plus, Planner& astar, const KnownMap& known,
                               const PlanRequest& req, const std::string& what) {
  const std::string query = what + " " + text(req.start) + "->" + text(req.goal) +
                            (req.allow_corner_cutting ? " cutting corners" : "");
  const PlanResult best = astar.plan(known, req);
  const PlanResult r = jps_plus.plan(known, req);
  EXPECT_EQ(r.status, best.status) << query;
  if (best.status == PlanStatus::Success && r.status == PlanStatus::Success) {
    expect_valid_path(known, req, r);
    EXPECT_EQ(straight_and_diagonal_steps(r.path), straight_and_diagonal_steps(best.path))
        << query << ": jps+ " << r.length_m << ", astar " << best.length_m;
  }
  return best.status;
}

/// Makes cell `c` of a known map occupied (a wall appears) or free (it goes).
void set_cell(KnownMap& known, Cell c, bool occupied) {
  (void)known.forget(known.index(c));
  (void)known.reveal(known.index(c), occupied);
}

// Every query of each MovingAI scenario in tests/data under both corner rules, with one table
// per rule and map; without corner cutting also MovingAI's optimal length (6 significant digits).
TEST(JpsPlusPlanner, ScenarioQueriesMatchAStarWithOneTablePerCornerRule) {
  const auto astar = make_planner("astar", nullptr);
  const std::string data = std::string(FSWEEP_TEST_DATA) + "/";
  for (const auto& [map_file, scen_file] :
       {std::pair{"arena.map", "arena.map.scen"}, std::pair{"den312d.map", "den312d.map.scen"},
        std::pair{"room-64-64-8.map", "room-64-64-8-random-1.scen"}}) {
    const KnownMap known = fully_known(load_movingai_map(data + map_file));
    const std::vector<ScenarioQuery> queries = load_scenario(data + scen_file);
    ASSERT_GT(queries.size(), 100U) << scen_file;
    JpsPlusPlanner jps_plus;
    int k = 0;
    for (const ScenarioQuery& q : queries) {
      for (const bool cut : {false, true}) {
        PlanRequest req = request_for(q.start, q.goal, cut);
        // Every start heading, and turns that cost (expect_valid_path checks the totals).
        req.start_heading = k++ % 8;
        req.energy = energy_preset("mei2006");
        (void)expect_astar_answer(jps_plus, *astar, known, req, scen_file);
        if (cut || q.optimal_length <= 0.0) continue;
        EXPECT_NEAR(jps_plus.plan(known, req).length_m, q.optimal_length, 1e-5 * q.optimal_length)
            << scen_file << " " << text(q.start) << "->" << text(q.goal);
      }
    }
    EXPECT_EQ(jps_plus.table_builds(), 2) << scen_file;
  }
}

// jps+ follows its diagonals as jps does (the straight jumps' jump points from each diagonal jump
// point opened directly, the diagonal jump points not settled), so on a scenario it settles about
// as many jump points as jps: a few more, its target jump points on the goal's row or column.
// Settling the diagonal jump points, as the 2011 search does, takes 1.9x jps's on den312d.
TEST(JpsPlusPlanner, SettlesAboutAsManyJumpPointsAsJps) {
  const std::string data = std::string(FSWEEP_TEST_DATA) + "/";
  const KnownMap known = fully_known(load_movingai_map(data + "den312d.map"));
  JpsPlusPlanner jps_plus;
  const auto jps = make_planner("jps", nullptr);
  long jps_plus_expansions = 0;
  long jps_expansions = 0;
  for (const ScenarioQuery& q : load_scenario(data + "den312d.map.scen")) {
    for (const bool cut : {false, true}) {
      const PlanRequest req = request_for(q.start, q.goal, cut);
      jps_plus_expansions += jps_plus.plan(known, req).expansions;
      jps_expansions += jps->plan(known, req).expansions;
    }
  }
  EXPECT_GE(jps_plus_expansions, jps_expansions);
  EXPECT_LE(jps_plus_expansions * 10, jps_expansions * 12);
}

// Seeded random maps, densities 0.05 to 0.4, some wider or taller than 64 cells: random pairs
// (some unreachable at the higher densities) and start == goal, under both corner rules.
TEST(JpsPlusPlanner, RandomMapsMatchAStar) {
  JpsPlusPlanner jps_plus;
  const auto astar = make_planner("astar", nullptr);
  int solved = 0;
  int unreachable = 0;
  int same_cell = 0;
  for (const double density : {0.05, 0.1, 0.2, 0.3, 0.4}) {
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
      const int width = seed == 5 ? 130 : 37 + static_cast<int>(seed);
      const int height = seed == 6 ? 70 : 29;
      const KnownMap known = testing::random_known_map(width, height, density, seed);
      Rng rng = make_rng(seed, "jps_plus_queries");
      for (int q = 0; q < 50; ++q) {
        const Cell start = testing::random_free_cell(known, rng);
        const Cell goal = q % 20 == 7 ? start : testing::random_free_cell(known, rng);
        for (const bool cut : {false, true}) {
          const std::string what = "density " + std::to_string(density) + " seed " + std::to_string(seed);
          const PlanStatus status =
              expect_astar_answer(jps_plus, *astar, known, request_for(start, goal, cut), what);
          if (status == PlanStatus::Success) ++(start == goal ? same_cell : solved);
          if (status == PlanStatus::NoPath) ++unreachable;
        }
      }
    }
  }
  // The draw covers what it claims to.
  EXPECT_GT(solved, 1000);
  EXPECT_GT(unreachable, 100);
  EXPECT_GT(same_cell, 50);
}

TEST(JpsPlusPlanner, UnreachableGoalIsNoPath) {
  const auto m = known_from_ascii({
      "S..#...",
      "...#.G.",
      "...#...",
  });
  JpsPlusPlanner jps_plus;
  for (const bool cut : {false, true}) {
    const PlanResult r = jps_plus.plan(m.known, request_for(m.start, m.goal, cut));
    EXPECT_EQ(r.status, PlanStatus::NoPath);
    EXPECT_TRUE(r.path.empty());
  }
}

TEST(JpsPlusPlanner, StartIsGoalGivesOneCellPath) {
  const auto m = known_from_ascii({
      "....",
      ".S..",
      "....",
  });
  JpsPlusPlanner jps_plus;
  const PlanResult r = jps_plus.plan(m.known, request_for(m.start, m.start));
  ASSERT_EQ(r.status, PlanStatus::Success);
  EXPECT_EQ(r.path, std::vector<Cell>{m.start});
  EXPECT_EQ(r.length_m, 0.0);
  EXPECT_EQ(r.expansions, 1);
}

TEST(JpsPlusPlanner, DiagonalGapBetweenTwoOccupiedCellsPassedOnlyCuttingCorners) {
  // The only way from the left part to the right one is the diagonal step (1,0) -> (2,1),
  // between the occupied (2,0) and (1,1). Each corner rule has its own table: asking for the
  // other one again is no change.
  const auto m = known_from_ascii({
      "S.#...",
      ".#..G.",
  });
  JpsPlusPlanner jps_plus;
  EXPECT_EQ(jps_plus.plan(m.known, request_for(m.start, m.goal, false)).status, PlanStatus::NoPath);
  const PlanRequest cut = request_for(m.start, m.goal, true);
  const PlanResult r = jps_plus.plan(m.known, cut);
  expect_valid_path(m.known, cut, r);
  EXPECT_NEAR(r.length_m, 3 + kSqrt2, 1e-12);  // (0,0) -> (1,0) -> (2,1) -> (4,1)
  EXPECT_EQ(jps_plus.plan(m.known, request_for(m.start, m.goal, false)).status, PlanStatus::NoPath);
  EXPECT_EQ(jps_plus.table_builds(), 2);
}

// A wall that appears between two queries and goes again: each query gives astar's length on
// the map as it is then, so each change rebuilt the table.
TEST(JpsPlusPlanner, WallAppearingAndGoingBetweenQueries) {
  auto m = known_from_ascii({
      "..........",
      "..........",
      "S........G",
      "..........",
      "..........",
  });
  JpsPlusPlanner jps_plus;
  GridPlanner astar(GridSearchKind::AStar);
  for (const bool cut : {false, true}) {
    const PlanRequest req = request_for(m.start, m.goal, cut);
    EXPECT_NEAR(jps_plus.plan(m.known, req).length_m, 9.0, 1e-12);
    // A wall across x = 5 but for (5,0). By hand, without corner cutting: (0,2) -> (4,0) (2
    // straight, 2 diagonal steps), east through (5,0) to (6,0), then (6,0) -> (9,2) (1 straight, 2
    // diagonal); cutting corners (0,2) -> (5,0) -> (9,2) is as long: 5 + 4 sqrt(2) either way.
    for (int y = 1; y < 5; ++y) set_cell(m.known, Cell{5, y}, true);
    const PlanResult around = jps_plus.plan(m.known, req);
    expect_valid_path(m.known, req, around);
    EXPECT_NEAR(around.length_m, 5 + 4 * kSqrt2, 1e-12);
    EXPECT_NEAR(astar.plan(m.known, req).length_m, 5 + 4 * kSqrt2, 1e-12);
    // Closed altogether, then open again.
    set_cell(m.known, Cell{5, 0}, true);
    EXPECT_EQ(jps_plus.plan(m.known, req).status, PlanStatus::NoPath);
    for (int y = 0; y < 5; ++y) set_cell(m.known, Cell{5, y}, false);
    EXPECT_NEAR(jps_plus.plan(m.known, req).length_m, 9.0, 1e-12);
  }
  EXPECT_EQ(jps_plus.table_builds(), 8);
}

// A map revealed in steps (a tenth of the unknown cells each, some free ones forgotten), planned
// between known free cells after each step: one rebuild per step and corner rule.
TEST(JpsPlusPlanner, MapRevealedInStepsMatchesAStar) {
  const KnownMap truth = testing::random_known_map(150, 90, 0.2, 5);
  KnownMap known(truth.width(), truth.height(), truth.resolution_m());
  JpsPlusPlanner jps_plus;
  const auto astar = make_planner("astar", nullptr);
  Rng rng = make_rng(5, "jps_plus_changing");
  int solved = 0;
  long steps_planned = 0;
  for (int step = 0; step < 12; ++step) {
    for (int i = 0; i < known.size(); ++i) {
      if (known.is_unknown(i) && uniform01(rng) < 0.1 + 0.08 * step) known.reveal(i, !truth.is_free(i));
      if (known.is_free(i) && uniform01(rng) < 0.01) (void)known.forget(i);
    }
    if (known.free_count() < 2) continue;
    ++steps_planned;
    for (int q = 0; q < 20; ++q) {
      const Cell start = testing::random_free_cell(known, rng);
      const Cell goal = testing::random_free_cell(known, rng);
      for (const bool cut : {false, true}) {
        const std::string what = "step " + std::to_string(step);
        if (expect_astar_answer(jps_plus, *astar, known, request_for(start, goal, cut), what) ==
            PlanStatus::Success)
          ++solved;
      }
    }
  }
  EXPECT_GT(solved, 100);
  EXPECT_EQ(jps_plus.table_builds(), 2 * steps_planned);
}

// Another map in the place of the one tabulated, made by as many reveals (the same revision),
// or a copy changed apart from its source: each is another map to the table.
TEST(JpsPlusPlanner, AnotherMapWithTheSameRevisionIsRetabulated) {
  const auto astar = make_planner("astar", nullptr);
  JpsPlusPlanner jps_plus;
  KnownMap known = testing::random_known_map(60, 40, 0.3, 11);
  const KnownMap other = testing::random_known_map(60, 40, 0.3, 12);
  ASSERT_EQ(known.revision(), other.revision());
  Rng rng = make_rng(11, "jps_plus_replaced");
  int solved = 0;
  for (int round = 0; round < 3; ++round) {
    if (round == 1) known = other;  // assigned in place: the same object, the same revision
    if (round == 2) {
      KnownMap copy = known;
      set_cell(copy, testing::random_free_cell(copy, rng), true);
      known = std::move(copy);
    }
    for (int q = 0; q < 40; ++q) {
      const PlanRequest req =
          request_for(testing::random_free_cell(known, rng), testing::random_free_cell(known, rng));
      if (expect_astar_answer(jps_plus, *astar, known, req, "round " + std::to_string(round)) ==
          PlanStatus::Success)
        ++solved;
    }
  }
  EXPECT_GT(solved, 60);
  EXPECT_EQ(jps_plus.table_builds(), 3);
}

// Straight jumps longer than a table entry holds (32767 steps): a 40,000-cell line with one side
// cell free near its far end (a jump point 39,990 steps from the start, and a wall as far behind
// it), along a row and along a column; the table cuts them by extra jump points.
TEST(JpsPlusPlanner, JumpsLongerThanATableEntryMatchAStar) {
  constexpr int kLength = 40000;
  const auto astar = make_planner("astar", nullptr);
  for (const bool along_row : {true, false}) {
    const auto at = [along_row](int along, int across) {
      return along_row ? Cell{along, across} : Cell{across, along};
    };
    KnownMap known(along_row ? kLength : 2, along_row ? 2 : kLength, 1.0);
    for (int i = 0; i < kLength; ++i) {
      known.reveal(known.index(at(i, 0)), false);
      known.reveal(known.index(at(i, 1)), i != kLength - 10);
    }
    JpsPlusPlanner jps_plus;
    for (const auto& [from, to] :
         {std::pair{at(0, 0), at(kLength - 1, 0)}, std::pair{at(0, 0), at(kLength - 10, 1)},
          std::pair{at(kLength - 1, 0), at(0, 0)}, std::pair{at(kLength - 10, 1), at(3, 0)},
          std::pair{at(5, 0), at(39000, 0)}}) {
      for (const bool cut : {false, true}) {
        EXPECT_EQ(expect_astar_answer(jps_plus, *astar, known, request_for(from, to, cut),
                                      along_row ? "row" : "column"),
                  PlanStatus::Success);
      }
    }
  }
}

TEST(JpsPlusPlanner, ExpansionBudgetCountsJumpPoints) {
  // 64 x 64 free cells, (0,0) -> (63,40): the start's diagonal jump stops on the goal's row at
  // (40,40) (a target jump point, 40 <= the 63 free diagonal steps), whose east jump sees the
  // goal 23 cells ahead: the goal is the 3rd settled.
  KnownMap known(64, 64, 1.0);
  for (int i = 0; i < known.size(); ++i) known.reveal(i, false);
  const PlanRequest req = request_for(Cell{0, 0}, Cell{63, 40});
  const PlanResult free_run = JpsPlusPlanner().plan(known, req);
  expect_valid_path(known, req, free_run);
  EXPECT_NEAR(free_run.length_m, 23 + 40 * kSqrt2, 1e-9);
  EXPECT_EQ(free_run.expansions, 3);
  EXPECT_EQ(JpsPlusPlanner({.max_expansions = 3}).plan(known, req).status, PlanStatus::Success);
  const PlanResult short_run = JpsPlusPlanner({.max_expansions = 2}).plan(known, req);
  EXPECT_EQ(short_run.status, PlanStatus::Timeout);
  EXPECT_EQ(short_run.expansions, 2);
  // A time limit that ends before the query starts searching: Timeout, the table kept.
  JpsPlusPlanner hurried({.time_limit_s = 1e-9});
  EXPECT_EQ(hurried.plan(known, req).status, PlanStatus::Timeout);
  EXPECT_EQ(hurried.table_builds(), 1);
}

// (Its capabilities are in test_registry.cpp's table.)
TEST(JpsPlusPlanner, RegisteredWithBudgetParams) {
  const auto planner = make_planner("jps+", {{"max_expansions", 7}, {"time_limit_s", 2.5}});
  EXPECT_EQ(planner->name(), "jps+");
  EXPECT_EQ(planner->budget().max_expansions, 7);
  EXPECT_EQ(planner->budget().time_limit_s, 2.5);
  EXPECT_THROW((void)make_planner("jps+", {{"allow_corner_cutting", true}}), ConfigError);
  EXPECT_THROW((void)make_planner("jps+", {{"max_expansions", -1}}), ConfigError);
}

}  // namespace test_jps_plus_planner
}  // namespace fsweep
