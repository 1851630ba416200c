/// OMPL's benchmark log of a plan benchmark (src/evaluation/ompl_benchmark_log.hpp), read back
/// line by line as OMPL's EBNF and ompl_benchmark_statistics read it: the exact preamble, the
/// properties, one row per query with its cells, progress lines, and the refused inputs.

#include <gtest/gtest.h>

#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "evaluation/ompl_benchmark_log.hpp"

namespace fsweep {
namespace test_ompl_benchmark_log {  // not anonymous: unity builds put it beside other test files' helpers

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

/// The cells of a run row ("a; b; ; c; "): split at "; ", the text after the last one dropped,
/// as the script reads them.
std::vector<std::string> cells_of(const std::string& row) {
  std::vector<std::string> cells;
  std::size_t begin = 0;
  for (std::size_t end = row.find("; "); end != std::string::npos; end = row.find("; ", begin)) {
    cells.push_back(row.substr(begin, end - begin));
    begin = end + 2;
  }
  EXPECT_EQ(begin, row.size()) << "a row ends with \"; \": " << row;
  return cells;
}

BenchmarkLogExperiment experiment() {
  BenchmarkLogExperiment e;
  e.name = "den312d.map+den 312d.map.scen";  // a space: one word in the log
  e.ompl_version = "1.5.2";
  e.host = "node-7";
  e.date = "2025-01-02T03:04:05Z";
  e.setup = "fsweep plan-bench\n|>>> not the end";
  e.cpuinfo = "model name: X\nlogical CPUs: 2\n";
  e.seed = 42;
  e.time_limit_s = std::numeric_limits<double>::infinity();
  e.total_time_s = 1.5;
  e.properties = {{"map_width", "INTEGER", "65"}, {"allow_corner_cutting", "BOOLEAN", "0"}};
  return e;
}

/// Two queries; astar solves the first and fails the second (GoalInvalid); RRTstar solves both
/// and sampled progress for the first (two samples) and none for the second.
struct Bench {
  std::vector<BenchQuery> queries{{Cell{1, 2}, Cell{3, 4}, 2.5}, {Cell{0, 0}, Cell{5, 0}, 5.0}};
  std::vector<BenchmarkLogPlanner> planners{
      {"astar", {{"max_expansions", 0}, {"time_limit_s", nullptr}}},
      {"ompl:RRTstar", {{"range", "0"}, {"simplify", true}, {"nested", {{"k", 1.5}}}}}};
  std::vector<std::vector<BenchPlan>> plans{
      {BenchPlan{PlanStatus::Success, 1.0, 2.5, 1, 0.25, 2.5, {}},
       BenchPlan{PlanStatus::GoalInvalid, 0.0, 0.0, 0, 1e-06, 0.0, {}}},
      {BenchPlan{PlanStatus::Success, 1.2, 3.0, 3, 0.5, 3.0,
                 PlanProgress{{"best cost REAL", "iterations INTEGER"},
                              {{0.001, {"inf", "0"}}, {0.25, {"3.000000", "120"}}}}},
       BenchPlan{PlanStatus::Success, 1.0, 5.0, 0, 0.5, 5.0, {}}}};
};

TEST(OmplBenchmarkLog, PreambleLinesAsOmplWritesThem) {
  const Bench b;
  const std::vector<std::string> lines =
      lines_of(ompl_benchmark_log(experiment(), b.queries, b.planners, b.plans));
  const std::vector<std::string> preamble{"OMPL version 1.5.2",
                                          "Experiment den312d.map+den_312d.map.scen",
                                          "2 experiment properties",
                                          "map_width INTEGER = 65",
                                          "allow_corner_cutting BOOLEAN = 0",
                                          "Running on node-7",
                                          "Starting at 2025-01-02T03:04:05Z",
                                          "<<<|",
                                          "fsweep plan-bench",
                                          " |>>> not the end",  // kept inside the block
                                          "|>>>",
                                          "<<<|",
                                          "model name: X",
                                          "logical CPUs: 2",
                                          "|>>>",
                                          "42 is the random seed",
                                          "inf seconds per run",
                                          "0 MB per run",
                                          "2 runs per planner",
                                          "1.5 seconds spent to collect the data",
                                          "1 enum type",
                                          "plan_status|Success|StartInvalid|GoalInvalid|NoPath|Timeout",
                                          "2 planners"};
  ASSERT_GE(lines.size(), preamble.size());
  for (std::size_t i = 0; i < preamble.size(); ++i) EXPECT_EQ(lines[i], preamble[i]) << "line " << i + 1;
}

TEST(OmplBenchmarkLog, PlannerBlocksHoldSettingsPropertiesRowsAndProgress) {
  const Bench b;
  const std::vector<std::string> lines =
      lines_of(ompl_benchmark_log(experiment(), b.queries, b.planners, b.plans));
  std::size_t i = 23;  // after the preamble (previous test)
  // astar: settings, the run properties, two rows, no progress.
  ASSERT_EQ(lines.at(i++), "astar");
  EXPECT_EQ(lines.at(i++), "2 common properties");
  EXPECT_EQ(lines.at(i++), "max_expansions = 0");
  EXPECT_EQ(lines.at(i++), "time_limit_s = null");
  EXPECT_EQ(lines.at(i++), "13 properties for each run");
  for (const std::string_view property : kBenchRunProperties) EXPECT_EQ(lines.at(i++), property);
  EXPECT_EQ(lines.at(i++), "2 runs");
  // time, solved, plan_status, length, ratio, energy, turns, query, start, goal, optimal.
  EXPECT_EQ(cells_of(lines.at(i++)), (std::vector<std::string>{"0.25", "1", "0", "2.5", "1", "2.5", "1", "0",
                                                               "1", "2", "3", "4", "2.5"}));
  // Unsolved (GoalInvalid = 2): no length, ratio, energy or turns.
  EXPECT_EQ(cells_of(lines.at(i++)),
            (std::vector<std::string>{"1e-06", "0", "2", "", "", "", "", "1", "0", "0", "5", "0", "5"}));
  EXPECT_EQ(lines.at(i++), ".");
  // RRTstar: nested settings joined by '.', strings bare; progress of the first run only.
  ASSERT_EQ(lines.at(i++), "ompl:RRTstar");
  EXPECT_EQ(lines.at(i++), "3 common properties");
  EXPECT_EQ(lines.at(i++), "nested.k = 1.5");
  EXPECT_EQ(lines.at(i++), "range = 0");
  EXPECT_EQ(lines.at(i++), "simplify = true");
  EXPECT_EQ(lines.at(i++), "13 properties for each run");
  i += kBenchRunProperties.size();
  EXPECT_EQ(lines.at(i++), "2 runs");
  EXPECT_EQ(cells_of(lines.at(i++)).at(3), "3");
  EXPECT_EQ(cells_of(lines.at(i++)).at(6), "0");
  EXPECT_EQ(lines.at(i++), "3 progress properties for each run");
  EXPECT_EQ(lines.at(i++), "time REAL");
  EXPECT_EQ(lines.at(i++), "best cost REAL");
  EXPECT_EQ(lines.at(i++), "iterations INTEGER");
  EXPECT_EQ(lines.at(i++), "2 runs");
  EXPECT_EQ(lines.at(i++), "0.001,inf,0,;0.25,3.000000,120,;");
  EXPECT_EQ(lines.at(i++), "");  // the second run sampled nothing
  EXPECT_EQ(lines.at(i++), ".");
  EXPECT_EQ(i, lines.size());
}

TEST(OmplBenchmarkLog, ExperimentNameFromMapAndQueries) {
  EXPECT_EQ(plan_bench_experiment_name("tests/data/den312d.map", "tests/data/den312d.map.scen", 100, 1),
            "den312d.map+den312d.map.scen");
  EXPECT_EQ(plan_bench_experiment_name("random:w=20,h=20,p=0.2,seed=2", "", 5, 3),
            "random:w=20,h=20,p=0.2,seed=2+pairs=5,seed=3");
}

TEST(OmplBenchmarkLog, InconsistentInputsAreRefused) {
  Bench b;
  b.plans[1].pop_back();  // a planner with fewer plans than queries
  EXPECT_THROW((void)ompl_benchmark_log(experiment(), b.queries, b.planners, b.plans), std::invalid_argument);
  Bench separator;
  separator.plans[1][0].progress.samples[1].values[0] = "1,5";
  EXPECT_THROW((void)ompl_benchmark_log(experiment(), separator.queries, separator.planners, separator.plans),
               std::invalid_argument);
  Bench other_properties;
  other_properties.plans[1][1].progress.properties = {"best cost REAL"};
  EXPECT_THROW((void)ompl_benchmark_log(experiment(), other_properties.queries, other_properties.planners,
                                        other_properties.plans),
               std::invalid_argument);
  Bench newline;
  newline.planners[0].name = "a\nb";
  EXPECT_THROW((void)ompl_benchmark_log(experiment(), newline.queries, newline.planners, newline.plans),
               std::invalid_argument);
}

}  // namespace test_ompl_benchmark_log
}  // namespace fsweep
