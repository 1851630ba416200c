#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>
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

TEST(PlannerRegistry, MakesNamedPlanners) {
  EXPECT_EQ(make_planner("astar", nlohmann::json::object())->name(), "astar");
  EXPECT_EQ(make_planner("dijkstra", nlohmann::json())->name(), "dijkstra");
}

}  // namespace
}  // namespace fsweep
