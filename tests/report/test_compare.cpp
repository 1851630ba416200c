// fsweep compare: a sweep's outputs against a baseline. A tiny sweep is run once; each test
// copies it, plants a change in the copy (or in both) and checks what compare_dirs makes of it.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/config_error.hpp"
#include "core/csv_format.hpp"
#include "core/csv_reader.hpp"
#include "planners/reproducibility.hpp"
#include "report/compare.hpp"
#include "report/compare_runs.hpp"
#include "sweep/sweep_plan.hpp"
#include "sweep/sweep_runner.hpp"
#include "sweep/sweep_test_files.hpp"

namespace fsweep {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using testing::read_file;
using testing::write_file;

/// 1 map x 2 strategies x 8 repetitions = 16 short runs, planner astar (reproducible); 8 runs
/// per configuration, as many as quantile checks need by default.
json tiny_sweep() {
  return json::parse(R"({
    "schema_version": 1,
    "name": "compare_test",
    "maps": ["rooms:w=24,h=20,door=2,seed=2"],
    "strategies": [{"name": "closest_frontier"}, {"name": "energy_aware"}],
    "repetitions": 8,
    "seed": 11
  })");
}

/// runs.csv as header and rows, editable and written back.
struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;

  [[nodiscard]] std::size_t col(const std::string& name) const {
    const auto it = std::find(header.begin(), header.end(), name);
    EXPECT_NE(it, header.end()) << name;
    return static_cast<std::size_t>(it - header.begin());
  }
  /// Applies `edit` to every row whose `column` equals `value`.
  void edit_rows(const std::string& column, const std::string& value,
                 const std::function<void(std::vector<std::string>&)>& edit) {
    const std::size_t c = col(column);
    for (auto& r : rows) {
      if (r[c] == value) edit(r);
    }
  }
  /// Multiplies numeric column `column` of the rows matching `match` by `factor(i)` (i counts
  /// the matching rows).
  void scale(const std::string& match_column, const std::string& match_value, const std::string& column,
             const std::function<double(std::size_t)>& factor) {
    const std::size_t c = col(column);
    std::size_t i = 0;
    edit_rows(match_column, match_value,
              [&](std::vector<std::string>& r) { r[c] = format_number(*parse_number(r[c]) * factor(i++)); });
  }
};

Table read_table(const std::string& path) {
  Table t;
  CsvReader in(path);
  t.header = in.header();
  while (in.next()) t.rows.push_back(in.fields());
  return t;
}

void write_table(const std::string& path, const Table& t) {
  std::string out;
  auto line = [&](const std::vector<std::string>& f) {
    for (std::size_t i = 0; i < f.size(); ++i) (out += i ? "," : "") += csv_field(f[i]);
    out += '\n';
  };
  line(t.header);
  for (const auto& r : t.rows) line(r);
  write_file(path, out);
}

/// The checks of `report` with status `s`.
std::vector<CompareCheck> with_status(const CompareReport& report, CheckStatus s) {
  std::vector<CompareCheck> out;
  for (const auto& k : report.checks) {
    if (k.status == s) out.push_back(k);
  }
  return out;
}

const ConfigComparison* config_with(const CompareReport& report, const std::string& text) {
  for (const auto& c : report.configs) {
    if (c.name.find(text) != std::string::npos) return &c;
  }
  return nullptr;
}

/// A bench.json: benchmark A with 3 iteration rows and a median aggregate (ns), B with
/// iteration rows only (in `b_unit`), times multiplied by `factor`.
std::string bench_json(double factor, const std::string& host, int mhz, const std::string& b_unit = "us") {
  json j;
  j["context"] = {{"host_name", host}, {"num_cpus", 2}, {"mhz_per_cpu", mhz}};
  json list = json::array();
  for (const double t : {1000.0, 1200.0, 1100.0}) {
    list.push_back({{"name", "BM_A"},
                    {"run_name", "BM_A"},
                    {"run_type", "iteration"},
                    {"real_time", t * factor},
                    {"cpu_time", t},
                    {"time_unit", "ns"}});
  }
  list.push_back({{"name", "BM_A_mean"},
                  {"run_name", "BM_A"},
                  {"run_type", "aggregate"},
                  {"aggregate_name", "mean"},
                  {"real_time", 1100.0 * factor},
                  {"time_unit", "ns"}});
  list.push_back({{"name", "BM_A_median"},
                  {"run_name", "BM_A"},
                  {"run_type", "aggregate"},
                  {"aggregate_name", "median"},
                  {"real_time", 1100.0 * factor},
                  {"time_unit", "ns"}});
  const double scale = b_unit == "us" ? 1.0 : 1000.0;  // B is 50 us
  for (const double t : {40.0, 60.0}) {
    list.push_back({{"name", "BM_B"},
                    {"run_type", "iteration"},
                    {"real_time", t * scale * factor},
                    {"time_unit", b_unit}});
  }
  j["benchmarks"] = list;
  return j.dump(1);
}

class CompareTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    source_ = new std::string(testing::fresh_dir("compare", "source"));
    RunnerOptions o;
    o.threads = 2;
    o.out_dir = *source_;
    o.progress = false;
    (void)run_sweep(SweepPlan::from_json(tiny_sweep(), "test.json"), o);
  }
  static void TearDownTestSuite() {
    fs::remove_all(*source_);
    delete source_;
  }
  void SetUp() override {
    root_ = testing::fresh_dir("compare", ::testing::UnitTest::GetInstance()->current_test_info()->name());
    base_ = root_ + "/base";
    new_ = root_ + "/new";
    fs::copy(*source_, base_, fs::copy_options::recursive);
    fs::copy(*source_, new_, fs::copy_options::recursive);
  }
  void TearDown() override { fs::remove_all(root_); }

  /// Gives closest_frontier's rows the non-reproducible planner ompl:PRMstar on both sides.
  void make_frontier_rows_prmstar() {
    for (const auto& d : {base_, new_}) {
      Table t = read_table(d + "/runs.csv");
      const std::size_t p = t.col("planner");
      t.edit_rows("strategy", "closest_frontier",
                  [&](std::vector<std::string>& r) { r[p] = "ompl:PRMstar"; });
      write_table(d + "/runs.csv", t);
      make_summary_older(d);
    }
  }

  /// Dates `dir`/summary.csv an hour before its runs.csv, so compare aggregates again (file
  /// times written within one clock tick may be equal).
  static void make_summary_older(const std::string& dir) {
    fs::last_write_time(dir + "/summary.csv", fs::last_write_time(dir + "/runs.csv") - std::chrono::hours(1));
  }

  // The fixture's sweeps take well under a second: judge their throughput all the same.
  [[nodiscard]] static CompareOptions options() {
    CompareOptions o;
    o.min_judged_sweep_wall_s = 0.0;
    return o;
  }

  [[nodiscard]] CompareReport compare(const CompareOptions& o = options()) const {
    return compare_dirs(new_, base_, o);
  }

  static std::string* source_;
  std::string root_, base_, new_;
};
std::string* CompareTest::source_ = nullptr;

TEST_F(CompareTest, IdenticalCopyHasNoRegression) {
  const CompareReport r = compare();
  EXPECT_EQ(r.regressions, 0U) << format_compare_table(r);
  ASSERT_EQ(r.configs.size(), 2U);
  for (const auto& c : r.configs) {
    EXPECT_TRUE(c.reproducible) << c.name;  // astar
    EXPECT_EQ(c.status, CheckStatus::Match) << c.name;
    EXPECT_EQ(c.baseline_runs, 8U);
    EXPECT_EQ(c.new_runs, 8U);
  }
  EXPECT_FALSE(r.sweep_hash_differs);
  EXPECT_TRUE(r.same_machine);
  EXPECT_TRUE(r.warnings.empty());
  const std::string table = format_compare_table(r);
  EXPECT_NE(table.find("compare: no regressions"), std::string::npos) << table;
}

TEST_F(CompareTest, ChangedReproducibleRunIsCaughtByRunKey) {
  Table t = read_table(new_ + "/runs.csv");
  const std::size_t d = t.col("distance_m");
  const std::string key = t.rows[5][t.col("run_key")];
  const std::string old_value = t.rows[5][d];
  t.rows[5][d] = format_number(*parse_number(old_value) + 1e-9);  // a tiny change still counts
  write_table(new_ + "/runs.csv", t);
  const CompareReport r = compare();
  EXPECT_EQ(r.regressions, 1U);
  const auto changed = with_status(r, CheckStatus::Changed);
  ASSERT_EQ(changed.size(), 2U);  // the run check and its configuration's runs_changed
  EXPECT_EQ(changed[0].kind, "run");
  EXPECT_NE(changed[0].name.find(key), std::string::npos);
  EXPECT_EQ(changed[0].metric, "distance_m");
  EXPECT_EQ(changed[0].baseline, old_value);
  EXPECT_EQ(changed[1].kind, "config");
  EXPECT_EQ(changed[1].current, "1");
  const std::string table = format_compare_table(r);
  EXPECT_NE(table.find(key), std::string::npos) << table;
  EXPECT_NE(table.find("compare: 1 regression"), std::string::npos) << table;
}

TEST_F(CompareTest, ChangedEndReasonTextIsAChange) {
  Table t = read_table(new_ + "/runs.csv");
  t.rows[0][t.col("end_reason")] = "stuck";
  write_table(new_ + "/runs.csv", t);
  const CompareReport r = compare();
  EXPECT_EQ(r.regressions, 1U);
  const auto changed = with_status(r, CheckStatus::Changed);
  ASSERT_FALSE(changed.empty());
  EXPECT_EQ(changed[0].metric, "end_reason");
  EXPECT_EQ(changed[0].current, "stuck");
}

TEST_F(CompareTest, TimingColumnsAreNotQuality) {
  Table t = read_table(new_ + "/runs.csv");
  for (const char* c : {"wall_time_s", "planner_time_s", "decision_time_s"}) {
    t.scale("strategy", "closest_frontier", c, [](std::size_t i) { return 3.0 + static_cast<double>(i); });
  }
  write_table(new_ + "/runs.csv", t);
  const CompareReport r = compare();
  EXPECT_EQ(r.regressions, 0U) << format_compare_table(r);
  EXPECT_TRUE(with_status(r, CheckStatus::Changed).empty());
  // The tiny runs are below the 0.05 s floor: their wall time is not judged.
  for (const auto& k : r.checks) {
    if (k.kind == "speed" && k.metric == "wall_time_s.median") {
      EXPECT_EQ(k.status, CheckStatus::NotJudged);
    }
  }
}

TEST_F(CompareTest, ConfigurationWallTimesAreInformational) {
  // Make the baseline's runs last 0.1 s (above the floor), NEW's x1.2 and x2.
  Table base = read_table(base_ + "/runs.csv");
  const std::size_t w = base.col("wall_time_s");
  for (auto& row : base.rows) row[w] = "0.1";
  write_table(base_ + "/runs.csv", base);
  Table cur = base;
  cur.scale("strategy", "closest_frontier", "wall_time_s", [](std::size_t) { return 1.2; });
  cur.scale("strategy", "energy_aware", "wall_time_s", [](std::size_t) { return 2.0; });
  write_table(new_ + "/runs.csv", cur);
  CompareReport r = compare();
  const auto slower = with_status(r, CheckStatus::Slower);
  ASSERT_EQ(slower.size(), 1U) << format_compare_table(r);
  EXPECT_NE(slower[0].name.find("energy_aware"), std::string::npos);
  EXPECT_NEAR(*slower[0].ratio, 2.0, 1e-12);
  // A run's wall time depends on what ran beside it: shown, never a failure, even strict.
  EXPECT_FALSE(slower[0].failure);
  EXPECT_EQ(r.regressions, 0U) << format_compare_table(r);
  CompareOptions strict = options();
  strict.strict_speed = true;
  EXPECT_EQ(compare(strict).regressions, 0U);
}

TEST_F(CompareTest, TooFewRunsForQuantilesAreNotJudged) {
  make_frontier_rows_prmstar();
  Table t = read_table(base_ + "/runs.csv");
  t.scale("planner", "ompl:PRMstar", "distance_m", [](std::size_t) { return 2.0; });
  write_table(new_ + "/runs.csv", t);
  EXPECT_EQ(compare().regressions, 1U);  // judged from 8 runs: twice as long is a regression
  CompareOptions nine = options();
  nine.min_quantile_runs = 9;
  const CompareReport r = compare(nine);
  const ConfigComparison* c = config_with(r, "ompl:PRMstar");
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->status, CheckStatus::NotJudged) << format_compare_table(r);
  EXPECT_FALSE(c->failure);
  EXPECT_EQ(r.regressions, 0U);
  EXPECT_NE(c->worst.find("fewer than 9 runs"), std::string::npos) << c->worst;
}

TEST_F(CompareTest, ShiftBeyondToleranceMustBeSignificant) {
  make_frontier_rows_prmstar();
  // Only 3 of the 8 runs 40% longer: the q75 moves 40%, beyond the 10% band, but a one-sided
  // Mann-Whitney test cannot tell 3 changed runs of 8 from noise at 1% (p = 0.037).
  Table t = read_table(base_ + "/runs.csv");
  t.scale("planner", "ompl:PRMstar", "distance_m", [](std::size_t i) { return i < 3 ? 1.4 : 1.0; });
  write_table(new_ + "/runs.csv", t);
  CompareReport r = compare();
  const ConfigComparison* c = config_with(r, "ompl:PRMstar");
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(r.regressions, 0U) << format_compare_table(r);
  bool p_seen = false;
  for (const auto& k : r.checks) {
    if (k.name != c->name || k.metric.rfind("distance_m.", 0) != 0) continue;
    ASSERT_TRUE(k.p_value.has_value());
    EXPECT_GE(*k.p_value, 0.01);
    p_seen = true;
  }
  EXPECT_TRUE(p_seen);
  // At the 50% level the same shift counts.
  CompareOptions loose = options();
  loose.significance = 0.5;
  EXPECT_EQ(compare(loose).regressions, 1U);
}

TEST(MannWhitney, HandWorkedCases) {
  // a = {1, 2, 3}, b = {4, 5, 6}: U = 9 (every pair), mean 4.5, variance 3 * 3 / 12 * 7 = 5.25,
  // z = (9 - 4.5 - 0.5) / sqrt(5.25) = 1.74574, p = 1 - Phi(z) = 0.040428.
  EXPECT_NEAR(mann_whitney_greater_p({1, 2, 3}, {4, 5, 6}), 0.040428, 1e-6);
  // The other direction: U = 0, z = (0 - 4.5 - 0.5) / sqrt(5.25) = -2.18218, p = 0.985452.
  EXPECT_NEAR(mann_whitney_greater_p({4, 5, 6}, {1, 2, 3}), 0.985452, 1e-6);
  // Ties: a = {1, 2, 2}, b = {2, 3, 3}. Pooled ranks 1, 3, 3, 3 (the 2s), 5.5, 5.5 (the 3s);
  // b's rank sum 3 + 5.5 + 5.5 = 14, U = 14 - 6 = 8; ties sum (27 - 3) + (8 - 2) = 30;
  // variance 9 / 12 * (7 - 30 / 30) = 4.5; z = (8 - 4.5 - 0.5) / sqrt(4.5) = 1.41421,
  // p = 0.078650.
  EXPECT_NEAR(mann_whitney_greater_p({1, 2, 2}, {2, 3, 3}), 0.078650, 1e-6);
  EXPECT_EQ(mann_whitney_greater_p({2, 2}, {2, 2, 2}), 1.0);  // all tied
  EXPECT_EQ(mann_whitney_greater_p({}, {1.0}), 1.0);
}

TEST_F(CompareTest, NonReproducibleConfigurationComparedByQuantiles) {
  make_frontier_rows_prmstar();
  const std::string label = "ompl:PRMstar";
  // Jitter within 10 %: a few percent either way, the quantiles move less than the band.
  Table t = read_table(new_ + "/runs.csv");
  t.scale("planner", label, "distance_m", [](std::size_t i) { return i % 2 == 0 ? 1.04 : 0.97; });
  t.scale("planner", label, "coverage", [](std::size_t i) { return i % 2 == 0 ? 0.99 : 1.0; });
  write_table(new_ + "/runs.csv", t);
  CompareReport r = compare();
  const ConfigComparison* c = config_with(r, label);
  ASSERT_NE(c, nullptr);
  EXPECT_FALSE(c->reproducible);
  EXPECT_EQ(c->status, CheckStatus::WithinTolerance) << format_compare_table(r);
  EXPECT_EQ(r.regressions, 0U);
  // Worse beyond the tolerance: 25 % longer.
  t = read_table(base_ + "/runs.csv");
  t.scale("planner", label, "distance_m", [](std::size_t) { return 1.25; });
  write_table(new_ + "/runs.csv", t);
  r = compare();
  c = config_with(r, label);
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->status, CheckStatus::Regressed) << format_compare_table(r);
  EXPECT_TRUE(c->failure);
  EXPECT_EQ(r.regressions, 1U);
  EXPECT_NE(c->worst.find("distance_m"), std::string::npos) << c->worst;
  EXPECT_NE(c->worst.find("+25.0%"), std::string::npos) << c->worst;
  // NEW's summary.csv, older than its runs.csv, was aggregated again: the boxes show x1.25.
  make_summary_older(new_);
  r = compare();
  c = config_with(r, label);
  ASSERT_NE(c, nullptr);
  ASSERT_TRUE(c->baseline_box[0] && c->new_box[0]);
  EXPECT_NEAR(c->new_box[0]->median, 1.25 * c->baseline_box[0]->median, 1e-9 * c->baseline_box[0]->median);
  EXPECT_NEAR(c->new_box[0]->q95, 1.25 * c->baseline_box[0]->q95, 1e-9 * c->baseline_box[0]->q95);
  // A higher tolerance accepts it.
  CompareOptions loose = options();
  loose.quality_tolerance = 0.3;
  EXPECT_EQ(compare(loose).regressions, 0U);
  // Better beyond the tolerance: 25 % shorter, not a failure.
  t = read_table(base_ + "/runs.csv");
  t.scale("planner", label, "distance_m", [](std::size_t) { return 0.75; });
  write_table(new_ + "/runs.csv", t);
  r = compare();
  c = config_with(r, label);
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->status, CheckStatus::Improved) << format_compare_table(r);
  EXPECT_FALSE(c->failure);
  EXPECT_EQ(r.regressions, 0U);
  // Coverage is better when higher: lower coverage is the regression.
  t = read_table(base_ + "/runs.csv");
  t.scale("planner", label, "coverage", [](std::size_t) { return 0.8; });
  write_table(new_ + "/runs.csv", t);
  r = compare();
  c = config_with(r, label);
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->status, CheckStatus::Regressed) << format_compare_table(r);
}

TEST_F(CompareTest, FewerCompleteRunsIsARegression) {
  make_frontier_rows_prmstar();
  // `count` of the 8 runs end stuck in NEW.
  const auto stuck = [&](int count) {
    Table t = read_table(base_ + "/runs.csv");
    int left = count;
    t.edit_rows("planner", "ompl:PRMstar", [&](std::vector<std::string>& r) {
      if (left-- > 0) r[t.col("end_reason")] = "stuck";
    });
    write_table(new_ + "/runs.csv", t);
    return compare();
  };
  // One stuck run of 8 is no evidence (one-sided Mann-Whitney on the 0/1 outcomes, p = 0.19).
  CompareReport r = stuck(1);
  EXPECT_EQ(r.regressions, 0U) << format_compare_table(r);
  // Five of 8: p = 0.005.
  r = stuck(5);
  const ConfigComparison* c = config_with(r, "ompl:PRMstar");
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->status, CheckStatus::Regressed) << format_compare_table(r);
  EXPECT_NE(c->worst.find("success_share"), std::string::npos) << c->worst;
}

TEST_F(CompareTest, MissingConfigurationFailsNewOneDoesNot) {
  Table t = read_table(new_ + "/runs.csv");
  const std::size_t s = t.col("strategy");
  const std::size_t label = t.col("strategy_label");
  std::erase_if(t.rows, [&](const std::vector<std::string>& r) { return r[s] == "energy_aware"; });
  write_table(new_ + "/runs.csv", t);
  CompareReport r = compare();
  EXPECT_EQ(r.regressions, 1U);
  const ConfigComparison* c = config_with(r, "energy_aware");
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->status, CheckStatus::Missing);
  EXPECT_TRUE(c->failure);
  // A configuration only in NEW (another label) is reported, not a failure.
  t = read_table(base_ + "/runs.csv");
  t.edit_rows("strategy", "energy_aware", [&](std::vector<std::string>& row) {
    row[label] = "EA-new";
    row[t.col("run_key")] += "x";
  });
  write_table(new_ + "/runs.csv", t);
  r = compare();
  c = config_with(r, "EA-new");
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->status, CheckStatus::New);
  EXPECT_FALSE(c->failure);
  EXPECT_EQ(config_with(r, "energy_aware")->status, CheckStatus::Missing);
  EXPECT_EQ(r.regressions, 1U);
}

TEST_F(CompareTest, MissingRunMakesItsConfigurationIncomplete) {
  Table t = read_table(new_ + "/runs.csv");
  const std::string key = t.rows[2][t.col("run_key")];
  t.rows.erase(t.rows.begin() + 2);
  write_table(new_ + "/runs.csv", t);
  const CompareReport r = compare();
  EXPECT_EQ(r.regressions, 1U);
  const auto missing = with_status(r, CheckStatus::Missing);
  ASSERT_EQ(missing.size(), 1U);
  EXPECT_EQ(missing[0].baseline, key);
  EXPECT_EQ(with_status(r, CheckStatus::Incomplete).size(), 0U);  // a config status, not a check
  bool incomplete = false;
  for (const auto& c : r.configs) incomplete |= c.status == CheckStatus::Incomplete;
  EXPECT_TRUE(incomplete);
}

TEST_F(CompareTest, DifferentSweepHashIsAWarning) {
  json m = json::parse(read_file(new_ + "/manifest.json"));
  m["sweep_hash"] = "0123456789abcdef";
  write_file(new_ + "/manifest.json", m.dump(2));
  const CompareReport r = compare();
  EXPECT_TRUE(r.sweep_hash_differs);
  EXPECT_EQ(r.regressions, 0U);
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_NE(format_compare_table(r).find("WARNING: the sweeps differ"), std::string::npos);
}

TEST_F(CompareTest, MicroBenchmarkRatios) {
  // Google Benchmark writes non-finite counters (the cv of a counter whose mean is 0) as NaN and
  // Infinity, words JSON does not have: read as null.
  std::string baseline = bench_json(1.0, "vm", 2100);
  baseline.insert(baseline.find("\"cpu_time\""), R"("exact":NaN,"gap":-Infinity,)");
  write_file(base_ + "/bench.json", baseline);
  // x1.1, B in ns instead of us: within tolerance.
  write_file(new_ + "/bench.json", bench_json(1.1, "vm", 2100, "ns"));
  CompareReport r = compare();
  std::map<std::string, CompareCheck> bench;
  for (const auto& k : r.checks) {
    if (k.kind == "bench") bench[k.name] = k;
  }
  ASSERT_EQ(bench.size(), 2U);
  EXPECT_EQ(bench["BM_A"].baseline, "1100");  // the median aggregate
  EXPECT_NEAR(*bench["BM_A"].ratio, 1.1, 1e-12);
  EXPECT_EQ(bench["BM_B"].baseline, "50000");  // mean of 40 us and 60 us, in ns
  EXPECT_NEAR(*bench["BM_B"].ratio, 1.1, 1e-12);
  EXPECT_EQ(bench["BM_A"].status, CheckStatus::WithinTolerance);
  EXPECT_EQ(r.regressions, 0U);
  // x2 on the same machine: both slower, failures.
  write_file(new_ + "/bench.json", bench_json(2.0, "vm", 2100));
  r = compare();
  EXPECT_EQ(with_status(r, CheckStatus::Slower).size(), 2U);
  EXPECT_EQ(r.regressions, 2U) << format_compare_table(r);
  // x2 on another CPU: a warning, informational...
  write_file(new_ + "/bench.json", bench_json(2.0, "vm", 3000));
  r = compare();
  EXPECT_FALSE(r.same_machine);
  EXPECT_EQ(with_status(r, CheckStatus::Slower).size(), 2U);
  EXPECT_EQ(r.regressions, 0U);
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_NE(r.warnings[0].find("mhz_per_cpu"), std::string::npos) << r.warnings[0];
  EXPECT_NE(format_compare_table(r).find("(informational)"), std::string::npos);
  // ... unless strict.
  CompareOptions strict = options();
  strict.strict_speed = true;
  EXPECT_EQ(compare(strict).regressions, 2U);
  // x0.5: faster, fine.
  write_file(new_ + "/bench.json", bench_json(0.5, "vm", 2100));
  r = compare();
  EXPECT_EQ(with_status(r, CheckStatus::Faster).size(), 2U);
  EXPECT_EQ(r.regressions, 0U);
}

TEST_F(CompareTest, DifferentCpuModelInManifestIsAnotherMachine) {
  json m = json::parse(read_file(new_ + "/manifest.json"));
  m["cpu_model"] = "Some Other CPU";
  m["wall_s"] = m["wall_s"].get<double>() * 3.0;  // 3x slower sweep
  write_file(new_ + "/manifest.json", m.dump(2));
  CompareReport r = compare();
  EXPECT_FALSE(r.same_machine);
  EXPECT_EQ(r.regressions, 0U) << format_compare_table(r);
  const auto slower = with_status(r, CheckStatus::Slower);
  ASSERT_EQ(slower.size(), 1U);
  EXPECT_EQ(slower[0].name, "sweep");
  EXPECT_NEAR(*slower[0].ratio, 3.0, 1e-9);
  CompareOptions strict = options();
  strict.strict_speed = true;
  EXPECT_EQ(compare(strict).regressions, 1U);
}

/// The sweep throughput check of a report (a test failure when there is none).
CompareCheck sweep_speed_check(const CompareReport& r) {
  for (const auto& k : r.checks) {
    if (k.kind == "speed" && k.name == "sweep") return k;
  }
  ADD_FAILURE() << "no sweep throughput check";
  return {};
}

TEST_F(CompareTest, ShortSweepsAreNotJudgedOnThroughput) {
  json m = json::parse(read_file(new_ + "/manifest.json"));
  m["wall_s"] = m["wall_s"].get<double>() * 3.0;  // 3x slower sweep on the same machine
  write_file(new_ + "/manifest.json", m.dump(2));
  EXPECT_EQ(compare().regressions, 1U);  // judged: the fixture's options judge any length
  CompareOptions defaults;
  const double base_wall = json::parse(read_file(base_ + "/manifest.json"))["wall_s"].get<double>();
  ASSERT_LT(base_wall, defaults.min_judged_sweep_wall_s);
  const CompareReport r = compare(defaults);
  EXPECT_EQ(r.regressions, 0U) << format_compare_table(r);
  const CompareCheck sweep = sweep_speed_check(r);
  EXPECT_EQ(sweep.status, CheckStatus::NotJudged);
  EXPECT_FALSE(sweep.failure);
  ASSERT_TRUE(sweep.ratio.has_value());
  EXPECT_NEAR(*sweep.ratio, 3.0, 1e-9);  // still shown
  ASSERT_FALSE(r.notes.empty());
  EXPECT_NE(r.notes.back().find("below the 10 s that are judged on speed"), std::string::npos)
      << r.notes.back();
  // Strict speed does not judge noise either: the minimum is about what a timing can say.
  defaults.strict_speed = true;
  EXPECT_EQ(compare(defaults).regressions, 0U);
}

TEST_F(CompareTest, MergedShardsHaveNoSweepThroughput) {
  // fsweep merge's manifest: the longest shard's wall time for runs of several processes.
  json m = json::parse(read_file(new_ + "/manifest.json"));
  m["shard"] = {{"index", 0}, {"count", 1}, {"merged_from", 4}};
  m["wall_s"] = m["wall_s"].get<double>() * 10.0;
  write_file(new_ + "/manifest.json", m.dump(2));
  const CompareReport r = compare();
  EXPECT_EQ(r.regressions, 0U) << format_compare_table(r);
  const CompareCheck sweep = sweep_speed_check(r);
  EXPECT_EQ(sweep.status, CheckStatus::NotJudged);
  EXPECT_TRUE(sweep.current.empty());
}

TEST_F(CompareTest, BadInputIsAConfigErrorNamingTheFile) {
  fs::remove(new_ + "/manifest.json");
  try {
    (void)compare();
    FAIL() << "no error";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find(new_ + "/manifest.json"), std::string::npos) << e.what();
  }
  fs::copy(base_ + "/manifest.json", new_ + "/manifest.json");
  std::string runs = read_file(new_ + "/runs.csv");
  runs.insert(runs.find('\n') + 1, "1,2\n");  // record 2 (line 2) with too few fields
  write_file(new_ + "/runs.csv", runs);
  try {
    (void)compare();
    FAIL() << "no error";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find(new_ + "/runs.csv:2"), std::string::npos) << e.what();
  }
  write_file(new_ + "/runs.csv", read_file(base_ + "/runs.csv"));
  write_file(new_ + "/bench.json", "{\"benchmarks\": [");
  EXPECT_THROW((void)compare(), ConfigError);
  write_file(new_ + "/bench.json", bench_json(1.0, "vm", 1, "minutes"));
  try {
    (void)compare();
    FAIL() << "no error";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("time_unit"), std::string::npos) << e.what();
  }
  EXPECT_THROW((void)compare_dirs(root_ + "/nowhere", base_, {}), ConfigError);
}

TEST_F(CompareTest, MissingSummaryIsAggregatedFirst) {
  fs::remove(base_ + "/summary.csv");
  const CompareReport r = compare();
  EXPECT_TRUE(fs::exists(base_ + "/summary.csv"));
  ASSERT_FALSE(r.notes.empty());
  EXPECT_NE(r.notes.back().find(base_ + " has no summary.csv"), std::string::npos) << r.notes.back();
  for (const auto& c : r.configs) {
    ASSERT_EQ(c.baseline_box.size(), 3U);
    ASSERT_TRUE(c.baseline_box[0].has_value()) << c.name;
    EXPECT_LE(c.baseline_box[0]->q05, c.baseline_box[0]->median);
    EXPECT_LE(c.baseline_box[0]->median, c.baseline_box[0]->q95);
  }
}

TEST_F(CompareTest, WithoutSummaryAndProgressTheBoxesAreLeftOut) {
  fs::remove(base_ + "/summary.csv");
  fs::remove(base_ + "/progress.csv");
  const CompareReport r = compare();
  EXPECT_FALSE(fs::exists(base_ + "/summary.csv"));
  EXPECT_EQ(r.regressions, 0U);
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_NE(r.warnings.back().find("box plots are left out"), std::string::npos) << r.warnings.back();
  for (const auto& c : r.configs) {
    EXPECT_EQ(c.status, CheckStatus::Match);
    EXPECT_FALSE(c.baseline_box[0].has_value());
    EXPECT_TRUE(c.new_box[0].has_value());
  }
}

TEST_F(CompareTest, OutputsAreWritten) {
  write_file(base_ + "/bench.json", bench_json(1.0, "vm", 2100));
  write_file(new_ + "/bench.json", bench_json(2.0, "vm", 2100));
  fs::create_directories(base_ + "/plots");
  write_file(base_ + "/plots/progress.png", "Ma");  // base64 "TWE="
  const CompareReport r = compare();
  const std::string out = root_ + "/out";
  write_compare_outputs(r, out);
  const std::string csv = read_file(out + "/compare.csv");
  EXPECT_EQ(csv.rfind("kind,name,metric,baseline,new,delta,ratio,tolerance,p_value,status,failure\n", 0), 0U);
  EXPECT_NE(csv.find("bench,BM_A,real_time_ns,1100,2200,,2,0.5,,slower,yes"), std::string::npos) << csv;
  const std::string html = read_file(out + "/compare.html");
  EXPECT_NE(html.find("<svg"), std::string::npos);
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_NE(html.find("data:image/png;base64,TWE="), std::string::npos);
  EXPECT_NE(html.find("2 regressions"), std::string::npos);
  EXPECT_FALSE(fs::exists(out + "/compare.csv.tmp"));
}

TEST(PlannerReproducible, FollowsThePlannerTable) {
  const std::map<std::string, std::string> none;
  const std::map<std::string, std::string> iterations{{"max_iterations", "2000"}, {"time_limit_s", "2"}};
  const std::map<std::string, std::string> unset{{"max_iterations", ""}};
  for (const char* grid : {"astar", "dijkstra", "lattice", "lattice_astar", "shortest_fewest_turns"}) {
    EXPECT_TRUE(planner_reproducible(grid, none)) << grid;
  }
  for (const char* anytime : {"ompl:RRTConnect", "ompl:KPIECE1", "ompl:RRTstar", "ompl:InformedRRTstar",
                              "ompl:BITstar", "ompl:LazyPRMstar"}) {
    EXPECT_FALSE(planner_reproducible(anytime, none)) << anytime;
    EXPECT_FALSE(planner_reproducible(anytime, unset)) << anytime;
    EXPECT_FALSE(planner_reproducible(anytime, {{"max_iterations", "0"}})) << anytime;
    EXPECT_TRUE(planner_reproducible(anytime, iterations)) << anytime;
  }
  EXPECT_FALSE(planner_reproducible("ompl:PRMstar", none));
  EXPECT_FALSE(planner_reproducible("ompl:PRMstar", iterations));
  EXPECT_FALSE(planner_reproducible("ompl:FMT", iterations));
  EXPECT_FALSE(planner_reproducible("no_such_planner", none));
}

}  // namespace
}  // namespace fsweep
