// `fsweep plan-bench` end to end: the table and both files for a scenario and for random pairs,
// and bad planner parameters reported with one message and exit code 2.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "cli/fsweep_process.hpp"

namespace test_cli_plan_bench {  // not anonymous: unity builds put it beside other test files' helpers

using Outcome = fsweep::testing::CliOutcome;
Outcome fsweep(const std::string& args) { return fsweep::testing::run_fsweep(args); }

std::string temp_dir(const std::string& name) { return fsweep::testing::fresh_temp_dir("pb", name); }
using fsweep::testing::count_lines;

TEST(CliPlanBench, ScenarioQueriesAgainstOptimalLengths) {
  const std::string out = temp_dir("scen");
  const std::string data = FSWEEP_TEST_DATA;
  const Outcome r = fsweep("plan-bench --map " + data + "/arena.map --scen " + data +
                           "/arena.map.scen --planners astar,ompl:RRTConnect --out " + out);
  ASSERT_EQ(r.code, 0) << r.output;
  // astar is optimal on every MovingAI query: ratio 1 (mean, median, q95), 100% success.
  EXPECT_NE(r.output.find("astar                       100.0        0   1.0000   1.0000   1.0000"),
            std::string::npos)
      << r.output;
  EXPECT_EQ(count_lines(out + "/summary.csv"), 3);  // header + 2 planners
  EXPECT_GT(count_lines(out + "/queries.csv"), 100);
  std::ifstream queries(out + "/queries.csv");
  std::string header;
  std::getline(queries, header);
  for (const char* col :
       {"optimal_cells", "astar.length_ratio", "ompl:RRTConnect.status", "ompl:RRTConnect.time_s"}) {
    EXPECT_NE(header.find(col), std::string::npos) << col;
  }
}

TEST(CliPlanBench, RandomPairsWithPlannerParameters) {
  const Outcome r = fsweep(
      "plan-bench --map random:w=20,h=20,p=0.2,seed=2 --pairs 5 --planners dijkstra,ompl:RRTstar "
      "--planner-param ompl:RRTstar.time_limit_s=0.01");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("5 queries (random reachable pairs"), std::string::npos) << r.output;
}

TEST(CliPlanBench, BadParametersAreOneMessage) {
  const Outcome unknown = fsweep(
      "plan-bench --map random:w=20,h=20,p=0.2,seed=2 --pairs 2 --planners ompl:RRTstar "
      "--planner-param ompl:RRTstar.rnage=3");
  EXPECT_EQ(unknown.code, 2);
  EXPECT_NE(unknown.output.find("unknown key 'rnage'; allowed:"), std::string::npos) << unknown.output;
  const Outcome other = fsweep(
      "plan-bench --map random:w=20,h=20,p=0.2,seed=2 --pairs 2 --planners astar --planner-param "
      "ompl:RRTstar.range=3");
  EXPECT_EQ(other.code, 2);
  EXPECT_NE(other.output.find("not a benchmarked planner"), std::string::npos) << other.output;
}

}  // namespace test_cli_plan_bench
