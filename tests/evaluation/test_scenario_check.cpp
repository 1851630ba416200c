#include <gtest/gtest.h>

#include <cctype>
#include <nlohmann/json.hpp>
#include <string>
#include <tuple>
#include <vector>

#include "core/config_error.hpp"
#include "evaluation/scenario_check.hpp"
#include "planners/planner_test_utils.hpp"
#include "planners/registry.hpp"
#include "world/map_loaders.hpp"

namespace fsweep {
namespace {

struct ScenarioCase {
  const char* map_file;
  const char* scen_file;
  int queries;  // rows in the file (SOURCES.md)
};

class MovingAiScenario : public ::testing::TestWithParam<std::tuple<ScenarioCase, std::string>> {};

// Golden numbers: MovingAI's optimal lengths (8-connected, sqrt(2) diagonals, no corner
// cutting), one per query in the .scen files copied from /work/shared/data/maps.
TEST_P(MovingAiScenario, AllQueriesMatchOptimalLengths) {
  const auto& [files, planner_name] = GetParam();
  const WorldMap map = load_movingai_map(std::string(FSWEEP_TEST_DATA) + "/" + files.map_file);
  const std::vector<ScenarioQuery> queries =
      load_scenario(std::string(FSWEEP_TEST_DATA) + "/" + files.scen_file);
  ASSERT_EQ(static_cast<int>(queries.size()), files.queries);
  const auto planner = make_planner(planner_name, nlohmann::json::object());
  const ScenarioReport report = check_scenario(map, queries, *planner);
  EXPECT_EQ(report.total, files.queries);
  EXPECT_EQ(report.mismatches, 0);
  EXPECT_EQ(report.matches, files.queries);
  for (const ScenarioQueryResult& r : report.queries) {
    EXPECT_TRUE(r.match) << files.scen_file << " bucket " << r.query.bucket << " (" << r.query.start.x << ","
                         << r.query.start.y << ")->(" << r.query.goal.x << "," << r.query.goal.y
                         << "): " << to_string(r.status) << " length " << r.length_cells << " optimal "
                         << r.optimal_cells;
  }
  EXPECT_GT(report.expansions, 0);
  EXPECT_GE(report.wall_time_s, report.plan_time_s);
}

INSTANTIATE_TEST_SUITE_P(
    Files, MovingAiScenario,
    ::testing::Combine(::testing::Values(ScenarioCase{"arena.map", "arena.map.scen", 160},
                                         ScenarioCase{"den312d.map", "den312d.map.scen", 320},
                                         ScenarioCase{"room-64-64-8.map", "room-64-64-8-random-1.scen",
                                                      1000}),
                       ::testing::Values(std::string("dijkstra"), std::string("astar"))),
    [](const auto& info) {
      std::string name = std::string(std::get<0>(info.param).map_file) + "_" + std::get<1>(info.param);
      for (char& c : name) {
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
      }
      return name;
    });

/// A 5x3 ground truth with a wall: the right column is unreachable from the left.
WorldMap walled_map() {
  WorldMap map;
  map.occupied = Grid<std::uint8_t>(5, 3, 0);
  for (int y = 0; y < 3; ++y) map.occupied.at(Cell{3, y}) = 1;
  map.source = "walled";
  return map;
}

ScenarioQuery query(Cell start, Cell goal, double optimal) {
  ScenarioQuery q;
  q.map_name = "walled";
  q.map_width = 5;
  q.map_height = 3;
  q.start = start;
  q.goal = goal;
  q.optimal_length = optimal;
  return q;
}

TEST(ScenarioCheck, CountsMismatchesAndUnreachableQueries) {
  const WorldMap map = walled_map();
  const std::vector<ScenarioQuery> queries{
      query({0, 0}, {2, 0}, 2.0),          // match
      query({0, 0}, {2, 2}, 2 * 1.41421),  // match within 1e-2 (6 printed digits)
      query({0, 0}, {2, 0}, 2.5),          // wrong optimum: mismatch
      query({0, 0}, {4, 0}, 0.0),          // GPPC "unreachable" and NoPath: match
      query({0, 0}, {1, 0}, 0.0),          // "unreachable" but a path exists: mismatch
      query({1, 1}, {1, 1}, 0.0),          // start == goal: a 0-length success, match
      query({0, 0}, {3, 1}, 3.0),          // goal in the wall: GoalInvalid, mismatch
  };
  const auto planner = make_planner("astar", nlohmann::json::object());
  const ScenarioReport report = check_scenario(map, queries, *planner);
  ASSERT_EQ(report.queries.size(), queries.size());
  EXPECT_EQ(report.total, 7);
  EXPECT_EQ(report.matches, 4);
  EXPECT_EQ(report.mismatches, 3);
  EXPECT_EQ(report.unreachable_expected, 2);
  const std::vector<bool> expected{true, true, false, true, false, true, false};
  for (std::size_t i = 0; i < expected.size(); ++i)
    EXPECT_EQ(report.queries[i].match, expected[i]) << "query " << i;
  EXPECT_EQ(report.queries[3].status, PlanStatus::NoPath);
  EXPECT_TRUE(report.queries[3].unreachable_expected);
  EXPECT_FALSE(report.queries[5].unreachable_expected);
  EXPECT_EQ(report.queries[6].status, PlanStatus::GoalInvalid);
  EXPECT_DOUBLE_EQ(report.queries[0].length_cells, 2.0);
}

TEST(ScenarioCheck, LengthsAreInCellsAtAnyResolution) {
  WorldMap map = walled_map();
  map.resolution_m = 0.05;
  const auto planner = make_planner("dijkstra", nlohmann::json::object());
  const ScenarioReport report = check_scenario(map, {query({0, 0}, {2, 2}, 2 * kSqrt2)}, *planner);
  EXPECT_EQ(report.mismatches, 0);
  EXPECT_NEAR(report.queries[0].length_cells, 2 * kSqrt2, 1e-12);
}

TEST(ScenarioCheck, ScenarioForAnotherMapIsAConfigError) {
  const WorldMap map = walled_map();
  ScenarioQuery q = query({0, 0}, {1, 0}, 1.0);
  q.map_width = 49;
  const auto planner = make_planner("astar", nlohmann::json::object());
  EXPECT_THROW((void)check_scenario(map, {q}, *planner), ConfigError);
}

}  // namespace
}  // namespace fsweep
