// The SQLite export of a result directory (src/report/sqlite_export.hpp): a real sweep's runs.csv
// and progress.csv read back by SQL cell by cell, configurations numbered as summary.csv's, the
// hand-written fixture's torn progress rows left out, and what it refuses.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/config_error.hpp"
#include "core/config_error_message.hpp"
#include "core/csv_reader.hpp"
#include "report/aggregate_fixture.hpp"
#include "report/sqlite_export.hpp"
#include "report/sqlite_test_db.hpp"
#include "sweep/sweep_plan.hpp"
#include "sweep/sweep_runner.hpp"
#include "sweep/sweep_test_files.hpp"

namespace fsweep {
namespace test_sqlite_export {  // not anonymous: unity builds put it beside other test files' helpers

namespace fs = std::filesystem;
using testing::number;
using testing::SqliteTestDb;
using testing::SqlRow;
using testing::SqlValue;

/// The SQL value `cell` must have read back as, for a column of SQL type `type`.
void expect_cell(const SqlValue& v, const std::string& cell, const std::string& type,
                 const std::string& where) {
  const std::optional<double> x = parse_number(cell);
  if (cell.empty() || (type != "TEXT" && std::isnan(*x))) {
    EXPECT_TRUE(std::holds_alternative<std::nullptr_t>(v)) << where << ": '" << cell << "'";
  } else if (type == "TEXT") {
    EXPECT_EQ(std::get<std::string>(v), cell) << where;
  } else if (type == "INTEGER") {
    EXPECT_EQ(std::get<std::int64_t>(v), std::stoll(cell)) << where;
  } else {
    EXPECT_EQ(std::get<double>(v), *x) << where << ": '" << cell << "'";  // the same double
  }
}

/// Every record of the CSV at `path` equals the row of `table` in the same place (SQL columns
/// from `first_column` on, in CSV order); returns the record count.
std::size_t expect_table_equals_csv(const SqliteTestDb& db, const std::string& table, const std::string& path,
                                    std::size_t first_column) {
  const auto rows = db.rows("SELECT * FROM " + table + " ORDER BY rowid");
  std::vector<std::string> types;
  for (const SqlRow& c : db.rows("PRAGMA table_info(" + table + ")"))
    types.push_back(std::get<std::string>(c[2]));
  CsvReader in(path);
  EXPECT_EQ(db.columns(table).size(), in.header().size() + first_column) << table;
  std::size_t n = 0;
  while (in.next()) {
    if (n >= rows.size()) break;
    for (std::size_t c = 0; c < in.fields().size(); ++c) {
      expect_cell(rows[n][c + first_column], in.fields()[c], types[c + first_column],
                  in.where() + " column " + in.header()[c]);
    }
    ++n;
  }
  EXPECT_EQ(rows.size(), n) << table;
  return n;
}

using testing::config_error;

/// 1 map x 2 strategies (closest_frontier has no strategy.w1: NULL there) x 3 repetitions.
class SqliteExportOfASweep : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new std::string(testing::fresh_dir("sqlite", "sweep"));
    RunnerOptions o;
    o.threads = 2;
    o.out_dir = *dir_;
    o.progress = false;
    (void)run_sweep(SweepPlan::from_json(nlohmann::json::parse(R"({
      "schema_version": 1, "name": "sqlite_test", "maps": ["rooms:w=24,h=20,door=2,seed=2"],
      "strategies": [{"name": "closest_frontier"}, {"name": "energy_aware"}], "repetitions": 3, "seed": 11})"),
                                         "test.json"),
                    o);
  }
  static void TearDownTestSuite() {
    fs::remove_all(*dir_);
    delete dir_;
  }
  static std::string* dir_;
};
std::string* SqliteExportOfASweep::dir_ = nullptr;

TEST_F(SqliteExportOfASweep, RunsAndProgressReadBackAsTheCsvs) {
  const SqliteExport e = export_sqlite(*dir_);
  EXPECT_EQ(e.path, *dir_ + "/results.sqlite");
  EXPECT_EQ(e.runs, 6U);
  EXPECT_EQ(e.configurations, 2U);
  const SqliteTestDb db(e.path);
  EXPECT_EQ(number(db.value("PRAGMA application_id")), kSqliteApplicationId);
  EXPECT_EQ(number(db.value("PRAGMA user_version")), kSqliteSchemaVersion);
  // runs: config_id, then every runs.csv column with its cell; progress: progress.csv's columns.
  EXPECT_EQ(expect_table_equals_csv(db, "runs", *dir_ + "/runs.csv", 1), 6U);
  EXPECT_EQ(expect_table_equals_csv(db, "progress", *dir_ + "/progress.csv", 0), e.progress_rows);
  EXPECT_GT(e.progress_rows, 6U);
  // Types by role (the file comment of sqlite_export.hpp).
  const auto type_of = [&](const std::string& column) {
    return std::get<std::string>(db.value("SELECT type FROM columns WHERE name = '" + column + "'"));
  };
  EXPECT_EQ(type_of("run_index"), "INTEGER");
  EXPECT_EQ(type_of("seed"), "TEXT");
  EXPECT_EQ(type_of("turns"), "REAL");
  EXPECT_EQ(type_of("coverage"), "REAL");
  EXPECT_EQ(type_of("strategy.w1"), "REAL");
  EXPECT_EQ(type_of("strategy"), "TEXT");
  EXPECT_EQ(type_of("end_reason"), "TEXT");
  EXPECT_EQ(std::get<std::string>(db.value("SELECT role FROM columns WHERE name = 'map.start'")), "instance");
  EXPECT_EQ(number(db.value("SELECT COUNT(*) FROM columns")),
            static_cast<double>(db.columns("runs").size() - 1));
  const auto manifest = nlohmann::json::parse(std::get<std::string>(db.value("SELECT json FROM manifest")));
  EXPECT_EQ(manifest.at("name"), "sqlite_test");
}

TEST_F(SqliteExportOfASweep, ConfigurationsAreSummaryCsvsConfigIds) {
  const std::string out = *dir_ + "/other.sqlite";
  (void)export_sqlite(*dir_, out);
  const SqliteTestDb db(out);
  // Each run's configuration row holds the run's config columns.
  const auto mismatches = db.value(
      "SELECT COUNT(*) FROM runs r JOIN configurations c USING (config_id) WHERE r.strategy IS NOT "
      "c.strategy OR "
      "r.\"strategy.w1\" IS NOT c.\"strategy.w1\" OR r.planner IS NOT c.planner");
  EXPECT_EQ(number(mismatches), 0.0);
  // The example query of the README: mean distance per configuration, as summary.csv has it.
  const auto means = db.rows(
      "SELECT config_id, c.strategy, AVG(distance_m), COUNT(*) FROM runs JOIN configurations c USING "
      "(config_id) "
      "GROUP BY config_id ORDER BY config_id");
  CsvReader summary(*dir_ + "/summary.csv");
  std::size_t i = 0;
  while (summary.next()) {
    ASSERT_LT(i, means.size());
    EXPECT_EQ(number(means[i][0]), std::stod(summary.fields()[summary.require_column("config_id")]));
    EXPECT_EQ(std::get<std::string>(means[i][1]), summary.fields()[summary.require_column("strategy")]);
    EXPECT_NEAR(number(means[i][2]), std::stod(summary.fields()[summary.require_column("distance_m.mean")]),
                1e-9);
    EXPECT_EQ(number(means[i][3]), std::stod(summary.fields()[summary.require_column("n")]));
    ++i;
  }
  EXPECT_EQ(i, means.size());
  fs::remove(out);
}

TEST_F(SqliteExportOfASweep, ReplacesOnlyItsOwnDatabase) {
  const std::string out = *dir_ + "/again.sqlite";
  (void)export_sqlite(*dir_, out);
  EXPECT_NO_THROW((void)export_sqlite(*dir_, out));  // its own database: replaced
  const std::string runs_before = testing::read_file(*dir_ + "/runs.csv");
  const std::string refused = config_error([&] { (void)export_sqlite(*dir_, *dir_ + "/runs.csv"); });
  EXPECT_NE(refused.find("runs.csv: exists and is not a database written by fsweep export-sqlite"),
            std::string::npos)
      << refused;
  EXPECT_EQ(testing::read_file(*dir_ + "/runs.csv"), runs_before);
  EXPECT_NE(config_error([&] { (void)export_sqlite(*dir_, *dir_); }).find("exists and is not a database"),
            std::string::npos);
  for (const auto& entry : fs::directory_iterator(*dir_)) {
    EXPECT_EQ(entry.path().filename().string().find(".tmp."), std::string::npos) << entry.path();
  }
  fs::remove(out);
}

TEST(SqliteExport, ProgressRowsOfRunsWithoutARunsRowAreLeftOut) {
  // The aggregate fixture: 7 runs in 3 configurations; progress.csv ends with 2 rows of a run
  // (run_key ...d0) that has no runs.csv row.
  const fs::path dir = testing::make_sweep_dir("sqlite_torn");
  const SqliteExport e = export_sqlite(dir.string());
  EXPECT_EQ(e.runs, 7U);
  EXPECT_EQ(e.configurations, 3U);
  EXPECT_EQ(e.progress_rows, 28U);
  const SqliteTestDb db(e.path);
  EXPECT_EQ(number(db.value("SELECT COUNT(*) FROM progress WHERE run_key = '00000000000000d0'")), 0.0);
  EXPECT_EQ(std::get<std::string>(db.value("SELECT end_detail FROM runs WHERE run_index = 3")),
            "planner failed, \"dock\" unreachable");
  EXPECT_TRUE(
      std::holds_alternative<std::nullptr_t>(db.value("SELECT \"strategy.w1\" FROM configurations WHERE "
                                                      "config_id = 2")));
  EXPECT_TRUE(db.rows("SELECT json FROM manifest").empty());  // the fixture has no manifest.json
  fs::remove_all(dir);
}

TEST(SqliteExport, BadInputIsOneLineNamingTheFile) {
  const fs::path dir = testing::make_sweep_dir("sqlite_bad");
  const std::string d = dir.string();
  const auto error = [](const std::string& from) {
    const std::string e = config_error([&] { (void)export_sqlite(from); });
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;
    return e;
  };
  EXPECT_NE(error(d + "/missing").find("/missing: no such result directory"), std::string::npos);
  fs::create_directories(d + "/empty/shard-notes");  // not a shard folder: no hint
  EXPECT_EQ(error(d + "/empty").find("sharded"), std::string::npos);
  fs::create_directories(d + "/empty/shard-0-of-2");
  EXPECT_NE(error(d + "/empty").find("empty: not a result directory: no runs.csv (a sharded run"),
            std::string::npos);
  const std::string runs = testing::read_file(d + "/runs.csv");
  const std::string progress = testing::read_file(d + "/progress.csv");

  testing::write_file(d + "/runs.csv", runs.substr(0, runs.find("\n1,") + 1) + "1,00000000000000b0,free\n");
  EXPECT_NE(error(d).find("runs.csv:3: "), std::string::npos) << error(d);  // too few fields
  std::string not_a_number = runs;
  not_a_number.replace(not_a_number.find(",complete,,1,10,"), 16, ",complete,,x,10,");
  testing::write_file(d + "/runs.csv", not_a_number);
  EXPECT_NE(error(d).find("runs.csv:2: column 'distance_m': 'x' is not a number"), std::string::npos)
      << error(d);
  std::string twice = runs;
  twice.replace(twice.find("00000000000000b0"), 16, "00000000000000a0");
  testing::write_file(d + "/runs.csv", twice);
  EXPECT_NE(error(d).find("runs.csv:3: run_key 00000000000000a0 is also on line 2"), std::string::npos)
      << error(d);
  testing::write_file(d + "/runs.csv", runs);
  testing::write_file(d + "/progress.csv", progress + "7,00000000000000d0,1,oops,1,1\n");
  EXPECT_NE(error(d).find("progress.csv:32: column 'explored_area_m2': 'oops' is not a number"),
            std::string::npos)
      << error(d);
  fs::remove(d + "/progress.csv");
  EXPECT_NE(error(d).find("progress.csv: missing"), std::string::npos);
  EXPECT_FALSE(fs::exists(d + "/results.sqlite"));
  fs::remove_all(dir);
}

}  // namespace test_sqlite_export
}  // namespace fsweep
