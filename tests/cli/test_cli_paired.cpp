// `fsweep paired` end to end: on the default sweep, paired.csv's differences and win/tie/loss
// counts against a recomputation from runs.csv written here; on an exact weight search, the mean
// difference against the objectives of search_ranks.csv and search_best.csv; on a hand-written
// directory, the counts of unpaired runs and mixed ends; and the refusals.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "cli/fsweep_process.hpp"
#include "core/csv_reader.hpp"

namespace paired_cli_test {

using fsweep::CsvReader;
using fsweep::testing::CliOutcome;
using fsweep::testing::fresh_temp_dir;
using fsweep::testing::run_fsweep;

/// A CSV file as rows of column -> cell.
std::vector<std::map<std::string, std::string>> read_rows(const std::string& path) {
  CsvReader in(path);
  std::vector<std::map<std::string, std::string>> rows;
  while (in.next()) {
    auto& row = rows.emplace_back();
    for (std::size_t c = 0; c < in.header().size(); ++c) row[in.header()[c]] = in.fields()[c];
  }
  return rows;
}

/// The default sweep's results (90 runs).
std::string default_sweep_dir() {
  const std::string out = fresh_temp_dir("paired", "default");
  const CliOutcome r = run_fsweep("run sweeps/default.json --quiet --out " + out, FSWEEP_SOURCE_DIR);
  EXPECT_EQ(r.code, 0) << r.output;
  return out;
}

TEST(CliPaired, DefaultSweepMatchesARecomputationFromRunsCsv) {
  const std::string dir = default_sweep_dir();
  const CliOutcome r = run_fsweep("paired " + dir + " --baseline CF");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("map class rooms"), std::string::npos) << r.output;
  // The recomputation: pairs by map class, map instance and seed (the default sweep varies only
  // the strategy besides them); differences side - CF; better is lower but for area_per_metre.
  const auto runs = read_rows(dir + "/runs.csv");
  std::map<std::string, const std::map<std::string, std::string>*> cf;
  for (const auto& run : runs) {
    if (run.at("strategy_label") == "CF")
      cf[run.at("map_class") + "|" + run.at("map") + "|" + run.at("seed")] = &run;
  }
  const auto paired = read_rows(dir + "/paired.csv");
  ASSERT_EQ(paired.size(), 2U * 2U * 3U);  // 2 classes x 2 sides x 3 metrics
  for (const auto& row : paired) {
    SCOPED_TRACE(row.at("map_class") + " " + row.at("label") + " " + row.at("metric"));
    EXPECT_EQ(row.at("baseline"), "CF");
    const std::string& metric = row.at("metric");
    std::vector<double> d;
    int wins = 0, ties = 0, losses = 0;
    for (const auto& run : runs) {
      if (run.at("strategy_label") != row.at("label") || run.at("map_class") != row.at("map_class")) continue;
      const auto& base = *cf.at(run.at("map_class") + "|" + run.at("map") + "|" + run.at("seed"));
      ASSERT_EQ(run.at("end_reason"), base.at("end_reason"));
      const double x = std::stod(run.at(metric));
      const double y = std::stod(base.at(metric));
      d.push_back(x - y);
      if (std::abs(x - y) <= 1e-9 * std::max(std::abs(x), std::abs(y))) {
        ++ties;
      } else if ((metric == "area_per_metre") == (x > y)) {
        ++wins;
      } else {
        ++losses;
      }
    }
    ASSERT_EQ(std::stoul(row.at("n_pairs")), d.size());
    double sum = 0;
    for (const double v : d) sum += v;
    std::sort(d.begin(), d.end());
    const double median = d.size() % 2 == 1 ? d[d.size() / 2] : (d[d.size() / 2 - 1] + d[d.size() / 2]) / 2;
    EXPECT_NEAR(std::stod(row.at("mean_diff")), sum / static_cast<double>(d.size()), 1e-9 * std::abs(sum));
    EXPECT_NEAR(std::stod(row.at("median_diff")), median, 1e-12 * std::max(1.0, std::abs(median)));
    EXPECT_EQ(std::stoi(row.at("wins")), wins);
    EXPECT_EQ(std::stoi(row.at("ties")), ties);
    EXPECT_EQ(std::stoi(row.at("losses")), losses);
    EXPECT_EQ(row.at("instances"), "5");
    EXPECT_EQ(row.at("unpaired"), "0");
    EXPECT_EQ(row.at("mixed_end"), "0");
    // The interval holds the mean; the p-value is a probability.
    EXPECT_LE(std::stod(row.at("ci95_lo")), std::stod(row.at("mean_diff")));
    EXPECT_GE(std::stod(row.at("ci95_hi")), std::stod(row.at("mean_diff")));
    EXPECT_GE(std::stod(row.at("wilcoxon_p_holm")), std::stod(row.at("wilcoxon_p")));
    EXPECT_EQ(row.at("wilcoxon_method"), "exact");
  }
  const std::string json = fsweep::testing::read_all(dir + "/paired.json");
  EXPECT_NE(json.find("\"resamples\": 10000"), std::string::npos) << json;
}

/// A hand-written directory of A and B on 6 maps x 2 seeds, B's distances off A's by varied amounts.
std::string varied_dir() {
  const std::string dir = fresh_temp_dir("paired", "varied");
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/manifest.json") << R"({"sweep": {"strategies": [{"name": "x", "label": "A"}]}})";
  std::ofstream runs(dir + "/runs.csv");
  runs << "run_index,run_key,map_class,strategy_label,map,strategy,seed,end_reason,end_detail,distance_m\n";
  int index = 0;
  for (int map = 0; map < 6; ++map) {
    for (int seed = 0; seed < 2; ++seed) {
      const double a = 100 + 10 * map + seed;
      const double b = a + ((map * 7 + seed * 3) % 11) - 4;
      runs << index << ",a" << index << ",c,A,m" << map << ",x," << seed << ",complete,," << a << "\n";
      ++index;
      runs << index << ",b" << index << ",c,B,m" << map << ",x," << seed << ",complete,," << b << "\n";
      ++index;
    }
  }
  return dir;
}

TEST(CliPaired, IsAPureFunctionOfTheFilesAndTheSeed) {
  const std::string dir = varied_dir();
  const std::string a = fresh_temp_dir("paired", "seed_a");
  const std::string b = fresh_temp_dir("paired", "seed_b");
  const std::string args = "paired " + dir + " --metric distance_m --resamples 500 ";
  ASSERT_EQ(run_fsweep(args + "--seed 7 --out " + a).code, 0);
  ASSERT_EQ(run_fsweep(args + "--seed 7 --out " + b).code, 0);
  EXPECT_EQ(fsweep::testing::read_all(a + "/paired.csv"), fsweep::testing::read_all(b + "/paired.csv"));
  ASSERT_EQ(run_fsweep(args + "--seed 8 --out " + b).code, 0);
  EXPECT_NE(fsweep::testing::read_all(a + "/paired.csv"), fsweep::testing::read_all(b + "/paired.csv"));
  EXPECT_EQ(read_rows(a + "/paired.csv").at(0).at("instances"), "6");
}

TEST(CliPaired, RefusesWhatItCannotCompare) {
  const std::string dir = varied_dir();
  CliOutcome r = run_fsweep("paired " + dir + " --baseline nobody");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("--baseline: no side 'nobody' in the results; sides: A, B"), std::string::npos)
      << r.output;
  r = run_fsweep("paired " + dir + " --metric speed");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("--metric: 'speed' is not a metric column"), std::string::npos) << r.output;
  r = run_fsweep("paired " + dir + " --metric distance_m --metric distance_m");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("--metric: 'distance_m' is given twice"), std::string::npos) << r.output;
  r = run_fsweep("paired " + dir + "/nothing-here");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("not a directory"), std::string::npos) << r.output;
  const std::string sim = fresh_temp_dir("paired", "sim_out");
  std::filesystem::create_directories(sim);
  std::ofstream(sim + "/run.csv") << "x\n";
  r = run_fsweep("paired " + dir + " --out " + sim);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("holds the output of fsweep sim"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(sim + "/paired.csv"));
  r = run_fsweep("paired " + dir + " --resamples 0");
  EXPECT_EQ(r.code, 2) << r.output;
}

/// A directory with a hand-written runs.csv: A and B on two maps x two seeds; one of B's runs is
/// missing (its A run is unpaired), and one pair ended differently; on a third map, A's distance
/// is infinite (no value for distance_m).
std::string handwritten_dir() {
  const std::string dir = fresh_temp_dir("paired", "hand");
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/manifest.json") << R"({"sweep": {"strategies": [{"name": "x", "label": "A"}]}})";
  std::ofstream(dir + "/runs.csv") << "run_index,run_key,map_class,strategy_label,map,strategy,seed,end_"
                                      "reason,end_detail,distance_m,coverage\n"
                                      "0,a0,c,A,m1,x,1,complete,,10,1\n"
                                      "1,b0,c,B,m1,x,1,complete,,12,1\n"
                                      "2,a1,c,A,m1,x,2,complete,,10,1\n"
                                      "3,b1,c,B,m1,x,2,range_limited,,8,0.5\n"
                                      "4,a2,c,A,m2,x,1,complete,,20,1\n"
                                      "5,b2,c,B,m2,x,1,complete,,20,1\n"
                                      "6,a3,c,A,m2,x,2,complete,,30,0.9\n"
                                      "7,a4,c,A,m3,x,1,complete,,inf,1\n"
                                      "8,b4,c,B,m3,x,1,complete,,5,1\n";
  return dir;
}

TEST(CliPaired, CountsUnpairedRunsAndMixedEndsAndLeavesThemOut) {
  const std::string dir = handwritten_dir();
  const CliOutcome r = run_fsweep("paired " + dir + " --metric distance_m --metric coverage");
  ASSERT_EQ(r.code, 0) << r.output;  // the baseline: the manifest's first strategy entry, A
  const auto rows = read_rows(dir + "/paired.csv");
  ASSERT_EQ(rows.size(), 2U);
  for (const auto& row : rows) {
    EXPECT_EQ(row.at("label"), "B");
    EXPECT_EQ(row.at("baseline"), "A");
    EXPECT_EQ(row.at("unpaired"), "1");
    EXPECT_EQ(row.at("mixed_end"), "1");
  }
  EXPECT_EQ(rows[0].at("n_pairs"), "2");
  EXPECT_EQ(rows[0].at("no_value"), "1");
  EXPECT_EQ(rows[0].at("instances"), "2");
  EXPECT_EQ(rows[1].at("n_pairs"), "3");  // coverage has a value on m3
  EXPECT_EQ(rows[1].at("no_value"), "0");
  EXPECT_EQ(rows[1].at("instances"), "3");
  EXPECT_EQ(rows[0].at("metric"), "distance_m");
  EXPECT_EQ(rows[0].at("mean_diff"), "1");  // (12 - 10 + 20 - 20) / 2
  EXPECT_EQ(rows[0].at("wins"), "0");
  EXPECT_EQ(rows[0].at("ties"), "1");
  EXPECT_EQ(rows[0].at("losses"), "1");
  EXPECT_EQ(rows[0].at("rel_diff_pct"), "10");  // median of 20% and 0%
  EXPECT_EQ(rows[1].at("metric"), "coverage");
  EXPECT_EQ(rows[1].at("ties"), "3");
  EXPECT_EQ(rows[1].at("wilcoxon_method"), "none");
  EXPECT_EQ(rows[1].at("wilcoxon_p"), "1");
}

TEST(CliPaired, ALabelOfSeveralConfigurationsNamesThem) {
  const std::string dir = fresh_temp_dir("paired", "grid");
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/manifest.json") << R"({"sweep": {}})";
  std::ofstream(dir + "/runs.csv")
      << "run_index,run_key,map_class,strategy_label,map,strategy,strategy.w1,strategy.w2,seed,end_reason,"
         "end_detail,distance_m\n"
         "0,a,c,grid,m,e,1,0,1,complete,,10\n"
         "1,b,c,grid,m,e,2,0,1,complete,,12\n"
         "2,c,c,CF,m,f,,,1,complete,,11\n";
  CliOutcome r = run_fsweep("paired " + dir + " --baseline grid");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("label 'grid' holds 2 strategy configurations; name one: grid w1=1, grid w1=2"),
            std::string::npos)
      << r.output;
  r = run_fsweep("paired " + dir + " --baseline 'grid w1=2' --metric distance_m");
  ASSERT_EQ(r.code, 0) << r.output;
  const auto rows = read_rows(dir + "/paired.csv");
  ASSERT_EQ(rows.size(), 2U);
  EXPECT_EQ(rows[0].at("label"), "grid w1=1");
  EXPECT_EQ(rows[0].at("mean_diff"), "-2");
  EXPECT_EQ(rows[1].at("label"), "CF");
  EXPECT_EQ(rows[1].at("ci95_lo"), "");  // one map instance: no interval
}

TEST(CliPaired, WeightSearchVectorsAgainstTheOptimumByInstance) {
  const std::string dir = fresh_temp_dir("paired", "search");
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/search.json") << R"({"schema_version": 1, "name": "paired_search",
    "maps": [{"generator": "rooms", "w": 40, "h": 30, "res": 0.5, "label": "rooms", "seeds": {"range": [1, 3], "step": 1}}],
    "strategies": [{"name": "energy_aware", "label": "exact", "search": {"mode": "all", "rank": [[1, 0, 0, 0], [3, 0, 2, 3]]},
                    "params": {"w1": [1, 3], "w2": [0], "w3": [0, 2], "w4": [0, 3]}}],
    "robot": {"sensor": {"range_m": 5}, "energy": "distance", "battery": 200}, "seed": 3})";
  ASSERT_EQ(run_fsweep("run " + dir + "/search.json --quiet --out " + dir + "/out").code, 0);
  const CliOutcome r = run_fsweep("paired " + dir + "/out --metric distance_to_final_coverage_m");
  ASSERT_EQ(r.code, 0) << r.output;
  // A behaviour's objective is the mean over the instances of distance_to_final_coverage_m, so a
  // vector's mean difference from the optimum is the difference of their objectives.
  double best = 0;
  for (const auto& row : read_rows(dir + "/out/search_best.csv")) {
    if (row.at("rank") == "1") best = std::stod(row.at("objective"));
  }
  std::map<std::string, double> objective;
  for (const auto& row : read_rows(dir + "/out/search_ranks.csv")) {
    objective["exact@" + row.at("w1") + "," + row.at("w2") + "," + row.at("w3") + "," + row.at("w4")] =
        std::stod(row.at("objective"));
  }
  const auto rows = read_rows(dir + "/out/paired.csv");
  ASSERT_EQ(rows.size(), 2U) << r.output;
  for (const auto& row : rows) {
    EXPECT_EQ(row.at("source"), "search 0");
    EXPECT_EQ(row.at("baseline"), "exact@best");
    EXPECT_EQ(row.at("n_pairs"), "3");
    ASSERT_TRUE(objective.count(row.at("label"))) << row.at("label");
    EXPECT_NEAR(std::stod(row.at("mean_diff")), objective[row.at("label")] - best, 1e-9 * best);
  }
}

TEST(CliPaired, CurvesAddTheCoverageCurveAnalysisOfEachLabel) {
  if (std::system("/usr/bin/python3 -c 'import matplotlib' >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "no matplotlib";
  const std::string dir = fresh_temp_dir("paired", "curves");
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/mei.json") << R"({"schema_version": 1, "name": "curves",
    "maps": [{"generator": "rooms", "w": 40, "h": 30, "label": "rooms", "seeds": {"range": [1, 3], "step": 1}}],
    "strategies": [{"name": "widest_frontier", "label": "widest"}, {"name": "orientation", "label": "orientation"}],
    "baseline": "widest", "planners": ["lattice"], "robot": {"sensor": {"range_m": 6}, "energy": "mei2006"},
    "progress_step_m": 2, "seed": 5})";
  ASSERT_EQ(run_fsweep("run " + dir + "/mei.json --quiet --out " + dir + "/out").code, 0);
  const CliOutcome r = run_fsweep("paired " + dir + "/out --curves");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("A = orientation, B = widest; 3 pairs"), std::string::npos) << r.output;
  for (const char* f : {"paired.csv", "paired_curves_orientation_pairs.csv",
                        "paired_curves_orientation_summary.csv", "paired_curves_orientation_rooms.png"}) {
    EXPECT_TRUE(std::filesystem::exists(dir + "/out/" + f)) << f;
  }
}

}  // namespace paired_cli_test
