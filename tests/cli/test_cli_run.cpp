// `fsweep run` end to end: the run count first, the outputs, resume, and exit codes.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include "cli/fsweep_process.hpp"

namespace {

using RunOutcome = fsweep::testing::CliOutcome;
RunOutcome fsweep_run(const std::string& args) { return fsweep::testing::run_fsweep("run " + args); }

std::string make_dir(const std::string& name) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("fsweep_cli_run_" + name + "_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

std::string write_sweep(const std::string& dir, int seed) {
  std::string path = dir + "/sweep.json";
  std::ofstream(path) << R"({
  "schema_version": 1,
  "name": "cli_run",
  "maps": ["rooms:w=24,h=20,door=2,seed=2"],
  "strategies": [{"name": "closest_frontier"}, {"name": "energy_aware", "params": {"w1": [0, 10]}}],
  "repetitions": 3,
  "seed": )" << seed << "\n}\n";
  return path;
}

std::size_t lines(const std::string& path) {
  std::ifstream in(path);
  std::size_t n = 0;
  std::string line;
  while (std::getline(in, line)) ++n;
  return n;
}

TEST(CliRun, RunsASweepFileAndResumes) {
  const std::string dir = make_dir("ok");
  const std::string sweep = write_sweep(dir, 1);
  const std::string out = dir + "/results";
  const RunOutcome r = fsweep_run(sweep + " --threads 2 --quiet --out " + out);
  ASSERT_EQ(r.code, 0) << r.output;
  // The count comes first, then where the results are.
  const auto count = r.output.find("sweep cli_run: 9 runs (3 configurations x 3 repetitions)");
  const auto where = r.output.find("results in " + out);
  EXPECT_NE(count, std::string::npos) << r.output;
  EXPECT_NE(where, std::string::npos) << r.output;
  EXPECT_LT(count, where);
  for (const char* f : {"runs.csv", "progress.csv", "manifest.json", "summary.csv", "best.csv"}) {
    EXPECT_TRUE(std::filesystem::exists(out + "/" + f)) << f;
  }
  EXPECT_EQ(lines(out + "/runs.csv"), 10U);
  std::ifstream manifest(out + "/manifest.json");
  std::stringstream text;
  text << manifest.rdbuf();
  EXPECT_NE(text.str().find(sweep), std::string::npos);  // sweep_file recorded

  const RunOutcome again = fsweep_run(sweep + " --quiet --out " + out);
  ASSERT_EQ(again.code, 0) << again.output;
  EXPECT_NE(again.output.find("0 ran, 9 already done"), std::string::npos) << again.output;
  EXPECT_EQ(lines(out + "/runs.csv"), 10U);
  std::filesystem::remove_all(dir);
}

TEST(CliRun, ChangedSweepNeedsFresh) {
  const std::string dir = make_dir("changed");
  const std::string out = dir + "/results";
  ASSERT_EQ(fsweep_run(write_sweep(dir, 1) + " --quiet --out " + out).code, 0);
  const RunOutcome refused = fsweep_run(write_sweep(dir, 2) + " --quiet --out " + out);
  EXPECT_EQ(refused.code, 2);
  EXPECT_NE(refused.output.find("--fresh"), std::string::npos) << refused.output;
  const RunOutcome fresh = fsweep_run(write_sweep(dir, 2) + " --quiet --fresh --out " + out);
  EXPECT_EQ(fresh.code, 0) << fresh.output;
  EXPECT_NE(fresh.output.find("9 ran"), std::string::npos) << fresh.output;
  std::filesystem::remove_all(dir);
}

TEST(CliRun, ShardWritesIntoItsSubdirectory) {
  const std::string dir = make_dir("shard");
  const std::string out = dir + "/results";
  const RunOutcome r = fsweep_run(write_sweep(dir, 1) + " --quiet --shard 1/4 --out " + out);
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("shard 1/4: 2 runs"), std::string::npos) << r.output;
  EXPECT_EQ(lines(out + "/shard-1-of-4/runs.csv"), 3U);
  std::filesystem::remove_all(dir);
}

TEST(CliRun, BadShardAndMissingFileAreExit2) {
  const std::string dir = make_dir("bad");
  const RunOutcome shard = fsweep_run(write_sweep(dir, 1) + " --quiet --shard 4/4 --out " + dir + "/r");
  EXPECT_EQ(shard.code, 2);
  EXPECT_NE(shard.output.find("--shard"), std::string::npos) << shard.output;
  const RunOutcome missing = fsweep_run(dir + "/nonexistent.json --quiet");
  EXPECT_EQ(missing.code, 2);
  EXPECT_NE(missing.output.find("nonexistent.json"), std::string::npos) << missing.output;
  std::filesystem::remove_all(dir);
}

TEST(CliRun, ThreadsAboveFourTimesTheHardwareThreadsAreExit2NamingTheBound) {
  const std::string dir = make_dir("threads");
  const int hardware = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  const std::string bound = std::to_string(4 * hardware);
  const std::string hint = "(4 x the " + std::to_string(hardware) + " hardware threads of this machine)";
  for (const std::string& threads : {std::to_string(4 * hardware + 1), std::string("100000")}) {
    const RunOutcome r =
        fsweep_run(write_sweep(dir, 1) + " --quiet --threads " + threads + " --out " + dir + "/r");
    EXPECT_EQ(r.code, 2) << r.output;
    EXPECT_NE(r.output.find("--threads: must be 0 (all cores) to " + bound + " " + hint + ", got " + threads),
              std::string::npos)
        << r.output;
    EXPECT_EQ(r.output.find("on " + threads + " threads"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir + "/r/runs.csv"));
  }
  // The bound itself is allowed.
  const RunOutcome ok =
      fsweep_run(write_sweep(dir, 1) + " --quiet --threads " + bound + " --out " + dir + "/r");
  EXPECT_EQ(ok.code, 0) << ok.output;
  EXPECT_NE(ok.output.find("on " + bound + " threads"), std::string::npos) << ok.output;
  std::filesystem::remove_all(dir);
}

TEST(CliRun, ProgressLinesOnStderrWhenNotATerminal) {
  const std::string dir = make_dir("progress");
  const RunOutcome r = fsweep_run(write_sweep(dir, 1) + " --out " + dir + "/r");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("9/9 runs (100.0%)"), std::string::npos) << r.output;
  std::filesystem::remove_all(dir);
}

}  // namespace
