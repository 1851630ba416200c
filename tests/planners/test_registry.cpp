#include <gtest/gtest.h>

#include <algorithm>
#include <iterator>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "core/config_error.hpp"
#include "planners/registry.hpp"

namespace fsweep {
namespace {

TEST(PlannerRegistry, NamesAreSortedAndIncludeGridPlanners) {
  const std::vector<std::string> names = planner_names();
  EXPECT_TRUE(std::is_sorted(names.begin(), names.end()));
  EXPECT_TRUE(std::adjacent_find(names.begin(), names.end()) == names.end());
  EXPECT_NE(std::find(names.begin(), names.end(), "astar"), names.end());
  EXPECT_NE(std::find(names.begin(), names.end(), "dijkstra"), names.end());
}

TEST(PlannerRegistry, UnknownNameListsKnownNames) {
  try {
    (void)make_planner("a-star", nlohmann::json::object(), "/planners/0");
    FAIL() << "no ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.where(), "/planners/0");
    const std::string what = e.what();
    EXPECT_NE(what.find("a-star"), std::string::npos) << what;
    for (const std::string& name : planner_names()) EXPECT_NE(what.find(name), std::string::npos) << what;
  }
}

TEST(PlannerRegistry, UnknownParamIsAConfigError) {
  try {
    (void)make_planner("astar", nlohmann::json{{"tie_brake", "low_g"}}, "/planners/0");
    FAIL() << "no ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_NE(e.where().find("/planners/0/params"), std::string::npos) << e.where();
  }
  EXPECT_THROW((void)make_planner("dijkstra", nlohmann::json::array()), ConfigError);
}

TEST(PlannerRegistry, CapabilitiesPerPlanner) {
  // The declared capabilities (README planner table): determinism, length-optimal, anytime.
  struct Expected {
    const char* name;
    Determinism determinism;
    bool optimal;
    bool anytime;
  };
  const Expected table[] = {
      {"astar", Determinism::Always, true, false},
      {"dijkstra", Determinism::Always, true, false},
      {"jps", Determinism::Always, true, false},
      {"jps+", Determinism::Always, true, false},
      {"lattice", Determinism::Always, false, false},  // energy-optimal, not length-optimal
      {"lattice_astar", Determinism::Always, false, false},
      {"shortest_fewest_turns", Determinism::Always, true, false},
      {"ompl:RRTConnect", Determinism::WithMaxIterations, false, false},
      {"ompl:KPIECE1", Determinism::WithMaxIterations, false, false},
      {"ompl:RRTstar", Determinism::WithMaxIterations, false, true},
      {"ompl:InformedRRTstar", Determinism::WithMaxIterations, false, true},
      {"ompl:BITstar", Determinism::WithMaxIterations, false, true},
      {"ompl:LazyPRMstar", Determinism::WithMaxIterations, false, true},
      {"ompl:PRMstar", Determinism::Never, false, true},
  };
  EXPECT_EQ(std::size(table), planner_names().size()) << "a planner is missing from this table";
  for (const Expected& e : table) {
    const std::optional<PlannerCapabilities> c = planner_capabilities(e.name);
    ASSERT_TRUE(c.has_value()) << e.name;
    EXPECT_EQ(c->determinism, e.determinism) << e.name;
    EXPECT_EQ(c->optimal, e.optimal) << e.name;
    EXPECT_EQ(c->anytime, e.anytime) << e.name;
  }
  EXPECT_FALSE(planner_capabilities("ompl:FMT").has_value());
  EXPECT_FALSE(planner_capabilities("a-star").has_value());
}

TEST(PlannerRegistry, MakesNamedPlanners) {
  EXPECT_EQ(make_planner("astar", nlohmann::json::object())->name(), "astar");
  EXPECT_EQ(make_planner("dijkstra", nlohmann::json())->name(), "dijkstra");
}

}  // namespace
}  // namespace fsweep
