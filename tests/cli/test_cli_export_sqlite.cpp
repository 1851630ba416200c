// `fsweep run --sqlite` and `fsweep export-sqlite` end to end: the database beside the CSVs, with
// their row counts; --fresh removes it; bad directories and damaged files are one message and exit
// code 2. (The database's contents: tests/report/test_sqlite_export.cpp.)
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "cli/fsweep_process.hpp"
#include "report/sqlite_test_db.hpp"

namespace test_cli_export_sqlite {  // not anonymous: unity builds put it beside other test files' helpers

using fsweep::testing::count_lines;
using fsweep::testing::number;
using fsweep::testing::run_fsweep;
using fsweep::testing::SqliteTestDb;

/// A fresh directory holding a 2-configuration x 2-repetition sweep file.
std::string sweep_dir(const std::string& name) {
  const std::string dir = fsweep::testing::fresh_temp_dir("sqlite", name);
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/sweep.json") << R"({"schema_version": 1, "name": "cli_sqlite",
    "maps": ["rooms:w=24,h=20,door=2,seed=2"],
    "strategies": [{"name": "closest_frontier"}, {"name": "energy_aware"}], "repetitions": 2, "seed": 5})";
  return dir;
}

TEST(CliExportSqlite, RunWritesTheDatabaseAfterTheRunAndFreshRemovesIt) {
  const std::string dir = sweep_dir("run");
  const std::string out = dir + "/results";
  const auto r = run_fsweep("run " + dir + "/sweep.json --quiet --threads 2 --sqlite --out " + out);
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("wrote " + out + "/results.sqlite (4 runs, 2 configurations, "), std::string::npos)
      << r.output;
  {
    const SqliteTestDb db(out + "/results.sqlite");
    EXPECT_EQ(number(db.value("SELECT COUNT(*) FROM runs")), count_lines(out + "/runs.csv") - 1);
    EXPECT_EQ(number(db.value("SELECT COUNT(*) FROM progress")), count_lines(out + "/progress.csv") - 1);
  }
  const auto fresh = run_fsweep("run " + dir + "/sweep.json --quiet --threads 2 --fresh --out " + out);
  ASSERT_EQ(fresh.code, 0) << fresh.output;
  EXPECT_FALSE(std::filesystem::exists(out + "/results.sqlite"));  // an output of the old run
  std::filesystem::remove_all(dir);
}

TEST(CliExportSqlite, ExportsADirectoryToAnyFileAndRefusesOthers) {
  const std::string dir = sweep_dir("export");
  const std::string out = dir + "/results";
  ASSERT_EQ(run_fsweep("run " + dir + "/sweep.json --quiet --threads 2 --out " + out).code, 0);
  EXPECT_FALSE(std::filesystem::exists(out + "/results.sqlite"));  // only with --sqlite
  const auto to_default = run_fsweep("export-sqlite " + out);
  ASSERT_EQ(to_default.code, 0) << to_default.output;
  EXPECT_EQ(to_default.output.rfind("wrote " + out + "/results.sqlite (4 runs, 2 configurations, ", 0), 0U)
      << to_default.output;
  const auto elsewhere = run_fsweep("export-sqlite " + out + " --out " + dir + "/mine.db");
  ASSERT_EQ(elsewhere.code, 0) << elsewhere.output;
  EXPECT_TRUE(std::filesystem::exists(dir + "/mine.db"));

  const auto clobber = run_fsweep("export-sqlite " + out + " --out " + out + "/summary.csv");
  EXPECT_EQ(clobber.code, 2);
  EXPECT_EQ(clobber.output,
            "fsweep: error: " + out +
                "/summary.csv: exists and is not a database written by fsweep export-sqlite; remove "
                "it or choose another --out (an export replaces only its own files)\n");
  const auto missing = run_fsweep("export-sqlite " + dir + "/nowhere");
  EXPECT_EQ(missing.code, 2);
  EXPECT_EQ(missing.output, "fsweep: error: " + dir + "/nowhere: no such result directory\n");
  const auto not_results = run_fsweep("export-sqlite " + dir);
  EXPECT_EQ(not_results.code, 2);
  EXPECT_EQ(not_results.output, "fsweep: error: " + dir + ": not a result directory: no runs.csv\n");
  std::ofstream(out + "/runs.csv", std::ios::app) << "9,torn";  // a torn last record
  const auto damaged = run_fsweep("export-sqlite " + out);
  EXPECT_EQ(damaged.code, 2);
  EXPECT_NE(damaged.output.find("fsweep: error: " + out + "/runs.csv:6: "), std::string::npos)
      << damaged.output;
  EXPECT_EQ(std::count(damaged.output.begin(), damaged.output.end(), '\n'), 1) << damaged.output;
  std::filesystem::remove_all(dir);
}

}  // namespace test_cli_export_sqlite
