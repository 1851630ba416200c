// A file the machine does not let `fsweep run` write, made here with a file size limit
// (RLIMIT_FSIZE, which `ulimit -f` sets; no root needed): the command exits 1, not killed by
// SIGXFSZ, naming the file and the OS error; every file it leaves is whole; and the same command
// run again without the limit ends with the files of an uninterrupted run. The same for an
// exact weight search whose journal reaches the limit, in mode all and mode best.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <csignal>
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli/fsweep_process.hpp"
#include "core/csv_reader.hpp"
#include "sweep/sweep_test_files.hpp"

namespace test_cli_write_failures {  // not anonymous: unity builds put it beside other test files' helpers

namespace fs = std::filesystem;
using fsweep::testing::read_all;
using nlohmann::json;

/// How a process ended and what it printed.
struct Ended {
  bool exited = false;  ///< it called exit(); false: a signal killed it
  int code = -1;        ///< its exit code, when it exited
  int signal = 0;       ///< the signal that killed it, when one did
  std::string output;   ///< stdout and stderr
};

/// Runs `fsweep ARGS` with files limited to `limit_bytes` (RLIMIT_FSIZE, as `ulimit -f` limits
/// them) and SIGXFSZ at its default action, which kills: as a shell with that limit starts it.
Ended run_fsweep(std::vector<std::string> args, rlim_t limit_bytes = RLIM_INFINITY) {
  const std::string binary = std::string(FSWEEP_BINARY_DIR) + "/bin/fsweep";
  args.insert(args.begin(), binary);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::array<int, 2> pipe_fds{};
  if (::pipe(pipe_fds.data()) != 0) return {};
  const pid_t pid = ::fork();
  if (pid == 0) {  // the child: only async-signal-safe calls before exec
    ::dup2(pipe_fds[1], STDOUT_FILENO);
    ::dup2(pipe_fds[1], STDERR_FILENO);
    ::close(pipe_fds[0]);
    ::close(pipe_fds[1]);
    rlimit limit{};
    ::getrlimit(RLIMIT_FSIZE, &limit);
    limit.rlim_cur = limit_bytes;
    if (::setrlimit(RLIMIT_FSIZE, &limit) != 0) ::_exit(126);
    ::signal(SIGXFSZ, SIG_DFL);
    ::execv(binary.c_str(), argv.data());
    ::_exit(127);
  }
  ::close(pipe_fds[1]);
  Ended e;
  std::array<char, 4096> buf{};
  for (ssize_t n = 0; (n = ::read(pipe_fds[0], buf.data(), buf.size())) > 0;)
    e.output.append(buf.data(), static_cast<std::size_t>(n));
  ::close(pipe_fds[0]);
  int status = 0;
  if (pid < 0 || ::waitpid(pid, &status, 0) != pid) return e;
  e.exited = WIFEXITED(status);
  e.code = e.exited ? WEXITSTATUS(status) : -1;
  e.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
  return e;
}

/// Expects `e` to be fsweep's exit 1 on a file it could not write: exited (not killed by
/// SIGXFSZ), one message naming `file` and the OS error, and what to do.
void expect_file_too_large(const Ended& e, const std::string& file, const std::string& note) {
  EXPECT_TRUE(e.exited) << "killed by signal " << e.signal << "\n" << e.output;
  EXPECT_EQ(e.code, 1) << e.output;
  EXPECT_NE(e.output.find("fsweep: error: " + file + ": write failed: File too large (" + note + ")"),
            std::string::npos)
      << e.output;
}

const std::string kResumeNote =
    "nothing was lost: rerun the same command to resume once the file size limit is raised";

/// The records of a CSV file without its `*_time_s` columns (they measure the machine, the only
/// cells that differ between equivalent runs); fails the test when the file is not whole (a
/// record cut short, a record with another field count than the header's).
std::vector<std::vector<std::string>> rows_without_timing(const std::string& path) {
  std::vector<std::vector<std::string>> rows;
  try {
    fsweep::CsvReader in(path);  // a last record without its newline is an error
    std::vector<bool> keep;
    std::vector<std::string> header;
    for (const std::string& name : in.header()) {
      keep.push_back(!name.ends_with("_time_s") && name.find("_time_s.") == std::string::npos);
      if (keep.back()) header.push_back(name);
    }
    rows.push_back(header);
    while (in.next()) {
      std::vector<std::string> row;
      for (std::size_t i = 0; i < in.fields().size(); ++i) {
        if (keep[i]) row.push_back(in.fields()[i]);
      }
      rows.push_back(std::move(row));
    }
  } catch (const std::exception& e) {
    ADD_FAILURE() << path << " is not whole: " << e.what();
  }
  return rows;
}

/// Expects every line of the JSON-lines file `path` to be whole JSON; returns the line count.
std::size_t whole_json_lines(const std::string& path) {
  const std::string text = read_all(path);
  EXPECT_TRUE(text.empty() || text.back() == '\n') << path << " ends in a torn line";
  std::size_t lines = 0;
  std::size_t begin = 0;
  for (std::size_t end = text.find('\n'); end != std::string::npos; end = text.find('\n', begin)) {
    EXPECT_FALSE(json::parse(text.substr(begin, end - begin), nullptr, false).is_discarded())
        << path << ":" << lines + 1;
    ++lines;
    begin = end + 1;
  }
  return lines;
}

/// Expects no temp file of a replaced file (`<name>.tmp.<pid>`) in `dir`.
void expect_no_temp_files(const std::string& dir) {
  for (const fs::directory_entry& e : fs::directory_iterator(dir)) {
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
  }
}

std::string manifest_status(const std::string& dir) {
  return json::parse(read_all(dir + "/manifest.json")).value("status", std::string());
}

/// 12 runs: one rooms map, 3 strategy configurations, 4 repetitions (runs.csv about 6 KB,
/// summary.csv about 12 KB).
std::string write_run_sweep(const std::string& dir) {
  fs::create_directories(dir);
  const std::string path = dir + "/sweep.json";
  fsweep::testing::write_file(path, R"({"schema_version": 1, "name": "write_failures",
    "maps": ["rooms:w=24,h=20,door=2,seed=2"],
    "strategies": [{"name": "closest_frontier"}, {"name": "energy_aware", "params": {"w1": [0, 10]}}],
    "repetitions": 4, "seed": 1})");
  return path;
}

/// The exact weight search of [0, 3]^4 on an office map in `mode` (all: 194 behaviours, a
/// journal of about 95 KB; best: about 56 KB), without a brute-force entry.
std::string write_search_sweep(const std::string& dir, const std::string& mode) {
  fs::create_directories(dir);
  const json axis = {{"range", {0, 3}}, {"step", 1}};
  json search = {{"method", "exact"}, {"mode", mode}};
  if (mode == "all") search["write_vectors"] = true;
  const json sweep = {{"schema_version", 1},
                      {"name", "write_failures_search"},
                      {"maps", {"office:w=32,h=32,seed=3"}},
                      {"strategies",
                       {{{"name", "energy_aware"},
                         {"label", "exact"},
                         {"search", search},
                         {"params", {{"w1", axis}, {"w2", axis}, {"w3", axis}, {"w4", axis}}}}}},
                      {"robot", {{"sensor", {{"range_m", 3}}}, {"battery", 120}}},
                      {"repetitions", 1},
                      {"seed", 5}};
  const std::string path = dir + "/sweep.json";
  fsweep::testing::write_file(path, sweep.dump(2));
  return path;
}

std::vector<std::string> run_args(const std::string& sweep, const std::string& out) {
  return {"run", sweep, "--threads", "2", "--quiet", "--out", out};
}

TEST(CliWriteFailures, ARunThatReachesTheFileSizeLimitExits1AndTheRerunEqualsAnUninterruptedRun) {
  const std::string dir = fsweep::testing::fresh_temp_dir("write_failures", "runs");
  const std::string sweep = write_run_sweep(dir);
  const std::string ref = dir + "/ref";
  const std::string out = dir + "/limited";
  ASSERT_EQ(run_fsweep(run_args(sweep, ref)).code, 0);

  // Half of runs.csv: it reaches the limit with about half of the runs written, before
  // progress.csv (the other file appended to, run by run) whose rows take fewer bytes.
  ASSERT_GT(fs::file_size(ref + "/runs.csv"), fs::file_size(ref + "/progress.csv"));
  const auto limit = static_cast<rlim_t>(fs::file_size(ref + "/runs.csv") / 2);
  const Ended limited = run_fsweep(run_args(sweep, out), limit);
  expect_file_too_large(limited, out + "/runs.csv", kResumeNote);
  const std::size_t rows = rows_without_timing(out + "/runs.csv").size() - 1;
  EXPECT_GT(rows, 0U);
  EXPECT_LT(rows, 12U);
  (void)rows_without_timing(out + "/progress.csv");
  EXPECT_EQ(manifest_status(out), "failed");
  EXPECT_FALSE(fs::exists(out + "/summary.csv"));
  expect_no_temp_files(out);

  const Ended again = run_fsweep(run_args(sweep, out));
  ASSERT_EQ(again.code, 0) << again.output;
  EXPECT_NE(again.output.find(std::to_string(rows) + " already done"), std::string::npos) << again.output;
  for (const char* f : {"runs.csv", "summary.csv", "best.csv", "progress_summary.csv"}) {
    EXPECT_EQ(rows_without_timing(out + "/" + f), rows_without_timing(ref + "/" + f)) << f;
  }
  EXPECT_EQ(read_all(out + "/progress.csv"), read_all(ref + "/progress.csv"));
  EXPECT_EQ(manifest_status(out), "complete");
}

TEST(CliWriteFailures, AFileWrittenWholeThatReachesTheLimitLeavesTheOldFileAndNoTempFile) {
  const std::string dir = fsweep::testing::fresh_temp_dir("write_failures", "whole");
  const std::string sweep = write_run_sweep(dir);
  const std::string out = dir + "/out";
  // Between runs.csv and summary.csv: the runs finish, the aggregation's summary.csv fails.
  const std::string ref = dir + "/ref";
  ASSERT_EQ(run_fsweep(run_args(sweep, ref)).code, 0);
  const std::uintmax_t runs = fs::file_size(ref + "/runs.csv");
  const std::uintmax_t summary = fs::file_size(ref + "/summary.csv");
  ASSERT_GT(summary, runs + 1000);
  const auto limit = static_cast<rlim_t>((runs + summary) / 2);

  const Ended limited = run_fsweep(run_args(sweep, out), limit);
  expect_file_too_large(limited, out + "/summary.csv", kResumeNote);
  EXPECT_EQ(rows_without_timing(out + "/runs.csv").size(), 13U);  // the header and every run
  EXPECT_FALSE(fs::exists(out + "/summary.csv"));
  expect_no_temp_files(out);
  const Ended again = run_fsweep(run_args(sweep, out));
  ASSERT_EQ(again.code, 0) << again.output;
  EXPECT_NE(again.output.find("0 ran, 12 already done"), std::string::npos) << again.output;
  EXPECT_EQ(rows_without_timing(out + "/summary.csv"), rows_without_timing(ref + "/summary.csv"));

  // An existing file stays as it was: `fsweep aggregate` rewrites summary.csv under the limit.
  const std::string before = read_all(out + "/summary.csv");
  const Ended aggregate = run_fsweep({"aggregate", out}, limit);
  EXPECT_TRUE(aggregate.exited) << aggregate.output;
  EXPECT_EQ(aggregate.code, 1) << aggregate.output;
  EXPECT_NE(aggregate.output.find(out + "/summary.csv: write failed: File too large"), std::string::npos)
      << aggregate.output;
  EXPECT_EQ(read_all(out + "/summary.csv"), before);
  expect_no_temp_files(out);
}

TEST(CliWriteFailures, AWeightSearchWhoseJournalReachesTheLimitExits1AndTheRerunFinishesIt) {
  for (const std::string mode : {"all", "best"}) {
    const std::string dir = fsweep::testing::fresh_temp_dir("write_failures", "search_" + mode);
    const std::string sweep = write_search_sweep(dir, mode);
    const std::string ref = dir + "/ref";
    const std::string out = dir + "/limited";
    ASSERT_EQ(run_fsweep(run_args(sweep, ref)).code, 0) << mode;
    const std::string journal = out + "/search_journal.jsonl";
    const std::uintmax_t journal_bytes = fs::file_size(ref + "/search_journal.jsonl");
    ASSERT_GT(journal_bytes, 40'000U) << mode << ": the other files must stay below half of it";

    const Ended limited = run_fsweep(run_args(sweep, out), static_cast<rlim_t>(journal_bytes / 2));
    expect_file_too_large(limited, journal, kResumeNote);
    EXPECT_GT(whole_json_lines(journal), 0U) << mode;
    EXPECT_FALSE(fs::exists(out + "/searches.json")) << mode;
    EXPECT_EQ(manifest_status(out), "failed") << mode;
    if (mode == "best") (void)rows_without_timing(out + "/search_anytime.csv");
    expect_no_temp_files(out);
    const std::string kept = read_all(journal);

    const Ended again = run_fsweep(run_args(sweep, out));
    ASSERT_EQ(again.code, 0) << mode << "\n" << again.output;
    // The rerun went on from the journal (not from the start), which now holds the whole search.
    const std::string resumed = read_all(journal);
    EXPECT_TRUE(resumed.starts_with(kept)) << mode;
    EXPECT_GT(resumed.size(), kept.size()) << mode;
    std::vector<std::string> files{"behaviours.csv", "search_best.csv"};
    if (mode == "all") {
      for (const char* f : {"search_summary.csv", "search_ranks.csv", "search_heatmaps.csv", "vectors.csv"})
        files.emplace_back(f);
    }
    for (const std::string& f : files)
      EXPECT_EQ(read_all(out + "/" + f), read_all(ref + "/" + f)) << mode << ": " << f;
    const json record = json::parse(read_all(out + "/searches.json"))["searches"][0];
    if (mode == "all") {
      EXPECT_GT(record["resumed_behaviours"].get<std::size_t>(), 0U);
    }
    if (mode == "best") {
      const json whole = json::parse(read_all(ref + "/searches.json"))["searches"][0];
      EXPECT_EQ(record["certificate"]["optimum"], whole["certificate"]["optimum"]);
      EXPECT_EQ(record["certificate"]["file"], "search_certificate_0.jsonl") << record["certificate"].dump();
    }
  }
}

TEST(CliWriteFailures, TheOtherCommandsReportAFileTheyCannotWriteTheSameWay) {
  // fsweep sim's CSVs (and plan-bench's, plan-compare's, slurm's script: the same helper) under
  // a limit smaller than its run.csv: exit 1 naming the file and the OS error, no file cut
  // short, no temp file left.
  const std::string out = fsweep::testing::fresh_dir("write_failures", "sim");
  const Ended e = run_fsweep({"sim", "--map", "rooms:w=40,h=30,door=3,seed=1", "--strategy",
                              "closest_frontier", "--robot", "sensor.range_m=6", "--out", out},
                             100);
  EXPECT_TRUE(e.exited) << "killed by signal " << e.signal << "\n" << e.output;
  EXPECT_EQ(e.code, 1) << e.output;
  EXPECT_NE(e.output.find(": write failed: File too large"), std::string::npos) << e.output;
  EXPECT_NE(e.output.find(out + "/"), std::string::npos) << e.output;
  for (const auto& entry : fs::directory_iterator(out)) {
    EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << entry.path();
    if (entry.path().extension() == ".csv") {
      EXPECT_LE(fs::file_size(entry.path()), 100U) << entry.path();
    }
  }
}

}  // namespace test_cli_write_failures
