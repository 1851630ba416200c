/// config_names.hpp: which columns tell configurations apart, and their short names.
#include <gtest/gtest.h>

#include "report/config_names.hpp"

namespace fsweep {
namespace test_config_names {

TEST(ConfigNames, APresetStandsForTheNumbersItDetermines) {
  const std::vector<std::string> names{"robot.energy.per_metre", "robot.energy.preset",
                                       "robot.sensor.range_m",   "planner",
                                       "planner.max_iterations", "sim.stuck_decisions"};
  const std::vector<std::vector<std::string>> rows{
      {"1", "distance", "4", "astar", "0", "100"},
      {"0", "mei2006", "4", "ompl:RRT", "500", "100"},
      {"1", "distance", "8", "astar", "0", "100"},
  };
  // per_metre follows the preset, max_iterations the planner; stuck_decisions never differs.
  EXPECT_EQ(telling_columns(names, rows), (std::vector<std::size_t>{1, 2, 3}));
}

TEST(ConfigNames, ColumnsThatOnlyMoveTogetherOutsideANamingColumnBothStay) {
  // w1 and w3 vary together (a zip): neither is a naming column, so both tell; the map class
  // determines the maps' resolution, which then says nothing more.
  const std::vector<std::string> names{"strategy.w1", "strategy.w3", "map_class", "map.resolution_m"};
  const std::vector<std::vector<std::string>> rows{
      {"10", "9", "a", "1"}, {"220", "104", "a", "1"}, {"10", "9", "b", "0.4"}, {"220", "104", "b", "0.4"}};
  EXPECT_EQ(telling_columns(names, rows), (std::vector<std::size_t>{0, 1, 2}));
}

TEST(ConfigNames, AStrategyIsItsLabelAndWhatDiffersWithinIt) {
  const std::vector<std::string> columns{"strategy_label", "strategy", "strategy.w1", "strategy.w3",
                                         "strategy.distance"};
  const std::vector<std::vector<std::string>> rows{{"CF", "closest_frontier", "", "", "path"},
                                                   {"EA", "energy_aware", "10", "9", "path"},
                                                   {"EA", "energy_aware", "220", "104", "path"},
                                                   {"EA free", "energy_aware", "10", "9", "path"}};
  EXPECT_EQ(strategy_names(columns, rows),
            (std::vector<std::string>{"CF", "EA w1=10 w3=9", "EA w1=220 w3=104", "EA free"}));
}

TEST(ConfigNames, ColumnTitlesLoseTheirPrefixes) {
  EXPECT_EQ(column_title("robot.energy.preset"), "energy");
  EXPECT_EQ(column_title("robot.sensor.range_m"), "sensor.range_m");
  EXPECT_EQ(column_title("planner"), "planner");
  EXPECT_EQ(column_title("planner.max_iterations"), "max_iterations");
  EXPECT_EQ(column_title("sim.stuck_decisions"), "stuck_decisions");
  EXPECT_EQ(column_title("map.resolution_m"), "map.resolution_m");
}

}  // namespace test_config_names
}  // namespace fsweep
