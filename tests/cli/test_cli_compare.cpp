// `fsweep compare NEW_DIR BASELINE_DIR` end to end: a sweep run by `fsweep run`, copied, compared
// with itself (exit 0), with a planted change (exit 1) and with bad input (exit 2).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "cli/fsweep_process.hpp"
#include "core/csv_format.hpp"
#include "sweep/csv_journal.hpp"

namespace {

namespace fs = std::filesystem;
using fsweep::testing::read_all;
using fsweep::testing::run_fsweep;

/// Runs a sweep of 1 map x 2 strategies x 2 repetitions (4 runs, planner astar) into
/// `dir`/base and copies it to `dir`/new.
void make_dirs(const std::string& dir) {
  fs::create_directories(dir);
  std::ofstream(dir + "/sweep.json") << R"({"schema_version": 1, "name": "cli_compare",
    "maps": ["rooms:w=24,h=20,door=2,seed=2"],
    "strategies": [{"name": "closest_frontier"}, {"name": "energy_aware"}],
    "repetitions": 2, "seed": 3})";
  const auto r = run_fsweep("run " + dir + "/sweep.json --quiet --out " + dir + "/base");
  ASSERT_EQ(r.code, 0) << r.output;
  fs::copy(dir + "/base", dir + "/new", fs::copy_options::recursive);
}

TEST(CliCompare, IdenticalCopyExits0AndWritesOutputs) {
  const std::string dir = fsweep::testing::fresh_temp_dir("compare", "same");
  make_dirs(dir);
  const auto r = run_fsweep("compare " + dir + "/new " + dir + "/base");
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("compare: no regressions"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("closest_frontier"), std::string::npos) << r.output;
  EXPECT_GE(fsweep::testing::count_lines(dir + "/new/compare/compare.csv"), 3);  // header + 2 configurations
  EXPECT_NE(read_all(dir + "/new/compare/compare.html").find("<svg"), std::string::npos);
  fs::remove_all(dir);
}

TEST(CliCompare, ChangedRunExits1AndNamesIt) {
  const std::string dir = fsweep::testing::fresh_temp_dir("compare", "changed");
  make_dirs(dir);
  // Row 1 (after the header): its distance_m cell gets another value.
  std::string runs = read_all(dir + "/new/runs.csv");
  std::istringstream in(runs);
  std::string header, row;
  std::getline(in, header);
  std::getline(in, row);
  const auto names = fsweep::split_csv_line(header);
  auto fields = fsweep::split_csv_line(row);
  const auto column =
      static_cast<std::size_t>(std::find(names.begin(), names.end(), "distance_m") - names.begin());
  ASSERT_LT(column, fields.size());
  fields[column] = "12345.5";
  std::string changed;
  for (std::size_t i = 0; i < fields.size(); ++i) (changed += i ? "," : "") += fsweep::csv_field(fields[i]);
  const std::string key = fields[1];  // run_key
  runs.replace(runs.find(row), row.size(), changed);
  std::ofstream(dir + "/new/runs.csv", std::ios::trunc) << runs;

  const auto r = run_fsweep("compare " + dir + "/new " + dir + "/base --out " + dir + "/report");
  EXPECT_EQ(r.code, 1) << r.output;
  EXPECT_NE(r.output.find(key), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("12345.5"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("compare: 1 regression"), std::string::npos) << r.output;
  const std::string csv = read_all(dir + "/report/compare.csv");
  EXPECT_NE(csv.find("run,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("distance_m"), std::string::npos) << csv;
  EXPECT_TRUE(fs::exists(dir + "/report/compare.html"));
  EXPECT_FALSE(fs::exists(dir + "/new/compare"));
  fs::remove_all(dir);
}

TEST(CliCompare, BadInputExits2) {
  const std::string dir = fsweep::testing::fresh_temp_dir("compare", "bad");
  make_dirs(dir);
  auto r = run_fsweep("compare " + dir + "/nowhere " + dir + "/base");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find(dir + "/nowhere"), std::string::npos) << r.output;
  r = run_fsweep("compare " + dir + "/new " + dir + "/base --quality-tolerance -1");
  EXPECT_EQ(r.code, 2) << r.output;
  std::ofstream(dir + "/new/manifest.json", std::ios::trunc) << "{ not json";
  r = run_fsweep("compare " + dir + "/new " + dir + "/base");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find(dir + "/new/manifest.json"), std::string::npos) << r.output;
  fs::remove(dir + "/base/runs.csv");
  r = run_fsweep("compare " + dir + "/new " + dir + "/base");
  EXPECT_EQ(r.code, 2) << r.output;
  fs::remove_all(dir);
}

TEST(CliCompare, StrictSpeedMakesAnotherMachinesSlowdownFail) {
  const std::string dir = fsweep::testing::fresh_temp_dir("compare", "strict");
  make_dirs(dir);
  const std::string bench = R"({"context": {"host_name": "H", "num_cpus": 2, "mhz_per_cpu": MHZ},
    "benchmarks": [{"name": "BM_X", "run_name": "BM_X", "run_type": "iteration", "real_time": T, "time_unit": "us"}]})";
  auto with = [&](const std::string& mhz, const std::string& t) {
    std::string s = bench;
    s.replace(s.find("MHZ"), 3, mhz);
    s.replace(s.find('T', s.find("real_time")), 1, t);
    return s;
  };
  std::ofstream(dir + "/base/bench.json") << with("2100", "10");
  std::ofstream(dir + "/new/bench.json") << with("3000", "30");
  auto r = run_fsweep("compare " + dir + "/new " + dir + "/base");
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("WARNING: different machine"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("BM_X"), std::string::npos) << r.output;
  r = run_fsweep("compare " + dir + "/new " + dir + "/base --strict-speed");
  EXPECT_EQ(r.code, 1) << r.output;
  r = run_fsweep("compare " + dir + "/new " + dir + "/base --strict-speed --speed-tolerance 2.5");
  EXPECT_EQ(r.code, 0) << r.output;
  fs::remove_all(dir);
}

TEST(CliCompare, ASweepOfASecondIsNotJudgedOnThroughputUnlessAsked) {
  const std::string dir = fsweep::testing::fresh_temp_dir("compare", "short");
  make_dirs(dir);
  // The same sweep, three times slower on the same machine: noise for a sweep of a few runs.
  const std::string manifest = read_all(dir + "/new/manifest.json");
  auto j = nlohmann::json::parse(manifest);
  j["wall_s"] = j["wall_s"].get<double>() * 3.0;
  std::ofstream(dir + "/new/manifest.json", std::ios::trunc) << j.dump(2);
  auto r = run_fsweep("compare " + dir + "/new " + dir + "/base");
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("that are judged on speed"), std::string::npos) << r.output;
  r = run_fsweep("compare " + dir + "/new " + dir + "/base --min-sweep-seconds 0");
  EXPECT_EQ(r.code, 1) << r.output;
  r = run_fsweep("compare " + dir + "/new " + dir + "/base --min-sweep-seconds -1");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("--min-sweep-seconds"), std::string::npos) << r.output;
  fs::remove_all(dir);
}

}  // namespace
