/// identical_repetition_warnings() (sweep_table.hpp): configurations whose repetitions cannot differ are
/// named before anything runs, and only those.
#include <gtest/gtest.h>

#include "sweep/sweep_table.hpp"

namespace fsweep {
namespace test_repetition_check {

using nlohmann::json;

/// A sweep of two rooms maps with `strategies`, `planners` and `robot`, 3 repetitions.
SweepPlan plan_with(const std::string& strategies, const std::string& planners, const std::string& robot,
                    int repetitions = 3, const std::string& map_extra = "") {
  const json sweep = json::parse(R"({"schema_version": 1, "name": "reps",
    "maps": [{"generator": "rooms", "w": 30, "h": 24, "label": "rooms", "seeds": [1, 2])" +
                                 map_extra +
                                 R"(}],
    "strategies": )" + strategies +
                                 R"(, "planners": )" + planners + R"(, "robot": )" + robot +
                                 R"(, "repetitions": )" + std::to_string(repetitions) + "}");
  return SweepPlan::from_json(sweep, "reps.json");
}

TEST(RepetitionCheck, NamesTheConfigurationsWithNothingRandom) {
  const SweepPlan plan = plan_with(R"([{"name": "closest_frontier", "label": "CF"},
                                        {"name": "random_frontier", "label": "R"}])",
                                   R"(["astar", "ompl:RRTConnect"])", R"({"sensor": {"range_m": 5}})");
  const auto w = identical_repetition_warnings(plan);
  ASSERT_EQ(w.size(), 1U);
  // CF with astar is fixed; random_frontier draws from its seed, RRTConnect samples from it.
  EXPECT_NE(w[0].find("1 of 4 configurations have nothing random in them"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("3 repetitions on a map instance will be 3 copies of one run"), std::string::npos)
      << w[0];
  EXPECT_NE(w[0].find("map classes rooms; strategies CF; planners astar."), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("\"seeds\""), std::string::npos) << w[0];
  // sweep_warnings() carries it, so expand, run, slurm and the manifest do.
  const auto all = sweep_warnings(plan);
  EXPECT_NE(std::find(all.begin(), all.end(), w[0]), all.end());
}

TEST(RepetitionCheck, SilentWhenEveryConfigurationDrawsFromItsSeed) {
  const std::string cf = R"([{"name": "closest_frontier"}])";
  // Sensor misses, a random start, one repetition.
  EXPECT_TRUE(identical_repetition_warnings(
                  plan_with(cf, R"(["astar"])", R"({"sensor": {"range_m": 5, "miss_probability": 0.05}})"))
                  .empty());
  EXPECT_TRUE(identical_repetition_warnings(
                  plan_with(cf, R"(["astar"])", R"({"sensor": {"range_m": 5}})", 3, R"(, "start": "random")"))
                  .empty());
  EXPECT_TRUE(identical_repetition_warnings(plan_with(cf, R"(["astar"])", R"({"sensor": {"range_m": 5}})", 1))
                  .empty());
}

TEST(RepetitionCheck, CountsTheFixedParametersOfAnEntry) {
  // A robot axis: the variant that misses cells is random, the other not.
  const SweepPlan plan =
      plan_with(R"([{"name": "closest_frontier", "label": "CF"}])", R"(["astar", "dijkstra"])",
                R"({"sensor": {"range_m": 5, "miss_probability": [0, 0.1]}})", 2);
  const auto w = identical_repetition_warnings(plan);
  ASSERT_EQ(w.size(), 1U);
  EXPECT_NE(w[0].find("2 of 4 configurations"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("planners astar, dijkstra; robots sensor.miss_probability=0."), std::string::npos)
      << w[0];
}

}  // namespace test_repetition_check
}  // namespace fsweep
