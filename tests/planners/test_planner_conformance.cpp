/// Every registered planner through the same checks (docs/dev/architecture.md, "Plugins and their
/// parameters"): valid 8-connected,
/// collision-free paths over known-free cells that start and end right, the documented
/// statuses for invalid or unreachable endpoints, the stop condition (a tiny expansion budget
/// or time limit ends every planner's query with Timeout), and the declared capabilities
/// (deterministic planners repeat themselves, optimal ones match astar's lengths; the grid
/// planners' optimality against MovingAI's lengths is in test_scenario_check.cpp).

#include <gtest/gtest.h>

#include <cctype>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "planner_test_utils.hpp"
#include "planners/registry.hpp"
#include "world/known_map.hpp"
#include "world/map_loaders.hpp"
#include "world/world_map.hpp"

namespace fsweep {
namespace test_planner_conformance {  // not anonymous: unity builds put it beside other test files' helpers

using testing::expect_valid_path;
using testing::known_from_ascii;

class PlannerConformance : public ::testing::TestWithParam<std::string> {
 protected:
  [[nodiscard]] bool ompl() const { return GetParam().rfind("ompl:", 0) == 0; }
  /// OMPL's anytime planners use their whole time budget on every query: a short one keeps
  /// the suite fast (NameAndCloneMatchRegistry still builds every planner with its defaults).
  std::unique_ptr<Planner> make() const {
    return make_planner(GetParam(),
                        ompl() ? nlohmann::json{{"time_limit_s", 0.02}} : nlohmann::json::object());
  }
  /// The planner with an expansion budget of `n`: `max_iterations` for OMPL planners (their
  /// termination checks), `max_expansions` for the others; a time limit it never reaches.
  std::unique_ptr<Planner> make_with_expansion_budget(long n) const {
    return make_planner(GetParam(),
                        {{"time_limit_s", 30.0}, {ompl() ? "max_iterations" : "max_expansions", n}});
  }
  [[nodiscard]] PlannerCapabilities capabilities() const {
    const std::optional<PlannerCapabilities> c = planner_capabilities(GetParam());
    EXPECT_TRUE(c.has_value()) << GetParam();
    return c.value_or(PlannerCapabilities{});
  }
};

PlanRequest request_for(Cell start, Cell goal, bool allow_corner_cutting = false) {
  PlanRequest r;
  r.start = start;
  r.goal = goal;
  r.allow_corner_cutting = allow_corner_cutting;
  r.seed = 42;
  return r;
}

TEST_P(PlannerConformance, NameAndCloneMatchRegistry) {
  const auto planner = make();
  EXPECT_EQ(planner->name(), GetParam());
  EXPECT_EQ(planner->clone()->name(), GetParam());
  EXPECT_NO_THROW((void)make_planner(GetParam(), nlohmann::json()));  // null params: defaults
}

TEST_P(PlannerConformance, ValidPathsOnArena) {
  const WorldMap map = load_movingai_map(std::string(FSWEEP_TEST_DATA) + "/arena.map");
  const KnownMap known = fully_known(map);
  const auto planner = make();
  Rng rng = make_rng(3, "conformance");
  int successes = 0;
  for (int q = 0; q < 40; ++q) {
    const PlanRequest req =
        request_for(testing::random_free_cell(known, rng), testing::random_free_cell(known, rng), q % 4 == 3);
    const PlanResult r = planner->plan(known, req);
    // Reachability through the same move rule, from the ground truth.
    const bool reachable = reachable_free(map, req.start, req.allow_corner_cutting).at(req.goal) != 0;
    if (!reachable) {
      EXPECT_TRUE(r.status == PlanStatus::NoPath || r.status == PlanStatus::Timeout) << to_string(r.status);
      continue;
    }
    if (r.status == PlanStatus::Timeout) continue;  // allowed for bounded (sampling) planners
    expect_valid_path(known, req, r);
    EXPECT_GE(r.length_m + 1e-9, octile_distance(req.start, req.goal) * known.resolution_m());
    EXPECT_GE(r.time_s, 0.0);
    ++successes;
  }
  EXPECT_GT(successes, 20);
}

TEST_P(PlannerConformance, AvoidsUnknownAndOccupiedCells) {
  const auto m = known_from_ascii({
      "S..?......",
      ".#.?.####.",
      ".#.?....#.",
      ".#......#.",
      ".####.#.#G",
  });
  const auto planner = make();
  for (const bool cut : {false, true}) {
    const PlanRequest req = request_for(m.start, m.goal, cut);
    const PlanResult r = planner->plan(m.known, req);
    if (r.status == PlanStatus::Timeout) continue;
    expect_valid_path(m.known, req, r);
  }
}

TEST_P(PlannerConformance, StartEqualsGoal) {
  const auto m = known_from_ascii({"...", ".S.", "..."});
  const auto planner = make();
  const PlanResult r = planner->plan(m.known, request_for(m.start, m.start));
  ASSERT_EQ(r.status, PlanStatus::Success);
  ASSERT_EQ(r.path.size(), 1U);
  EXPECT_EQ(r.path[0], m.start);
  EXPECT_EQ(r.length_m, 0.0);
}

TEST_P(PlannerConformance, GoalInsideObstacle) {
  const auto m = known_from_ascii({"S...", ".##.", "...."});
  const auto planner = make();
  for (const Cell goal : {Cell{1, 1}, Cell{4, 0}, Cell{0, 3}, Cell{-1, -1}}) {
    const PlanResult r = planner->plan(m.known, request_for(m.start, goal));
    EXPECT_EQ(r.status, PlanStatus::GoalInvalid) << goal.x << "," << goal.y;
    EXPECT_TRUE(r.path.empty());
  }
}

TEST_P(PlannerConformance, GoalUnknown) {
  const auto m = known_from_ascii({"S..?"});
  const PlanResult r = make()->plan(m.known, request_for(m.start, Cell{3, 0}));
  EXPECT_EQ(r.status, PlanStatus::GoalInvalid);
}

TEST_P(PlannerConformance, StartInsideObstacleOrUnknown) {
  const auto m = known_from_ascii({"#..G", "?..."});
  const auto planner = make();
  for (const Cell start : {Cell{0, 0}, Cell{0, 1}, Cell{9, 9}}) {
    const PlanResult r = planner->plan(m.known, request_for(start, m.goal));
    EXPECT_EQ(r.status, PlanStatus::StartInvalid) << start.x << "," << start.y;
    EXPECT_TRUE(r.path.empty());
  }
  // Both ends invalid: the start is reported (check_endpoints in planner.hpp).
  EXPECT_EQ(planner->plan(m.known, request_for(Cell{0, 0}, Cell{0, 0})).status, PlanStatus::StartInvalid);
}

TEST_P(PlannerConformance, GoalBehindWallIsNoPath) {
  const auto m = known_from_ascii({"S.#..", "..#..", "..#.G"});
  const PlanResult r = make()->plan(m.known, request_for(m.start, m.goal));
  EXPECT_TRUE(r.status == PlanStatus::NoPath || r.status == PlanStatus::Timeout) << to_string(r.status);
  EXPECT_TRUE(r.path.empty());
}

TEST_P(PlannerConformance, NoCornerCutUnlessAllowed) {
  // The left pocket's only ways out are the diagonal gaps below (1,2), between two blocked
  // cells each: passable only with corner cutting.
  const auto m = known_from_ascii({"S.#..", "..#..", "#.#.G", ".#...", "....."});
  const auto planner = make();
  const PlanRequest strict = request_for(m.start, m.goal, false);
  const PlanResult r = planner->plan(m.known, strict);
  EXPECT_TRUE(r.status == PlanStatus::NoPath || r.status == PlanStatus::Timeout) << to_string(r.status);
  const PlanRequest cut = request_for(m.start, m.goal, true);
  const PlanResult rc = planner->plan(m.known, cut);
  if (rc.status != PlanStatus::Timeout) expect_valid_path(m.known, cut, rc);
}

/// A winding corridor: the goal is 42 moves away, reachable only through both bends.
testing::AsciiKnownMap winding_corridor() {
  return known_from_ascii({
      "S.........",
      "#########.",
      "..........",
      ".#########",
      ".........G",
  });
}

TEST_P(PlannerConformance, TinyExpansionBudgetTimesOut) {
  const auto m = winding_corridor();
  const auto planner = make_with_expansion_budget(2);
  EXPECT_EQ(planner->budget().max_expansions, 2);
  for (const bool cut : {false, true}) {
    const PlanResult r = planner->plan(m.known, request_for(m.start, m.goal, cut));
    EXPECT_EQ(r.status, PlanStatus::Timeout) << to_string(r.status);
    EXPECT_TRUE(r.path.empty());
    EXPECT_EQ(r.length_m, 0.0);
  }
  // The same planner still solves what fits in its budget.
  const PlanResult same = planner->plan(m.known, request_for(m.start, m.start));
  EXPECT_EQ(same.status, PlanStatus::Success);
}

TEST_P(PlannerConformance, TinyTimeLimitTimesOut) {
  const auto m = winding_corridor();
  const auto planner = make_planner(GetParam(), {{"time_limit_s", 1e-9}});
  EXPECT_EQ(planner->budget().time_limit_s, 1e-9);
  const PlanResult r = planner->plan(m.known, request_for(m.start, m.goal));
  EXPECT_EQ(r.status, PlanStatus::Timeout) << to_string(r.status);
  EXPECT_TRUE(r.path.empty());
  EXPECT_LT(r.time_s, 0.25);  // OMPL's set-up and tear-down on top of a budget spent at once
}

TEST_P(PlannerConformance, DefaultBudgetBoundsOnlyOmplTime) {
  const SearchBudget budget = make_planner(GetParam(), nullptr)->budget();
  if (ompl()) {
    EXPECT_EQ(budget.time_limit_s, 0.5);  // OmplPlannerParams' default
  } else {
    EXPECT_EQ(budget.time_limit_s, std::numeric_limits<double>::infinity());
  }
  EXPECT_EQ(budget.max_expansions, 0);
}

/// The planners declared deterministic (Always, or WithMaxIterations) and length-optimal.
class DeterministicPlanner : public PlannerConformance {};
class OptimalPlanner : public PlannerConformance {};

TEST_P(DeterministicPlanner, RepeatsItself) {
  const PlannerCapabilities caps = capabilities();
  // Deterministic as declared: Always with the defaults, WithMaxIterations with an iteration
  // budget (and a time limit it never reaches). Two instances, other queries in between.
  const auto make_bounded = [&] {
    return caps.determinism == Determinism::Always
               ? make_planner(GetParam(), nullptr)
               : make_planner(GetParam(), {{"time_limit_s", 30.0}, {"max_iterations", 300}});
  };
  const KnownMap known = testing::random_known_map(24, 24, 0.25, 5);
  Rng rng = make_rng(5, "conformance_determinism");
  std::vector<PlanRequest> queries;
  for (std::uint64_t q = 0; q < 6; ++q) {
    PlanRequest req =
        request_for(testing::random_free_cell(known, rng), testing::random_free_cell(known, rng));
    req.seed = 100 + q;
    queries.push_back(req);
  }
  const auto first = make_bounded();
  const auto second = make_bounded();
  std::vector<PlanResult> a;
  for (const PlanRequest& q : queries) a.push_back(first->plan(known, q));
  std::vector<PlanResult> b(queries.size());
  for (std::size_t i = queries.size(); i-- > 0;) b[i] = second->plan(known, queries[i]);  // other order
  for (std::size_t i = 0; i < queries.size(); ++i) {
    EXPECT_EQ(a[i].status, b[i].status) << "query " << i;
    EXPECT_EQ(a[i].path, b[i].path) << "query " << i;
    EXPECT_EQ(a[i].expansions, b[i].expansions) << "query " << i;
  }
}

TEST_P(OptimalPlanner, MatchesAStarLengths) {
  const KnownMap known = testing::random_known_map(30, 30, 0.25, 6);
  const auto planner = make();
  const auto astar = make_planner("astar", nullptr);
  Rng rng = make_rng(6, "conformance_optimal");
  int solved = 0;
  for (int q = 0; q < 30; ++q) {
    const PlanRequest req =
        request_for(testing::random_free_cell(known, rng), testing::random_free_cell(known, rng), q % 2 == 1);
    const PlanResult best = astar->plan(known, req);
    const PlanResult r = planner->plan(known, req);
    ASSERT_EQ(r.status, best.status);
    if (best.status != PlanStatus::Success) continue;
    EXPECT_NEAR(r.length_m, best.length_m, 1e-9);
    ++solved;
  }
  EXPECT_GT(solved, 10);
}

/// Registered names whose capabilities satisfy `keep`.
template <typename Keep>
std::vector<std::string> names_where(Keep keep) {
  std::vector<std::string> names;
  for (const std::string& name : planner_names()) {
    if (keep(planner_capabilities(name).value())) names.push_back(name);
  }
  return names;
}

/// Test-name suffix of a planner name (gtest allows only letters, digits and '_').
std::string test_name(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = info.param;
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return name;
}

INSTANTIATE_TEST_SUITE_P(Registered, PlannerConformance, ::testing::ValuesIn(planner_names()), test_name);
INSTANTIATE_TEST_SUITE_P(Registered, DeterministicPlanner,
                         ::testing::ValuesIn(names_where([](const PlannerCapabilities& c) {
                           return c.determinism != Determinism::Never;
                         })),
                         test_name);
INSTANTIATE_TEST_SUITE_P(
    Registered, OptimalPlanner,
    ::testing::ValuesIn(names_where([](const PlannerCapabilities& c) { return c.optimal; })), test_name);

}  // namespace test_planner_conformance
}  // namespace fsweep
