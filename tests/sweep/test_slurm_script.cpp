// The `fsweep slurm` scripts: array range, packing of shards into tasks when N > MaxArraySize,
// optional directives, threads from the allocation, absolute paths, the merge dependency, and
// the parsers of scontrol and sbatch output. The packed script is also run with bash for each
// array index to check that the shards it runs are the ones slurm_task_shards names.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "core/config_error.hpp"
#include "sweep/slurm_script.hpp"
#include "sweep/sweep_test_files.hpp"

namespace fsweep {
namespace {

SlurmScriptOptions options() {
  SlurmScriptOptions o;
  o.fsweep = "/opt/fsweep/bin/fsweep";
  o.sweep_file = "/home/u/sweeps/big.json";
  o.out_dir = "/scratch/u/results/big";
  o.work_dir = "/home/u";
  o.name = "big";
  o.shards = 4;
  return o;
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

/// The `#SBATCH` lines of a script, in order.
std::vector<std::string> directives(const std::string& script) {
  std::vector<std::string> out;
  std::size_t at = 0;
  while (at < script.size()) {
    const std::size_t end = script.find('\n', at);
    const std::string line = script.substr(at, end - at);
    if (line.starts_with("#SBATCH ")) out.push_back(line.substr(8));
    if (end == std::string::npos) break;
    at = end + 1;
  }
  return out;
}

TEST(SlurmScript, ArrayCoversOneTaskPerShardBelowTheLimit) {
  const std::string s = render_slurm_array_script(options());
  EXPECT_TRUE(s.starts_with("#!/bin/bash\n"));
  const std::vector<std::string> want = {"--job-name=fsweep-big", "--array=0-3", "--cpus-per-task=1",
                                         "--output=/scratch/u/results/big/slurm/logs/%A_%a.out"};
  EXPECT_EQ(directives(s), want);
  EXPECT_TRUE(contains(s, "shards=4\ntasks=4\n"));
}

TEST(SlurmScript, PackingPutsEveryShardInExactlyOneTask) {
  struct Case {
    std::uint64_t shards, max_array_size, tasks;
  };
  // tasks = min(N, K), worked by hand.
  const Case cases[] = {{1, 1001, 1},       {4, 1001, 4},       {4, 3, 3},  {4, 4, 4},
                        {5, 2, 2},          {7, 3, 3},          {10, 1, 1}, {1001, 1001, 1001},
                        {1002, 1001, 1001}, {3000, 1001, 1001}, {2, 5, 2}};
  for (const Case& c : cases) {
    SCOPED_TRACE("N=" + std::to_string(c.shards) + " K=" + std::to_string(c.max_array_size));
    ASSERT_EQ(slurm_array_tasks(c.shards, c.max_array_size), c.tasks);
    std::vector<int> seen(c.shards, 0);
    for (std::uint64_t t = 0; t < c.tasks; ++t) {
      const auto shards = slurm_task_shards(t, c.shards, c.max_array_size);
      ASSERT_FALSE(shards.empty());
      EXPECT_EQ(shards.front(), t);
      for (std::size_t i = 0; i < shards.size(); ++i) {
        ASSERT_LT(shards[i], c.shards);
        EXPECT_EQ(shards[i] % c.tasks, t);
        if (i > 0) {
          EXPECT_EQ(shards[i], shards[i - 1] + c.tasks);
        }
        ++seen[shards[i]];
      }
    }
    for (std::uint64_t s = 0; s < c.shards; ++s) EXPECT_EQ(seen[s], 1) << "shard " << s;
    EXPECT_TRUE(slurm_task_shards(c.tasks, c.shards, c.max_array_size).empty());
    SlurmScriptOptions o = options();
    o.shards = c.shards;
    o.max_array_size = c.max_array_size;
    EXPECT_TRUE(
        contains(render_slurm_array_script(o), "#SBATCH --array=0-" + std::to_string(c.tasks - 1) + "\n"));
  }
  // 7 shards over 3 tasks, by hand: {0, 3, 6}, {1, 4}, {2, 5}.
  EXPECT_EQ(slurm_task_shards(0, 7, 3), (std::vector<std::uint64_t>{0, 3, 6}));
  EXPECT_EQ(slurm_task_shards(1, 7, 3), (std::vector<std::uint64_t>{1, 4}));
  EXPECT_EQ(slurm_task_shards(2, 7, 3), (std::vector<std::uint64_t>{2, 5}));
}

TEST(SlurmScript, HugeShardCountsDoNotOverflow) {
  // N = 2^64 - 1 shards over T = 2^64 - 2 tasks: task 0 runs shards 0 and T; the last task
  // runs T - 1 only (T - 1 + T would wrap around).
  const std::uint64_t n = UINT64_MAX;
  const std::uint64_t t = UINT64_MAX - 1;
  EXPECT_EQ(slurm_task_shards(0, n, t), (std::vector<std::uint64_t>{0, t}));
  EXPECT_EQ(slurm_task_shards(t - 1, n, t), (std::vector<std::uint64_t>{t - 1}));
}

TEST(SlurmScript, OptionalDirectivesOnlyWhenGiven) {
  SlurmScriptOptions o = options();
  for (const std::string& s : {render_slurm_array_script(o), render_slurm_merge_script(o)}) {
    EXPECT_FALSE(contains(s, "--partition")) << s;
    EXPECT_FALSE(contains(s, "--time")) << s;
    EXPECT_FALSE(contains(s, "--mem")) << s;
  }
  o.partition = "long";
  o.time = "2-00:00:00";
  o.mem = "8G";
  o.cpus = 16;
  const auto array = directives(render_slurm_array_script(o));
  const std::vector<std::string> want = {"--job-name=fsweep-big",
                                         "--array=0-3",
                                         "--cpus-per-task=16",
                                         "--partition=long",
                                         "--time=2-00:00:00",
                                         "--mem=8G",
                                         "--output=/scratch/u/results/big/slurm/logs/%A_%a.out"};
  EXPECT_EQ(array, want);
  const auto merge = directives(render_slurm_merge_script(o));
  const std::vector<std::string> want_merge = {"--job-name=fsweep-big-merge",
                                               "--cpus-per-task=1",
                                               "--partition=long",
                                               "--time=2-00:00:00",
                                               "--mem=8G",
                                               "--output=/scratch/u/results/big/slurm/logs/merge_%j.out"};
  EXPECT_EQ(merge, want_merge);
}

TEST(SlurmScript, AccountQosGresAndSbatchLinesAreDirectivesInOrder) {
  SlurmScriptOptions o = options();
  o.partition = "gpu";
  o.account = "proj-42_a.b";
  o.qos = "long";
  o.gres = "gpu:a100:1";
  o.sbatch_lines = {"--constraint=a100&ib", "#SBATCH --exclusive", "#SBATCH   --mail-type=END,FAIL",
                    "--mem-per-gpu=4G"};
  const auto array = directives(render_slurm_array_script(o));
  const std::vector<std::string> want = {
      "--job-name=fsweep-big", "--array=0-3",
      "--cpus-per-task=1",     "--partition=gpu",
      "--account=proj-42_a.b", "--qos=long",
      "--gres=gpu:a100:1",     "--output=/scratch/u/results/big/slurm/logs/%A_%a.out",
      "--constraint=a100&ib",  "--exclusive",
      "--mail-type=END,FAIL",  "--mem-per-gpu=4G"};
  EXPECT_EQ(array, want);
  // The merge job: the same account, qos and extra lines, no gres (it runs fsweep merge on one CPU).
  const auto merge = directives(render_slurm_merge_script(o));
  const std::vector<std::string> want_merge = {"--job-name=fsweep-big-merge",
                                               "--cpus-per-task=1",
                                               "--partition=gpu",
                                               "--account=proj-42_a.b",
                                               "--qos=long",
                                               "--output=/scratch/u/results/big/slurm/logs/merge_%j.out",
                                               "--constraint=a100&ib",
                                               "--exclusive",
                                               "--mail-type=END,FAIL",
                                               "--mem-per-gpu=4G"};
  EXPECT_EQ(merge, want_merge);
}

TEST(SlurmScript, SetupLinesRunAfterCdAndBeforeFsweepInOrder) {
  SlurmScriptOptions o = options();
  o.setup_lines = {"module load gcc/12", "source venv/bin/activate", "export OMP_NUM_THREADS=1 # one"};
  const std::string setup = "module load gcc/12\nsource venv/bin/activate\nexport OMP_NUM_THREADS=1 # one\n";
  const std::string array = render_slurm_array_script(o);
  // In the array script, with `set -u` off around them (module and conda scripts read unset
  // variables), after the directory change and before the shard loop.
  EXPECT_TRUE(contains(array, "cd -- /home/u || exit 2\n# setup (fsweep slurm --setup), in order:\nset +u\n" +
                                  setup + "set -u\nfailed=0\n"))
      << array;
  const std::string merge = render_slurm_merge_script(o);
  EXPECT_TRUE(contains(merge, "cd -- /home/u || exit 2\n# setup (fsweep slurm --setup), in order:\n" + setup +
                                  "exec /opt/fsweep/bin/fsweep merge /scratch/u/results/big\n"))
      << merge;
  // Without setup lines the scripts are as before.
  EXPECT_FALSE(contains(render_slurm_array_script(options()), "setup"));
  EXPECT_FALSE(contains(render_slurm_merge_script(options()), "setup"));
}

TEST(SlurmScript, BadAccountQosGresSbatchAndSetupLinesNameTheOption) {
  const auto refused = [](auto edit, const std::string& option, const std::string& part) {
    SlurmScriptOptions o = options();
    edit(o);
    for (const bool array : {true, false}) {
      try {
        (void)(array ? render_slurm_array_script(o) : render_slurm_merge_script(o));
        ADD_FAILURE() << "accepted: " << part;
      } catch (const ConfigError& e) {
        EXPECT_EQ(e.where(), option) << e.what();
        EXPECT_TRUE(contains(e.what(), part)) << e.what();
      }
    }
  };
  refused([](SlurmScriptOptions& o) { o.account = "a b"; }, "--account", "letters, digits");
  refused([](SlurmScriptOptions& o) { o.account = "proj\n#SBATCH --exclusive"; }, "--account",
          "'proj\\n#SBATCH --exclusive'");
  refused([](SlurmScriptOptions& o) { o.qos = "high;rm"; }, "--qos", "letters, digits");
  refused([](SlurmScriptOptions& o) { o.qos = std::string("lo\0ng", 5); }, "--qos", "'lo\\0ng'");
  refused([](SlurmScriptOptions& o) { o.gres = "gpu:1 --exclusive"; }, "--gres", "whitespace");
  refused([](SlurmScriptOptions& o) { o.gres = std::string("gpu\0", 4); }, "--gres", "NUL");
  refused([](SlurmScriptOptions& o) { o.partition = std::string("a\0b", 3); }, "--partition", "NUL");
  const std::string form = "allowed: --option or --option=value";
  for (const std::string bad :
       {"constraint=a100", "-C a100", "--constraint a100", "--constraint=a b", "--Constraint=x", "--", "--=x",
        "--comment=\"x\"", "#SBATCH", "", "--exclusive\n--nodes=2", "#SBATCH\t--exclusive", "--x\\y"}) {
    refused([&](SlurmScriptOptions& o) { o.sbatch_lines = {"--exclusive", bad}; }, "--sbatch", form);
  }
  // Directives fsweep writes itself, also abbreviated (sbatch reads --part as --partition).
  refused([](SlurmScriptOptions& o) { o.sbatch_lines = {"--array=0-9"}; }, "--sbatch",
          "sets --array, which fsweep slurm writes itself; the array covers the shards");
  refused([](SlurmScriptOptions& o) { o.sbatch_lines = {"#SBATCH --part=debug"}; }, "--sbatch",
          "sets --partition, which fsweep slurm writes itself; use --partition");
  refused([](SlurmScriptOptions& o) { o.sbatch_lines = {"--output=/tmp/x"}; }, "--sbatch",
          "the logs go to <out>/slurm/logs");
  refused([](SlurmScriptOptions& o) { o.sbatch_lines = {"--cpus=4"}; }, "--sbatch", "use --cpus");
  refused([](SlurmScriptOptions& o) { o.sbatch_lines = {"--acc=x"}; }, "--sbatch", "use --account");
  for (const std::string& bad :
       {std::string("echo a\necho b"), std::string("echo a\r"), std::string("a\0b", 3)}) {
    refused([&](SlurmScriptOptions& o) { o.setup_lines = {"true", bad}; }, "--setup", "is not one line");
  }
  // Near misses that are fine: longer options beginning with a reserved name, any shell text.
  SlurmScriptOptions o = options();
  o.sbatch_lines = {"--mem-per-cpu=2G", "--time-min=10", "--gres-flags=enforce-binding", "--exclusive"};
  o.setup_lines = {"", "cd \"$HOME\" && echo '$x' \\", "# a comment"};
  EXPECT_NO_THROW((void)render_slurm_array_script(o));
}

TEST(SlurmScript, ShardsRunWithTheAllocatedCpusAndAbsolutePaths) {
  const std::string s = render_slurm_array_script(options());
  EXPECT_TRUE(contains(s, "cd -- /home/u || exit 2\n"));
  EXPECT_TRUE(contains(s,
                       "/opt/fsweep/bin/fsweep run /home/u/sweeps/big.json --out /scratch/u/results/big "
                       "--shard \"$shard/$shards\""));
  EXPECT_TRUE(contains(s, "--threads \"${SLURM_CPUS_PER_TASK:-1}\" --quiet"));
  const std::string m = render_slurm_merge_script(options());
  EXPECT_TRUE(
      contains(m, "cd -- /home/u || exit 2\nexec /opt/fsweep/bin/fsweep merge /scratch/u/results/big\n"));
}

TEST(SlurmScript, RelativePathsAndUnsafeValuesAreConfigErrors) {
  const auto bad = [](auto edit) {
    SlurmScriptOptions o = options();
    edit(o);
    EXPECT_THROW((void)render_slurm_array_script(o), ConfigError);
    EXPECT_THROW((void)render_slurm_merge_script(o), ConfigError);
  };
  bad([](SlurmScriptOptions& o) { o.fsweep = "build/bin/fsweep"; });
  bad([](SlurmScriptOptions& o) { o.sweep_file = "sweeps/big.json"; });
  bad([](SlurmScriptOptions& o) { o.out_dir = "results/big"; });
  bad([](SlurmScriptOptions& o) { o.work_dir = ""; });
  bad([](SlurmScriptOptions& o) { o.out_dir = "/scratch/my results"; });
  bad([](SlurmScriptOptions& o) { o.partition = "a b"; });
  bad([](SlurmScriptOptions& o) { o.time = "1:00\n#SBATCH --exclusive"; });
  bad([](SlurmScriptOptions& o) { o.mem = "'4G'"; });
  bad([](SlurmScriptOptions& o) { o.cpus = 0; });
  bad([](SlurmScriptOptions& o) { o.shards = 0; });
  bad([](SlurmScriptOptions& o) { o.max_array_size = 0; });
  EXPECT_THROW((void)slurm_array_tasks(0, 10), ConfigError);
  EXPECT_THROW((void)slurm_array_tasks(3, 0), ConfigError);
}

TEST(SlurmScript, PathsAreShellQuotedAndPercentEscapedInOutput) {
  SlurmScriptOptions o = options();
  o.fsweep = "/home/o'neil/fsweep";
  o.work_dir = "/home/my dir";
  o.out_dir = "/scratch/100%";
  const std::string s = render_slurm_array_script(o);
  EXPECT_TRUE(contains(s, "cd -- '/home/my dir' || exit 2"));
  EXPECT_TRUE(contains(s, "'/home/o'\\''neil/fsweep' run"));
  EXPECT_TRUE(contains(s, "#SBATCH --output=/scratch/100%%/slurm/logs/%A_%a.out\n"));
  EXPECT_EQ(shell_quote("plain/path-1.json"), "plain/path-1.json");
  EXPECT_EQ(shell_quote(""), "''");
  EXPECT_EQ(shell_quote("a b"), "'a b'");
  EXPECT_EQ(shell_quote("$HOME"), "'$HOME'");
  EXPECT_EQ(shell_command({"sbatch", "--parsable", "/a b/x"}), "sbatch --parsable '/a b/x'");
}

TEST(SlurmScript, MergeWaitsForTheArrayWithAfterany) {
  EXPECT_EQ(slurm_array_submit_command("/r/big"),
            (std::vector<std::string>{"sbatch", "--parsable", "/r/big/slurm/array.sbatch"}));
  EXPECT_EQ(slurm_merge_submit_command("/r/big", "4242"),
            (std::vector<std::string>{"sbatch", "--parsable", "--dependency=afterany:4242",
                                      "/r/big/slurm/merge.sbatch"}));
  EXPECT_TRUE(contains(render_slurm_merge_script(options()), "afterany"));
}

TEST(SlurmScript, ParsesSchedulerOutput) {
  EXPECT_EQ(parse_max_array_size("MaxArraySize            = 1001\nMaxJobCount = 10000\n"), 1001U);
  EXPECT_EQ(parse_max_array_size("Foo = 1\n  MaxArraySize=3\n"), 3U);
  EXPECT_EQ(parse_max_array_size("MaxArraySize = 0\n"), 0U);
  EXPECT_EQ(parse_max_array_size("MaxJobCount = 10000\n"), std::nullopt);
  EXPECT_EQ(parse_max_array_size("MaxArraySize = lots\n"), std::nullopt);
  EXPECT_EQ(parse_max_array_size(""), std::nullopt);
  EXPECT_EQ(parse_sbatch_job_id("1234\n"), "1234");
  EXPECT_EQ(parse_sbatch_job_id("987;cluster1\n"), "987");
  EXPECT_EQ(parse_sbatch_job_id("sbatch: error: invalid partition\n"), std::nullopt);
  EXPECT_EQ(parse_sbatch_job_id(""), std::nullopt);
}

/// The lines of `text` that start with `prefix`, each with its newline.
std::string lines_starting_with(const std::string& text, const std::string& prefix) {
  std::string out;
  std::size_t at = 0;
  while (at < text.size()) {
    const std::size_t end = text.find('\n', at);
    const std::string line = text.substr(at, end == std::string::npos ? std::string::npos : end - at);
    if (line.starts_with(prefix)) out += line + "\n";
    if (end == std::string::npos) break;
    at = end + 1;
  }
  return out;
}

/// Runs `script` with bash as array task `task` (SLURM_ARRAY_TASK_ID) with a fake fsweep that
/// prints its --shard argument, and returns {exit status, output}.
std::pair<int, std::string> run_as_task(const std::string& dir, const SlurmScriptOptions& o,
                                        const std::string& task, bool fail_shard_one = false) {
  const std::string script = dir + "/array.sbatch";
  testing::write_file(script, render_slurm_array_script(o));
  testing::write_file(
      o.fsweep,
      std::string("#!/bin/sh\nwhile [ $# -gt 0 ]; do\n  [ \"$1\" = --shard ] && echo \"shard $2 "
                  "threads $4\" && ") +
          (fail_shard_one ? "[ \"$2\" = 1/" + std::to_string(o.shards) + " ] && exit 3\n" : "true\n") +
          "  shift\ndone\n");
  std::filesystem::permissions(o.fsweep, std::filesystem::perms::owner_all);
  const std::string cmd =
      "env SLURM_ARRAY_TASK_ID=" + task + " SLURM_CPUS_PER_TASK=3 bash " + script + " 2>&1";
  FILE* p = ::popen(cmd.c_str(), "r");
  std::string out;
  char buf[512];
  std::size_t n = 0;
  while ((n = std::fread(buf, 1, sizeof(buf), p)) > 0) out.append(buf, n);
  const int raw = ::pclose(p);
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, out};
}

TEST(SlurmScript, PackedTaskRunsItsShardsFromTheArrayIndex) {
  const std::string dir = testing::fresh_dir("slurm", "packed");
  SlurmScriptOptions o = options();
  o.fsweep = dir + "/fake_fsweep";
  o.work_dir = dir;
  o.shards = 7;
  o.max_array_size = 3;
  std::multiset<std::string> all;
  for (std::uint64_t t = 0; t < 3; ++t) {
    const auto [rc, out] = run_as_task(dir, o, std::to_string(t));
    EXPECT_EQ(rc, 0) << out;
    std::string want;
    for (const std::uint64_t s : slurm_task_shards(t, 7, 3)) {
      want += "shard " + std::to_string(s) + "/7 threads 3\n";
      all.insert(std::to_string(s));
    }
    const std::string got = lines_starting_with(out, "shard ");  // the fake's lines only
    EXPECT_EQ(got, want) << out;
  }
  EXPECT_EQ(all.size(), 7U);
  EXPECT_EQ(std::set<std::string>(all.begin(), all.end()).size(), 7U);
  // An index the script was not written for, or none: exit 2 without running anything.
  for (const std::string bad : {"3", "", "x"}) {
    const auto [rc, out] = run_as_task(dir, o, bad);
    EXPECT_EQ(rc, 2) << out;
    EXPECT_FALSE(contains(out, "threads")) << out;
  }
  // Setup lines run first, in order, with unset variables allowed, then the shards.
  o.setup_lines = {"echo \"setup one ${FSWEEP_SURELY_UNSET_VARIABLE}\"", "echo setup two"};
  const auto [setup_rc, setup_out] = run_as_task(dir, o, "0");
  EXPECT_EQ(setup_rc, 0) << setup_out;
  EXPECT_EQ(lines_starting_with(setup_out, "s"),
            "setup one \nsetup two\nshard 0/7 threads 3\nshard 3/7 threads 3\n"
            "shard 6/7 threads 3\n")
      << setup_out;
  o.setup_lines.clear();
  // A failing shard: the task still runs its other shards, then exits 1.
  const auto [rc, out] = run_as_task(dir, o, "1", /*fail_shard_one=*/true);
  EXPECT_EQ(rc, 1) << out;
  EXPECT_TRUE(contains(out, "shard 4/7 threads 3")) << out;
  EXPECT_TRUE(contains(out, "shard 1/7 failed (exit 3)")) << out;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace fsweep
