/// Every registered planner through the same checks (docs/architecture.md, "Plugins and their parameters"):
/// valid 8-connected, collision-free paths over known-free cells that start and end right, and the documented
/// statuses for invalid or unreachable endpoints. Optimality is not checked here (sampling
/// planners are not optimal); the grid planners' optimality is in test_scenario_check.cpp.

#include <gtest/gtest.h>

#include <cctype>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "planner_test_utils.hpp"
#include "planners/registry.hpp"
#include "world/known_map.hpp"
#include "world/map_loaders.hpp"
#include "world/world_map.hpp"

namespace fsweep {
namespace {

using testing::expect_valid_path;
using testing::known_from_ascii;

class PlannerConformance : public ::testing::TestWithParam<std::string> {
 protected:
  /// OMPL's anytime planners use their whole time budget on every query: a short one keeps
  /// the suite fast (NameAndCloneMatchRegistry still builds every planner with its defaults).
  std::unique_ptr<Planner> make() const {
    const bool ompl = GetParam().rfind("ompl:", 0) == 0;
    return make_planner(GetParam(), ompl ? nlohmann::json{{"time_limit_s", 0.02}} : nlohmann::json::object());
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

INSTANTIATE_TEST_SUITE_P(Registered, PlannerConformance, ::testing::ValuesIn(planner_names()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string name = info.param;
                           for (char& c : name) {
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           }
                           return name;
                         });

}  // namespace
}  // namespace fsweep
