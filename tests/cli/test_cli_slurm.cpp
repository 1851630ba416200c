// `fsweep slurm` end to end without a cluster: with PATH emptied (no sbatch, no scontrol) it
// validates the sweep, writes the scripts with absolute paths and prints them (exit 0); bad
// input is exit 2 and writes nothing.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli/fsweep_process.hpp"

namespace test_cli_slurm {  // not anonymous: unity builds put it beside other test files' helpers

namespace fs = std::filesystem;
using fsweep::testing::run_fsweep;

/// A sweep of 1 map x 2 strategies x 5 repetitions = 10 runs, written to `dir`/sweep.json.
std::string write_sweep(const std::string& dir) {
  fs::create_directories(dir);
  std::string path = dir + "/sweep.json";
  std::ofstream(path) << R"({"schema_version": 1, "name": "cli_slurm",
    "maps": ["rooms:w=24,h=20,door=2,seed=2"],
    "strategies": [{"name": "closest_frontier"}, {"name": "energy_aware"}],
    "repetitions": 5, "seed": 3})";
  return path;
}

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Runs a shell command line; exit code and its stdout and stderr.
fsweep::testing::CliOutcome run_shell(const std::string& cmd) {
  fsweep::testing::CliOutcome out;
  FILE* pipe = popen((cmd + " 2>&1").c_str(), "r");
  if (pipe == nullptr) return out;
  char buf[4096];
  std::size_t n = 0;
  while ((n = std::fread(buf, 1, sizeof(buf), pipe)) > 0) out.output.append(buf, n);
  const int status = pclose(pipe);
  out.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return out;
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(CliSlurm, WithoutSbatchWritesAndPrintsThePackedScripts) {
  const std::string dir = fsweep::testing::fresh_temp_dir("slurm", "dry");
  write_sweep(dir);
  // Relative sweep path and --out, run from `dir`: the scripts must hold absolute ones.
  const std::string cmd =
      "cd " + dir + " && env PATH=/nonexistent " + std::string(FSWEEP_BINARY_DIR) +
      "/bin/fsweep slurm sweep.json --tasks 4 --max-array-size 3 --cpus 2 --time 10:00 --out out";
  const auto out = run_shell(cmd);
  ASSERT_EQ(out.code, 0) << out.output;
  EXPECT_TRUE(has(out.output,
                  "sweep cli_slurm: 10 runs (2 configurations x 5 repetitions) in 4 shards of 2 to 3 runs"))
      << out.output;
  EXPECT_TRUE(has(out.output, "array: 3 tasks (MaxArraySize 3, from --max-array-size); packed"))
      << out.output;
  EXPECT_TRUE(has(out.output, "sbatch is not on PATH: not submitted")) << out.output;
  EXPECT_TRUE(has(out.output, "--dependency=afterany:\"$array_id\"")) << out.output;
  const std::string abs_dir = fs::canonical(dir).string();
  const std::string array = slurp(dir + "/out/slurm/array.sbatch");
  EXPECT_TRUE(has(array, "#SBATCH --array=0-2\n")) << array;
  EXPECT_TRUE(has(array, "#SBATCH --cpus-per-task=2\n")) << array;
  EXPECT_TRUE(has(array, "#SBATCH --time=10:00\n")) << array;
  EXPECT_FALSE(has(array, "--partition")) << array;
  EXPECT_TRUE(has(array, " run " + abs_dir + "/sweep.json --out " + abs_dir + "/out --shard")) << array;
  EXPECT_TRUE(has(array, "cd -- " + abs_dir + " ")) << array;
  EXPECT_TRUE(has(out.output, array)) << "the printed script differs from the file";
  EXPECT_TRUE(has(slurp(dir + "/out/slurm/merge.sbatch"), " merge " + abs_dir + "/out\n"));
  EXPECT_TRUE(fs::is_directory(dir + "/out/slurm/logs"));
  fs::remove_all(dir);
}

TEST(CliSlurm, ASearchSweepSaysHowManyShardsItsBlocksCanUse) {
  // A search alone has no runs to count; its box of 2 x 8 values of w1 holds 2 blocks of 8^4, so
  // 3 shards leave one with nothing to search.
  const std::string dir = fsweep::testing::fresh_temp_dir("slurm", "search");
  fs::create_directories(dir);
  std::ofstream(dir + "/sweep.json") << R"({"schema_version": 1, "name": "cli_slurm_search",
    "maps": ["rooms:w=24,h=20,door=2,seed=2"],
    "strategies": [{"name": "energy_aware", "search": {"mode": "best"},
                    "params": {"w1": {"range": [0, 15], "step": 1}, "w2": [0, 1], "w3": [0, 1], "w4": [0, 1]}}],
    "seed": 3})";
  const auto out = run_shell("cd " + dir + " && env PATH=/nonexistent " + std::string(FSWEEP_BINARY_DIR) +
                             "/bin/fsweep slurm sweep.json --tasks 3 --out out");
  ASSERT_EQ(out.code, 0) << out.output;
  EXPECT_FALSE(has(out.output, "more shards than runs")) << out.output;
  EXPECT_TRUE(has(out.output, "exact weight search 0: 128 weight vectors in 2 blocks of 8^4")) << out.output;
  EXPECT_TRUE(has(out.output, "note: more shards than search 0's blocks: 1 shard has none of it"))
      << out.output;
  EXPECT_TRUE(
      has(slurp(dir + "/out/slurm/merge.sbatch"), "names a shard whose weight search did not finish"));
  fs::remove_all(dir);
}

/// The lines of `text` in order, from the first that starts with `first` to the first after it
/// that starts with `last`, both included; empty when either is missing.
std::vector<std::string> lines_between(const std::string& text, const std::string& first,
                                       const std::string& last) {
  std::vector<std::string> out;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (out.empty() && !line.starts_with(first)) continue;
    out.push_back(line);
    if (out.size() > 1 && line.starts_with(last)) return out;
  }
  return {};
}

TEST(CliSlurm, ClusterOptionsReachBothScriptsInOrder) {
  const std::string dir = fsweep::testing::fresh_temp_dir("slurm", "cluster");
  const std::string sweep = write_sweep(dir);
  // --sbatch --exclusive: a value that looks like an option, taken as the value (one per --sbatch);
  // the sweep file after it stays the positional argument.
  const auto r = run_fsweep(
      "slurm --tasks 2 --dry-run --account proj_a --qos normal --gres gpu:1 --sbatch --exclusive "
      "--sbatch '#SBATCH --constraint=a100' --setup 'module load gcc/12' --setup 'source "
      "\"$HOME/venv/bin/activate\"' "
      "--sbatch=--mail-type=END " +
      sweep + " --out " + dir + "/out");
  ASSERT_EQ(r.code, 0) << r.output;
  const std::string array = slurp(dir + "/out/slurm/array.sbatch");
  const std::vector<std::string> want_array_directives = {
      "#SBATCH --cpus-per-task=1",
      "#SBATCH --account=proj_a",
      "#SBATCH --qos=normal",
      "#SBATCH --gres=gpu:1",
      "#SBATCH --output=" + dir + "/out/slurm/logs/%A_%a.out",
      "#SBATCH --exclusive",
      "#SBATCH --constraint=a100",
      "#SBATCH --mail-type=END"};
  EXPECT_EQ(lines_between(array, "#SBATCH --cpus-per-task", "#SBATCH --mail-type"), want_array_directives)
      << array;
  const std::vector<std::string> want_setup = {"# setup (fsweep slurm --setup), in order:", "set +u",
                                               "module load gcc/12", "source \"$HOME/venv/bin/activate\"",
                                               "set -u"};
  EXPECT_EQ(lines_between(array, "# setup", "set -u"), want_setup) << array;
  EXPECT_LT(array.find("set -u\nfailed=0"), array.find(" run " + sweep)) << array;
  const std::string merge = slurp(dir + "/out/slurm/merge.sbatch");
  const std::vector<std::string> want_merge_directives = {
      "#SBATCH --cpus-per-task=1", "#SBATCH --account=proj_a",
      "#SBATCH --qos=normal",      "#SBATCH --output=" + dir + "/out/slurm/logs/merge_%j.out",
      "#SBATCH --exclusive",       "#SBATCH --constraint=a100",
      "#SBATCH --mail-type=END"};
  EXPECT_EQ(lines_between(merge, "#SBATCH --cpus-per-task", "#SBATCH --mail-type"), want_merge_directives)
      << merge;
  EXPECT_TRUE(has(merge, "module load gcc/12\nsource \"$HOME/venv/bin/activate\"\nexec ")) << merge;
  fs::remove_all(dir);
}

TEST(CliSlurm, BadClusterOptionsAreExit2NamingTheOption) {
  const std::string dir = fsweep::testing::fresh_temp_dir("slurm", "badcluster");
  const std::string sweep = write_sweep(dir);
  const auto refused = [&](const std::string& options, const std::string& part) {
    const auto r = run_fsweep("slurm " + sweep + " --tasks 2 --dry-run --out " + dir + "/out " + options);
    EXPECT_EQ(r.code, 2) << options << "\n" << r.output;
    EXPECT_TRUE(has(r.output, part)) << options << "\n" << r.output;
    EXPECT_FALSE(fs::exists(dir + "/out")) << options;
  };
  refused("--account 'my account'", "--account: must be a name of letters, digits, '_', '.' and '-'");
  refused("--qos 'a$(reboot)'", "--qos: must be a name of letters, digits");
  refused("--gres 'gpu:1 x'", "--gres: must not contain whitespace");
  refused("--sbatch constraint=a100",
          "--sbatch: 'constraint=a100' is not an sbatch option; allowed: --option or --option=value");
  refused("--sbatch \"$(printf -- '--exclusive\\n--nodes=2')\"",
          "--sbatch: '--exclusive\\n--nodes=2' is not");
  refused("--sbatch --array=0-99", "--sbatch: '--array=0-99' sets --array, which fsweep slurm writes itself");
  refused("--setup \"$(printf 'echo a\\necho b')\"", "--setup: 'echo a\\necho b' is not one line");
  fs::remove_all(dir);
}

TEST(CliSlurm, BadInputIsExit2AndWritesNothing) {
  const std::string dir = fsweep::testing::fresh_temp_dir("slurm", "bad");
  const std::string sweep = write_sweep(dir);
  auto r = run_fsweep("slurm " + sweep + " --tasks 0 --dry-run --out " + dir + "/out");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_TRUE(has(r.output, "--tasks")) << r.output;
  r = run_fsweep("slurm " + dir + "/missing.json --tasks 2 --dry-run --out " + dir + "/out");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_TRUE(has(r.output, "missing.json")) << r.output;
  r = run_fsweep("slurm " + sweep + " --tasks 2 --dry-run --partition 'a b' --out " + dir + "/out");
  EXPECT_EQ(r.code, 2) << r.output;
  r = run_fsweep("slurm " + sweep + " --tasks 2 --dry-run --fsweep " + dir + "/no-such-fsweep --out " + dir +
                 "/out");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_FALSE(fs::exists(dir + "/out"));
  // The sweep's directory may not hold another command's output (cli/output_dir.hpp).
  ASSERT_EQ(run_fsweep("sim --map free:w=10,h=10 --out " + dir + "/sim").code, 0);
  r = run_fsweep("slurm " + sweep + " --tasks 2 --dry-run --out " + dir + "/sim");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_TRUE(has(r.output, "/sim: holds the output of fsweep sim")) << r.output;
  EXPECT_FALSE(fs::exists(dir + "/sim/slurm"));
  fs::remove_all(dir);
}

}  // namespace test_cli_slurm
