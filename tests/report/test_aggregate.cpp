// summary.csv, progress_summary.csv and best.csv against hand-computed values, and the CSV
// reader's handling of quoting and malformed files.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <stdexcept>

#include "core/config_error.hpp"
#include "core/config_error_message.hpp"
#include "core/csv_reader.hpp"
#include "report/aggregate.hpp"
#include "report/aggregate_fixture.hpp"

namespace fsweep {
namespace {

using testing::make_sweep_dir;
using testing::write_text;
using Row = std::map<std::string, std::string>;

std::vector<Row> read_rows(const std::filesystem::path& path) {
  CsvReader in(path.string());
  std::vector<Row> rows;
  while (in.next()) {
    Row& row = rows.emplace_back();
    for (std::size_t i = 0; i < in.header().size(); ++i) row[in.header()[i]] = in.fields()[i];
  }
  return rows;
}

double num(const Row& row, const std::string& column) {
  const auto it = row.find(column);
  if (it == row.end()) throw std::runtime_error("no column " + column);
  return std::stod(it->second);
}

std::vector<std::string> best_order(const std::filesystem::path& dir, const std::string& objective) {
  aggregate(dir.string(), AggregateOptions{objective});
  std::vector<std::string> ids;
  for (const auto& row : read_rows(dir / "best.csv")) ids.push_back(row.at("config_id"));
  return ids;
}

using testing::config_error;

TEST(Summary, GroupsRunsByConfigurationIgnoringSeed) {
  const auto dir = make_sweep_dir("group");
  aggregate(dir.string(), {});
  const auto rows = read_rows(dir / "summary.csv");
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].at("config_id"), "0");
  EXPECT_EQ(rows[0].at("strategy.w1"), "10");
  EXPECT_EQ(rows[0].at("n"), "4");
  EXPECT_EQ(rows[1].at("strategy.w1"), "20");
  EXPECT_EQ(rows[1].at("n"), "2");
  EXPECT_EQ(rows[2].at("map_class"), "rooms");
  // Row 4 ran on another map instance (seed=7) of class "free": pooled into configuration 0.
  EXPECT_EQ(rows[0].count("map"), 0U);
  EXPECT_EQ(rows[2].at("strategy"), "closest_frontier");
  EXPECT_EQ(rows[2].at("strategy.w1"), "");
  EXPECT_EQ(rows[2].at("n"), "1");
  for (const char* gone : {"seed", "run_index", "run_key", "end_reason", "end_detail", "distance_m"}) {
    EXPECT_EQ(rows[0].count(gone), 0u) << gone;
  }
  std::filesystem::remove_all(dir);
}

TEST(Summary, CountsDistinctRunsBesideN) {
  // Configuration 0: the same map instance three times with the same outcome (only the seed and the
  // wall time differ: repetitions with nothing random), and once on another map. Configuration 1:
  // two seeds with different outcomes.
  const auto dir = make_sweep_dir("distinct");
  write_text(
      dir / "runs.csv",
      "run_index,run_key,map_class,map,strategy,seed,end_reason,end_detail,distance_m,energy,wall_time_s\n"
      "0,k0,c,m1,a,1,complete,,5,5,0.1\n"
      "1,k1,c,m1,a,2,complete,,5,5,0.3\n"
      "2,k2,c,m1,a,3,complete,,5,5,0.2\n"
      "3,k3,c,m2,a,1,complete,,5,5,0.2\n"
      "4,k4,c,m1,b,1,complete,,5,5,0.1\n"
      "5,k5,c,m1,b,2,range_limited,,5,5,0.1\n");
  write_text(dir / "progress.csv", "run_index,run_key,distance_m,explored_area_m2,coverage,energy\n");
  aggregate(dir.string(), AggregateOptions{"energy"});
  const auto rows = read_rows(dir / "summary.csv");
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].at("n"), "4");
  EXPECT_EQ(rows[0].at("n_distinct"), "2");
  EXPECT_EQ(rows[1].at("n"), "2");
  EXPECT_EQ(rows[1].at("n_distinct"), "2");
  std::filesystem::remove_all(dir);
}

// Config 0's distances are 1, 2, 3, 4: mean 2.5, std sqrt(5/3) (squares 2.25 + 0.25 + 0.25 +
// 2.25 over n - 1 = 3), quantiles as in Quantile.Type7MatchesHandComputation.
TEST(Summary, StatisticsMatchHandComputation) {
  const auto dir = make_sweep_dir("stats");
  aggregate(dir.string(), {});
  const auto rows = read_rows(dir / "summary.csv");
  const Row& a = rows[0];
  EXPECT_DOUBLE_EQ(num(a, "distance_m.mean"), 2.5);
  EXPECT_NEAR(num(a, "distance_m.std"), std::sqrt(5.0 / 3.0), 1e-12);
  EXPECT_EQ(num(a, "distance_m.min"), 1.0);
  EXPECT_NEAR(num(a, "distance_m.q05"), 1.15, 1e-12);
  EXPECT_NEAR(num(a, "distance_m.q25"), 1.75, 1e-12);
  EXPECT_NEAR(num(a, "distance_m.median"), 2.5, 1e-12);
  EXPECT_NEAR(num(a, "distance_m.q75"), 3.25, 1e-12);
  EXPECT_NEAR(num(a, "distance_m.q95"), 3.85, 1e-12);
  EXPECT_EQ(num(a, "distance_m.max"), 4.0);
  // Two runs: energies 50 and 10 -> mean 30, std sqrt(800), q05 = 10 + 0.05 * 40 = 12.
  const Row& b = rows[1];
  EXPECT_DOUBLE_EQ(num(b, "energy.mean"), 30.0);
  EXPECT_NEAR(num(b, "energy.std"), std::sqrt(800.0), 1e-12);
  EXPECT_NEAR(num(b, "energy.q05"), 12.0, 1e-12);
  // One run: std 0, every quantile the value.
  const Row& c = rows[2];
  EXPECT_EQ(num(c, "energy.std"), 0.0);
  EXPECT_EQ(num(c, "energy.q05"), 25.0);
  EXPECT_EQ(num(c, "energy.max"), 25.0);
  std::filesystem::remove_all(dir);
}

TEST(Summary, EmptyCellsAreSkipped) {
  const auto dir = make_sweep_dir("empty");
  aggregate(dir.string(), {});
  const auto rows = read_rows(dir / "summary.csv");
  EXPECT_EQ(rows[2].at("competitive_ratio.mean"), "");
  EXPECT_EQ(rows[2].at("competitive_ratio.median"), "");
  EXPECT_DOUBLE_EQ(num(rows[0], "competitive_ratio.median"), 1.25);
  std::filesystem::remove_all(dir);
}

// Config 0's coverages 1, 1, 0.5 and "nan": the NaN is no value, mean (1 + 1 + 0.5) / 3.
TEST(Summary, NanCellsAreSkipped) {
  const auto dir = make_sweep_dir("nan_cell");
  std::string runs = testing::kRunsCsv;
  runs.replace(runs.find(",12.5,1,2,2\n"), 12, ",12.5,nan,2,2\n");
  write_text(dir / "runs.csv", runs);
  aggregate(dir.string(), {});
  const auto rows = read_rows(dir / "summary.csv");
  EXPECT_EQ(rows[0].at("n"), "4");
  EXPECT_NEAR(num(rows[0], "coverage.mean"), 2.5 / 3.0, 1e-12);
  EXPECT_EQ(num(rows[0], "coverage.min"), 0.5);
  std::filesystem::remove_all(dir);
}

TEST(Summary, CountsEndReasons) {
  const auto dir = make_sweep_dir("ends");
  aggregate(dir.string(), {});
  const auto rows = read_rows(dir / "summary.csv");
  EXPECT_EQ(rows[0].at("end.complete"), "3");
  EXPECT_EQ(rows[0].at("end.range_limited"), "1");
  EXPECT_EQ(rows[0].at("end.error"), "0");
  EXPECT_EQ(rows[1].at("end.stuck"), "1");
  EXPECT_EQ(rows[1].at("end.complete"), "1");
  EXPECT_EQ(rows[2].at("end.error"), "1");
  for (const char* every : {"end.target_reached", "end.step_limit", "end.battery_depleted"}) {
    EXPECT_EQ(rows[0].at(every), "0") << every;
  }
  std::filesystem::remove_all(dir);
}

// Medians: distance to final coverage 2.5 / 2 / 0; area per metre 14.25 / 5.8 / 0 (larger is
// better); energy 25 / 30 / 25 (configs 0 and 2 tie: configuration order).
TEST(Best, RanksByEachObjectivesMedian) {
  const auto dir = make_sweep_dir("best");
  EXPECT_EQ(best_order(dir, "distance_to_final_coverage_m"), (std::vector<std::string>{"2", "1", "0"}));
  EXPECT_EQ(best_order(dir, "area_per_metre"), (std::vector<std::string>{"0", "1", "2"}));
  EXPECT_EQ(best_order(dir, "energy"), (std::vector<std::string>{"0", "2", "1"}));
  const auto rows = read_rows(dir / "best.csv");
  EXPECT_EQ(rows[0].at("rank"), "1");
  EXPECT_EQ(rows[0].at("n"), "4");
  EXPECT_DOUBLE_EQ(num(rows[0], "energy.median"), 25.0);
  EXPECT_NEAR(num(rows[0], "energy.q05"), 11.5, 1e-12);
  EXPECT_NEAR(num(rows[0], "energy.q95"), 38.5, 1e-12);
  EXPECT_EQ(rows[0].at("strategy.w1"), "10");
  std::filesystem::remove_all(dir);
}

TEST(Best, RunsThatNeverReachTheCoverageTargetRankAsTheWorst) {
  // distance_to_coverage_target_m: w1=10 reached it once in three runs (median: a run without a
  // value, so no median, ranked last); w1=20 twice (8.5); w1=30 two runs of three (median 7).
  const auto dir = make_sweep_dir("coverage_target");
  write_text(dir / "runs.csv",
             "run_index,run_key,map_class,map,strategy,strategy.w1,seed,end_reason,end_detail,distance_m,"
             "distance_to_coverage_target_m,optimal_distance_m,competitive_ratio\n"
             "0,00000000000000a0,free,free,energy_aware,10,1,target_reached,,5,5,,\n"
             "1,00000000000000a1,free,free,energy_aware,10,2,range_limited,,3,,,\n"
             "2,00000000000000a2,free,free,energy_aware,10,3,range_limited,,4,,,\n"
             "3,00000000000000b0,free,free,energy_aware,20,1,target_reached,,8,8,,\n"
             "4,00000000000000b1,free,free,energy_aware,20,2,target_reached,,9,9,,\n"
             "5,00000000000000c0,free,free,energy_aware,30,1,target_reached,,7,7,,\n"
             "6,00000000000000c1,free,free,energy_aware,30,2,stuck,,2,,,\n"
             "7,00000000000000c2,free,free,energy_aware,30,3,target_reached,,6,6,,\n");
  write_text(dir / "progress.csv", "run_index,run_key,distance_m,explored_area_m2,coverage,energy\n");
  EXPECT_EQ(best_order(dir, "distance_to_coverage_target_m"), (std::vector<std::string>{"2", "1", "0"}));
  const auto rows = read_rows(dir / "best.csv");
  EXPECT_DOUBLE_EQ(num(rows[0], "distance_to_coverage_target_m.median"), 7.0);
  EXPECT_EQ(rows[0].at("n"), "3");
  EXPECT_EQ(rows[0].at("distance_to_coverage_target_m.q95"), "") << "the worst 5% never reached it";
  EXPECT_DOUBLE_EQ(num(rows[1], "distance_to_coverage_target_m.median"), 8.5);
  EXPECT_EQ(rows[2].at("distance_to_coverage_target_m.median"), "");
  std::filesystem::remove_all(dir);
}

TEST(Best, DefaultsToDistanceToFinalCoverageThenManifest) {
  const auto dir = make_sweep_dir("manifest");
  EXPECT_EQ(best_order(dir, ""), (std::vector<std::string>{"2", "1", "0"}));
  write_text(dir / "manifest.json",
             R"({"sweep": {"output": {"objective": "energy"}}, "objective": "energy"})");
  EXPECT_EQ(best_order(dir, ""), (std::vector<std::string>{"0", "2", "1"}));
  EXPECT_EQ(best_order(dir, "area_per_metre"), (std::vector<std::string>{"0", "1", "2"}));
  std::filesystem::remove_all(dir);
}

TEST(Best, UnknownObjectiveListsTheAllowedOnes) {
  const auto dir = make_sweep_dir("objective");
  const std::string msg = config_error([&] { aggregate(dir.string(), AggregateOptions{"speed"}); });
  EXPECT_NE(msg.find("speed"), std::string::npos) << msg;
  EXPECT_NE(msg.find("area_per_metre"), std::string::npos) << msg;
  std::filesystem::remove_all(dir);
}

/// progress_summary.csv rows of one configuration, keyed by distance text.
std::map<double, Row> bands_of(const std::filesystem::path& dir, const std::string& config_id) {
  std::map<double, Row> out;
  for (const auto& row : read_rows(dir / "progress_summary.csv")) {
    if (row.at("config_id") == config_id) out[num(row, "distance_m")] = row;
  }
  return out;
}

// Config 0 on the 0.75 m grid. Runs end at 1 (final area 22), 2 (32), 3 (35, on the grid) and 4
// (50); a run that ended before a bin counts with its final area. E.g. at 2.25 m: samples 34
// and 35, ended runs 22 and 32 -> {22, 32, 34, 35}: mean 30.75, q05 = 22 + 0.15 * 10 = 23.5,
// q50 = 33, q95 = 34 + 0.85 * 1 = 34.85. The closing bin at 4 m holds the final areas.
TEST(Progress, BandsCarryTheFinalAreaOfRunsThatEnded) {
  const auto dir = make_sweep_dir("progress");
  aggregate(dir.string(), {});
  const auto a = bands_of(dir, "0");
  struct Expected {
    double distance_m, mean, q05, q50, q95;
  };
  const std::vector<Expected> expected{
      {0.0, 10, 10, 10, 10},           {0.75, 20, 15.75, 20, 24.25},  {1.5, 26.75, 22.45, 27.5, 30},
      {2.25, 30.75, 23.5, 33, 34.85},  {3.0, 33.5, 23.5, 33.5, 43.5}, {3.75, 34.25, 23.5, 33.5, 46.05},
      {4.0, 34.75, 23.5, 33.5, 47.75},
  };
  ASSERT_EQ(a.size(), expected.size());
  for (const auto& e : expected) {
    ASSERT_EQ(a.count(e.distance_m), 1u) << e.distance_m;
    const Row& r = a.at(e.distance_m);
    EXPECT_EQ(r.at("n"), "4") << e.distance_m;
    EXPECT_NEAR(num(r, "explored_area_m2.mean"), e.mean, 1e-9) << e.distance_m;
    EXPECT_NEAR(num(r, "explored_area_m2.q05"), e.q05, 1e-9) << e.distance_m;
    EXPECT_NEAR(num(r, "explored_area_m2.q50"), e.q50, 1e-9) << e.distance_m;
    EXPECT_NEAR(num(r, "explored_area_m2.q95"), e.q95, 1e-9) << e.distance_m;
  }
  // Config 1 at 1.5 m: run b1's sample 12 and run b0's final 9 (it ended there on the grid).
  const auto b = bands_of(dir, "1");
  EXPECT_EQ(b.size(), 5u);  // 0, 0.75, 1.5, 2.25 and the closing 2.5
  EXPECT_DOUBLE_EQ(num(b.at(1.5), "explored_area_m2.mean"), 10.5);
  EXPECT_DOUBLE_EQ(num(b.at(2.5), "explored_area_m2.q50"), 11.5);
  // Config 2 never moved: one bin at 0 m with its only sample.
  const auto c = bands_of(dir, "2");
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(num(c.at(0.0), "explored_area_m2.mean"), 3.0);
  // The torn run 00000000000000d0 (no runs.csv row) is ignored: no 99 anywhere.
  for (const auto& [d, r] : a) EXPECT_LT(num(r, "explored_area_m2.q95"), 99.0);
  std::filesystem::remove_all(dir);
}

TEST(Malformed, ShortRowNamesFileAndLine) {
  const auto dir = make_sweep_dir("short");
  write_text(dir / "runs.csv",
             "run_index,run_key,map,strategy,seed,end_reason,end_detail,distance_m\n"
             "0,k0,free,closest_frontier,1,complete,,3\n"
             "1,k1,free,closest_frontier,2,complete\n");
  const std::string msg = config_error([&] { aggregate(dir.string(), AggregateOptions{"energy"}); });
  EXPECT_NE(msg.find("runs.csv:3"), std::string::npos) << msg;
  EXPECT_NE(msg.find("fields: expected 8, as many as the header"), std::string::npos) << msg;
  std::filesystem::remove_all(dir);
}

TEST(Malformed, NonNumericMetricNamesColumnAndLine) {
  const auto dir = make_sweep_dir("nan");
  std::string runs = testing::kRunsCsv;
  runs.replace(runs.find(",40,"), 4, ",forty,");
  write_text(dir / "runs.csv", runs);
  const std::string msg = config_error([&] { aggregate(dir.string(), {}); });
  EXPECT_NE(msg.find("runs.csv:8"), std::string::npos) << msg;
  EXPECT_NE(msg.find("energy"), std::string::npos) << msg;
  EXPECT_NE(msg.find("forty"), std::string::npos) << msg;
  std::filesystem::remove_all(dir);
}

TEST(Malformed, UnclosedQuoteAndTornLastLineNameFileAndLine) {
  const auto dir = make_sweep_dir("quote");
  write_text(dir / "progress.csv",
             "run_index,run_key,distance_m,explored_area_m2\n0,k0,0,1\n0,\"k0,0.75,2\n");
  std::string msg = config_error([&] { aggregate(dir.string(), {}); });
  EXPECT_NE(msg.find("progress.csv:3"), std::string::npos) << msg;
  EXPECT_NE(msg.find("that is never closed: expected a closing quote"), std::string::npos) << msg;
  std::string runs = testing::kRunsCsv;
  runs.pop_back();  // no final newline: a torn write
  write_text(dir / "runs.csv", runs);
  msg = config_error([&] { aggregate(dir.string(), {}); });
  EXPECT_NE(msg.find("runs.csv:8"), std::string::npos) << msg;
  EXPECT_NE(msg.find("newline"), std::string::npos) << msg;
  std::filesystem::remove_all(dir);
}

TEST(Malformed, MissingRunsCsvNamesTheFile) {
  const auto dir = make_sweep_dir("missing");
  std::filesystem::remove(dir / "runs.csv");
  const std::string msg = config_error([&] { aggregate(dir.string(), {}); });
  EXPECT_NE(msg.find("runs.csv"), std::string::npos) << msg;
  std::filesystem::remove_all(dir);
}

TEST(CsvReader, ReadsQuotedFieldsWithCommasQuotesAndNewlines) {
  const auto dir = make_sweep_dir("reader");
  write_text(dir / "q.csv", "a,b,c\r\n\"x,1\",\"say \"\"hi\"\"\",\"two\nlines\"\n,,\nplain,+2,-1e3\n");
  CsvReader in((dir / "q.csv").string());
  EXPECT_EQ(in.header(), (std::vector<std::string>{"a", "b", "c"}));
  ASSERT_TRUE(in.next());
  EXPECT_EQ(in.fields(), (std::vector<std::string>{"x,1", "say \"hi\"", "two\nlines"}));
  EXPECT_EQ(in.line(), 2u);
  ASSERT_TRUE(in.next());
  EXPECT_EQ(in.fields(), (std::vector<std::string>{"", "", ""}));
  EXPECT_EQ(in.line(), 4u);  // the quoted newline counts
  ASSERT_TRUE(in.next());
  EXPECT_EQ(parse_number(in.fields()[1]), 2.0);
  EXPECT_EQ(parse_number(in.fields()[2]), -1000.0);
  EXPECT_FALSE(parse_number(in.fields()[0]).has_value());
  EXPECT_FALSE(in.next());
  EXPECT_FALSE(parse_number("").has_value());
  EXPECT_FALSE(parse_number("1.5x").has_value());
  EXPECT_TRUE(std::isinf(*parse_number("inf")));
  std::filesystem::remove_all(dir);
}

TEST(CsvReader, QuoteInsideUnquotedFieldIsAnError) {
  const auto dir = make_sweep_dir("stray");
  write_text(dir / "q.csv", "a,b\n1,2\n3,x\"y\n");
  CsvReader in((dir / "q.csv").string());
  ASSERT_TRUE(in.next());
  const std::string msg = config_error([&] { (void)in.next(); });
  EXPECT_NE(msg.find("q.csv:3"), std::string::npos) << msg;
  std::filesystem::remove_all(dir);
}

TEST(CsvReader, DamageIsNamedWithFileLineAndWhatWasExpected) {
  const auto dir = make_sweep_dir("damaged");
  const auto message_for = [&](const std::string& text) {
    write_text(dir / "runs.csv", text);
    CsvReader in((dir / "runs.csv").string());
    return config_error([&] {
      while (in.next()) {
      }
    });
  };
  const std::string file = (dir / "runs.csv").string();
  const std::string cr = message_for("a,b\n1,2\n3,4\r5\n");
  EXPECT_EQ(
      cr.find(file + ":3: a carriage return (\\r) inside the line, not followed by a line feed: expected "
                     "each line to end with a line feed (\\n) or \\r\\n (the file is damaged"),
      0U)
      << cr;
  const std::string after_quote = message_for("a,b\n1,\"2\"x\n");
  EXPECT_EQ(
      after_quote.find(file + ":2: field 2 has 'x' after its closing quote: expected a comma or the end "
                              "of the line"),
      0U)
      << after_quote;
  const std::string unclosed = message_for("a,b\n1,2\n\"3,4\n");
  EXPECT_EQ(unclosed.find(file + ":3: field 1 opens a quote (\") that is never closed: expected a closing "
                                 "quote before the end of the file"),
            0U)
      << unclosed;
  const std::string fields = message_for("a,b\n1,2,3\n");
  EXPECT_EQ(fields.find(file + ":2: the line has 3 fields: expected 2, as many as the header"), 0U) << fields;
  const std::string one = message_for("a,b\n1,2\ngarbage\n");
  EXPECT_EQ(one.find(file + ":3: the line has 1 field: expected 2, as many as the header"), 0U) << one;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace fsweep
