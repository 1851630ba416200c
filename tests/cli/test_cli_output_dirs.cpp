// A command never writes over another command's output directory (issue 18): `sim`, `run`,
// `merge`, `plan-bench`, `plan-compare` and `compare` (and `slurm`, test_cli_slurm.cpp) recognise what an
// existing directory holds (cli/output_dir.hpp) and refuse another command's with exit 2, before writing
// anything; rerunning a command into its own kind of output stays allowed.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "cli/fsweep_process.hpp"

namespace test_cli_output_dirs {  // not anonymous: unity builds put it beside other test files' helpers

namespace fs = std::filesystem;
using fsweep::testing::read_all;
using fsweep::testing::run_fsweep;
using fsweep::testing::write_named_sweep;

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

const char* const kSim = "sim --map rooms:w=24,h=20,door=2,seed=2 --out ";

TEST(CliOutputDirs, SimRefusesASweepsResultsAndTheSweepStillResumes) {
  const std::string dir = fsweep::testing::fresh_temp_dir("outdirs", "sim_into_sweep");
  const std::string sweep = write_named_sweep(dir, "outdirs", 1);
  const std::string out = dir + "/results";
  ASSERT_EQ(run_fsweep("run " + sweep + " --quiet --out " + out).code, 0);
  const std::string progress = read_all(out + "/progress.csv");

  const auto r = run_fsweep(kSim + out);
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, out + ": holds the results of sweep 'outdirs' (manifest.json, runs.csv); "
                                       "choose another --out"))
      << r.output;
  EXPECT_EQ(read_all(out + "/progress.csv"), progress);
  EXPECT_FALSE(fs::exists(out + "/run.csv"));
  EXPECT_FALSE(fs::exists(out + "/trajectory.png"));

  const auto again = run_fsweep("run " + sweep + " --quiet --out " + out);
  EXPECT_EQ(again.code, 0) << again.output;
  EXPECT_TRUE(contains(again.output, "0 ran, 2 already done")) << again.output;
  EXPECT_EQ(run_fsweep("aggregate " + out).code, 0);
  fs::remove_all(dir);
}

TEST(CliOutputDirs, SimRerunsIntoItsOwnOutputButARunDoesNot) {
  const std::string dir = fsweep::testing::fresh_temp_dir("outdirs", "run_into_sim");
  const std::string sweep = write_named_sweep(dir, "outdirs", 1);
  const std::string out = dir + "/sim";
  ASSERT_EQ(run_fsweep(kSim + out).code, 0);
  const auto rerun = run_fsweep(kSim + out + " --seed 4");
  EXPECT_EQ(rerun.code, 0) << rerun.output;
  const std::string run_csv = read_all(out + "/run.csv");

  const auto r = run_fsweep("run " + sweep + " --quiet --out " + out);
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_TRUE(
      contains(r.output, out + ": holds the output of fsweep sim (run.csv, progress.csv, trajectory.png); "
                               "choose another --out"))
      << r.output;
  EXPECT_EQ(read_all(out + "/run.csv"), run_csv);
  EXPECT_FALSE(fs::exists(out + "/runs.csv"));
  EXPECT_FALSE(fs::exists(out + "/manifest.json"));
  fs::remove_all(dir);
}

TEST(CliOutputDirs, PlannerBenchmarksAndCompareRefuseEachOthersDirectories) {
  const std::string dir = fsweep::testing::fresh_temp_dir("outdirs", "planners");
  const std::string bench = dir + "/bench";
  const std::string pairs = dir + "/pairs";
  const std::string plan_bench =
      "plan-bench --map random:w=16,h=16,p=0.1,seed=2 --pairs 3 --planners astar --out ";
  const std::string plan_compare =
      "plan-compare --map random:w=16,h=16,p=0.1,seed=2 --pairs 3 --planners astar,dijkstra --out ";
  ASSERT_EQ(run_fsweep(plan_bench + bench).code, 0);
  EXPECT_EQ(run_fsweep(plan_bench + bench).code, 0);  // its own kind: replaced
  ASSERT_EQ(run_fsweep(plan_compare + pairs).code, 0);
  EXPECT_EQ(run_fsweep(plan_compare + pairs).code, 0);
  const std::string bench_summary = read_all(bench + "/summary.csv");
  const std::string pairs_summary = read_all(pairs + "/summary.csv");

  auto r = run_fsweep(plan_compare + bench);
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, bench + ": holds the output of fsweep plan-bench (queries.csv, summary.csv, "
                                         "ompl_benchmark.log); choose another --out"))
      << r.output;
  r = run_fsweep(plan_bench + pairs);
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, pairs + ": holds the output of fsweep plan-compare (pairs.csv, summary.csv, "
                                         "manifest.json); choose another --out"))
      << r.output;
  r = run_fsweep(kSim + bench);
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_EQ(read_all(bench + "/summary.csv"), bench_summary);
  EXPECT_EQ(read_all(pairs + "/summary.csv"), pairs_summary);
  EXPECT_FALSE(fs::exists(bench + "/pairs.csv"));
  EXPECT_FALSE(fs::exists(pairs + "/queries.csv"));
  EXPECT_FALSE(fs::exists(bench + "/run.csv"));
  fs::remove_all(dir);
}

TEST(CliOutputDirs, CompareRefusesAnotherCommandsDirectory) {
  const std::string dir = fsweep::testing::fresh_temp_dir("outdirs", "compare");
  const std::string sweep = write_named_sweep(dir, "outdirs", 1);
  const std::string results = dir + "/results";
  const std::string sim = dir + "/sim";
  ASSERT_EQ(run_fsweep("run " + sweep + " --quiet --out " + results).code, 0);
  ASSERT_EQ(run_fsweep(kSim + sim).code, 0);
  const auto r = run_fsweep("compare " + results + " " + results + " --out " + sim);
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, sim + ": holds the output of fsweep sim")) << r.output;
  EXPECT_FALSE(fs::exists(sim + "/compare.csv"));
  const auto own = run_fsweep("compare " + results + " " + results);  // into results/compare, its own
  EXPECT_EQ(own.code, 0) << own.output;
  EXPECT_EQ(run_fsweep("compare " + results + " " + results).code, 0);
  fs::remove_all(dir);
}

TEST(CliOutputDirs, MergeRefusesADirectoryOfAnotherCommand) {
  const std::string dir = fsweep::testing::fresh_temp_dir("outdirs", "merge_sim");
  const std::string sweep = write_named_sweep(dir, "outdirs", 1);
  const std::string shards = dir + "/shards";
  const std::string sim = dir + "/sim";
  ASSERT_EQ(run_fsweep(kSim + sim).code, 0);
  for (const std::string shard : {"0", "1"}) {  // a complete split, moved in by hand
    ASSERT_EQ(run_fsweep("run " + sweep + " --quiet --out " + shards + " --shard " + shard + "/2").code, 0);
    fs::rename(shards + "/shard-" + shard + "-of-2", sim + "/shard-" + shard + "-of-2");
  }
  const std::string progress = read_all(sim + "/progress.csv");
  const auto r = run_fsweep("merge " + sim);
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, sim + ": holds the output of fsweep sim")) << r.output;
  EXPECT_EQ(read_all(sim + "/progress.csv"), progress);
  EXPECT_FALSE(fs::exists(sim + "/runs.csv"));
  fs::remove_all(dir);
}

TEST(CliOutputDirs, ADirectoryOfShardsIsASweepsAndPlotAndReportKeepOffOtherFiles) {
  const std::string dir = fsweep::testing::fresh_temp_dir("outdirs", "shards_plots");
  const std::string sweep = write_named_sweep(dir, "outdirs", 1);
  const std::string shards = dir + "/shards";
  const std::string results = dir + "/results";
  const std::string sim = dir + "/sim";
  ASSERT_EQ(run_fsweep("run " + sweep + " --quiet --out " + shards + " --shard 0/2").code, 0);
  const auto into_shards = run_fsweep(kSim + shards);
  EXPECT_EQ(into_shards.code, 2) << into_shards.output;
  EXPECT_TRUE(contains(into_shards.output, shards + ": holds the shards of a sweep (shard-0-of-2)"))
      << into_shards.output;
  EXPECT_FALSE(fs::exists(shards + "/run.csv"));

  ASSERT_EQ(run_fsweep("run " + sweep + " --quiet --out " + results).code, 0);
  ASSERT_EQ(run_fsweep(kSim + sim).code, 0);
  const std::string runs = read_all(results + "/runs.csv");
  // plot --out: not into another command's directory.
  const auto plot = run_fsweep("plot " + results + " --out " + sim);
  EXPECT_EQ(plot.code, 2) << plot.output;
  EXPECT_TRUE(contains(plot.output, sim + ": holds the output of fsweep sim")) << plot.output;
  EXPECT_FALSE(fs::exists(sim + "/metrics.png"));
  // report --out: a new file or an earlier page, never another file or a directory.
  const auto over_runs = run_fsweep("report " + results + " --out " + results + "/runs.csv");
  EXPECT_EQ(over_runs.code, 2) << over_runs.output;
  EXPECT_TRUE(contains(over_runs.output,
                       "--out: " + results + "/runs.csv exists and is not a page fsweep report wrote"))
      << over_runs.output;
  EXPECT_EQ(read_all(results + "/runs.csv"), runs);
  const auto into_dir = run_fsweep("report " + results + " --out " + sim);
  EXPECT_EQ(into_dir.code, 2) << into_dir.output;
  EXPECT_TRUE(contains(into_dir.output, "--out: " + sim + " is a directory")) << into_dir.output;
  const std::string page = dir + "/page.html";
  ASSERT_EQ(run_fsweep("report " + results + " --no-trajectories --out " + page).code, 0);
  const auto again = run_fsweep("report " + results + " --no-trajectories --out " + page);  // its own page
  EXPECT_EQ(again.code, 0) << again.output;
  fs::remove_all(dir);
}

}  // namespace test_cli_output_dirs
