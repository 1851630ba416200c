/// `jps` against `astar`: the same shortest lengths (and so the same numbers of straight and
/// diagonal steps) on every query of the MovingAI scenarios in tests/data and on seeded random
/// maps under both corner rules, plus the jump-point specifics (expansions, budget, paths filled in).

#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "core/config_error.hpp"
#include "planner_test_utils.hpp"
#include "planners/grid_planner.hpp"
#include "planners/jps_planner.hpp"
#include "planners/registry.hpp"
#include "world/energy_model.hpp"
#include "world/known_map.hpp"
#include "world/map_loaders.hpp"

namespace fsweep {
namespace test_jps_planner {  // not anonymous: unity builds put it beside other test files' helpers

using testing::expect_valid_path;
using testing::known_from_ascii;
using testing::request_for;

/// Straight and diagonal steps of a cell chain.
struct StepCounts {
  int straight = 0;
  int diagonal = 0;
  friend bool operator==(const StepCounts&, const StepCounts&) = default;
};

StepCounts step_counts(const std::vector<Cell>& path) {
  StepCounts n;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const bool diagonal = path[i].x != path[i - 1].x && path[i].y != path[i - 1].y;
    ++(diagonal ? n.diagonal : n.straight);
  }
  return n;
}

/// Plans `req` with both planners and checks that jps answers as astar does: the same status;
/// on Success a valid path of the same length (1e-9 relative: the sums of 1 and sqrt(2) may
/// round differently) and the same straight and diagonal step counts. Returns astar's status.
PlanStatus expect_same_as_astar(Planner& jps, Planner& astar, const KnownMap& known, const PlanRequest& req,
                                const std::string& what) {
  const PlanResult best = astar.plan(known, req);
  const PlanResult r = jps.plan(known, req);
  EXPECT_EQ(r.status, best.status) << what;
  if (best.status != PlanStatus::Success || r.status != PlanStatus::Success) return best.status;
  expect_valid_path(known, req, r);
  EXPECT_NEAR(r.length_m, best.length_m, 1e-9 * best.length_m) << what;
  EXPECT_EQ(step_counts(r.path), step_counts(best.path))
      << what << ": jps " << step_counts(r.path).straight << "+" << step_counts(r.path).diagonal
      << " steps, astar " << step_counts(best.path).straight << "+" << step_counts(best.path).diagonal;
  return best.status;
}

std::string query_text(const PlanRequest& req) {
  return "(" + std::to_string(req.start.x) + "," + std::to_string(req.start.y) + ")->(" +
         std::to_string(req.goal.x) + "," + std::to_string(req.goal.y) + ")" +
         (req.allow_corner_cutting ? " cutting corners" : "");
}

struct ScenarioFiles {
  const char* map_file;
  const char* scen_file;
  friend void PrintTo(const ScenarioFiles& f, std::ostream* os) { *os << f.scen_file; }
};

class JpsScenario : public ::testing::TestWithParam<ScenarioFiles> {};

// Every query of the file under both corner rules; under MovingAI's rule (no corner cutting)
// also the file's optimal length (6 significant digits).
TEST_P(JpsScenario, EveryQueryMatchesAStar) {
  const WorldMap map = load_movingai_map(std::string(FSWEEP_TEST_DATA) + "/" + GetParam().map_file);
  const KnownMap known = fully_known(map);
  const std::vector<ScenarioQuery> queries =
      load_scenario(std::string(FSWEEP_TEST_DATA) + "/" + GetParam().scen_file);
  ASSERT_GT(queries.size(), 100U);
  JpsPlanner jps;
  const auto astar = make_planner("astar", nullptr);
  long jps_expansions = 0;
  long astar_expansions = 0;
  for (const ScenarioQuery& q : queries) {
    for (const bool cut : {false, true}) {
      const PlanRequest req = request_for(q.start, q.goal, cut);
      (void)expect_same_as_astar(jps, *astar, known, req, query_text(req));
      if (cut || q.optimal_length <= 0.0) continue;
      const PlanResult r = jps.plan(known, req);
      EXPECT_NEAR(r.length_m, q.optimal_length, 1e-5 * q.optimal_length) << query_text(req);
      jps_expansions += r.expansions;
      astar_expansions += astar->plan(known, req).expansions;
    }
  }
  // Jump points are a small part of the cells A* settles.
  EXPECT_LT(jps_expansions * 4, astar_expansions);
}

INSTANTIATE_TEST_SUITE_P(Files, JpsScenario,
                         ::testing::Values(ScenarioFiles{"arena.map", "arena.map.scen"},
                                           ScenarioFiles{"den312d.map", "den312d.map.scen"},
                                           ScenarioFiles{"room-64-64-8.map", "room-64-64-8-random-1.scen"}),
                         [](const ::testing::TestParamInfo<ScenarioFiles>& info) {
                           std::string name = info.param.map_file;
                           for (char& c : name) {
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           }
                           return name;
                         });

/// A free cell with an occupied or outside 8-neighbour (the map must have one).
Cell random_cell_by_wall(const KnownMap& known, Rng& rng) {
  for (;;) {
    const Cell c = testing::random_free_cell(known, rng);
    for (const Cell d : kDirections) {
      if (!known.is_free(Cell{c.x + d.x, c.y + d.y})) return c;
    }
  }
}

/// 2x2 blocks with two occupied cells on one diagonal and two free ones on the other: the gap a
/// diagonal step may pass only with corner cutting.
int diagonal_gaps(const KnownMap& known) {
  int gaps = 0;
  for (int y = 0; y + 1 < known.height(); ++y) {
    for (int x = 0; x + 1 < known.width(); ++x) {
      const bool a = known.is_free(Cell{x, y});
      const bool b = known.is_free(Cell{x + 1, y});
      const bool c = known.is_free(Cell{x, y + 1});
      const bool d = known.is_free(Cell{x + 1, y + 1});
      if ((a && d && !b && !c) || (b && c && !a && !d)) ++gaps;
    }
  }
  return gaps;
}

// Seeded random maps, densities 0.1 to 0.4: random pairs (some unreachable at the higher
// densities), start == goal, and goals next to walls, under both corner rules.
TEST(JpsPlanner, RandomMapsMatchAStar) {
  JpsPlanner jps;
  const auto astar = make_planner("astar", nullptr);
  int solved = 0;
  int unreachable = 0;
  int same_cell = 0;
  int gaps = 0;
  for (const double density : {0.1, 0.2, 0.3, 0.4}) {
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
      const KnownMap known = testing::random_known_map(37 + static_cast<int>(seed), 29, density, seed);
      gaps += diagonal_gaps(known);
      Rng rng = make_rng(seed, "jps_queries");
      for (int q = 0; q < 60; ++q) {
        const Cell start = testing::random_free_cell(known, rng);
        Cell goal = q % 3 == 0 ? random_cell_by_wall(known, rng) : testing::random_free_cell(known, rng);
        if (q % 20 == 7) goal = start;
        for (const bool cut : {false, true}) {
          PlanRequest req = request_for(start, goal, cut);
          // Every start heading, and turns that cost (expect_valid_path checks the totals).
          req.start_heading = q % 8;
          req.energy = energy_preset("mei2006");
          const std::string what =
              "density " + std::to_string(density) + " seed " + std::to_string(seed) + " " + query_text(req);
          const PlanStatus status = expect_same_as_astar(jps, *astar, known, req, what);
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
  EXPECT_GT(gaps, 500);
}

// Maps wider and taller than a word of 64 cells (jumps scan rows and columns by words, with
// the forced-neighbour bits carried across word boundaries), and a map that is partly known and
// changes between queries (cells revealed, some forgotten): the bits follow it.
TEST(JpsPlanner, MultiWordAndChangingMapsMatchAStar) {
  JpsPlanner jps;
  const auto astar = make_planner("astar", nullptr);
  int solved = 0;
  for (const auto& [width, height] : {std::pair{130, 70}, std::pair{64, 129}, std::pair{200, 65}}) {
    for (const double density : {0.05, 0.25}) {
      const std::uint64_t seed = static_cast<std::uint64_t>(width + height);
      const KnownMap known = testing::random_known_map(width, height, density, seed);
      Rng rng = make_rng(seed, "jps_wide_queries");
      for (int q = 0; q < 40; ++q) {
        const Cell start = testing::random_free_cell(known, rng);
        const Cell goal = testing::random_free_cell(known, rng);
        for (const bool cut : {false, true}) {
          const PlanRequest req = request_for(start, goal, cut);
          if (expect_same_as_astar(jps, *astar, known, req, query_text(req)) == PlanStatus::Success) ++solved;
        }
      }
    }
  }
  EXPECT_GT(solved, 400);
  // A map revealed in steps: each step reveals a random tenth of the unknown cells (a tenth of
  // those occupied), forgets a few free ones, and plans between known free cells.
  const KnownMap truth = testing::random_known_map(150, 90, 0.2, 5);
  KnownMap known(truth.width(), truth.height(), truth.resolution_m());
  Rng rng = make_rng(5, "jps_changing");
  int changing = 0;
  for (int step = 0; step < 12; ++step) {
    for (int i = 0; i < known.size(); ++i) {
      if (known.is_unknown(i) && uniform01(rng) < 0.1 + 0.08 * step) known.reveal(i, !truth.is_free(i));
      if (known.is_free(i) && uniform01(rng) < 0.01) (void)known.forget(i);
    }
    if (known.free_count() < 2) continue;
    for (int q = 0; q < 20; ++q) {
      const Cell start = testing::random_free_cell(known, rng);
      const Cell goal = testing::random_free_cell(known, rng);
      for (const bool cut : {false, true}) {
        const PlanRequest req = request_for(start, goal, cut);
        const std::string what = "step " + std::to_string(step) + " " + query_text(req);
        if (expect_same_as_astar(jps, *astar, known, req, what) == PlanStatus::Success) ++changing;
      }
    }
  }
  EXPECT_GT(changing, 100);
}

TEST(JpsPlanner, DiagonalGapBetweenTwoOccupiedCellsIsNotPassed) {
  // The only way from S to G is the diagonal step (1,1) -> (2,2), between the occupied (2,1)
  // and (1,2): passable only with corner cutting.
  const auto m = known_from_ascii({
      "S.##",
      "..##",
      "##..",
      "##.G",
  });
  JpsPlanner jps;
  EXPECT_EQ(jps.plan(m.known, request_for(m.start, m.goal, false)).status, PlanStatus::NoPath);
  const PlanRequest cut = request_for(m.start, m.goal, true);
  const PlanResult r = jps.plan(m.known, cut);
  expect_valid_path(m.known, cut, r);
  EXPECT_NEAR(r.length_m, 3 * kSqrt2, 1e-12);
}

TEST(JpsPlanner, TurnsAroundCornerWithoutCuttingIt) {
  // Forced neighbour: going east along row 0 the wall below ends at x = 3; the shortest way to
  // G turns down there, and without corner cutting it may not cut the wall's corner (2,1).
  const auto m = known_from_ascii({
      "S......",
      "###....",
      "###....",
      "G......",
  });
  JpsPlanner jps;
  GridPlanner astar(GridSearchKind::AStar);
  for (const bool cut : {false, true}) {
    const PlanRequest req = request_for(m.start, m.goal, cut);
    const PlanResult r = jps.plan(m.known, req);
    expect_valid_path(m.known, req, r);
    EXPECT_NEAR(r.length_m, astar.plan(m.known, req).length_m, 1e-12);
  }
  // Hand calculation without corner cutting: (0,0) -> (3,0) east, (3,0) -> (3,3) south (the
  // diagonal (3,2) -> (2,3) would cut the corner (2,2)), (3,3) -> (0,3) west: 3 + 3 + 3.
  EXPECT_NEAR(jps.plan(m.known, request_for(m.start, m.goal, false)).length_m, 9.0, 1e-12);
  // With corner cutting (2,0) -> (3,1) and (3,2) -> (2,3) pass the corners: 2 + sqrt(2) + 1 +
  // sqrt(2) + 2.
  EXPECT_NEAR(jps.plan(m.known, request_for(m.start, m.goal, true)).length_m, 5 + 2 * kSqrt2, 1e-12);
}

TEST(JpsPlanner, GoalNextToWallInCorridor) {
  // The goal sits mid-corridor with no forced neighbour: the jump must stop on it.
  const auto m = known_from_ascii({
      "#########",
      "S...G....",
      "#########",
  });
  JpsPlanner jps;
  const PlanRequest req = request_for(m.start, m.goal);
  const PlanResult r = jps.plan(m.known, req);
  expect_valid_path(m.known, req, r);
  EXPECT_EQ(r.path.size(), 5U);
  EXPECT_EQ(r.expansions, 2);  // the start, then the goal
}

TEST(JpsPlanner, SettlesFewJumpPointsOnOpenMap) {
  // 64 x 64 free cells: 40 diagonal and 23 straight steps, but only two jump points; astar
  // settles at least the 64 cells of its path.
  KnownMap known(64, 64, 1.0);
  for (int i = 0; i < known.size(); ++i) known.reveal(i, false);
  JpsPlanner jps;
  const PlanRequest req = request_for(Cell{0, 0}, Cell{63, 40});
  const PlanResult r = jps.plan(known, req);
  expect_valid_path(known, req, r);
  EXPECT_NEAR(r.length_m, 23 + 40 * kSqrt2, 1e-9);
  EXPECT_EQ(r.path.size(), 64U);  // every cell filled in, one per step
  // The start and the goal: the diagonal jump from the start finds the goal by the east jump
  // from (40,40), which is not opened itself (the 2011 search settles it too, 3 expansions).
  EXPECT_EQ(r.expansions, 2);
  // The segment is filled in diagonally first, then straight.
  EXPECT_EQ(r.path[40], (Cell{40, 40}));
  EXPECT_EQ(r.path[41], (Cell{41, 40}));
  EXPECT_GE(GridPlanner(GridSearchKind::AStar).plan(known, req).expansions, 64);
}

TEST(JpsPlanner, ExpansionBudgetCountsJumpPoints) {
  // The winding corridor of the conformance suite: the jump points without corner cutting are
  // the start, (9,0), (9,2), (0,2), (0,4) and the goal; the goal is the 6th settled.
  const auto m = known_from_ascii({
      "S.........",
      "#########.",
      "..........",
      ".#########",
      ".........G",
  });
  const PlanRequest req = request_for(m.start, m.goal);
  const PlanResult free_run = JpsPlanner().plan(m.known, req);
  expect_valid_path(m.known, req, free_run);
  EXPECT_EQ(free_run.expansions, 6);
  EXPECT_EQ(JpsPlanner({.max_expansions = 6}).plan(m.known, req).status, PlanStatus::Success);
  const PlanResult short_run = JpsPlanner({.max_expansions = 5}).plan(m.known, req);
  EXPECT_EQ(short_run.status, PlanStatus::Timeout);
  EXPECT_EQ(short_run.expansions, 5);
}

TEST(JpsPlanner, RegisteredWithBudgetParams) {
  const auto planner = make_planner("jps", {{"max_expansions", 7}, {"time_limit_s", 2.5}});
  EXPECT_EQ(planner->name(), "jps");
  EXPECT_EQ(planner->budget().max_expansions, 7);
  EXPECT_EQ(planner->budget().time_limit_s, 2.5);
  const PlannerCapabilities caps = planner_capabilities("jps").value();
  EXPECT_EQ(caps.determinism, Determinism::Always);
  EXPECT_TRUE(caps.optimal);
  EXPECT_FALSE(caps.anytime);
  EXPECT_THROW((void)make_planner("jps", {{"allow_corner_cutting", true}}), ConfigError);
  EXPECT_THROW((void)make_planner("jps", {{"max_expansions", -1}}), ConfigError);
}

}  // namespace test_jps_planner
}  // namespace fsweep
