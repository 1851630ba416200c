// `fsweep plan-bench --out`'s ompl_benchmark.log through OMPL's own ompl_benchmark_statistics
// into Planner Arena's SQLite database: the experiment, the planners, every run's values equal to
// queries.csv's, and the anytime planner's progress.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "cli/fsweep_process.hpp"
#include "core/csv_reader.hpp"
#include "planners/ompl_planner.hpp"
#include "report/sqlite_test_db.hpp"

namespace test_cli_plan_bench_arena {  // not anonymous: unity builds put it beside other test files' helpers

using fsweep::testing::number;
using fsweep::testing::SqliteTestDb;
using fsweep::testing::SqlRow;

/// queries.csv as one map from column name to cell per row.
std::vector<std::map<std::string, std::string>> read_queries(const std::string& path) {
  fsweep::CsvReader in(path);
  std::vector<std::map<std::string, std::string>> rows;
  while (in.next()) {
    auto& row = rows.emplace_back();
    for (std::size_t c = 0; c < in.header().size(); ++c) row[in.header()[c]] = in.fields()[c];
  }
  return rows;
}

double csv_number(const std::map<std::string, std::string>& row, const std::string& column) {
  return *fsweep::parse_number(row.at(column));
}

/// `db` is `csv` or one of its neighbouring doubles: the script hands SQLite the log's text, and
/// SQLite 3.40 (Debian 12) reads a few decimal texts one unit in the last place off (e.g.
/// 5.6107e-05); the text itself is the CSV's.
::testing::AssertionResult same_number(double db, double csv) {
  if (db == csv || db == std::nextafter(csv, INFINITY) || db == std::nextafter(csv, -INFINITY)) {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure() << db << " is not " << csv << " (nor a neighbouring double)";
}

/// Progress samples in the log's block of `planner`: the ';' of its progress lines.
long progress_samples_in_log(const std::string& log_path, const std::string& planner) {
  std::ifstream in(log_path);
  std::string line;
  while (std::getline(in, line) && line != planner) {
  }
  while (std::getline(in, line) && line.find("progress properties for each run") == std::string::npos) {
  }
  const int properties = std::stoi(line);
  for (int i = 0; i <= properties; ++i) std::getline(in, line);  // the properties, "N runs"
  const int runs = std::stoi(line);
  long samples = 0;
  for (int r = 0; r < runs && std::getline(in, line); ++r)
    samples += std::count(line.begin(), line.end(), ';');
  return samples;
}

TEST(CliPlanBenchArena, LogBecomesThePlannerArenaDatabaseWithTheCsvValues) {
  // OMPL's script, from Debian's ompl-demos (scripts/bootstrap installs it).
  const auto which = fsweep::testing::run_command("command -v ompl_benchmark_statistics");
  ASSERT_EQ(which.code, 0)
      << "ompl_benchmark_statistics is not on PATH: install Debian's ompl-demos (scripts/bootstrap)";
  const std::string script = which.output.substr(0, which.output.find('\n'));
  const std::string out = fsweep::testing::fresh_temp_dir("arena", "log");
  const std::string data = FSWEEP_TEST_DATA;
  const auto bench = fsweep::testing::run_fsweep(
      "plan-bench --map " + data + "/arena.map --scen " + data +
      "/arena.map.scen --planners astar,ompl:RRTConnect,ompl:RRTstar --planner-param "
      "ompl:RRTstar.max_iterations=300 --progress-interval 0.001 --out " +
      out);
  ASSERT_EQ(bench.code, 0) << bench.output;
  const std::string db_path = out + "/benchmark.db";
  const auto stats = fsweep::testing::run_command(script + " " + out + "/ompl_benchmark.log -d " + db_path);
  ASSERT_EQ(stats.code, 0) << stats.output;

  const auto queries = read_queries(out + "/queries.csv");
  ASSERT_EQ(queries.size(), 160U);  // arena.map.scen's queries, all reachable
  const SqliteTestDb db(db_path);

  // 1. One experiment, named after map and scenario, with the preamble's facts.
  const auto experiments = db.rows(
      "SELECT name, runcount, version, seed, timelimit, memorylimit, map_width, map_height FROM experiments");
  ASSERT_EQ(experiments.size(), 1U);
  EXPECT_EQ(std::get<std::string>(experiments[0][0]), "arena.map+arena.map.scen");
  EXPECT_EQ(number(experiments[0][1]), 160.0);
  EXPECT_EQ(std::get<std::string>(experiments[0][2]), "OMPL " + fsweep::ompl_version());
  EXPECT_EQ(std::get<std::string>(experiments[0][3]), "1");
  EXPECT_EQ(number(experiments[0][4]), INFINITY);  // astar has no time limit
  EXPECT_EQ(number(experiments[0][5]), 0.0);
  EXPECT_EQ(number(experiments[0][6]), 49.0);
  EXPECT_EQ(number(experiments[0][7]), 49.0);

  // 2. The planners, in order, with their settings; the status enum.
  const auto configs = db.rows("SELECT id, name, settings FROM plannerConfigs ORDER BY id");
  ASSERT_EQ(configs.size(), 3U);
  const std::vector<std::string> names{"astar", "ompl:RRTConnect", "ompl:RRTstar"};
  for (std::size_t i = 0; i < names.size(); ++i) EXPECT_EQ(std::get<std::string>(configs[i][1]), names[i]);
  EXPECT_NE(std::get<std::string>(configs[2][2]).find("max_iterations = 300"), std::string::npos);
  const auto statuses = db.rows("SELECT description FROM enums WHERE name = 'plan_status' ORDER BY value");
  ASSERT_EQ(statuses.size(), 5U);
  EXPECT_EQ(std::get<std::string>(statuses[0][0]), "Success");
  EXPECT_EQ(std::get<std::string>(statuses[4][0]), "Timeout");

  // 3. Every run equals its queries.csv cells (the log writes the CSV's text).
  for (const auto& config : configs) {
    const std::string planner = std::get<std::string>(config[1]);
    const auto runs = db.rows(
        "SELECT query, time, solved, e.description, solution_length, length_ratio, energy, turns, start_x, "
        "start_y, "
        "goal_x, goal_y, optimal_length FROM runs JOIN enums e ON e.name = 'plan_status' AND e.value = "
        "runs.plan_status WHERE plannerid = " +
        std::to_string(std::get<std::int64_t>(config[0])) + " ORDER BY runs.id");
    ASSERT_EQ(runs.size(), queries.size()) << planner;
    for (std::size_t q = 0; q < runs.size(); ++q) {
      const SqlRow& r = runs[q];
      const auto& csv = queries[q];
      EXPECT_EQ(number(r[0]), static_cast<double>(q));
      EXPECT_TRUE(same_number(number(r[1]), csv_number(csv, planner + ".time_s")))
          << planner << " query " << q;
      const std::string status = csv.at(planner + ".status");
      EXPECT_EQ(std::get<std::string>(r[3]), status) << planner << " query " << q;
      EXPECT_EQ(number(r[2]), status == "Success" ? 1.0 : 0.0);
      if (status == "Success") {
        const double ratio = csv_number(csv, planner + ".length_ratio");
        EXPECT_TRUE(same_number(number(r[5]), ratio)) << planner << " query " << q;
        EXPECT_NEAR(number(r[4]), ratio * csv_number(csv, "optimal_cells"), 1e-9 * number(r[4]));
        EXPECT_TRUE(same_number(number(r[6]), csv_number(csv, planner + ".energy")));
        EXPECT_EQ(number(r[7]), csv_number(csv, planner + ".turns"));
      } else {
        for (const int c : {4, 5, 6, 7}) EXPECT_TRUE(std::holds_alternative<std::nullptr_t>(r[c]));
      }
      EXPECT_EQ(number(r[8]), csv_number(csv, "start_x"));
      EXPECT_EQ(number(r[9]), csv_number(csv, "start_y"));
      EXPECT_EQ(number(r[10]), csv_number(csv, "goal_x"));
      EXPECT_EQ(number(r[11]), csv_number(csv, "goal_y"));
      EXPECT_TRUE(same_number(number(r[12]), csv_number(csv, "optimal_cells")));
    }
  }

  // 4. Progress: only RRTstar reports it, every run at least at its first check and its end,
  //    with a live best cost (none before a path: NULL); as many rows as the log has samples.
  const auto progress = db.rows(
      "SELECT p.name, runs.query, progress.time, progress.best_cost, runs.solved FROM progress JOIN runs ON "
      "runs.id "
      "= progress.runid JOIN plannerConfigs p ON p.id = runs.plannerid ORDER BY runs.id, progress.time");
  EXPECT_EQ(static_cast<long>(progress.size()),
            progress_samples_in_log(out + "/ompl_benchmark.log", "ompl:RRTstar"));
  std::map<double, int> samples_per_query;
  for (std::size_t i = 0; i < progress.size(); ++i) {
    const SqlRow& p = progress[i];
    EXPECT_EQ(std::get<std::string>(p[0]), "ompl:RRTstar");
    ++samples_per_query[number(p[1])];
    const bool first = i == 0 || number(progress[i - 1][1]) != number(p[1]);
    const bool last = i + 1 == progress.size() || number(progress[i + 1][1]) != number(p[1]);
    if (first) {
      EXPECT_TRUE(std::holds_alternative<std::nullptr_t>(p[3])) << "query " << number(p[1]);
    }
    if (last) {
      // A solved run ends with its path's cost; an unsolved one has none.
      EXPECT_EQ(std::holds_alternative<double>(p[3]), number(p[4]) == 1.0) << "query " << number(p[1]);
    }
  }
  EXPECT_EQ(samples_per_query.size(), queries.size());
  for (const auto& [query, n] : samples_per_query) EXPECT_GE(n, 2) << "query " << query;
  std::filesystem::remove_all(out);
}

}  // namespace test_cli_plan_bench_arena
