// `fsweep run` end to end: the run count first, the outputs, resume, and exit codes.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
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

std::string write_sweep(const std::string& dir, int seed, int repetitions = 3) {
  std::string path = dir + "/sweep.json";
  std::ofstream(path) << R"({
  "schema_version": 1,
  "name": "cli_run",
  "maps": ["rooms:w=24,h=20,door=2,seed=2"],
  "strategies": [{"name": "closest_frontier"}, {"name": "energy_aware", "params": {"w1": [0, 10]}}],
  "repetitions": )" << repetitions
                      << R"(,
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

TEST(CliRun, AGrownSweepFileRunsOnlyItsNewRunsAndAShrunkOneIsExit2) {
  const std::string dir = make_dir("grown");
  const std::string out = dir + "/results";
  ASSERT_EQ(fsweep_run(write_sweep(dir, 1) + " --quiet --out " + out).code, 0);
  const RunOutcome grown = fsweep_run(write_sweep(dir, 1, 4) + " --quiet --out " + out);
  ASSERT_EQ(grown.code, 0) << grown.output;
  for (const char* part :
       {"sweep cli_run: 12 runs (3 configurations x 4 repetitions)",
        "extended the results of an earlier version of the sweep file (sweep_hash ",
        "its 9 finished runs kept, in this sweep's run order", "done: 3 ran, 9 already done"}) {
    EXPECT_NE(grown.output.find(part), std::string::npos) << part << "\nnot in:\n" << grown.output;
  }
  EXPECT_EQ(lines(out + "/runs.csv"), 13U);
  const RunOutcome shrunk = fsweep_run(write_sweep(dir, 1, 2) + " --quiet --out " + out);
  EXPECT_EQ(shrunk.code, 2);
  EXPECT_NE(shrunk.output.find("which does not have 6 of its 12 finished runs"), std::string::npos)
      << shrunk.output;
  EXPECT_EQ(lines(out + "/runs.csv"), 13U);
  // A rerun with nothing to do keeps the sessions that ran, and their speed.
  ASSERT_EQ(fsweep_run(write_sweep(dir, 1, 4) + " --quiet --out " + out).code, 0);
  std::stringstream text;
  text << std::ifstream(out + "/manifest.json").rdbuf();
  const auto manifest = nlohmann::json::parse(text.str());
  EXPECT_EQ(manifest["sessions"].size(), 3U);
  EXPECT_EQ(manifest["runs"]["ran"], 12U);
  EXPECT_GT(manifest["runs_per_s"].get<double>(), 0.0);
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

/// manifest.json of `dir` as JSON.
nlohmann::json manifest_of(const std::string& dir) {
  return nlohmann::json::parse(fsweep::testing::read_all(dir + "/manifest.json"));
}

TEST(CliRun, OverridesChangeTheSweepTheManifestRecordsThemAndAResumeGivesThemAgain) {
  const std::string dir = make_dir("overrides");
  const std::string sweep = write_sweep(dir, 1);
  const std::string out = dir + "/results";
  const std::string overrides = " repetitions=1 'strategies[1].params.w1=[0,10,20]' seed=5 name=my_run";
  const RunOutcome r = fsweep_run(sweep + overrides + " --quiet --out " + out);
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("sweep my_run: 4 runs (4 configurations x 1 repetitions)"), std::string::npos)
      << r.output;
  const nlohmann::json manifest = manifest_of(out);
  EXPECT_EQ(manifest["overrides"],
            nlohmann::json::parse(
                R"(["repetitions=1", "strategies[1].params.w1=[0,10,20]", "seed=5", "name=my_run"])"));
  EXPECT_EQ(manifest["sweep"]["repetitions"], 1);  // the sweep that ran, which the hash is of
  EXPECT_EQ(manifest["sweep"]["seed"], 5);
  EXPECT_EQ(manifest["sweep"]["strategies"][1]["params"]["w1"], nlohmann::json::parse("[0, 10, 20]"));
  EXPECT_EQ(manifest["sweep_file"], sweep);
  EXPECT_EQ(lines(out + "/runs.csv"), 5U);
  // The same overrides again: every run is done.
  const RunOutcome again = fsweep_run(sweep + overrides + " --quiet --out " + out);
  ASSERT_EQ(again.code, 0) << again.output;
  EXPECT_NE(again.output.find("0 ran, 4 already done"), std::string::npos) << again.output;
  // The report page names them.
  const RunOutcome report = fsweep::testing::run_fsweep("report " + out + " --out " + dir + "/report.html");
  ASSERT_EQ(report.code, 0) << report.output;
  EXPECT_NE(fsweep::testing::read_all(dir + "/report.html")
                .find("<th>command-line overrides</th><td>repetitions=1  strategies[1].params.w1=[0,10,20]  "
                      "seed=5  name=my_run</td>"),
            std::string::npos);
  // Without them it is another sweep (other seeds, so other run keys).
  const RunOutcome without = fsweep_run(sweep + " --quiet --out " + out);
  EXPECT_EQ(without.code, 2) << without.output;
  EXPECT_EQ(lines(out + "/runs.csv"), 5U);
  std::filesystem::remove_all(dir);
}

TEST(CliRun, AnOverrideThatCannotApplyOrMakesTheSweepInvalidIsExit2NamingIt) {
  const std::string dir = make_dir("bad_overrides");
  const std::string sweep = write_sweep(dir, 1);
  const RunOutcome invalid = fsweep_run(sweep + " robot.battery=-1 --quiet --out " + dir + "/r");
  EXPECT_EQ(invalid.code, 2);
  EXPECT_NE(invalid.output.find("fsweep: error: " + sweep +
                                ": 1 problem in the sweep with its command-line "
                                "overrides:\n" +
                                sweep +
                                ": override 'robot.battery=-1': /robot/battery: value -1 "
                                "out of range; allowed: a number > 0, or null"),
            std::string::npos)
      << invalid.output;
  const RunOutcome missing = fsweep_run(sweep + " 'maps[99].w=3' --quiet --out " + dir + "/r");
  EXPECT_EQ(missing.code, 2);
  EXPECT_NE(
      missing.output.find(sweep + ": override 'maps[99].w=3': maps has 1 entry (maps[0]), so there is no "
                                  "maps[99]"),
      std::string::npos)
      << missing.output;
  EXPECT_FALSE(std::filesystem::exists(dir + "/r"));
  std::filesystem::remove_all(dir);
}

TEST(CliRun, OverridesReachEveryShardOfASlurmJobAndItsMerge) {
  const std::string dir = make_dir("slurm_overrides");
  const std::string sweep = write_sweep(dir, 1);
  const std::string out = dir + "/results";
  const RunOutcome slurm = fsweep::testing::run_command(
      "env PATH=/usr/bin:/bin " + std::string(FSWEEP_BINARY_DIR) + "/bin/fsweep slurm " + sweep +
      " seed=7 'strategies[1].params.w1=[0,10,20]' --tasks 2 --dry-run --out " + out);
  ASSERT_EQ(slurm.code, 0) << slurm.output;
  EXPECT_NE(slurm.output.find("sweep cli_run: 12 runs (4 configurations x 3 repetitions) in 2 shards"),
            std::string::npos)
      << slurm.output;
  const std::string script = out + "/slurm/array.sbatch";
  EXPECT_NE(fsweep::testing::read_all(script).find(
                " run " + sweep + " seed=7 'strategies[1].params.w1=[0,10,20]' --out " + out),
            std::string::npos)
      << fsweep::testing::read_all(script);
  // Both array tasks, run here as Slurm would, then the merge.
  for (const char* task : {"0", "1"}) {
    const RunOutcome shard =
        fsweep::testing::run_command("SLURM_ARRAY_TASK_ID=" + std::string(task) + " bash " + script);
    ASSERT_EQ(shard.code, 0) << shard.output;
  }
  const nlohmann::json expected = nlohmann::json::parse(R"(["seed=7", "strategies[1].params.w1=[0,10,20]"])");
  EXPECT_EQ(manifest_of(out + "/shard-1-of-2")["overrides"], expected);
  EXPECT_EQ(manifest_of(out + "/shard-1-of-2")["sweep"]["seed"], 7);
  const RunOutcome merge = fsweep::testing::run_fsweep("merge " + out);
  ASSERT_EQ(merge.code, 0) << merge.output;
  EXPECT_EQ(manifest_of(out)["overrides"], expected);
  EXPECT_EQ(lines(out + "/runs.csv"), 13U);
  std::filesystem::remove_all(dir);
}

}  // namespace
