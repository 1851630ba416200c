/// OMPL planners (src/planners/ompl_planner.hpp) and the exact segment geometry under them
/// (src/planners/ompl_segment_walk.hpp): hand-worked segment walks, valid paths and statuses for
/// every OMPL planner on tiny maps, parameter validation, and seed reproducibility.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "core/config_error.hpp"
#include "planner_test_utils.hpp"
#include "planners/ompl_planner.hpp"
#include "planners/ompl_segment_walk.hpp"
#include "planners/registry.hpp"

namespace fsweep {
namespace test_ompl_planner {  // not anonymous: unity builds put it beside other test files' helpers

using testing::expect_valid_path;
using testing::known_from_ascii;

/// The kind registered as "ompl:<name>".
const OmplPlannerKind& kind_of(std::string_view name) {
  return ompl_planner_kind("ompl:" + std::string(name));
}

struct WalkStep {
  Cell from;
  Cell to;
  double t;
};

std::vector<WalkStep> walk(PlanePoint a, PlanePoint b, bool cut = false) {
  std::vector<WalkStep> steps;
  walk_segment_cells(a, b, cut, [&](Cell from, Cell to, double t) {
    steps.push_back({from, to, t});
    return true;
  });
  return steps;
}

PlanRequest request_for(Cell start, Cell goal, std::uint64_t seed = 7, bool cut = false) {
  PlanRequest r;
  r.start = start;
  r.goal = goal;
  r.seed = seed;
  r.allow_corner_cutting = cut;
  return r;
}

OmplPlanner make_ompl(const OmplPlannerKind& kind, const nlohmann::json& params) {
  return OmplPlanner(kind, ompl_planner_params(kind).read(params, "planner/params"));
}

// --- Segment geometry (hand-worked) ---------------------------------------------------------

TEST(OmplSegmentWalk, HorizontalSegmentCrossesEachCellOnce) {
  // (0.5,0.5) -> (2.5,0.5): x = 1 at t = 0.5/2 = 0.25, x = 2 at t = 1.5/2 = 0.75.
  const std::vector<WalkStep> s = walk({0.5, 0.5}, {2.5, 0.5});
  ASSERT_EQ(s.size(), 2U);
  EXPECT_EQ(s[0].to, (Cell{1, 0}));
  EXPECT_DOUBLE_EQ(s[0].t, 0.25);
  EXPECT_EQ(s[1].to, (Cell{2, 0}));
  EXPECT_DOUBLE_EQ(s[1].t, 0.75);
}

TEST(OmplSegmentWalk, DiagonalThroughVerticesIsDiagonalMoves) {
  // (0.5,0.5) -> (2.5,2.5) passes the vertices (1,1) at t = 0.25 and (2,2) at t = 0.75.
  const std::vector<WalkStep> s = walk({0.5, 0.5}, {2.5, 2.5});
  ASSERT_EQ(s.size(), 2U);
  EXPECT_EQ(s[0].from, (Cell{0, 0}));
  EXPECT_EQ(s[0].to, (Cell{1, 1}));
  EXPECT_DOUBLE_EQ(s[0].t, 0.25);
  EXPECT_EQ(s[1].to, (Cell{2, 2}));
}

TEST(OmplSegmentWalk, ShallowSegmentVisitsEveryClippedCell) {
  // (0.5,0.5) -> (2.5,1.5): x = 1 at t = 0.25 (cell (1,0)), y = 1 at t = 0.5 (cell (1,1)),
  // x = 2 at t = 0.75 (cell (2,1)).
  const std::vector<WalkStep> s = walk({0.5, 0.5}, {2.5, 1.5});
  ASSERT_EQ(s.size(), 3U);
  EXPECT_EQ(s[0].to, (Cell{1, 0}));
  EXPECT_EQ(s[1].to, (Cell{1, 1}));
  EXPECT_DOUBLE_EQ(s[1].t, 0.5);
  EXPECT_EQ(s[2].to, (Cell{2, 1}));
  EXPECT_DOUBLE_EQ(s[2].t, 0.75);
}

TEST(OmplSegmentWalk, BlockedCellStopsTheSegmentWhereItIsEntered) {
  const auto m = known_from_ascii({"...", ".#."});
  const SegmentCheck c = check_segment(m.known, {0.5, 0.5}, {2.5, 1.5}, false);
  EXPECT_FALSE(c.free);
  EXPECT_DOUBLE_EQ(c.blocked_t, 0.5);  // enters (1,1) at y = 1 (see above)
  EXPECT_TRUE(check_segment(m.known, {0.5, 0.5}, {2.5, 0.5}, false).free);
  EXPECT_FALSE(check_segment(m.known, {1.5, 1.5}, {2.5, 0.5}, false).free);  // starts blocked
  EXPECT_EQ(check_segment(m.known, {1.5, 1.5}, {2.5, 0.5}, false).blocked_t, 0.0);
}

TEST(OmplSegmentWalk, VertexBetweenTwoBlockedCellsOnlyWithCornerCutting) {
  const auto m = known_from_ascii({".#", "#."});
  EXPECT_FALSE(check_segment(m.known, {0.5, 0.5}, {1.5, 1.5}, false).free);
  EXPECT_TRUE(check_segment(m.known, {0.5, 0.5}, {1.5, 1.5}, true).free);
  // One blocked side is a cut corner too (the MovingAI rule of octile_grid.hpp).
  const auto one = known_from_ascii({".#", ".."});
  EXPECT_FALSE(check_segment(one.known, {0.5, 0.5}, {1.5, 1.5}, false).free);
  EXPECT_TRUE(check_segment(one.known, {0.5, 0.5}, {1.5, 1.5}, true).free);
}

TEST(OmplSegmentWalk, SegmentNearAVertexIsCheckedStrictlyInBothModes) {
  // Passes 1e-12 cells below the vertex (1,1), so it clips the blocked cell (1,0): without
  // corner cutting that counts as a vertex crossing (both sides must be free), with it as an
  // orthogonal move into (1,0). Blocked either way.
  const auto m = known_from_ascii({".#", ".."});
  EXPECT_FALSE(check_segment(m.known, {0.5, 0.5}, {1.5, 1.5 - 2e-12}, true).free);
  EXPECT_FALSE(check_segment(m.known, {0.5, 0.5}, {1.5, 1.5 - 2e-12}, false).free);
}

TEST(OmplSegmentWalk, PolylineChainTakesDiagonalsWhereAllowed) {
  // Walked cells (0,0) (1,0) (1,1) (2,1): the corner (0,0)->(1,0)->(1,1) becomes a diagonal.
  const auto open = known_from_ascii({"...", "..."});
  const std::vector<Cell> chain = polyline_cell_chain(open.known, {{0.5, 0.5}, {2.5, 1.5}}, false);
  EXPECT_EQ(chain, (std::vector<Cell>{{0, 0}, {1, 1}, {2, 1}}));
  // With (0,1) blocked the first diagonal would cut a corner; (1,0)->(1,1)->(2,1) still
  // becomes (1,0)->(2,1).
  const auto blocked = known_from_ascii({"...", "#.."});
  EXPECT_EQ(polyline_cell_chain(blocked.known, {{0.5, 0.5}, {2.5, 1.5}}, false),
            (std::vector<Cell>{{0, 0}, {1, 0}, {2, 1}}));
  EXPECT_EQ(polyline_cell_chain(blocked.known, {{0.5, 0.5}, {2.5, 1.5}}, true),
            (std::vector<Cell>{{0, 0}, {1, 1}, {2, 1}}));
  // Two segments joined at a shared vertex (the corner at (2,0) becomes a diagonal); one
  // point is one cell.
  EXPECT_EQ(polyline_cell_chain(open.known, {{0.5, 0.5}, {2.5, 0.5}, {2.5, 1.5}}, false),
            (std::vector<Cell>{{0, 0}, {1, 0}, {2, 1}}));
  EXPECT_EQ(polyline_cell_chain(open.known, {{0.5, 0.5}}, false), (std::vector<Cell>{{0, 0}}));
}

// --- Planners --------------------------------------------------------------------------------

class OmplPlannerKinds : public ::testing::TestWithParam<OmplPlannerKind> {};

TEST_P(OmplPlannerKinds, FindsValidPathAroundWalls) {
  // Diagonal gaps next to blocked cells, an unknown pocket and a detour through the bottom.
  const auto m = known_from_ascii({
      "S..#......",
      ".#.#.####.",
      ".#.#...?#.",
      ".#...#.?#.",
      ".####..#.G",
  });
  // LazyPRMstar with an iteration budget, not a wall-clock one: 0.1 s ran out for it in the
  // sanitizer tree on a loaded machine (a flaky Timeout); its time limit only guards a hang.
  OmplPlanner planner = GetParam().name == "ompl:LazyPRMstar"
                            ? make_ompl(GetParam(), {{"time_limit_s", 30.0}, {"max_iterations", 250}})
                            : make_ompl(GetParam(), {{"time_limit_s", 0.1}});
  for (const bool cut : {false, true}) {
    const PlanRequest req = request_for(m.start, m.goal, 11, cut);
    const PlanResult r = planner.plan(m.known, req);
    ASSERT_EQ(r.status, PlanStatus::Success) << planner.name() << " cut=" << cut;
    expect_valid_path(m.known, req, r);  // every cell free, 8-neighbours, no cut corner
    EXPECT_GT(r.expansions, 0);
  }
}

TEST_P(OmplPlannerKinds, WalledOffGoalTimesOutWithinBudget) {
  const auto m = known_from_ascii({"S..#...", "...#...", "...#..G"});
  OmplPlanner planner = make_ompl(GetParam(), {{"time_limit_s", 0.05}});
  const PlanResult r = planner.plan(m.known, request_for(m.start, m.goal));
  EXPECT_TRUE(r.status == PlanStatus::Timeout || r.status == PlanStatus::NoPath) << to_string(r.status);
  EXPECT_TRUE(r.path.empty());
  EXPECT_LT(r.time_s, 0.05 + 0.25);  // budget plus OMPL's set-up and tear-down
}

TEST_P(OmplPlannerKinds, DiagonalGapBetweenBlockedCellsIsClosedWithoutCornerCutting) {
  // The only ways from S to G are diagonal gaps between two blocked cells. Without corner
  // cutting there is no path. With it, a gap is a single point of the plane that sampled
  // segments almost never pass exactly, so a path is not required; if one is found it must
  // be valid.
  const auto m = known_from_ascii({"S.#", ".#.", "#.G"});
  OmplPlanner planner = make_ompl(GetParam(), {{"time_limit_s", 0.05}});
  const PlanResult strict = planner.plan(m.known, request_for(m.start, m.goal, 3, false));
  EXPECT_TRUE(strict.status == PlanStatus::Timeout || strict.status == PlanStatus::NoPath)
      << to_string(strict.status);
  const PlanRequest cut = request_for(m.start, m.goal, 3, true);
  const PlanResult r = planner.plan(m.known, cut);
  if (r.status == PlanStatus::Success) expect_valid_path(m.known, cut, r);
}

TEST_P(OmplPlannerKinds, InvalidEndpointsAreStatuses) {
  const auto m = known_from_ascii({"S.#", "..?"});
  OmplPlanner planner = make_ompl(GetParam(), nullptr);
  EXPECT_EQ(planner.plan(m.known, request_for(Cell{2, 0}, m.start)).status, PlanStatus::StartInvalid);
  EXPECT_EQ(planner.plan(m.known, request_for(m.start, Cell{2, 1})).status, PlanStatus::GoalInvalid);
  EXPECT_EQ(planner.plan(m.known, request_for(m.start, Cell{5, 5})).status, PlanStatus::GoalInvalid);
}

INSTANTIATE_TEST_SUITE_P(All, OmplPlannerKinds, ::testing::ValuesIn(ompl_planner_kinds()),
                         [](const ::testing::TestParamInfo<OmplPlannerKind>& info) {
                           return std::string(info.param.name.substr(5));
                         });

TEST(OmplPlanner, RandomMapsWithUnknownCellsGiveValidPaths) {
  // 30x30 maps, each cell unknown with probability 0.1, else occupied with probability 0.25;
  // queries reachable by astar (same move rule). Every returned chain is checked cell by cell.
  const auto astar = make_planner("astar", nullptr);
  for (const std::uint64_t map_seed : {1U, 2U, 3U}) {
    KnownMap known(30, 30, 0.5);
    Rng cells = make_rng(map_seed, "ompl_test_map");
    for (int i = 0; i < known.size(); ++i) {
      if (uniform01(cells) >= 0.1) known.reveal(i, uniform01(cells) < 0.25);
    }
    Rng rng = make_rng(map_seed, "ompl_test_queries");
    for (const char* kind : {"RRTConnect", "KPIECE1", "BITstar"}) {
      OmplPlanner planner = make_ompl(kind_of(kind), {{"time_limit_s", 0.05}});
      int solved = 0;
      for (int q = 0; q < 6; ++q) {
        PlanRequest req;
        do {  // a reachable query (unreachable ones are covered above)
          req = request_for(testing::random_free_cell(known, rng), testing::random_free_cell(known, rng),
                            static_cast<std::uint64_t>(q), q % 2 == 1);
        } while (astar->plan(known, req).status != PlanStatus::Success);
        const PlanResult r = planner.plan(known, req);
        if (r.status != PlanStatus::Success) continue;  // the budget may run out
        expect_valid_path(known, req, r);
        ++solved;
      }
      EXPECT_GT(solved, 0) << planner.name() << " map " << map_seed;
    }
  }
}

TEST(OmplPlanner, IterationBudgetEndsTheQuery) {
  const auto m = known_from_ascii({"S..#...", "...#...", "...#..G"});
  OmplPlanner planner = make_ompl(kind_of("RRTstar"), {{"time_limit_s", 10.0}, {"max_iterations", 50}});
  const PlanResult r = planner.plan(m.known, request_for(m.start, m.goal));
  EXPECT_EQ(r.status, PlanStatus::Timeout);
  EXPECT_LT(r.time_s, 1.0);  // far below the 10 s time limit
}

// --- Parameters -------------------------------------------------------------------------------

TEST(OmplPlannerParams, UnknownKeyListsKnownOnes) {
  try {
    (void)make_planner("ompl:RRTConnect", {{"rnage", 2.0}});
    FAIL() << "expected a ConfigError";
  } catch (const ConfigError& e) {
    const std::string msg = e.what();
    EXPECT_EQ(e.where(), "planner/params/rnage");
    for (const char* known : {"range", "intermediate_states", "time_limit_s", "max_iterations", "simplify"}) {
      EXPECT_NE(msg.find(known), std::string::npos) << known << " missing from: " << msg;
    }
  }
  const ParamDecl<OmplPlannerParams> decl = ompl_planner_params(kind_of("RRTstar"));
  std::vector<std::string> names;
  for (const ParamSpec& spec : decl.specs()) names.push_back(spec.name);
  for (const char* known : {"goal_bias", "range", "rewire_factor", "time_limit_s"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), known), names.end()) << known;
  }
}

TEST(OmplPlannerParams, ValuesAreCheckedByOmplAndByUs) {
  const OmplPlannerParams p = ompl_planner_params(kind_of("RRTstar"))
                                  .read({{"range", 2.5}, {"goal_bias", "0.1"}, {"simplify", false}}, "p");
  EXPECT_EQ(p.ompl.at("range"), "2.5");
  EXPECT_EQ(p.ompl.at("goal_bias"), "0.1");
  EXPECT_FALSE(p.simplify);
  EXPECT_THROW((void)ompl_planner_params(kind_of("RRTstar")).read({{"range", "far"}}, "p"), ConfigError);
  EXPECT_THROW((void)ompl_planner_params(kind_of("RRTstar")).read({{"range", {1, 2}}}, "p"), ConfigError);
  EXPECT_THROW((void)ompl_planner_params(kind_of("RRTstar")).read({{"time_limit_s", 0}}, "p"), ConfigError);
  EXPECT_THROW((void)ompl_planner_params(kind_of("RRTstar")).read({{"time_limit_s", "1"}}, "p"), ConfigError);
  EXPECT_THROW((void)ompl_planner_params(kind_of("RRTstar")).read({{"max_iterations", -1}}, "p"),
               ConfigError);
  EXPECT_THROW((void)ompl_planner_params(kind_of("RRTstar")).read({{"max_iterations", 1.5}}, "p"),
               ConfigError);
  EXPECT_THROW((void)ompl_planner_params(kind_of("RRTstar")).read(nlohmann::json::array(), "p"), ConfigError);
}

TEST(OmplPlannerParams, OmplParameterChangesThePlanner) {
  // A range of 0.5 cell makes RRTConnect take many short extensions: more validity checks
  // than with the default range (a fraction of the map extent) on the same open map and seed.
  const KnownMap open = testing::random_known_map(30, 30, 0.0, 1);
  const PlanRequest req = request_for(Cell{0, 0}, Cell{29, 29});
  OmplPlanner coarse = make_ompl(kind_of("RRTConnect"), {{"time_limit_s", 1.0}});
  OmplPlanner fine = make_ompl(kind_of("RRTConnect"), {{"time_limit_s", 1.0}, {"range", 0.5}});
  const PlanResult rc = coarse.plan(open, req);
  const PlanResult rf = fine.plan(open, req);
  ASSERT_EQ(rc.status, PlanStatus::Success);
  ASSERT_EQ(rf.status, PlanStatus::Success);
  EXPECT_GT(rf.expansions, rc.expansions);
}

// --- Reproducibility ---------------------------------------------------------------------------

TEST(OmplPlannerSeeds, SameSeedSamePathAlsoInParallel) {
  const KnownMap known = testing::random_known_map(30, 30, 0.25, 5);
  Rng rng = make_rng(9, "ompl_queries");
  std::vector<PlanRequest> queries;
  const auto astar = make_planner("astar", nullptr);
  while (queries.size() < 4) {
    const PlanRequest q = request_for(testing::random_free_cell(known, rng),
                                      testing::random_free_cell(known, rng), 100 + queries.size());
    if (astar->plan(known, q).status == PlanStatus::Success) queries.push_back(q);  // reachable
  }
  // Every single-threaded planner, ended by a solution (RRTConnect, KPIECE1) or by iterations
  // (the anytime planners).
  const auto anytime = [](int iterations) {
    return nlohmann::json{{"time_limit_s", 5.0}, {"max_iterations", iterations}};
  };
  const std::vector<std::pair<const char*, nlohmann::json>> setups{
      {"RRTConnect", {{"time_limit_s", 5.0}, {"simplify", false}}},
      {"KPIECE1", {{"time_limit_s", 5.0}}},
      {"RRTstar", anytime(3000)},
      {"InformedRRTstar", anytime(3000)},
      {"BITstar", anytime(1000)},
      {"LazyPRMstar", anytime(300)},
  };
  EXPECT_EQ(kind_of("PRMstar").capabilities.determinism, Determinism::Never);  // why it is not here
  for (const auto& [kind_name, params] : setups) {
    const OmplPlannerKind& kind = kind_of(kind_name);
    ASSERT_EQ(kind.capabilities.determinism, Determinism::WithMaxIterations) << kind.name;
    const auto run_all = [&, params = params]() {
      OmplPlanner planner = make_ompl(kind, params);
      std::vector<PlanResult> results;
      for (const PlanRequest& q : queries) results.push_back(planner.plan(known, q));
      return results;
    };
    const std::vector<PlanResult> first = run_all();
    std::vector<PlanResult> a;
    std::vector<PlanResult> b;
    std::thread ta([&] { a = run_all(); });
    std::thread tb([&] { b = run_all(); });
    ta.join();
    tb.join();
    int distinct_paths = 0;
    int successes = 0;
    for (std::size_t q = 0; q < queries.size(); ++q) {
      EXPECT_EQ(first[q].status, a[q].status);
      EXPECT_EQ(first[q].path, a[q].path) << kind.name << " query " << q;
      EXPECT_EQ(first[q].path, b[q].path) << kind.name << " query " << q;
      EXPECT_EQ(first[q].expansions, b[q].expansions);
      if (q > 0 && first[q].path != first[q - 1].path) ++distinct_paths;
      if (first[q].status == PlanStatus::Success) ++successes;
    }
    EXPECT_GT(distinct_paths, 0) << kind.name;
    EXPECT_GE(successes, 2) << kind.name;  // not vacuous: half the queries solved
  }
}

TEST(OmplPlannerSeeds, OtherSeedOtherTree) {
  // Same query, different seeds: the sampled trees differ (vertex counts or paths).
  const KnownMap open = testing::random_known_map(30, 30, 0.1, 2);
  OmplPlanner planner = make_ompl(kind_of("RRTConnect"), {{"time_limit_s", 2.0}, {"simplify", false}});
  const Cell s = open.is_free(Cell{0, 0}) ? Cell{0, 0} : Cell{1, 1};
  const Cell g = open.is_free(Cell{29, 29}) ? Cell{29, 29} : Cell{28, 28};
  ASSERT_EQ(make_planner("astar", nullptr)->plan(open, request_for(s, g)).status, PlanStatus::Success);
  int differing = 0;
  const PlanResult base = planner.plan(open, request_for(s, g, 1));
  for (std::uint64_t seed = 2; seed < 6; ++seed) {
    const PlanResult r = planner.plan(open, request_for(s, g, seed));
    if (r.path != base.path || r.expansions != base.expansions) ++differing;
  }
  EXPECT_GT(differing, 0);
}

}  // namespace test_ompl_planner
}  // namespace fsweep
