// `fsweep aggregate` and `fsweep plot` end to end on a hand-written sweep directory
// (tests/sweep/aggregate_fixture.hpp).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "cli/fsweep_process.hpp"
#include "report/aggregate_fixture.hpp"

namespace {

using Outcome = fsweep::testing::CliOutcome;
Outcome fsweep_cli(const std::string& args) { return fsweep::testing::run_fsweep(args); }

std::string first_line_after_header(const std::filesystem::path& path) {
  std::ifstream f(path);
  std::string line;
  std::getline(f, line);
  std::getline(f, line);
  return line;
}

bool python_has_matplotlib() {
  return std::filesystem::exists("/usr/bin/python3") &&
         std::system("/usr/bin/python3 -c 'import matplotlib' >/dev/null 2>&1") == 0;
}

TEST(CliAggregate, WritesSummaryProgressAndBest) {
  const auto dir = fsweep::testing::make_sweep_dir("cli_aggregate");
  const Outcome r = fsweep_cli("aggregate " + dir.string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("3 configurations"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("config_id 2"), std::string::npos) << r.output;  // distance to final coverage 0
  for (const char* f : {"summary.csv", "progress_summary.csv", "best.csv"}) {
    EXPECT_TRUE(std::filesystem::exists(dir / f)) << f;
    EXPECT_FALSE(std::filesystem::exists(dir / (std::string(f) + ".tmp"))) << f;
  }
  EXPECT_EQ(first_line_after_header(dir / "best.csv").substr(0, 4), "1,2,");
  std::filesystem::remove_all(dir);
}

TEST(CliAggregate, ObjectiveOptionReranks) {
  const auto dir = fsweep::testing::make_sweep_dir("cli_objective");
  const Outcome r = fsweep_cli("aggregate " + dir.string() + " --objective area_per_metre");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_EQ(first_line_after_header(dir / "best.csv").substr(0, 4), "1,0,");
  std::filesystem::remove_all(dir);
}

TEST(CliAggregate, BadInputIsExit2NamingFileAndLine) {
  const auto dir = fsweep::testing::make_sweep_dir("cli_bad");
  fsweep::testing::write_text(dir / "runs.csv", "run_key,seed,end_reason,distance_m\nk0,1,complete\n");
  Outcome r = fsweep_cli("aggregate " + dir.string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("runs.csv:2"), std::string::npos) << r.output;
  r = fsweep_cli("aggregate " + dir.string() + " --objective speed");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("speed"), std::string::npos) << r.output;
  r = fsweep_cli("aggregate /nonexistent/sweep");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("/nonexistent/sweep/runs.csv"), std::string::npos) << r.output;
  std::filesystem::remove_all(dir);
}

TEST(CliPlot, DrawsProgressAndMetricsPngs) {
  if (!python_has_matplotlib()) GTEST_SKIP() << "/usr/bin/python3 has no matplotlib";
  const auto dir = fsweep::testing::make_sweep_dir("cli_plot");
  // No summary yet: plot aggregates first.
  const Outcome r = fsweep_cli("plot " + dir.string());
  ASSERT_EQ(r.code, 0) << r.output;
  for (const char* f : {"plots/progress.png", "plots/metrics.png", "summary.csv"}) {
    ASSERT_TRUE(std::filesystem::exists(dir / f)) << f;
    EXPECT_GT(std::filesystem::file_size(dir / f), 1000u) << f;
  }
  std::ifstream png(dir / "plots/progress.png", std::ios::binary);
  std::array<char, 4> magic{};
  png.read(magic.data(), magic.size());
  EXPECT_EQ(std::string(magic.data() + 1, 3), "PNG");
  // One weight varies: no heat map (needs two).
  EXPECT_FALSE(std::filesystem::exists(dir / "plots/heatmap_w1_w2.png"));
  std::filesystem::remove_all(dir);
}

TEST(CliPlot, HeatMapForTwoVaryingWeightsInOutDir) {
  if (!python_has_matplotlib()) GTEST_SKIP() << "/usr/bin/python3 has no matplotlib";
  const auto dir = fsweep::testing::make_sweep_dir("cli_heatmap");
  fsweep::testing::write_text(
      dir / "runs.csv",
      "run_index,run_key,map,strategy,strategy.w1,strategy.w2,seed,end_reason,end_detail,"
      "distance_m,energy,coverage,distance_to_final_coverage_m\n"
      "0,k0,free,energy_aware,0,0,1,complete,,10,10,1,9\n"
      "1,k1,free,energy_aware,0,5,1,complete,,12,12,1,11\n"
      "2,k2,free,energy_aware,0,10,1,complete,,14,14,1,13\n"
      "3,k3,free,energy_aware,5,0,1,complete,,14,14,1,13\n"
      "4,k4,free,energy_aware,5,5,1,complete,,16,16,1,15\n"
      "5,k5,free,energy_aware,5,10,1,complete,,18,18,1,17\n"
      "6,k6,free,energy_aware,10,0,1,complete,,18,18,1,17\n"
      "7,k7,free,energy_aware,10,5,1,complete,,20,20,1,19\n"
      "8,k8,free,energy_aware,10,10,1,complete,,11,11,1,10\n");
  // A 3 x 3 grid of (w1, w2): heat maps need at least three values of each weight.
  fsweep::testing::write_text(dir / "progress.csv",
                              "run_index,run_key,distance_m,explored_area_m2,coverage,energy\n"
                              "0,k0,0,1,0.1,0\n0,k0,10,9,1,10\n"
                              "1,k1,0,1,0.1,0\n1,k1,12,9,1,12\n"
                              "2,k2,0,1,0.1,0\n2,k2,14,9,1,14\n"
                              "3,k3,0,1,0.1,0\n3,k3,14,9,1,14\n"
                              "4,k4,0,1,0.1,0\n4,k4,16,9,1,16\n"
                              "5,k5,0,1,0.1,0\n5,k5,18,9,1,18\n"
                              "6,k6,0,1,0.1,0\n6,k6,18,9,1,18\n"
                              "7,k7,0,1,0.1,0\n7,k7,20,9,1,20\n"
                              "8,k8,0,1,0.1,0\n8,k8,11,9,1,11\n");
  const std::string out = (dir / "figures").string();
  ASSERT_EQ(fsweep_cli("aggregate " + dir.string()).code, 0);
  const Outcome r = fsweep_cli("plot " + dir.string() + " --out " + out);
  ASSERT_EQ(r.code, 0) << r.output;
  // --top reaches the script; a bad value is refused with exit code 2.
  const Outcome top = fsweep_cli("plot " + dir.string() + " --out " + out + "_top3 --top 3");
  ASSERT_EQ(top.code, 0) << top.output;
  EXPECT_TRUE(std::filesystem::exists(out + "_top3/progress.png"));
  EXPECT_EQ(fsweep_cli("plot " + dir.string() + " --top 0").code, 2);
  for (const char* f : {"progress.png", "metrics.png", "heatmap_w1_w2.png"}) {
    EXPECT_TRUE(std::filesystem::exists(out + "/" + f)) << f;
  }
  std::filesystem::remove_all(dir);
}

TEST(CliPlot, FindsAPythonWithMatplotlibOnPathAndNamesTheOneThatFailed) {
  if (!python_has_matplotlib()) GTEST_SKIP() << "/usr/bin/python3 has no matplotlib";
  const auto dir = fsweep::testing::make_sweep_dir("cli_python");
  // 1. A python3 first on PATH without matplotlib (its import check fails): the next one is used.
  const auto bin = dir / "bin";
  std::filesystem::create_directories(bin);
  fsweep::testing::write_text(bin / "python3",
                              "#!/bin/sh\necho \"$@\" >> " + (dir / "calls").string() + "\nexit 1\n");
  std::filesystem::permissions(bin / "python3", std::filesystem::perms::owner_all);
  const std::string path = "PATH='" + bin.string() + ":/usr/bin:/bin' ";
  Outcome r = fsweep::testing::run_command(path + FSWEEP_BINARY_DIR "/bin/fsweep plot " + dir.string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(fsweep::testing::read_all((dir / "calls").string()).find("-c import matplotlib"),
            std::string::npos);
  // 2. One that has "matplotlib" but whose run of the script fails: the message names it.
  fsweep::testing::write_text(bin / "python3", "#!/bin/sh\n[ \"$1\" = -c ] && exit 0\nexit 3\n");
  r = fsweep::testing::run_command(path + FSWEEP_BINARY_DIR "/bin/fsweep plot " + dir.string());
  EXPECT_EQ(r.code, 1) << r.output;
  EXPECT_NE(r.output.find("tools/plot.py failed with " + (bin / "python3").string() + " (exit code 3)"),
            std::string::npos)
      << r.output;
  std::filesystem::remove_all(dir);
}

TEST(CliPlot, ExactSearchExpandRunAndHeatMaps) {
  if (!python_has_matplotlib()) GTEST_SKIP() << "/usr/bin/python3 has no matplotlib";
  // A sweep of one search entry (no runs of its own) over w1 x w3 = {0, 1, 2}^2.
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("fsweep_cli_search_plot_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  fsweep::testing::write_text(
      dir / "sweep.json",
      R"({"schema_version": 1, "name": "plot_search", "maps": ["office:w=32,h=32,seed=3"],
          "strategies": [{"name": "energy_aware", "search": {"mode": "all", "rank": [[1, 0, 2, 0]]},
                          "params": {"w1": [0, 1, 2], "w2": 0, "w3": [0, 1, 2], "w4": 0}}],
          "robot": {"sensor": {"range_m": 3}, "battery": 120}, "seed": 5})");
  const Outcome expand = fsweep_cli("expand " + (dir / "sweep.json").string());
  ASSERT_EQ(expand.code, 0) << expand.output;
  EXPECT_NE(
      expand.output.find("exact weight searches (after the runs): 1\n  0: energy_aware, mode all, map class"),
      std::string::npos)
      << expand.output;
  EXPECT_NE(expand.output.find("w1 0..2 (3 values) x w2 0 x w3 0..2 (3 values) x w4 0 = 9 vectors"),
            std::string::npos)
      << expand.output;
  const std::string out = (dir / "out").string();
  const Outcome run = fsweep_cli("run " + (dir / "sweep.json").string() + " --out " + out + " --quiet");
  ASSERT_EQ(run.code, 0) << run.output;
  EXPECT_NE(run.output.find("exact weight search: 1 search, 9 weight vectors; "), std::string::npos)
      << run.output;
  EXPECT_NE(run.output.find("search_heatmaps.csv"), std::string::npos) << run.output;
  const Outcome plot = fsweep_cli("plot " + out);
  ASSERT_EQ(plot.code, 0) << plot.output;
  // Only w1 and w3 have two values or more.
  EXPECT_TRUE(std::filesystem::exists(out + "/plots/search0_w1_w3.png")) << plot.output;
  EXPECT_FALSE(std::filesystem::exists(out + "/plots/search0_w1_w2.png"));
  std::filesystem::remove_all(dir);
}

}  // namespace
