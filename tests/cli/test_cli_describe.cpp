// `fsweep describe` (src/cli/describe_command.cpp): printed from the registries' declarations.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli/fsweep_process.hpp"

namespace fsweep {
namespace {

using testing::run_fsweep;

TEST(CliDescribe, ListsTheKindsAndTheNamesOfAKind) {
  const auto kinds = run_fsweep("describe");
  EXPECT_EQ(kinds.code, 0) << kinds.output;
  for (const char* k : {"planner", "strategy", "generator", "energy"}) {
    EXPECT_NE(kinds.output.find(k), std::string::npos) << k;
  }
  const auto strategies = run_fsweep("describe strategy");
  EXPECT_EQ(strategies.code, 0);
  for (const char* s : {"closest_frontier", "energy_aware", "gbl", "mcdm", "target_seeking"}) {
    EXPECT_NE(strategies.output.find(s), std::string::npos) << s;
  }
}

TEST(CliDescribe, EnergyAwareWeightsHaveDefaultRangeAndDoc) {
  const auto out = run_fsweep("describe strategy energy_aware --format json");
  ASSERT_EQ(out.code, 0) << out.output;
  const auto j = nlohmann::json::parse(out.output);
  ASSERT_EQ(j["params"].size(), 6U);
  EXPECT_EQ(j["params"][5]["name"], "unit");
  EXPECT_EQ(j["params"][5]["default"], "m");
  const auto& w1 = j["params"][0];
  EXPECT_EQ(w1["name"], "w1");
  EXPECT_EQ(w1["default"], 10.0);
  EXPECT_EQ(w1["allowed"], "a number in [0, 250]");
  EXPECT_NE(w1["doc"].get<std::string>().find("d_g"), std::string::npos);
  EXPECT_EQ(j["params"][3]["default"], 20.0);  // w4
}

TEST(CliDescribe, OmplPlannerListsItsOmplParameters) {
  const auto out = run_fsweep("describe planner ompl:RRTstar");
  ASSERT_EQ(out.code, 0) << out.output;
  for (const char* p :
       {"time_limit_s", "max_iterations", "simplify", "range", "goal_bias", "rewire_factor"}) {
    EXPECT_NE(out.output.find(p), std::string::npos) << p;
  }
}

TEST(CliDescribe, UnknownKindOrNameIsExitTwoListingTheKnown) {
  const auto kind = run_fsweep("describe planers");
  EXPECT_EQ(kind.code, 2);
  EXPECT_NE(
      kind.output.find("unknown kind 'planers'; known: planner, strategy, generator, energy, robot, sim"),
      std::string::npos)
      << kind.output;
  const auto name = run_fsweep("describe generator roms");
  EXPECT_EQ(name.code, 2);
  EXPECT_NE(name.output.find("unknown generator 'roms'; known:"), std::string::npos) << name.output;
}

TEST(CliDescribe, RobotAndSimSettingsListTheirParametersWithNestedSensorFlattened) {
  const auto robot = run_fsweep("describe robot --format json");
  ASSERT_EQ(robot.code, 0) << robot.output;
  const auto j = nlohmann::json::parse(robot.output);
  std::vector<std::string> names;
  for (const auto& p : j["params"]) names.push_back(p["name"].get<std::string>());
  EXPECT_EQ(names, (std::vector<std::string>{"sensor.range_m", "sensor.fov_deg", "sensor.miss_probability",
                                             "sensor.model", "sensor.beams", "energy", "battery", "dock",
                                             "start_heading", "allow_corner_cutting"}));
  EXPECT_EQ(j["params"][0]["allowed"], "a number > 0");
  EXPECT_EQ(j["params"][0]["unit"], "m");
  EXPECT_EQ(j["params"][3]["allowed"], "one of \"grid\", \"beams\"");
  EXPECT_EQ(j["params"][3]["default"], "grid");
  EXPECT_EQ(j["params"][4]["allowed"], "an integer in [1, 100000]");
  EXPECT_EQ(j["params"][8]["allowed"], "an integer in [0, 7]");
  const auto sim = run_fsweep("describe sim");
  ASSERT_EQ(sim.code, 0) << sim.output;
  for (const char* p :
       {"cluster_max_length_m", "max_steps", "stuck_decisions", "progress_step_m", "stop_at_cell"}) {
    EXPECT_NE(sim.output.find(p), std::string::npos) << p;
  }
  const auto named = run_fsweep("describe robot sensor");
  EXPECT_EQ(named.code, 2);
  EXPECT_NE(named.output.find("robot has no names"), std::string::npos) << named.output;
}

}  // namespace
}  // namespace fsweep
