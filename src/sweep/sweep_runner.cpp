#include "sweep/sweep_runner.hpp"

#include <fcntl.h>
#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/global_control.h>
#include <oneapi/tbb/info.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/parallel_pipeline.h>
#include <oneapi/tbb/task_arena.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <thread>

#include "core/config_error.hpp"
#include "core/random.hpp"
#include "report/aggregate.hpp"
#include "report/runs_schema.hpp"
#include "sweep/csv_journal.hpp"
#include "sweep/done_runs.hpp"
#include "sweep/manifest.hpp"
#include "sweep/merge.hpp"
#include "sweep/progress_meter.hpp"
#include "sweep/sweep_table.hpp"
#include "sweep/weight_search_runner.hpp"

namespace fsweep {
inline namespace sweep {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

/// Runs in flight or waiting for the in-order writer, per thread.
constexpr std::size_t kTokensPerThread = 16;

constexpr const char* kOutputFiles[] = {
    "runs.csv",           "progress.csv",         "manifest.json",    "summary.csv",
    "best.csv",           "progress_summary.csv", "searches.json",    "behaviours.csv",
    "search_summary.csv", "search_best.csv",      "search_ranks.csv", "search_heatmaps.csv",
    "vectors.csv",        "search_journal.jsonl", "results.sqlite"};

/// Set by SIGINT/SIGTERM while run_sweep runs (a signal handler can only reach a global).
std::atomic<bool> stop_requested{false};  // NOLINT(cppcoreguidelines-avoid-non-const-global-variables)
static_assert(std::atomic<bool>::is_always_lock_free);

extern "C" void on_stop_signal(int /*signal*/) { stop_requested.store(true); }

/// Installs the stop handlers for its lifetime. SA_RESETHAND: a second signal kills.
class StopSignals {
 public:
  StopSignals() {
    stop_requested.store(false);
    struct sigaction sa {};
    sa.sa_handler = on_stop_signal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESETHAND | SA_RESTART;
    ::sigaction(SIGINT, &sa, &old_int_);
    ::sigaction(SIGTERM, &sa, &old_term_);
  }
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;
  ~StopSignals() {
    ::sigaction(SIGINT, &old_int_, nullptr);
    ::sigaction(SIGTERM, &old_term_, nullptr);
  }

 private:
  struct sigaction old_int_ {};
  struct sigaction old_term_ {};
};

/// An exclusive flock on `<dir>/.fsweep.lock` for its lifetime.
class DirectoryLock {
 public:
  explicit DirectoryLock(const std::string& dir) {
    const std::string path = dir + "/.fsweep.lock";
    fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0) throw ConfigError(dir, "cannot create " + path + " (is the output directory writable?)");
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      ::close(fd_);
      throw ConfigError(dir, "another fsweep run is writing to this directory");
    }
  }
  DirectoryLock(const DirectoryLock&) = delete;
  DirectoryLock& operator=(const DirectoryLock&) = delete;
  ~DirectoryLock() { ::close(fd_); }

 private:
  int fd_ = -1;
};

std::string output_directory(const SweepPlan& plan, const RunnerOptions& o) {
  std::string dir = o.out_dir.empty() ? plan.output_dir() : o.out_dir;
  if (dir.empty()) dir = ".";
  if (o.shard_count > 1) {
    dir += "/" + shard_dir_name(o.shard_index, o.shard_count);
  }
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    throw ConfigError(dir, "cannot create the output directory: " + ec.message());
  return dir;
}

/// Runs of the shard: indices i < n with i % count == index.
std::uint64_t shard_size(std::uint64_t n, std::uint64_t index, std::uint64_t count) {
  return n > index ? (n - index - 1) / count + 1 : 0;
}

/// What survives of earlier invocations: the done runs, after repairing both files.
struct Resumed {
  DoneRuns done;
  std::uint64_t failed = 0;  ///< done rows whose end_reason is `error`
  /// The largest run_index of a done row; runs below it that are not done fill gaps.
  std::optional<std::uint64_t> last_index;
  bool in_order = true;  ///< the done rows are in ascending run_index order
};

/// A cell quoted in a message: at most 40 characters, non-printable bytes as '?'.
std::string quoted_cell(std::string_view cell) {
  constexpr std::size_t kMax = 40;
  std::string out = "'";
  for (const char c : cell.substr(0, kMax)) out += (c >= 0x20 && c < 0x7f) ? c : '?';
  out += cell.size() > kMax ? "...'" : "'";
  return out;
}

std::string field_count_reason(std::size_t got, std::size_t expected) {
  return "the line has " + std::to_string(got) + (got == 1 ? " field" : " fields") +
         ", where the header has " + std::to_string(expected);
}

/// Tells on stderr every line repair() dropped, and why.
void report_dropped(const CsvJournal& journal, const CsvRepairStats& stats, const char* what) {
  for (const CsvDroppedLines& d : stats.dropped_lines) {
    std::fprintf(stderr, "fsweep: dropped %s: %s\n", d.describe(journal.path()).c_str(), what);
  }
}

/// Refuses done rows whose run_key is not the key `plan` gives their run_index: their inputs
/// changed since they ran (a map file edited: run keys cover the map's content; or keys of
/// another fsweep version), so they are not this sweep's results. Keys are computed in parallel.
void verify_done_keys(const SweepPlan& plan, const DoneRuns& done, const std::string& runs_path) {
  const std::vector<DoneRuns::Row>& rows = done.rows();
  std::vector<std::uint64_t> expected(rows.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rows.size()), [&](const auto& range) {
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      expected[i] = parse_run_key(plan.run_key(rows[i].index)).value_or(0);
    }
  });
  std::size_t stale = 0;
  std::string examples;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (rows[i].key == expected[i]) continue;
    if (++stale <= 3) {
      examples += (stale > 1 ? "; run " : "run ") + std::to_string(rows[i].index) + ": " +
                  hex64(rows[i].key) + " in the file, " + hex64(expected[i]) + " now";
    }
  }
  if (stale == 0) return;
  throw ConfigError(runs_path, std::to_string(stale) + " of its " + std::to_string(rows.size()) +
                                   " runs have another run_key than this sweep gives them (" + examples +
                                   "): their inputs changed since they ran (an edited map file, or keys of "
                                   "another fsweep version); use --fresh to start over, or another output "
                                   "directory");
}

/// The shard a runner writes: runs i with i % count == index.
struct ShardOf {
  std::uint64_t index = 0;
  std::uint64_t count = 1;
};

Resumed repair_outputs(const SweepPlan& plan, ShardOf shard, const SweepTable& table, CsvJournal& runs,
                       CsvJournal& progress) {
  Resumed r;
  const std::size_t fields = table.columns().size();
  const std::size_t key_col = table.column(kRunKeyColumn);
  const std::size_t index_col = table.column(kRunIndexColumn);
  const std::size_t end_col = table.column(kEndReasonColumn);
  const std::size_t progress_key_col = SweepTable::progress_column(kRunKeyColumn);
  const std::size_t progress_index_col = SweepTable::progress_column(kRunIndexColumn);
  const std::string error(to_string(EndReason::Error));
  std::vector<bool> seen;  // by run_index: a row for it was kept
  const CsvRepairStats run_stats = runs.repair(
      [&](const std::vector<std::string>& f) -> std::string {
        if (f.size() != fields) return field_count_reason(f.size(), fields);
        const auto key = parse_run_key(f[key_col]);
        if (!key) return "its run_key " + quoted_cell(f[key_col]) + " is not 16 hexadecimal digits";
        const auto index = parse_run_index(f[index_col]);
        if (!index) return "its run_index " + quoted_cell(f[index_col]) + " is not a whole number";
        if (*index >= plan.run_count()) {
          return "its run_index " + f[index_col] + " is not below the sweep's " +
                 std::to_string(plan.run_count()) + " runs";
        }
        if (*index % shard.count != shard.index) {
          return "its run_index " + f[index_col] + " is not of shard " + std::to_string(shard.index) + "/" +
                 std::to_string(shard.count);
        }
        const auto slot = static_cast<std::size_t>(*index / shard.count);
        if (slot >= seen.size()) seen.resize(slot + 1, false);
        if (seen[slot]) return "run " + f[index_col] + " has a row earlier in the file";
        seen[slot] = true;
        r.done.add(*key, *index);
        if (r.last_index && *index < *r.last_index) r.in_order = false;
        r.last_index = std::max(r.last_index.value_or(0), *index);
        if (f[end_col] == error) ++r.failed;
        return {};
      },
      [&] {
        r.done.seal();
        verify_done_keys(plan, r.done, runs.path());  // refuses before runs.csv is touched
      });
  report_dropped(runs, run_stats, "its run is done again (if it is this sweep's), in run order");
  const CsvRepairStats progress_stats =
      progress.repair([&](const std::vector<std::string>& f) -> std::string {
        if (f.size() != SweepTable::kProgressFields)
          return field_count_reason(f.size(), SweepTable::kProgressFields);
        const auto key = parse_run_key(f[progress_key_col]);
        if (!key) return "its run_key " + quoted_cell(f[progress_key_col]) + " is not 16 hexadecimal digits";
        const auto index = parse_run_index(f[progress_index_col]);
        if (!index) return "its run_index " + quoted_cell(f[progress_index_col]) + " is not a whole number";
        if (!r.done.contains(*key, *index)) {
          return "run " + std::to_string(*index) + " (run_key " + f[progress_key_col] +
                 ") has no complete row in runs.csv (it did not finish, or its row was dropped)";
        }
        return {};
      });
  report_dropped(progress, progress_stats, "its run's progress is written again with the run");
  return r;
}

/// True when the CSV file at `path` has a line after its header.
bool has_rows(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  return std::getline(in, line) && std::getline(in, line);
}

/// One run moving through the pipeline.
struct Job {
  std::uint64_t index = 0;
  RunRows rows;
};

}  // namespace

int hardware_threads() { return std::max(1, static_cast<int>(std::thread::hardware_concurrency())); }

int max_threads() { return kThreadsPerHardwareThread * hardware_threads(); }

RunnerReport run_sweep(const SweepPlan& plan, const RunnerOptions& options) {
  // 1. Options, directory, lock, previous outputs.
  if (options.threads < 0 || options.threads > max_threads()) {
    throw ConfigError("--threads", "must be 0 (all cores) to " + std::to_string(max_threads()) + " (" +
                                       std::to_string(kThreadsPerHardwareThread) + " x the " +
                                       std::to_string(hardware_threads()) +
                                       " hardware threads of this machine), got " +
                                       std::to_string(options.threads));
  }
  if (options.shard_count == 0 || options.shard_index >= options.shard_count) {
    throw ConfigError("--shard", "must be i/n with 0 <= i < n, got " + std::to_string(options.shard_index) +
                                     "/" + std::to_string(options.shard_count));
  }
  const int threads = options.threads > 0 ? options.threads : tbb::info::default_concurrency();
  const auto wall_start = Clock::now();
  RunnerReport report;
  report.threads = threads;
  report.out_dir = output_directory(plan, options);
  const std::string& dir = report.out_dir;
  const DirectoryLock lock(dir);

  // Temp files of a runner killed while replacing a file ("runs.csv.tmp.<pid>").
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    for (const char* f : {"runs.csv", "progress.csv", "manifest.json"}) {
      if (name.starts_with(std::string(f) + ".tmp.")) fs::remove(entry.path());
    }
  }

  const std::string manifest_path = dir + "/manifest.json";
  const std::string hash = sweep_hash(plan.source());
  if (options.fresh) {
    for (const char* f : kOutputFiles) fs::remove(dir + "/" + f);
  } else if (const auto old = read_manifest(manifest_path)) {
    const std::string old_hash = (*old)["sweep_hash"].get<std::string>();
    if (old_hash != hash) {
      throw ConfigError(dir, "holds the outputs of a different sweep file (hash " + old_hash + ", this one " +
                                 hash + "); use --fresh to start over, or another output directory");
    }
    if (!old->contains("maps") && has_rows(dir + "/runs.csv")) {
      throw ConfigError(dir,
                        "holds the results of an older fsweep: its manifest.json does not record the maps' "
                        "content, and its run keys differ from this version's; use --fresh to start over, or "
                        "another output directory");
    }
    if (const auto changed = changed_maps(*old, plan); !changed.empty() && has_rows(dir + "/runs.csv")) {
      std::string list;
      for (const std::string& c : changed) list += (list.empty() ? "" : "; ") + c;
      throw ConfigError(dir, "holds the results of other maps than this sweep's (" + list +
                                 "); use --fresh to start over, or another output directory");
    }
  }

  const SweepTable table(plan);
  CsvJournal runs(dir + "/runs.csv", table.header());
  CsvJournal progress(dir + "/progress.csv", SweepTable::progress_header());
  Resumed resumed = repair_outputs(plan, {options.shard_index, options.shard_count}, table, runs, progress);

  ManifestInfo info;
  info.sweep_file = options.sweep_file;
  info.threads = threads;
  info.shard_index = options.shard_index;
  info.shard_count = options.shard_count;
  info.start_utc = utc_now_iso8601();
  info.status = "running";
  info.runs.total = shard_size(plan.run_count(), options.shard_index, options.shard_count);
  info.runs.done = resumed.done.size();
  info.runs.failed = resumed.failed;
  write_manifest(manifest_path, manifest_json(plan, info));
  report.total = info.runs.total;

  // 2. The pipeline: dispatch in index order (skipping done runs), simulate in parallel, write
  //    in index order.
  ProgressMeter meter(report.total, "runs", options.progress);
  std::atomic<std::uint64_t> skipped{0};
  std::uint64_t next = options.shard_index;
  bool announced_stop = false;
  const auto flush_both = [&] {
    progress.flush();  // progress rows first: a runs.csv row marks its run as done
    runs.flush();
  };

  auto dispatch = [&](tbb::flow_control& fc) -> Job {
    while (true) {
      if (stop_requested.load()) {
        if (!announced_stop && options.progress) {
          std::fputs("\nfsweep: stopping: finishing the runs in flight (press Ctrl-C again to abort)\n",
                     stderr);
        }
        announced_stop = true;
        fc.stop();
        return {};
      }
      if (next >= plan.run_count()) {
        fc.stop();
        return {};
      }
      Job job;
      job.index = next;
      next += options.shard_count;
      if (resumed.done.has(job.index)) {  // its row's key was verified against the plan's
        skipped.fetch_add(1);
        continue;
      }
      return job;
    }
  };
  auto simulate_run = [&](Job job) -> Job {
    job.rows = table.run(plan, plan.run(job.index));
    return job;
  };
  // Runs below the last done one fill gaps (rows dropped by the repair): they are held and
  // both files are rewritten in run order (temp file and rename) before the first run past the
  // done ones is appended, or at the end.
  const std::size_t index_col = table.column(kRunIndexColumn);
  const std::size_t progress_index_col = SweepTable::progress_column(kRunIndexColumn);
  std::vector<std::pair<std::uint64_t, std::string>> held_runs;
  std::vector<std::pair<std::uint64_t, std::string>> held_progress;
  bool reorder = !resumed.in_order;
  const auto put_in_order = [&] {
    if (!reorder && held_runs.empty()) return;
    progress.rewrite_in_order(progress_index_col, std::move(held_progress));  // progress first, as always
    runs.rewrite_in_order(index_col, std::move(held_runs));
    held_progress.clear();
    held_runs.clear();
    reorder = false;
  };
  auto write = [&](Job job) {
    ++report.ran;
    if (job.rows.failed) ++report.failed;
    if (resumed.last_index && job.index < *resumed.last_index) {
      held_progress.emplace_back(job.index, std::move(job.rows.progress_rows));
      held_runs.emplace_back(job.index, std::move(job.rows.run_row));
    } else {
      put_in_order();
      progress.append(job.rows.progress_rows);
      runs.append(job.rows.run_row);
      flush_both();  // two write(2) calls per run: nothing next to a simulation
    }
    const std::uint64_t s = skipped.load();
    meter.update(s + report.ran, s);
  };

  // Only while dispatching and searching: Ctrl-C during the aggregation kills.
  std::optional<StopSignals> signals(std::in_place);
  try {
    // More threads than cores: oneTBB caps its workers at the core count unless told.
    std::optional<tbb::global_control> allow;
    if (threads > tbb::info::default_concurrency()) {
      allow.emplace(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
    }
    tbb::task_arena arena(threads);
    arena.execute([&] {
      tbb::parallel_pipeline(kTokensPerThread * static_cast<std::size_t>(threads),
                             tbb::make_filter<void, Job>(tbb::filter_mode::serial_in_order, dispatch) &
                                 tbb::make_filter<Job, Job>(tbb::filter_mode::parallel, simulate_run) &
                                 tbb::make_filter<Job, void>(tbb::filter_mode::serial_in_order, write));
    });
    put_in_order();
    flush_both();
  } catch (...) {
    info.status = "failed";
    info.end_utc = utc_now_iso8601();
    try {
      flush_both();
      write_manifest(manifest_path, manifest_json(plan, info));
    } catch (...) {  // NOLINT(bugprone-empty-catch): the first error is the one to report
    }
    throw;
  }

  // 3. Counts, manifest, aggregation.
  report.skipped = skipped.load();
  meter.finish(report.skipped + report.ran, report.skipped);
  report.interrupted = stop_requested.load() && report.skipped + report.ran < report.total;
  report.wall_s = std::chrono::duration<double>(Clock::now() - wall_start).count();
  report.runs_per_s = report.wall_s > 0 ? static_cast<double>(report.ran) / report.wall_s : 0.0;

  info.runs.skipped = report.skipped;
  info.runs.ran = report.ran;
  info.runs.done = report.skipped + report.ran;
  info.runs.failed = resumed.failed + report.failed;
  info.end_utc = utc_now_iso8601();
  info.wall_s = report.wall_s;
  info.runs_per_s = report.runs_per_s;
  info.status = report.interrupted ? "interrupted" : "complete";
  if (!report.interrupted && !plan.search_units().empty()) {
    // 4. The exact weight searches (weight_search_runner.hpp): searches.json is written last, so
    //    its presence means every search file is complete.
    if (fs::exists(dir + "/searches.json")) {
      report.searches_done_before = true;
    } else {
      info.status = "running";
      write_manifest(manifest_path, manifest_json(plan, info));
      // A stop after the last run was dispatched ends the searches at once (nothing searched).
      report.searches = run_weight_searches(plan, dir, threads, options.progress, options.shard_index,
                                            options.shard_count, &stop_requested);
      report.interrupted = report.searches.interrupted;
      info.status = report.interrupted ? "interrupted" : "complete";
      info.end_utc = utc_now_iso8601();
      report.wall_s = std::chrono::duration<double>(Clock::now() - wall_start).count();
      info.wall_s = report.wall_s;
    }
  }
  signals.reset();
  write_manifest(manifest_path, manifest_json(plan, info));

  if (!report.interrupted && options.shard_count == 1) aggregate(dir, {});
  return report;
}

}  // namespace sweep
}  // namespace fsweep
