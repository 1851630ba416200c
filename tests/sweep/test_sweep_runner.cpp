// The sweep runner: outputs independent of the thread count, resume after SIGKILL, torn lines,
// Ctrl-C, changed sweeps, failed runs, the competitive-ratio columns and the manifest.
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "core/config_error.hpp"
#include "core/csv_format.hpp"
#include "report/paired.hpp"
#include "report/report_tables.hpp"
#include "sweep/csv_journal.hpp"
#include "sweep/merge.hpp"
#include "sweep/sweep_plan.hpp"
#include "sweep/sweep_runner.hpp"
#include "sweep/sweep_table.hpp"
#include "sweep/sweep_test_files.hpp"
#include "sweep/sweep_test_run.hpp"

extern char** environ;  // NOLINT(readability-redundant-declaration): for posix_spawn

namespace fsweep {
namespace test_sweep_runner {  // not anonymous: unity builds put it beside other test files' helpers

namespace fs = std::filesystem;
using nlohmann::json;

constexpr const char* kChildSweepEnv = "FSWEEP_RUNNER_CHILD_SWEEP";
constexpr const char* kChildOutEnv = "FSWEEP_RUNNER_CHILD_OUT";

std::string temp_dir(const std::string& name) { return testing::fresh_dir("runner", name); }

using testing::read_file;
using testing::write_file;

/// 2 maps x 3 strategy configurations x 2 sensor ranges x 4 repetitions = 48 runs of varied
/// length (so that with 2 threads they finish out of order).
json small_sweep() {
  return json::parse(R"({
    "schema_version": 1,
    "name": "runner_test",
    "maps": ["rooms:w=30,h=24,door=3,seed=1", "rooms:w=24,h=20,door=2,seed=2"],
    "strategies": [{"name": "closest_frontier"}, {"name": "energy_aware", "params": {"w1": [0, 10]}}],
    "robot": {"sensor": {"range_m": [4, 7]}},
    "repetitions": 4,
    "seed": 11
  })");
}

/// 96 longer runs (about 0.5 s on 2 threads), for killing and interrupting mid-way.
json long_sweep() {
  json sweep = small_sweep();
  sweep["maps"] = {"rooms:w=60,h=45,door=3,seed=1", "rooms:w=50,h=40,door=3,seed=2"};
  sweep["repetitions"] = 8;
  return sweep;
}

RunnerReport run(const json& sweep, const std::string& dir, int threads, bool fresh = false) {
  RunnerOptions o = testing::quiet_runner(dir, threads);
  o.fresh = fresh;
  return run_sweep(SweepPlan::from_json(sweep, "test.json"), o);
}

/// CSV records (quoted newlines stay inside their record), without the newlines.
std::vector<std::string> records(const std::string& text) {
  std::vector<std::string> out;
  std::string cur;
  bool quoted = false;
  for (const char c : text) {
    if (c == '"') quoted = !quoted;
    if (c == '\n' && !quoted) {
      out.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  if (!cur.empty()) out.push_back(cur);
  return out;
}

/// The records as CSV text again, one per line.
std::string joined_records(const std::vector<std::string>& recs) {
  std::string out;
  for (const auto& r : recs) out += r + "\n";
  return out;
}

/// The CSV text with the columns named `*_time_s` (and summary.csv's `*_time_s.<statistic>`)
/// removed: they measure the machine, so they are the only cells allowed to differ between
/// equivalent runs.
std::string without_timing(const std::string& text) {
  const auto recs = records(text);
  if (recs.empty()) return {};
  const auto header = split_csv_line(recs[0]);
  std::vector<bool> keep(header.size());
  for (std::size_t i = 0; i < header.size(); ++i) {
    keep[i] = !header[i].ends_with("_time_s") && header[i].find("_time_s.") == std::string::npos;
  }
  std::string out;
  for (const auto& r : recs) {
    const auto f = split_csv_line(r);
    EXPECT_EQ(f.size(), header.size()) << r;
    for (std::size_t i = 0; i < f.size() && i < keep.size(); ++i) {
      if (keep[i]) out += csv_field(f[i]) + ",";
    }
    out += "\n";
  }
  return out;
}

std::vector<std::string> column(const std::string& csv_text, const std::string& name) {
  const auto recs = records(csv_text);
  const auto header = split_csv_line(recs.at(0));
  const auto it = std::find(header.begin(), header.end(), name);
  EXPECT_NE(it, header.end()) << name;
  if (it == header.end()) return {};
  const auto c = static_cast<std::size_t>(it - header.begin());
  std::vector<std::string> out;
  for (std::size_t i = 1; i < recs.size(); ++i) out.push_back(split_csv_line(recs[i]).at(c));
  return out;
}

void expect_same_outputs(const std::string& a, const std::string& b) {
  const std::string runs_a = read_file(a + "/runs.csv");
  ASSERT_FALSE(runs_a.empty());
  EXPECT_EQ(without_timing(runs_a), without_timing(read_file(b + "/runs.csv")));
  EXPECT_EQ(read_file(a + "/progress.csv"), read_file(b + "/progress.csv"));
}

std::size_t data_rows(const std::string& path) { return records(read_file(path)).size() - 1; }

/// What a resumed small_sweep() reported and printed on stderr.
struct Resumed {
  RunnerReport report;
  std::string err;
};

/// Resumes small_sweep() in `dir` with `runs` as its runs.csv and the progress.csv and
/// manifest.json of `ref`, a finished run of it (a damaged or edited journal).
Resumed resume_with_runs(const std::string& ref, const std::string& dir, const std::string& runs) {
  write_file(dir + "/runs.csv", runs);
  fs::copy_file(ref + "/progress.csv", dir + "/progress.csv");
  fs::copy_file(ref + "/manifest.json", dir + "/manifest.json");
  ::testing::internal::CaptureStderr();
  const RunnerReport r = run(small_sweep(), dir, 2);
  return {r, ::testing::internal::GetCapturedStderr()};
}

/// Starts this test binary again running only SweepRunnerChild (the sweep named by the
/// environment): a fresh process, as fork() would not be safe after oneTBB started threads.
pid_t spawn_child(const std::string& sweep_file, const std::string& out) {
  ::setenv(kChildSweepEnv, sweep_file.c_str(), 1);
  ::setenv(kChildOutEnv, out.c_str(), 1);
  // This process may be one shard of its executable (the sanitizer build's ctest): the child
  // runs its one test whatever shard that test falls in (gtest read these at start-up already).
  ::unsetenv("GTEST_TOTAL_SHARDS");
  ::unsetenv("GTEST_SHARD_INDEX");
  std::string self = fs::read_symlink("/proc/self/exe").string();
  std::string filter = "--gtest_filter=SweepRunnerChild.RunsTheSweepNamedInTheEnvironment";
  char* argv[] = {self.data(), filter.data(), nullptr};
  pid_t pid = -1;
  const int rc = ::posix_spawn(&pid, self.c_str(), nullptr, nullptr, argv, environ);
  ::unsetenv(kChildSweepEnv);
  ::unsetenv(kChildOutEnv);
  return rc == 0 ? pid : -1;
}

TEST(SweepRunnerChild, RunsTheSweepNamedInTheEnvironment) {
  const char* sweep = std::getenv(kChildSweepEnv);
  const char* out = std::getenv(kChildOutEnv);
  if (sweep == nullptr || out == nullptr) GTEST_SKIP() << "only runs as the child of ResumeAfterSigkill";
  RunnerOptions o = testing::quiet_runner(out);
  (void)run_sweep(SweepPlan::from_file(sweep), o);
}

TEST(SweepRunner, ThreadsDoNotChangeOutputs) {
  const std::string one = temp_dir("threads1");
  const std::string two = temp_dir("threads2");
  const RunnerReport r1 = run(small_sweep(), one, 1);
  const RunnerReport r2 = run(small_sweep(), two, 2);
  EXPECT_EQ(r1.total, 48U);
  EXPECT_EQ(r1.ran, 48U);
  EXPECT_EQ(r2.ran, 48U);
  EXPECT_FALSE(r2.interrupted);
  EXPECT_EQ(data_rows(one + "/runs.csv"), 48U);
  expect_same_outputs(one, two);
  // Rows are in run-index order.
  const auto index = column(read_file(two + "/runs.csv"), "run_index");
  for (std::size_t i = 0; i < index.size(); ++i) EXPECT_EQ(index[i], std::to_string(i));
  fs::remove_all(one);
  fs::remove_all(two);
}

/// Starts `sweep` writing to `dir` in a child process and kills it (SIGKILL) once runs.csv has
/// 3 rows; returns the rows it had then.
std::size_t kill_mid_sweep(const json& sweep, const std::string& dir) {
  const std::string sweep_file = dir + "/sweep.json";
  write_file(sweep_file, sweep.dump(2));
  const pid_t pid = spawn_child(sweep_file, dir);
  EXPECT_GT(pid, 0);
  if (pid <= 0) return 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (std::chrono::steady_clock::now() < deadline) {
    if (fs::exists(dir + "/runs.csv") && data_rows(dir + "/runs.csv") >= 3) break;
    std::this_thread::sleep_for(std::chrono::microseconds(500));
  }
  ::kill(pid, SIGKILL);
  int status = 0;
  ::waitpid(pid, &status, 0);
  EXPECT_TRUE(WIFSIGNALED(status)) << "the child finished before it could be killed";
  EXPECT_EQ(nlohmann::json::parse(read_file(dir + "/manifest.json"))["status"], "running");
  return data_rows(dir + "/runs.csv");
}

/// Cuts the file in the middle of its last record, as a kill during its write(2) would.
void tear_last_line(const std::string& path) {
  const std::string text = read_file(path);
  const std::string last = records(text).back();
  const std::size_t start = text.size() - (text.ends_with('\n') ? 1 : 0) - last.size();
  ASSERT_GT(last.size(), 1U);
  fs::resize_file(path, start + last.size() / 2);
}

TEST(SweepRunner, ResumeAfterSigkillEqualsUninterrupted) {
  const json sweep = long_sweep();
  const std::string ref = temp_dir("sigkill_ref");
  const std::string killed = temp_dir("sigkill");
  ASSERT_EQ(run(sweep, ref, 2).ran, 96U);
  ASSERT_LT(kill_mid_sweep(sweep, killed), 96U);

  const RunnerReport r = run(sweep, killed, 2);
  EXPECT_EQ(r.skipped + r.ran, 96U);
  EXPECT_GE(r.skipped, 3U);
  expect_same_outputs(ref, killed);
  EXPECT_EQ(nlohmann::json::parse(read_file(killed + "/manifest.json"))["status"], "complete");
  fs::remove_all(ref);
  fs::remove_all(killed);
}

// A kill rarely lands inside a write(2); this one is made to: both files end mid-line.
TEST(SweepRunner, ResumeAfterSigkillThatTornTheLastLinesEqualsUninterrupted) {
  const json sweep = long_sweep();
  const std::string ref = temp_dir("sigkill_torn_ref");
  const std::string killed = temp_dir("sigkill_torn");
  ASSERT_EQ(run(sweep, ref, 2).ran, 96U);
  const std::size_t done_at_kill = kill_mid_sweep(sweep, killed);
  ASSERT_LT(done_at_kill, 96U);
  ASSERT_GE(done_at_kill, 3U);
  tear_last_line(killed + "/runs.csv");
  tear_last_line(killed + "/progress.csv");
  ASSERT_NE(read_file(killed + "/runs.csv").back(), '\n');
  ASSERT_NE(read_file(killed + "/progress.csv").back(), '\n');

  ::testing::internal::CaptureStderr();
  const RunnerReport r = run(sweep, killed, 2);
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(r.skipped, done_at_kill - 1);  // the torn row's run is done again
  EXPECT_EQ(r.skipped + r.ran, 96U);
  EXPECT_NE(err.find("runs.csv:" + std::to_string(done_at_kill + 1) + ": the last line is cut short"),
            std::string::npos)
      << err;
  // Nothing lost, nothing twice, in run order (and the same bytes as an uninterrupted sweep).
  const auto index = column(read_file(killed + "/runs.csv"), "run_index");
  ASSERT_EQ(index.size(), 96U);
  for (std::size_t i = 0; i < index.size(); ++i) EXPECT_EQ(index[i], std::to_string(i));
  expect_same_outputs(ref, killed);
  fs::remove_all(ref);
  fs::remove_all(killed);
}

TEST(SweepRunner, DamagedRowsInTheMiddleAreReportedAndRedoneInRunOrder) {
  const std::string ref = temp_dir("damaged_ref");
  const std::string dir = temp_dir("damaged");
  ASSERT_EQ(run(small_sweep(), ref, 2).ran, 48U);

  // runs.csv: run 5's row lost its last 3 fields (line 7), a garbage line follows run 20's row
  // (line 23), run 30's row has a carriage return in its run_key (line 33). progress.csv whole.
  const auto run_recs = records(read_file(ref + "/runs.csv"));
  ASSERT_EQ(run_recs.size(), 49U);
  std::string runs = run_recs[0] + "\n";
  for (std::size_t i = 1; i < run_recs.size(); ++i) {
    std::string rec = run_recs[i];
    if (i == 6) {
      auto f = split_csv_line(rec);
      f.resize(f.size() - 3);
      rec = csv_record(f);
    }
    if (i == 31) rec.insert(rec.find(',') + 1, "\r");
    runs += rec + "\n";
    if (i == 21) runs += "#### not a row ####\n";
  }
  const auto [r, err] = resume_with_runs(ref, dir, runs);
  EXPECT_EQ(r.skipped, 46U);
  EXPECT_EQ(r.ran, 2U);
  expect_same_outputs(ref, dir);  // in run order, each run once
  for (const std::string& expected :
       {dir + "/runs.csv:7: the line has " + std::to_string(split_csv_line(run_recs[6]).size() - 3) +
            " fields, where the header has " + std::to_string(split_csv_line(run_recs[6]).size()),
        dir + "/runs.csv:23: the line has 1 field, where",
        dir + "/runs.csv:33: a carriage return (\\r) inside the line", std::string("run 5 (run_key "),
        std::string("run 30 (run_key ")}) {
    EXPECT_NE(err.find(expected), std::string::npos) << expected << "\nnot in:\n" << err;
  }
  EXPECT_NE(err.find(dir + "/progress.csv:"), std::string::npos) << err;
  fs::remove_all(ref);
  fs::remove_all(dir);
}

TEST(SweepRunner, TornLinesAreDroppedAndRedone) {
  const std::string ref = temp_dir("torn_ref");
  const std::string torn = temp_dir("torn");
  ASSERT_EQ(run(small_sweep(), ref, 2).ran, 48U);

  // runs.csv: the header, 10 complete rows and half of the 11th, with no newline; progress.csv:
  // the rows of runs 0..10 (run 10 has no runs.csv row: it was not done) and half a row of 11.
  const auto run_recs = records(read_file(ref + "/runs.csv"));
  std::string runs = run_recs[0] + "\n";
  for (int i = 1; i <= 10; ++i) runs += run_recs[static_cast<std::size_t>(i)] + "\n";
  runs += run_recs[11].substr(0, run_recs[11].size() / 2);
  std::string progress;
  const auto progress_recs = records(read_file(ref + "/progress.csv"));
  progress += progress_recs[0] + "\n";
  std::string run11;
  for (std::size_t i = 1; i < progress_recs.size(); ++i) {
    const auto f = split_csv_line(progress_recs[i]);
    if (std::stoi(f[0]) <= 10) progress += progress_recs[i] + "\n";
    if (std::stoi(f[0]) == 11 && run11.empty()) run11 = progress_recs[i];
  }
  ASSERT_FALSE(run11.empty());
  progress += run11.substr(0, run11.size() / 2);
  write_file(torn + "/runs.csv", runs);
  write_file(torn + "/progress.csv", progress);
  fs::copy_file(ref + "/manifest.json", torn + "/manifest.json");
  write_file(torn + "/progress.csv.tmp.99999", "left by a runner killed mid-rewrite");

  const RunnerReport r = run(small_sweep(), torn, 2);
  EXPECT_EQ(r.skipped, 10U);
  EXPECT_EQ(r.ran, 38U);
  expect_same_outputs(ref, torn);
  EXPECT_FALSE(fs::exists(torn + "/progress.csv.tmp.99999"));
  fs::remove_all(ref);
  fs::remove_all(torn);
}

TEST(SweepRunner, InterruptStopsAfterFlushingAndResumes) {
  const json sweep = long_sweep();
  const std::string ref = temp_dir("sigint_ref");
  const std::string dir = temp_dir("sigint");
  ASSERT_EQ(run(sweep, ref, 2).ran, 96U);

  testing::InterruptWhen interrupter(
      [&] { return fs::exists(dir + "/runs.csv") && data_rows(dir + "/runs.csv") >= 3; });
  const RunnerReport first = run(sweep, dir, 2);
  interrupter.join();
  ASSERT_TRUE(first.interrupted) << "the sweep finished before the interrupt";
  EXPECT_LT(first.ran, 96U);
  // Everything that ran was flushed: one complete row per run.
  EXPECT_EQ(data_rows(dir + "/runs.csv"), first.ran);
  EXPECT_EQ(read_file(dir + "/runs.csv").back(), '\n');
  EXPECT_EQ(nlohmann::json::parse(read_file(dir + "/manifest.json"))["status"], "interrupted");
  EXPECT_FALSE(fs::exists(dir + "/summary.csv"));

  const RunnerReport second = run(sweep, dir, 2);
  EXPECT_FALSE(second.interrupted);
  EXPECT_EQ(second.skipped, first.ran);
  expect_same_outputs(ref, dir);
  fs::remove_all(ref);
  fs::remove_all(dir);
}

TEST(SweepRunner, AStopSignalSentTwiceAtOnceStopsOnce) {
  // timeout(1) sends its signal to the process and then to its process group: two SIGINTs
  // within milliseconds are one stop (a second one a second or more later would kill). Runs
  // on a large map keep the sweep stopping (finishing its runs in flight) when the second comes.
  json sweep = long_sweep();
  sweep["maps"] = {"rooms:w=240,h=180,door=3,seed=1"};
  const std::string dir = temp_dir("sigint_twice");
  testing::InterruptWhen interrupter(
      [&] { return fs::exists(dir + "/runs.csv") && data_rows(dir + "/runs.csv") >= 3; }, 2);
  const RunnerReport first = run(sweep, dir, 2);
  interrupter.join();
  ASSERT_TRUE(first.interrupted) << "the sweep finished before the interrupt";
  EXPECT_EQ(nlohmann::json::parse(read_file(dir + "/manifest.json"))["status"], "interrupted");
  fs::remove_all(dir);
}

TEST(SweepRunner, ResumeSkipsDone) {
  const std::string dir = temp_dir("skip");
  ASSERT_EQ(run(small_sweep(), dir, 2).ran, 48U);
  const std::string runs = read_file(dir + "/runs.csv");
  const std::string progress = read_file(dir + "/progress.csv");
  const RunnerReport again = run(small_sweep(), dir, 2);
  EXPECT_EQ(again.ran, 0U);
  EXPECT_EQ(again.skipped, 48U);
  EXPECT_FALSE(again.interrupted);
  EXPECT_EQ(read_file(dir + "/runs.csv"), runs);  // byte-identical, timing columns included
  EXPECT_EQ(read_file(dir + "/progress.csv"), progress);
  fs::remove_all(dir);
}

TEST(SweepRunner, ChangedSweepRefusesWithoutFresh) {
  const std::string dir = temp_dir("changed");
  ASSERT_EQ(run(small_sweep(), dir, 2).ran, 48U);
  json changed = small_sweep();
  changed["seed"] = 12;
  try {
    (void)run(changed, dir, 2);
    FAIL() << "a changed sweep was accepted";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("--fresh"), std::string::npos) << e.what();
  }
  const RunnerReport fresh = run(changed, dir, 2, true);
  EXPECT_EQ(fresh.ran, 48U);
  EXPECT_EQ(fresh.skipped, 0U);
  EXPECT_EQ(column(read_file(dir + "/runs.csv"), "seed").size(), 48U);

  // Without the manifest, runs.csv's columns still tell a different sweep apart.
  fs::remove(dir + "/manifest.json");
  json other = small_sweep();
  other["strategies"] = json::parse(R"([{"name": "closest_frontier"}])");
  EXPECT_THROW((void)run(other, dir, 2), ConfigError);
  fs::remove_all(dir);
}

/// A 12x10 MovingAI map: walls around, free inside, start (2, 2).
std::string small_movingai_map() {
  std::string text = "type octile\nheight 10\nwidth 12\nmap\n";
  for (int y = 0; y < 10; ++y) {
    for (int x = 0; x < 12; ++x) text += (x == 0 || y == 0 || x == 11 || y == 9) ? '@' : '.';
    text += '\n';
  }
  return text;
}

TEST(SweepRunner, AnEditedMapFileIsRefusedAndNothingIsTouched) {
  const std::string dir = temp_dir("edited_map");
  const std::string map_dir = temp_dir("edited_map_files");
  const std::string map_path = map_dir + "/m.map";
  write_file(map_path, small_movingai_map());
  json sweep = small_sweep();
  sweep["maps"] = json::array({json{{"file", map_path}, {"start", "2;2"}}});
  ASSERT_EQ(run(sweep, dir, 2).ran, 24U);
  // The same file content again: every run is done.
  EXPECT_EQ(run(sweep, dir, 2).skipped, 24U);
  const auto manifest = json::parse(read_file(dir + "/manifest.json"));
  ASSERT_EQ(manifest["maps"].size(), 1U);
  EXPECT_EQ(manifest["maps"][0]["content_hash"].get<std::string>().size(), 16U);
  const std::string runs = read_file(dir + "/runs.csv");
  const std::string progress = read_file(dir + "/progress.csv");
  const std::vector<std::string> keys = column(runs, "run_key");

  // One cell of the file becomes a wall: same sweep file, same path, other map.
  std::string edited = small_movingai_map();
  edited[edited.find("map\n") + 4 + 5 * 13 + 6] = '@';  // row 5, column 6
  write_file(map_path, edited);
  try {
    (void)run(sweep, dir, 2);
    FAIL() << "results of the old map content were resumed";
  } catch (const ConfigError& e) {
    const std::string what = e.what();
    for (const std::string& part : {dir + ": holds the results of other maps", std::string(map_path),
                                    std::string("changed: content hash"), std::string("--fresh")}) {
      EXPECT_NE(what.find(part), std::string::npos) << part << "\nnot in: " << what;
    }
  }
  EXPECT_EQ(read_file(dir + "/runs.csv"), runs);  // nothing touched
  EXPECT_EQ(read_file(dir + "/progress.csv"), progress);
  EXPECT_EQ(json::parse(read_file(dir + "/manifest.json")), manifest);

  // Every run of the edited map has another key.
  ASSERT_EQ(run(sweep, dir, 2, true).ran, 24U);
  const std::vector<std::string> new_keys = column(read_file(dir + "/runs.csv"), "run_key");
  ASSERT_EQ(new_keys.size(), keys.size());
  for (std::size_t i = 0; i < keys.size(); ++i) EXPECT_NE(new_keys[i], keys[i]) << i;
  fs::remove_all(dir);
  fs::remove_all(map_dir);
}

TEST(SweepRunner, RowsWhoseKeyIsNotTheSweepsAreRefused) {
  const std::string dir = temp_dir("stale_keys");
  ASSERT_EQ(run(small_sweep(), dir, 2).ran, 48U);
  auto recs = records(read_file(dir + "/runs.csv"));
  // Run 7's row with another valid key, as results of other inputs or another fsweep have.
  auto f = split_csv_line(recs[8]);
  ASSERT_EQ(f[0], "7");
  const std::string old_key = f[1];
  f[1] = old_key == "0123456789abcdef" ? "fedcba9876543210" : "0123456789abcdef";
  recs[8] = csv_record(f);
  const std::string runs = joined_records(recs);
  write_file(dir + "/runs.csv", runs);
  const std::string progress = read_file(dir + "/progress.csv");
  try {
    (void)run(small_sweep(), dir, 2);
    FAIL() << "a row of other inputs was accepted";
  } catch (const ConfigError& e) {
    const std::string what = e.what();
    for (const std::string& part :
         {dir + "/runs.csv: 1 of its 48 runs have another run_key",
          "run 7: " + f[1] + " in the file, " + old_key + " now", std::string("--fresh")}) {
      EXPECT_NE(what.find(part), std::string::npos) << part << "\nnot in: " << what;
    }
  }
  EXPECT_EQ(read_file(dir + "/runs.csv"), runs);  // nothing touched
  EXPECT_EQ(read_file(dir + "/progress.csv"), progress);

  // A manifest of an fsweep that did not record the maps' content: refused, since keys changed.
  json manifest = json::parse(read_file(dir + "/manifest.json"));
  manifest.erase("maps");
  write_file(dir + "/manifest.json", manifest.dump(2));
  try {
    (void)run(small_sweep(), dir, 2);
    FAIL() << "a manifest without map contents was resumed";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("does not record the maps' content"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

TEST(SweepRunner, RepeatedAndForeignRowsAreDroppedAndReported) {
  const std::string ref = temp_dir("repeated_ref");
  const std::string dir = temp_dir("repeated");
  ASSERT_EQ(run(small_sweep(), ref, 2).ran, 48U);
  const auto recs = records(read_file(ref + "/runs.csv"));
  std::string runs = joined_records(recs);
  runs += recs[11] + "\n";  // run 10 again
  auto f = split_csv_line(recs[12]);
  f[0] = "4800";  // beyond the sweep
  runs += csv_record(f) + "\n";
  const auto [r, err] = resume_with_runs(ref, dir, runs);
  EXPECT_EQ(r.skipped, 48U);
  EXPECT_EQ(r.ran, 0U);
  expect_same_outputs(ref, dir);
  for (const std::string& expected :
       {dir + "/runs.csv:50: run 10 has a row earlier in the file",
        dir + "/runs.csv:51: its run_index 4800 is not below the sweep's 48 runs"}) {
    EXPECT_NE(err.find(expected), std::string::npos) << expected << "\nnot in:\n" << err;
  }
  fs::remove_all(ref);
  fs::remove_all(dir);
}

TEST(SweepRunner, FailedRunIsRecorded) {
  const std::string dir = temp_dir("failed");
  json sweep = small_sweep();
  sweep["sim"] = {{"max_steps", 5}};
  const RunnerReport r = run(sweep, dir, 2);
  EXPECT_EQ(r.ran, 48U);
  EXPECT_FALSE(r.interrupted);
  const auto reasons = column(read_file(dir + "/runs.csv"), "end_reason");
  ASSERT_EQ(reasons.size(), 48U);
  for (const auto& reason : reasons) EXPECT_EQ(reason, "step_limit");
  const auto detail = column(read_file(dir + "/runs.csv"), "end_detail");
  EXPECT_NE(detail.at(0).find("step cap"), std::string::npos) << detail.at(0);
  fs::remove_all(dir);
}

TEST(SweepRunner, CompetitiveRatioColumns) {
  // The star-pattern optimum applies in free space with a battery, when only travel costs
  // energy and the reachable disc (radius r/2 around the dock) lies inside the map. The
  // travel-only Mei model costs 1 per cell length, so at 0.5 m per cell 2 per metre.
  const json sweep = json::parse(R"({
    "schema_version": 1,
    "name": "competitive_test",
    "maps": ["free:w=81,h=81", "free:w=161,h=161,res=0.5", "free:w=41,h=41", "rooms:w=30,h=24,door=3,seed=1"],
    "strategies": [{"name": "closest_frontier"}],
    "robot": {"sensor": {"range_m": 5}, "battery": 60,
              "energy": ["distance", {"preset": "mei2006", "per_stop": 0, "per_turn": [0, 0, 0, 0]}, "mei2006"]}
  })");
  const std::string dir = temp_dir("competitive");
  ASSERT_EQ(run(sweep, dir, 2).ran, 12U);
  const std::string csv = read_file(dir + "/runs.csv");
  const auto optimum = column(csv, "optimal_distance_m");
  const auto ratio = column(csv, "competitive_ratio");
  const auto distance = column(csv, "distance_m");
  // Hand calculation, d* = pi r^2 / (2 r_s) with r_s = 5 m:
  // distance model: r = 60 / 1 = 60 m -> d* = 3600 pi / 10 = 1130.97 m;
  // travel-only Mei at 1 m/cell: r = 60 / (0 + 1 / 1) = 60 m -> the same;
  // travel-only Mei at 0.5 m/cell: r = 60 / (0 + 1 / 0.5) = 30 m -> d* = 900 pi / 10 = 282.74 m.
  const double d60 = M_PI * 60.0 * 60.0 / 10.0;
  const double d30 = M_PI * 30.0 * 30.0 / 10.0;
  // Rows: map-major, energy fastest. Applicable: 81x81 (r/2 = 30 cells fits around the centre
  // 40) with the two travel-only models; 161x161 at 0.5 m (r/2 = 30 m = 60 cells fits around 80)
  // with distance (r = 60 m, r/2 = 60 cells) and travel-only Mei (r = 30 m, r/2 = 30 cells).
  const std::vector<std::pair<std::size_t, double>> applicable{{0, d60}, {1, d60}, {3, d60}, {4, d30}};
  for (const auto& [i, expected] : applicable) {
    ASSERT_FALSE(optimum[i].empty()) << i;
    EXPECT_NEAR(std::stod(optimum[i]), expected, 1e-9 * expected) << i;
    EXPECT_NEAR(std::stod(ratio[i]), std::stod(distance[i]) / expected, 1e-12) << i;
  }
  // Empty: Mei with stop and turn costs (rows 2, 5, 8), the 41x41 map whose 30 m disc does not
  // fit (rows 6-8), the rooms map (rows 9-11).
  for (const std::size_t i : {2U, 5U, 6U, 7U, 8U, 9U, 10U, 11U}) {
    EXPECT_TRUE(optimum[i].empty()) << i;
    EXPECT_TRUE(ratio[i].empty()) << i;
  }
  fs::remove_all(dir);
}

/// Two competitive room maps (seeds 1, 2) and one that is not, closest frontier and
/// energy-aware, sensor 4 m: 6 runs.
json competitive_sweep() {
  return json::parse(R"({
    "schema_version": 1,
    "name": "offline_optimum_test",
    "competitive": true,
    "maps": [{"generator": "rooms", "w": 30, "h": 24, "door": 2, "seeds": [1, 2]},
             {"spec": "rooms:w=24,h=20,door=2,seed=3", "competitive": false}],
    "strategies": [{"name": "closest_frontier"}, {"name": "energy_aware"}],
    "robot": {"sensor": {"range_m": 4}},
    "repetitions": 1
  })");
}

TEST(SweepRunner, OfflineOptimumColumnsAreCertifiedCachedAndTheSameResumedShardedOrOnOneThread) {
  const std::string dir = temp_dir("offline_optimum");
  const RunnerReport first = run(competitive_sweep(), dir, 2);
  ASSERT_EQ(first.ran, 6U);
  EXPECT_EQ(first.optima.needed, 2U);  // one per competitive map: one robot, a fixed start
  EXPECT_EQ(first.optima.computed, 2U);
  EXPECT_EQ(first.optima.cached, 0U);
  const std::string csv = read_file(dir + "/runs.csv");
  const auto header = split_csv_line(records(csv).at(0));
  ASSERT_GE(header.size(), kCompetitiveColumns.size());
  EXPECT_EQ(std::vector<std::string>(header.end() - static_cast<std::ptrdiff_t>(kCompetitiveColumns.size()),
                                     header.end()),
            std::vector<std::string>(kCompetitiveColumns.begin(), kCompetitiveColumns.end()));
  const auto lower = column(csv, "optimum_lower_m");
  const auto upper = column(csv, "optimum_upper_m");
  const auto exact = column(csv, "optimum_exact");
  const auto ratio_min = column(csv, "competitive_ratio_min");
  const auto ratio_max = column(csv, "competitive_ratio_max");
  const auto note = column(csv, "competitive_note");
  const auto end = column(csv, "end_reason");
  const auto completeness = column(csv, "completeness");
  const auto distance = column(csv, "distance_to_final_coverage_m");
  ASSERT_EQ(note.size(), 6U);
  int with_ratio = 0;
  for (std::size_t i = 0; i < 4; ++i) {  // the competitive maps' runs: bounds always
    SCOPED_TRACE("run " + std::to_string(i) + ", note '" + note[i] + "'");
    ASSERT_FALSE(lower[i].empty());
    ASSERT_FALSE(upper[i].empty());
    EXPECT_TRUE(exact[i] == "0" || exact[i] == "1");
    EXPECT_LE(std::stod(lower[i]), std::stod(upper[i]));
    const bool solved = end[i] == "complete" && std::stod(completeness[i]) >= 1.0;
    EXPECT_EQ(!ratio_max[i].empty(), solved);
    EXPECT_EQ(!ratio_min[i].empty(), solved);
    if (!solved) {
      EXPECT_FALSE(note[i].empty());
      continue;
    }
    ++with_ratio;
    EXPECT_TRUE(note[i].empty());
    // The lower bound is never above a run that revealed every observable cell.
    EXPECT_GE(std::stod(ratio_max[i]), 1.0 - 1e-9);
    EXPECT_LE(std::stod(ratio_min[i]), std::stod(ratio_max[i]));
    EXPECT_DOUBLE_EQ(std::stod(ratio_max[i]), std::stod(distance[i]) / std::stod(lower[i]));
    EXPECT_DOUBLE_EQ(std::stod(ratio_min[i]), std::stod(distance[i]) / std::stod(upper[i]));
  }
  EXPECT_GT(with_ratio, 0);
  for (std::size_t i = 4; i < 6; ++i) {  // the map that is not competitive
    EXPECT_EQ(note[i], "map not competitive");
    EXPECT_TRUE(lower[i].empty() && upper[i].empty() && exact[i].empty() && ratio_min[i].empty() &&
                ratio_max[i].empty());
  }
  // The cache: one row per key; the manifest records the resolved setting.
  EXPECT_EQ(data_rows(dir + "/optima.csv"), 2U);
  const json manifest = json::parse(read_file(dir + "/manifest.json"));
  EXPECT_EQ(manifest["maps"][0]["competitive"], true);
  EXPECT_EQ(manifest["maps"][2]["competitive"], false);
  EXPECT_TRUE(manifest.contains("optimum_solver"));
  // summary.csv carries the numeric columns, not the note.
  const std::string summary = read_file(dir + "/summary.csv");
  EXPECT_NE(summary.find("competitive_ratio_max.median"), std::string::npos);
  EXPECT_NE(summary.find("optimum_lower_m.mean"), std::string::npos);
  EXPECT_EQ(summary.find("competitive_note"), std::string::npos);
  // The report's table: one row per competitive map, with its bounds and how many runs have a ratio.
  const std::string table = optimum_html(dir + "/runs.csv");
  EXPECT_NE(table.find("seed=1"), std::string::npos) << table;
  EXPECT_NE(table.find("seed=2"), std::string::npos);
  EXPECT_EQ(table.find("seed=3"), std::string::npos);  // not competitive: no row
  std::size_t rows = 0;
  for (std::size_t at = table.find("<tr"); at != std::string::npos; at = table.find("<tr", at + 1)) ++rows;
  EXPECT_EQ(rows, 3U);  // the header and the two maps
  EXPECT_NE(table.find("runs with a ratio"), std::string::npos);
  EXPECT_EQ(table.find("star optimum"), std::string::npos);  // no free map
  // fsweep paired compares the ratios (smaller is better).
  PairedOptions paired;
  paired.metrics = {"competitive_ratio_min", "competitive_ratio_max"};
  paired.resamples = 100;
  EXPECT_EQ(paired_comparison(dir, paired).metrics, paired.metrics);

  // Resumed with half of the runs done: the cache is read, nothing is solved, the same rows.
  const std::string resumed = temp_dir("offline_optimum_resumed");
  const auto recs = records(csv);
  write_file(resumed + "/runs.csv", joined_records({recs.begin(), recs.begin() + 4}));
  fs::copy_file(dir + "/progress.csv", resumed + "/progress.csv");
  fs::copy_file(dir + "/manifest.json", resumed + "/manifest.json");
  fs::copy_file(dir + "/optima.csv", resumed + "/optima.csv");
  const RunnerReport again = run(competitive_sweep(), resumed, 2);
  EXPECT_EQ(again.ran, 3U);
  EXPECT_EQ(again.optima.cached, 2U);
  EXPECT_EQ(again.optima.computed, 0U);
  expect_same_outputs(dir, resumed);
  // A finished sweep solves nothing.
  EXPECT_EQ(run(competitive_sweep(), resumed, 2).optima.needed, 0U);

  // One thread, no cache: solved again, to the same cells.
  const std::string single = temp_dir("offline_optimum_single");
  const RunnerReport one = run(competitive_sweep(), single, 1);
  EXPECT_EQ(one.optima.computed, 2U);
  expect_same_outputs(dir, single);
  for (const char* c : {"map_hash", "robot", "lower_m", "upper_m", "exact"})  // time_s aside
    EXPECT_EQ(column(read_file(single + "/optima.csv"), c), column(read_file(dir + "/optima.csv"), c)) << c;

  // Shards solve the keys of their own runs; merged, the unsharded rows.
  const std::string sharded = temp_dir("offline_optimum_sharded");
  for (std::uint64_t s = 0; s < 2; ++s)
    EXPECT_EQ(testing::run_test_shard(competitive_sweep(), sharded, s, 2).optima.needed, 2U);
  ASSERT_TRUE(merge_shards(sharded).written);
  EXPECT_EQ(without_timing(read_file(sharded + "/runs.csv")), without_timing(csv));
  // The merged folder holds the shards' optima (for a later resume or a changed sweep there).
  for (const char* c : {"map_hash", "robot", "lower_m", "upper_m", "exact"})
    EXPECT_EQ(column(read_file(sharded + "/optima.csv"), c), column(read_file(dir + "/optima.csv"), c)) << c;

  // A sweep without a competitive map has none of the columns and no optima.csv.
  json plain = competitive_sweep();
  plain.erase("competitive");
  const std::string none = temp_dir("offline_optimum_none");
  EXPECT_EQ(run(plain, none, 2).optima.needed, 0U);
  EXPECT_EQ(read_file(none + "/runs.csv").find("optimum_lower_m"), std::string::npos);
  EXPECT_FALSE(fs::exists(none + "/optima.csv"));
  for (const std::string& d : {dir, resumed, single, sharded, none}) fs::remove_all(d);
}

TEST(SweepRunner, AFreeMapThatClipsTheReachableDiscOrItsSensorBandHasNoOptimumAndSaysWhy) {
  // r = 60 m, r_s = 5 m, 1 m cells: d* needs the disc of radius r/2 = 30 cells around the dock,
  // its 5-cell sensor band and one cell more: 36 free cells beyond the dock each way. The free
  // generator draws an occupied frame, so free:w=75 (dock 37;37) has exactly 36 (cells 38..73)
  // and free:w=73 (dock 36;36) one too few; the rooms map is no free-space setting at all.
  const json sweep = json::parse(R"({
    "schema_version": 1,
    "name": "clipped_test",
    "maps": ["free:w=75,h=75", "free:w=73,h=73", "rooms:w=30,h=24,door=3,seed=1"],
    "strategies": [{"name": "closest_frontier"}],
    "robot": {"sensor": {"range_m": 5}, "battery": 60}
  })");
  const SweepPlan plan = SweepPlan::from_json(sweep, "clipped.json");
  const std::vector<std::string> warnings = clipped_free_space_warnings(plan);
  ASSERT_EQ(warnings.size(), 1U);
  EXPECT_NE(warnings[0].find("map 'free:w=73,h=73' (73x73 cells of 1 m, dock 36;36)"), std::string::npos)
      << warnings[0];
  EXPECT_NE(warnings[0].find("half-width of 36 cells (r/2 + r_s + 1 cell), the map has 35"),
            std::string::npos)
      << warnings[0];
  const StarOptimum fits = star_optimum(plan.maps()[0], plan.robots()[0].params);
  EXPECT_EQ(fits.status, StarOptimum::Status::Ok);
  EXPECT_EQ(fits.half_width_cells, 36);
  EXPECT_EQ(fits.needed_cells, 36);
  EXPECT_EQ(star_optimum(plan.maps()[2], plan.robots()[0].params).status, StarOptimum::Status::NotApplicable);

  const std::string dir = temp_dir("clipped");
  ASSERT_EQ(run(sweep, dir, 2).ran, 3U);
  const std::string csv = read_file(dir + "/runs.csv");
  const auto check = column(csv, "optimum_check");
  const auto optimum = column(csv, "optimal_distance_m");
  const auto ratio = column(csv, "competitive_ratio");
  EXPECT_EQ(check, (std::vector<std::string>{"ok", "clipped: half-width 35 < 36 cells", ""}));
  EXPECT_NEAR(std::stod(optimum.at(0)), M_PI * 60.0 * 60.0 / 10.0, 1e-9);
  EXPECT_FALSE(ratio.at(0).empty());
  for (const std::size_t i : {1U, 2U}) {
    EXPECT_TRUE(optimum.at(i).empty()) << i;
    EXPECT_TRUE(ratio.at(i).empty()) << i;
  }
  // A config column: best.csv and summary.csv carry it, one configuration per value.
  const auto best_checks = column(read_file(dir + "/best.csv"), "optimum_check");
  EXPECT_EQ(best_checks.size(), 3U);
  EXPECT_NE(std::find(best_checks.begin(), best_checks.end(), "clipped: half-width 35 < 36 cells"),
            best_checks.end());
  EXPECT_EQ(column(read_file(dir + "/summary.csv"), "optimum_check").size(), 3U);
  const json manifest = json::parse(read_file(dir + "/manifest.json"));
  EXPECT_EQ(manifest["warnings"], json(warnings));
  fs::remove_all(dir);

  // A sweep without a free map has no such column.
  const std::string plain = temp_dir("no_free");
  ASSERT_EQ(run(small_sweep(), plain, 2).ran, 48U);
  EXPECT_EQ(read_file(plain + "/runs.csv").find("optimum_check"), std::string::npos);
  const json plain_manifest = json::parse(read_file(plain + "/manifest.json"));
  for (const auto& w : plain_manifest["warnings"])
    EXPECT_EQ(w.get<std::string>().find("clips the free-space optimum"), std::string::npos) << w;
  fs::remove_all(plain);
}

TEST(SweepRunner, AParameterRecordedOnlyAwayFromItsDefaultHasItsColumnWhenSwept) {
  // energy_aware's `unit` is left out of the resolved parameters at its default ("m"), so the
  // header's representative (the first value) lacks it; the "cell" runs still need the column.
  const json sweep = json::parse(R"({
    "schema_version": 1,
    "name": "unit_test",
    "maps": ["rooms:w=30,h=24,door=3,seed=1"],
    "strategies": [{"name": "energy_aware", "params": {"unit": ["m", "cell"]}}, {"name": "closest_frontier"}]
  })");
  const std::string dir = temp_dir("unit_column");
  const RunnerReport r = run(sweep, dir, 2);
  EXPECT_EQ(r.ran, 3U);
  EXPECT_EQ(r.failed, 0U);
  const std::string csv = read_file(dir + "/runs.csv");
  EXPECT_EQ(column(csv, "strategy.unit"), (std::vector<std::string>{"", "cell", ""}));
  EXPECT_EQ(column(csv, "end_reason"), (std::vector<std::string>{"complete", "complete", "complete"}));
  fs::remove_all(dir);
}

TEST(SweepRunner, ManifestHasTheFields) {
  const std::string dir = temp_dir("manifest");
  const RunnerReport r = run(small_sweep(), dir, 2);
  const json m = json::parse(read_file(dir + "/manifest.json"));
  for (const char* key : {"sweep", "sweep_file", "sweep_hash", "name", "runs", "git_revision", "compiler",
                          "libraries", "host", "cpu_model", "threads", "start_utc", "end_utc", "wall_s",
                          "runs_per_s", "status", "seed", "objective", "sessions"}) {
    EXPECT_TRUE(m.contains(key)) << key;
  }
  EXPECT_EQ(m["sweep"], small_sweep());
  EXPECT_EQ(m["sweep_file"], "");
  EXPECT_EQ(m["sweep_hash"].get<std::string>().size(), 16U);
  EXPECT_EQ(m["name"], "runner_test");
  EXPECT_EQ(m["status"], "complete");
  EXPECT_EQ(m["threads"], 2);
  EXPECT_EQ(m["runs"]["total"], 48);
  EXPECT_EQ(m["runs"]["done"], 48);
  EXPECT_EQ(m["runs"]["ran"], 48);
  EXPECT_EQ(m["runs"]["skipped"], 0);
  EXPECT_EQ(m["runs"]["failed"], 0);
  EXPECT_GT(m["runs_per_s"].get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(m["wall_s"].get<double>(), r.wall_s);
  EXPECT_TRUE(m["libraries"].contains("oneTBB"));
  EXPECT_TRUE(m["libraries"].contains("nlohmann_json"));
  EXPECT_EQ(m["start_utc"].get<std::string>().size(), 20U);  // 2024-05-01T12:34:56Z
  EXPECT_EQ(m["end_utc"].get<std::string>().back(), 'Z');
  fs::remove_all(dir);
}

TEST(SweepRunner, ShardsPartitionTheRuns) {
  // For N = 1 (no shard directory), 2, 3, 7 and 50 (more shards than the 48 runs, so two are
  // empty): every run index is in exactly one shard, shard s holds the indices with
  // index % N == s under the run key the freshly expanded plan gives that index, rerunning a
  // shard finds all of its runs done (membership is stable under resume), and the shards'
  // rows put together are the unsharded run's.
  const std::string ref = temp_dir("shard_ref");
  ASSERT_EQ(run(small_sweep(), ref, 2).ran, 48U);
  const auto ref_rows = records(without_timing(read_file(ref + "/runs.csv")));
  const SweepPlan plan = SweepPlan::from_json(small_sweep(), "");
  for (const std::uint64_t n : {1U, 2U, 3U, 7U, 50U}) {
    SCOPED_TRACE("N=" + std::to_string(n));
    const std::string dir = temp_dir("shards_" + std::to_string(n));
    std::vector<std::string> merged(ref_rows.size());
    merged[0] = ref_rows[0];
    std::vector<int> seen(48, 0);
    for (std::uint64_t s = 0; s < n; ++s) {
      const std::uint64_t size = s < 48 ? (48 - s - 1) / n + 1 : 0;
      const RunnerReport r = testing::run_test_shard(small_sweep(), dir, s, n);
      EXPECT_EQ(r.total, size);
      EXPECT_EQ(r.ran, size);
      EXPECT_EQ(r.out_dir, n == 1 ? dir : dir + "/shard-" + std::to_string(s) + "-of-" + std::to_string(n));
      const auto rows = records(without_timing(read_file(r.out_dir + "/runs.csv")));
      ASSERT_EQ(rows.size(), size + 1);
      EXPECT_EQ(rows[0], ref_rows[0]);  // the whole sweep's header
      for (std::size_t i = 1; i < rows.size(); ++i) {
        const auto fields = split_csv_line(rows[i]);
        const std::size_t index = std::stoul(fields[0]);
        ASSERT_LT(index, 48U);
        EXPECT_EQ(index % n, s);
        EXPECT_EQ(fields[1], plan.run_key(index));
        ++seen[index];
        merged.at(index + 1) = rows[i];
      }
      if (s == n / 2) {  // resume: nothing left to do, files unchanged
        const std::string before = read_file(r.out_dir + "/runs.csv");
        const RunnerReport again = testing::run_test_shard(small_sweep(), dir, s, n);
        EXPECT_EQ(again.ran, 0U);
        EXPECT_EQ(again.skipped, size);
        EXPECT_EQ(read_file(r.out_dir + "/runs.csv"), before);
      }
    }
    for (std::size_t i = 0; i < seen.size(); ++i) EXPECT_EQ(seen[i], 1) << "run_index " << i;
    EXPECT_EQ(merged, ref_rows);
    fs::remove_all(dir);
  }
  fs::remove_all(ref);
}

TEST(SweepRunner, BadOptionsAreConfigErrors) {
  const SweepPlan plan = SweepPlan::from_json(small_sweep(), "");
  RunnerOptions o;
  o.out_dir = temp_dir("bad_options");
  o.progress = false;
  o.shard_index = 2;
  o.shard_count = 2;
  EXPECT_THROW((void)run_sweep(plan, o), ConfigError);
  o.shard_index = 0;
  o.shard_count = 1;
  o.threads = -1;
  EXPECT_THROW((void)run_sweep(plan, o), ConfigError);
  fs::remove_all(o.out_dir);
}

/// The shape of sweeps/default.json, small: two map classes of generated maps with two seeds
/// each, closest frontier and two energy-aware weight vectors, a sensor that misses cells (so
/// that repetitions differ), a battery; 12 configurations.
json default_shaped_sweep(int repetitions) {
  json sweep = json::parse(R"({
    "schema_version": 1,
    "name": "extend_test",
    "maps": [
      {"generator": "rooms", "w": 30, "h": 24, "door": 3, "label": "rooms", "seeds": {"range": [1, 2], "step": 1}},
      {"generator": "office", "w": 32, "h": 32, "label": "office", "seeds": {"range": [1, 2], "step": 1}}
    ],
    "strategies": [
      {"name": "closest_frontier", "label": "CF"},
      {"name": "energy_aware", "label": "EA free", "params": {"w1": 10, "w2": 0, "w3": 9, "w4": 20}},
      {"name": "energy_aware", "label": "EA Manhattan", "params": {"w1": 220, "w2": 21, "w3": 104, "w4": 100}}
    ],
    "robot": {"sensor": {"range_m": 4, "miss_probability": 0.05}, "energy": "distance", "battery": 150},
    "progress_step_m": 5,
    "seed": 1
  })");
  sweep["repetitions"] = repetitions;
  return sweep;
}

/// Expects the result files of `dir` to equal those of `ref` (timing columns aside).
void expect_same_results(const std::string& dir, const std::string& ref) {
  for (const char* f : {"runs.csv", "summary.csv", "progress_summary.csv", "best.csv"}) {
    EXPECT_EQ(without_timing(read_file(dir + "/" + f)), without_timing(read_file(ref + "/" + f))) << f;
  }
  EXPECT_EQ(read_file(dir + "/progress.csv"), read_file(ref + "/progress.csv"));
}

TEST(SweepRunner, ExtendingAFinishedSweepRunsOnlyTheNewRunsAndEqualsAFreshSweep) {
  // 3 repetitions grown to 4: the finished runs get other run indices (repetition is the
  // fastest axis), so both files are rewritten in the new order.
  const std::string dir = temp_dir("extend");
  const std::string ref = temp_dir("extend_ref");
  ASSERT_EQ(run(default_shaped_sweep(3), dir, 2).ran, 36U);
  const json before = json::parse(read_file(dir + "/manifest.json"));
  const RunnerReport grown = run(default_shaped_sweep(4), dir, 2);
  EXPECT_EQ(grown.total, 48U);
  EXPECT_EQ(grown.ran, 12U);
  EXPECT_EQ(grown.skipped, 36U);
  EXPECT_EQ(grown.kept, 36U);
  EXPECT_EQ(grown.extended_from, before["sweep_hash"].get<std::string>());
  EXPECT_FALSE(grown.interrupted);
  ASSERT_EQ(run(default_shaped_sweep(4), ref, 2).ran, 48U);
  expect_same_results(dir, ref);

  // The manifest is the grown sweep's, and keeps the first session as it was.
  const json m = json::parse(read_file(dir + "/manifest.json"));
  EXPECT_EQ(m["sweep"], default_shaped_sweep(4));
  ASSERT_EQ(m["sessions"].size(), 2U);
  EXPECT_EQ(m["sessions"][0], before["sessions"][0]);
  EXPECT_EQ(m["sessions"][0]["sweep_hash"], before["sweep_hash"]);
  EXPECT_EQ(m["sessions"][1]["sweep_hash"], m["sweep_hash"]);
  EXPECT_EQ(m["sessions"][1]["runs"]["ran"], 12U);
  EXPECT_EQ(m["sessions"][1]["runs"]["skipped"], 36U);
  EXPECT_EQ(m["runs"]["ran"], 48U);
  EXPECT_EQ(m["runs"]["done"], 48U);
  EXPECT_EQ(m["start_utc"], before["start_utc"]);

  // Run again: nothing left to do.
  const RunnerReport again = run(default_shaped_sweep(4), dir, 2);
  EXPECT_EQ(again.ran, 0U);
  EXPECT_TRUE(again.extended_from.empty());
  expect_same_results(dir, ref);
}

TEST(SweepRunner, ExtendingTakesNewMapsStrategyEntriesColumnsAndLabels) {
  // A map put first and a strategy entry with its own column (strategy.unit) put first, so every
  // finished run moves; closest_frontier and the map class relabelled: labels are not in run keys,
  // so the finished rows take the new ones.
  const json base = json::parse(R"({
    "schema_version": 1,
    "name": "extend_entries",
    "maps": [{"generator": "rooms", "w": 30, "h": 24, "door": 3, "label": "rooms", "seeds": [1, 2]}],
    "strategies": [{"name": "closest_frontier", "label": "CF"}],
    "robot": {"sensor": {"range_m": 4, "miss_probability": 0.05}},
    "repetitions": 2,
    "seed": 3
  })");
  json grown = base;
  grown["maps"] = json::parse(R"([{"spec": "rooms:w=24,h=20,door=2,seed=2", "label": "small"},
    {"generator": "rooms", "w": 30, "h": 24, "door": 3, "label": "rooms 30x24", "seeds": [1, 2]}])");
  grown["strategies"] =
      json::parse(R"([{"name": "energy_aware", "label": "EA cell", "params": {"unit": "cell"}},
    {"name": "closest_frontier", "label": "closest"}])");
  const std::string dir = temp_dir("extend_entries");
  const std::string ref = temp_dir("extend_entries_ref");
  ASSERT_EQ(run(base, dir, 2).ran, 4U);
  ASSERT_EQ(read_file(dir + "/runs.csv").find("strategy.unit"), std::string::npos);
  const RunnerReport r = run(grown, dir, 2);
  EXPECT_EQ(r.kept, 4U);
  EXPECT_EQ(r.ran, 8U);
  ASSERT_EQ(run(grown, ref, 2).ran, 12U);
  expect_same_results(dir, ref);
  const std::vector<std::string> labels = column(read_file(dir + "/runs.csv"), "strategy_label");
  EXPECT_EQ(std::count(labels.begin(), labels.end(), "closest"), 6);
  const std::vector<std::string> classes = column(read_file(dir + "/runs.csv"), "map_class");
  EXPECT_EQ(std::count(classes.begin(), classes.end(), "rooms 30x24"), 8);
}

TEST(SweepRunner, ASweepThatDropsOrChangesFinishedRunsIsRefusedAndNothingIsTouched) {
  const std::string dir = temp_dir("shrink");
  ASSERT_EQ(run(default_shaped_sweep(3), dir, 2).ran, 36U);
  const std::string runs = read_file(dir + "/runs.csv");
  const std::string progress = read_file(dir + "/progress.csv");
  const std::string manifest = read_file(dir + "/manifest.json");
  json changed = default_shaped_sweep(3);
  changed["strategies"][1]["params"]["w1"] = 11;
  json other_seed = default_shaped_sweep(4);
  other_seed["seed"] = 2;
  const std::vector<std::pair<json, std::vector<std::string>>> cases{
      // 2 repetitions: the 12 runs of repetition 2 go; run 2 is the first configuration's.
      {default_shaped_sweep(2),
       {"which does not have 12 of its 36 finished runs (run 2 (map 'rooms seed=1', strategy 'CF', "
        "repetition 2); run 5 (map 'rooms seed=1', strategy 'EA free' "
        "{\"w1\":10,\"w2\":0,\"w3\":9,\"w4\":20}, "
        "repetition 2); ...)"}},
      // Another weight: EA free's 4 maps x 3 repetitions are other runs now.
      {changed,
       {"which does not have 12 of its 36 finished runs (run 3 (map 'rooms seed=1', strategy 'EA free'"}},
      // Another sweep seed: every run seed, so every run, changed, although runs are added too.
      {other_seed, {"which does not have 36 of its 36 finished runs"}}};
  for (const auto& [sweep, parts] : cases) {
    try {
      (void)run(sweep, dir, 2);
      ADD_FAILURE() << "accepted: " << sweep.dump();
    } catch (const ConfigError& e) {
      const std::string what = e.what();
      for (const std::string& part :
           {dir + ": holds the outputs of another version of this sweep file (sweep_hash ", parts.at(0),
            std::string("not by removing or changing finished ones; use --fresh to start over, or another "
                        "output directory")}) {
        EXPECT_NE(what.find(part), std::string::npos) << part << "\nnot in: " << what;
      }
    }
    EXPECT_EQ(read_file(dir + "/runs.csv"), runs);  // nothing touched
    EXPECT_EQ(read_file(dir + "/progress.csv"), progress);
    EXPECT_EQ(read_file(dir + "/manifest.json"), manifest);
  }
}

TEST(SweepRunner, AShardIsExtendedOnTheChangedSweepsShard) {
  // A map seed added to the last map class adds runs at the end: every finished run keeps its
  // index, so each shard keeps its runs; the merge (into a directory holding the merge of the
  // sweep before) equals an unsharded run. More repetitions move runs across shards: refused.
  const std::string dir = temp_dir("extend_shards");
  const std::string ref = temp_dir("extend_shards_ref");
  json more_maps = default_shaped_sweep(3);
  more_maps["maps"][1]["seeds"]["range"] = {1, 3};
  const auto shard = [&](const json& sweep, std::uint64_t i) {
    return testing::run_test_shard(sweep, dir, i, 2);
  };
  for (std::uint64_t i = 0; i < 2; ++i) ASSERT_EQ(shard(default_shaped_sweep(3), i).ran, 18U);
  ASSERT_TRUE(merge_shards(dir).written);
  for (std::uint64_t i = 0; i < 2; ++i) {
    const RunnerReport r = shard(more_maps, i);
    EXPECT_EQ(r.kept, 18U);
    EXPECT_EQ(r.ran, i == 0 ? 5U : 4U);  // runs 36..44
  }
  const MergeReport merged = merge_shards(dir);
  ASSERT_TRUE(merged.written) << (merged.problems.empty() ? "" : merged.problems.front());
  ASSERT_EQ(run(more_maps, ref, 2).ran, 45U);
  expect_same_results(dir, ref);
  const json m = json::parse(read_file(dir + "/manifest.json"));
  EXPECT_EQ(m["sessions"].size(), 4U);  // both shards' sessions of both sweeps

  json more_reps = more_maps;
  more_reps["repetitions"] = 4;
  const std::string shard_runs = read_file(dir + "/shard-0-of-2/runs.csv");
  try {
    (void)shard(more_reps, 0);
    FAIL() << "runs of other shards were accepted";
  } catch (const ConfigError& e) {
    const std::string what = e.what();
    for (const std::string& part :
         {std::string("belong to other shards (run indices change with the sweep: run "),
          std::string("extend the merged results instead")}) {
      EXPECT_NE(what.find(part), std::string::npos) << part << "\nnot in: " << what;
    }
  }
  EXPECT_EQ(read_file(dir + "/shard-0-of-2/runs.csv"), shard_runs);
  // The merged directory is extended as a whole.
  const RunnerReport whole = run(more_reps, dir, 2);
  EXPECT_EQ(whole.kept, 45U);
  EXPECT_EQ(whole.ran, 15U);
}

/// The records of `csv` (header first) whose field `column` is one of `keys`, as CSV text.
std::string rows_of(const std::string& csv, const std::string& column_name,
                    const std::set<std::string>& keys) {
  const auto recs = records(csv);
  const auto header = split_csv_line(recs.at(0));
  const auto at =
      static_cast<std::size_t>(std::find(header.begin(), header.end(), column_name) - header.begin());
  std::string out = recs[0] + "\n";
  for (std::size_t i = 1; i < recs.size(); ++i) {
    if (keys.count(split_csv_line(recs[i]).at(at)) != 0) out += recs[i] + "\n";
  }
  return out;
}

TEST(SweepRunner, AKillWhileAnExtensionMovesTheRowsIsRepairedByTheNextRun) {
  // The extension rewrites progress.csv, then runs.csv, then the manifest. A kill after the first
  // or the second rewrite leaves the earlier sweep's manifest with moved rows; the next run
  // finds every row's place again from its key.
  const std::string old = temp_dir("kill_extend_old");
  const std::string moved = temp_dir("kill_extend_moved");
  const std::string ref = temp_dir("kill_extend_ref");
  ASSERT_EQ(run(default_shaped_sweep(3), old, 2).ran, 36U);
  fs::copy(old, moved);
  ASSERT_EQ(run(default_shaped_sweep(4), moved, 2).ran, 12U);
  ASSERT_EQ(run(default_shaped_sweep(4), ref, 2).ran, 48U);
  const std::vector<std::string> old_keys = column(read_file(old + "/runs.csv"), "run_key");
  const std::set<std::string> keys(old_keys.begin(), old_keys.end());
  for (const bool runs_moved : {false, true}) {
    SCOPED_TRACE(runs_moved ? "both files moved" : "progress.csv moved");
    const std::string dir = temp_dir(runs_moved ? "kill_extend_both" : "kill_extend_progress");
    fs::remove_all(dir);
    fs::copy(old, dir);
    write_file(dir + "/progress.csv", rows_of(read_file(moved + "/progress.csv"), "run_key", keys));
    if (runs_moved) write_file(dir + "/runs.csv", rows_of(read_file(moved + "/runs.csv"), "run_key", keys));
    const RunnerReport r = run(default_shaped_sweep(4), dir, 2);
    EXPECT_EQ(r.kept, 36U);
    EXPECT_EQ(r.ran, 12U);
    expect_same_results(dir, ref);
  }
}

TEST(SweepRunner, ASweepWithExactWeightSearchesIsNotExtended) {
  const std::string dir = temp_dir("extend_search");
  const json base = default_shaped_sweep(1);
  ASSERT_EQ(run(base, dir, 2).ran, 12U);
  const std::string runs = read_file(dir + "/runs.csv");
  json with_search = base;
  with_search["strategies"].push_back(json::parse(
      R"({"name": "energy_aware", "label": "exact", "search": {"method": "exact", "mode": "best"}, "params": {}})"));
  try {
    (void)run(with_search, dir, 2);
    FAIL() << "a sweep with a search was extended";
  } catch (const ConfigError& e) {
    EXPECT_NE(
        std::string(e.what()).find("a sweep with exact weight searches (\"search\" entries) is not extended"),
        std::string::npos)
        << e.what();
  }
  EXPECT_EQ(read_file(dir + "/runs.csv"), runs);
}

TEST(SweepRunner, TheManifestKeepsEverySession) {
  const std::string dir = temp_dir("sessions");
  const RunnerReport first = run(small_sweep(), dir, 2);
  const json m1 = json::parse(read_file(dir + "/manifest.json"));
  ASSERT_EQ(m1["sessions"].size(), 1U);
  const json& s1 = m1["sessions"][0];
  for (const char* key : {"start_utc", "end_utc", "status", "sweep_hash", "sweep_file", "fsweep_version",
                          "git_revision", "host", "threads", "shard", "runs", "wall_s", "runs_per_s"}) {
    EXPECT_TRUE(s1.contains(key)) << key;
  }
  EXPECT_EQ(s1["runs"]["ran"], 48U);
  EXPECT_EQ(s1["start_utc"], m1["start_utc"]);
  EXPECT_DOUBLE_EQ(s1["wall_s"].get<double>(), first.wall_s);
  EXPECT_DOUBLE_EQ(s1["runs_per_s"].get<double>(), first.runs_per_s);

  // A rerun with nothing to do is a session of its own: the first one's timing stays, and so do
  // the top-level figures over the sessions that simulated runs.
  const RunnerReport second = run(small_sweep(), dir, 1);
  ASSERT_EQ(second.ran, 0U);
  const json m2 = json::parse(read_file(dir + "/manifest.json"));
  ASSERT_EQ(m2["sessions"].size(), 2U);
  EXPECT_EQ(m2["sessions"][0], s1);
  EXPECT_EQ(m2["sessions"][1]["runs"]["ran"], 0U);
  EXPECT_EQ(m2["sessions"][1]["runs"]["skipped"], 48U);
  EXPECT_EQ(m2["sessions"][1]["threads"], 1);
  EXPECT_EQ(m2["threads"], 1);  // the last session's
  EXPECT_EQ(m2["start_utc"], m1["start_utc"]);
  EXPECT_EQ(m2["runs"]["ran"], 48U);
  EXPECT_EQ(m2["runs"]["skipped"], 48U);
  EXPECT_NEAR(m2["runs_per_s"].get<double>(), first.runs_per_s, 1e-9 * first.runs_per_s);
  EXPECT_DOUBLE_EQ(m2["wall_s"].get<double>(), first.wall_s + second.wall_s);

  // A manifest of an fsweep that kept only the last invocation: that one becomes the first session.
  json old = m1;
  old.erase("sessions");
  write_file(dir + "/manifest.json", old.dump(2));
  (void)run(small_sweep(), dir, 2);
  const json m3 = json::parse(read_file(dir + "/manifest.json"));
  ASSERT_EQ(m3["sessions"].size(), 2U);
  for (const char* key : {"start_utc", "end_utc", "sweep_hash", "wall_s", "runs_per_s", "threads"}) {
    EXPECT_EQ(m3["sessions"][0][key], m1[key]) << key;
  }
  EXPECT_EQ(m3["sessions"][0]["runs"]["ran"], 48U);
  EXPECT_GT(m3["runs_per_s"].get<double>(), 0.0);
}

}  // namespace test_sweep_runner
}  // namespace fsweep
