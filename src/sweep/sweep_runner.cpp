#include "sweep/sweep_runner.hpp"

#include <fcntl.h>
#include <oneapi/tbb/global_control.h>
#include <oneapi/tbb/info.h>
#include <oneapi/tbb/parallel_pipeline.h>
#include <oneapi/tbb/task_arena.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <memory>
#include <optional>
#include <thread>

#include "core/config_error.hpp"
#include "core/files.hpp"
#include "core/io_error.hpp"
#include "core/json_text.hpp"
#include "report/aggregate.hpp"
#include "report/runs_schema.hpp"
#include "report/search_schema.hpp"
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

constexpr const char* kOutputFiles[] = {"runs.csv",      "progress.csv",     "manifest.json",
                                        "summary.csv",   "best.csv",         "progress_summary.csv",
                                        kSearchesFile,   kBehavioursFile,    kSearchSummaryFile,
                                        kSearchBestFile, kSearchRanksFile,   kSearchHeatmapsFile,
                                        kVectorsFile,    kSearchJournalFile, "results.sqlite",
                                        kOptimaFile,     kSearchAnytimeFile, kSearchProbesFile};

/// Set by SIGINT/SIGTERM while run_sweep runs (a signal handler can only reach a global).
std::atomic<bool> stop_requested{false};  // NOLINT(cppcoreguidelines-avoid-non-const-global-variables)
static_assert(std::atomic<bool>::is_always_lock_free);

/// When the first stop signal came (CLOCK_MONOTONIC nanoseconds; 0: none yet).
std::atomic<std::int64_t> first_stop_ns{0};  // NOLINT(cppcoreguidelines-avoid-non-const-global-variables)
static_assert(std::atomic<std::int64_t>::is_always_lock_free);

/// A second stop signal kills only when it comes a second or more after the first: `timeout`
/// signals the process and then its process group, so one stop can arrive twice at once.
constexpr std::int64_t kSecondSignalNs = 1'000'000'000;

extern "C" void on_stop_signal(int signal) {
  timespec now{};
  ::clock_gettime(CLOCK_MONOTONIC, &now);  // async-signal-safe
  const std::int64_t ns = static_cast<std::int64_t>(now.tv_sec) * 1'000'000'000 + now.tv_nsec;
  std::int64_t first = 0;
  if (first_stop_ns.compare_exchange_strong(first, ns)) {
    stop_requested.store(true);
    return;
  }
  if (ns - first < kSecondSignalNs) return;
  ::signal(signal, SIG_DFL);  // the second stop: killed by it, as without a handler
  ::raise(signal);
}

/// Installs the stop handlers for its lifetime. A second signal, a second or more after the
/// first, kills.
class StopSignals {
 public:
  StopSignals() {
    stop_requested.store(false);
    first_stop_ns.store(0);
    struct sigaction sa {};
    sa.sa_handler = on_stop_signal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESTART;
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
    if (fd_ < 0)
      throw IoError(path, "cannot create the lock file (is the output directory writable?)", errno);
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

/// One run moving through the pipeline.
struct Job {
  std::uint64_t index = 0;
  RunRows rows;
};

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

void check_options(const RunnerOptions& options) {
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
  if (options.max_memory && options.max_memory->bytes == 0)
    throw ConfigError("--max-memory", "must be > 0 bytes");
}

/// Removes the temp files of a runner killed while replacing a file ("runs.csv.tmp.<pid>").
void remove_torn_replacements(const std::string& dir) {
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    for (const char* f : {"runs.csv", "progress.csv", "manifest.json"}) {
      if (name.starts_with(std::string(f) + ".tmp.")) fs::remove(entry.path());
    }
  }
}

/// What the directory's earlier outputs allow: with `fresh`, none are kept; outputs of an
/// earlier version of the sweep file are extended (extend_outputs() refuses unless the change
/// only adds runs); outputs of an older fsweep or of other maps are refused. Returns the earlier
/// sessions of the manifest.
nlohmann::json reconcile_earlier_outputs(const SweepPlan& plan, const RunnerOptions& options,
                                         const SweepTable& table, const std::string& dir,
                                         RunnerReport& report) {
  nlohmann::json sessions = nlohmann::json::array();
  if (options.fresh) {
    for (const char* f : kOutputFiles) fs::remove(dir + "/" + f);
    std::error_code ec;  // a directory not made yet holds nothing
    for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
      const std::string name = e.path().filename().string();
      if (is_search_certificate_file(name) || is_search_status_file(name)) fs::remove(e.path());
    }
    return sessions;
  }
  const auto old = read_manifest(dir + "/manifest.json");
  if (!old) return sessions;
  sessions = manifest_sessions(*old);
  const std::string old_hash = (*old)["sweep_hash"].get<std::string>();
  if (old_hash != sweep_hash(plan.source()) &&
      !same_sweep_but_description(old->value("sweep", nlohmann::json()), plan.source())) {
    report.kept = extend_outputs(plan, ShardOf{options.shard_index, options.shard_count}, table, dir, *old);
    report.extended_from = old_hash;
  } else if (!old->contains("maps") && has_rows(dir + "/runs.csv")) {
    throw ConfigError(dir,
                      "holds the results of an older fsweep: its manifest.json does not record the maps' "
                      "content, and its run keys differ from this version's; use --fresh to start over, or "
                      "another output directory");
  } else if (const auto changed = changed_maps(*old, plan); !changed.empty() && has_rows(dir + "/runs.csv")) {
    std::string list;
    for (const std::string& c : changed) list += (list.empty() ? "" : "; ") + c;
    throw ConfigError(dir, "holds the results of other maps than this sweep's (" + list +
                               "); use --fresh to start over, or another output directory");
  }
  return sessions;
}

/// The runs of a sweep (or shard) through oneTBB's pipeline: dispatched in index order (skipping
/// done runs), simulated in parallel, written in index order. A run below the largest run_index
/// in the files (a gap a dropped row left, a new run of an extended sweep) is appended like any
/// other; both files are put in run order (temp file and rename) once the runs end, also when
/// interrupted.
class RunPipeline {
 public:
  RunPipeline(const SweepPlan& plan, const RunnerOptions& options, const SweepTable& table,
              const Resumed& resumed, CsvJournal& runs, CsvJournal& progress, RunnerReport& report)
      : plan_(plan),
        options_(options),
        table_(table),
        resumed_(resumed),
        runs_(runs),
        progress_(progress),
        report_(report),
        meter_(report.total, "runs", options.progress),
        next_(options.shard_index),
        index_col_(table.column(kRunIndexColumn)),
        progress_index_col_(SweepTable::progress_column(kRunIndexColumn)),
        last_index_(resumed.last_index),
        reorder_(!resumed.in_order) {}

  /// Runs every run not done on `threads` threads until they are all written or a stop is
  /// requested (SIGINT, SIGTERM).
  void run(int threads) {
    // More threads than cores: oneTBB caps its workers at the core count unless told.
    std::optional<tbb::global_control> allow;
    if (threads > tbb::info::default_concurrency()) {
      allow.emplace(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
    }
    tbb::task_arena arena(threads);
    arena.execute([&] {
      tbb::parallel_pipeline(
          kTokensPerThread * static_cast<std::size_t>(threads),
          tbb::make_filter<void, Job>(tbb::filter_mode::serial_in_order, [this](tbb::flow_control& fc) {
            return dispatch(fc);
          }) & tbb::make_filter<Job, Job>(tbb::filter_mode::parallel, [this](Job job) {
            return simulate(std::move(job));
          }) & tbb::make_filter<Job, void>(tbb::filter_mode::serial_in_order, [this](const Job& job) {
            write(job);
          }));
    });
    put_in_order();
    flush();
  }

  /// Writes what the journals hold: progress rows first (a runs.csv row marks its run as done).
  void flush() {
    progress_.flush();
    runs_.flush();
  }

  /// Runs skipped as done before; the meter's last line.
  std::uint64_t finish() {
    const std::uint64_t skipped = skipped_.load();
    meter_.finish(skipped + report_.ran, skipped);
    return skipped;
  }

 private:
  Job dispatch(tbb::flow_control& fc) {
    while (true) {
      if (stop_requested.load()) {
        if (!announced_stop_ && options_.progress) {
          std::fputs("\nfsweep: stopping: finishing the runs in flight (press Ctrl-C again to abort)\n",
                     stderr);
        }
        announced_stop_ = true;
        fc.stop();
        return {};
      }
      if (next_ >= plan_.run_count()) {
        fc.stop();
        return {};
      }
      Job job;
      job.index = next_;
      next_ += options_.shard_count;
      if (resumed_.done.has(job.index)) {  // its row's key was verified against the plan's
        skipped_.fetch_add(1);
        continue;
      }
      return job;
    }
  }

  Job simulate(Job job) const {
    job.rows = table_.run(plan_, plan_.run(job.index));
    return job;
  }

  void write(const Job& job) {
    ++report_.ran;
    if (job.rows.failed) ++report_.failed;
    if (last_index_ && job.index < *last_index_) reorder_ = true;
    last_index_ = std::max(last_index_.value_or(0), job.index);
    progress_.append(job.rows.progress_rows);
    runs_.append(job.rows.run_row);
    flush();  // two write(2) calls per run: nothing next to a simulation
    const std::uint64_t s = skipped_.load();
    meter_.update(s + report_.ran, s);
  }

  void put_in_order() {
    if (!reorder_) return;
    progress_.rewrite_in_order(progress_index_col_);  // progress first, as always
    runs_.rewrite_in_order(index_col_);
    reorder_ = false;
  }

  const SweepPlan& plan_;
  const RunnerOptions& options_;
  const SweepTable& table_;
  const Resumed& resumed_;
  CsvJournal& runs_;
  CsvJournal& progress_;
  RunnerReport& report_;
  ProgressMeter meter_;
  std::atomic<std::uint64_t> skipped_{0};
  std::uint64_t next_;
  bool announced_stop_ = false;
  const std::size_t index_col_;
  const std::size_t progress_index_col_;
  std::optional<std::uint64_t> last_index_;
  bool reorder_;
};

/// The manifest's record of a session whose runs ended: counts, end time, status.
void record_end(const RunnerReport& report, const Resumed& resumed, ManifestInfo& info) {
  info.runs.skipped = report.skipped;
  info.runs.ran = report.ran;
  info.runs.done = report.skipped + report.ran;
  info.runs.failed = resumed.failed + report.failed;
  info.runs.ran_failed = report.failed;
  info.end_utc = utc_now_iso8601();
  info.wall_s = report.wall_s;
  info.runs_per_s = report.runs_per_s;
  info.status = report.interrupted ? "interrupted" : "complete";
}

/// manifest_json() with the weight searches' memory limit, `max_memory`: {bytes, source} (null
/// when none could be read), at the top level and in this session's entry (the limit may change
/// from one session to the next). Only in sweeps with searches: the limit guards nothing else.
nlohmann::json manifest_of(const SweepPlan& plan, const ManifestInfo& info, const RunnerReport& report) {
  nlohmann::json manifest = manifest_json(plan, info);
  if (plan.search_units().empty()) return manifest;
  nlohmann::json limit = nullptr;
  if (report.max_memory) limit = {{"bytes", report.max_memory->bytes}, {"source", report.max_memory->source}};
  manifest["max_memory"] = limit;
  manifest["sessions"].back()["max_memory"] = limit;
  return manifest;
}

/// The exact weight searches (weight_search_runner.hpp), after the runs: searches.json is
/// written last, so its presence (a whole one, a record per search) means every search file is
/// complete and nothing is searched.
/// A search the memory guard stopped leaves the manifest "failed": the environment, not the
/// user, ended it, as a file that cannot be written does.
void run_searches(const SweepPlan& plan, const RunnerOptions& options, int threads,
                  const std::string& manifest_path, Clock::time_point wall_start, ManifestInfo& info,
                  RunnerReport& report) {
  const std::string& dir = report.out_dir;
  if (const std::optional<std::string> text = read_file(dir + "/" + kSearchesFile)) {
    // A searches.json that is not whole (cut short, edited) marks nothing: the searches read
    // their journals back and write their files again.
    const nlohmann::json done = parse_json_or_discard(*text);
    if (done.is_object() && done.contains("searches") && done.at("searches").is_array() &&
        done.at("searches").size() == plan.search_units().size()) {
      report.searches_done_before = true;
      return;
    }
    if (!fs::exists(dir + "/" + kSearchJournalFile)) {  // a merge's: its journals are the shards'
      throw ConfigError(dir + "/" + kSearchesFile,
                        "not whole, and no search_journal.jsonl beside it to write it again from (the "
                        "directory of a merge, whose journals are its shards'): run `fsweep merge` on the "
                        "shards' directory again");
    }
  }
  info.status = "running";
  write_manifest(manifest_path, manifest_of(plan, info, report));
  // A stop after the last run was dispatched ends the searches at once (nothing searched).
  try {
    report.searches =
        run_weight_searches(plan, dir, threads, options.progress, options.shard_index, options.shard_count,
                            &stop_requested, SearchMemoryGuard{report.max_memory, options.resident_memory});
  } catch (...) {  // e.g. a journal that cannot be written: the manifest says so, as for the runs
    info.status = "failed";
    info.end_utc = utc_now_iso8601();
    record_failed_manifest(manifest_path, manifest_of(plan, info, report));
    throw;
  }
  report.interrupted = report.searches.interrupted;
  info.status = report.searches.memory_stop ? "failed" : report.interrupted ? "interrupted" : "complete";
  info.end_utc = utc_now_iso8601();
  report.wall_s = seconds_since(wall_start);
  info.wall_s = report.wall_s;
}

}  // namespace

int hardware_threads() { return std::max(1, static_cast<int>(std::thread::hardware_concurrency())); }

int max_threads() { return kThreadsPerHardwareThread * hardware_threads(); }

RunnerReport run_sweep(const SweepPlan& plan, const RunnerOptions& options) {
  // 1. Options, directory, lock, earlier outputs, the manifest of this session.
  check_options(options);
  const int threads = options.threads > 0 ? options.threads : tbb::info::default_concurrency();
  const auto wall_start = Clock::now();
  RunnerReport report;
  report.threads = threads;
  report.max_memory = options.max_memory ? options.max_memory : default_memory_limit();
  report.out_dir = output_directory(plan, options);
  const std::string& dir = report.out_dir;
  const DirectoryLock lock(dir);
  remove_torn_replacements(dir);
  const std::string manifest_path = dir + "/manifest.json";
  SweepTable table(plan);
  nlohmann::json sessions = reconcile_earlier_outputs(plan, options, table, dir, report);

  CsvJournal runs(dir + "/runs.csv", table.header());
  CsvJournal progress(dir + "/progress.csv", SweepTable::progress_header());
  const Resumed resumed =
      repair_outputs(plan, ShardOf{options.shard_index, options.shard_count}, table, runs, progress);

  ManifestInfo info;
  info.sweep_file = options.sweep_file;
  info.threads = threads;
  info.shard_index = options.shard_index;
  info.shard_count = options.shard_count;
  info.start_utc = utc_now_iso8601();
  info.status = "running";
  info.sessions = std::move(sessions);
  info.runs.total = shard_size(plan.run_count(), options.shard_index, options.shard_count);
  info.runs.done = resumed.done.size();
  info.runs.failed = resumed.failed;
  write_manifest(manifest_path, manifest_of(plan, info, report));
  report.total = info.runs.total;

  // The offline optima of the runs on competitive maps, once per key before the runs (so the
  // workers only read them), from optima.csv or computed; none when every run is done.
  if (plan.competitive() && resumed.done.size() < info.runs.total) {
    table.use_optima(std::make_shared<const OptimumTable>(
        OptimumTable::prepare(plan, dir, options.shard_index, options.shard_count,
                              std::min(threads, tbb::info::default_concurrency()), report.optima)));
  }

  // 2. The runs. Ctrl-C stops them (and the searches) cleanly; during the aggregation it kills.
  RunPipeline pipeline(plan, options, table, resumed, runs, progress, report);
  std::optional<StopSignals> signals(std::in_place);
  try {
    pipeline.run(threads);
  } catch (...) {
    info.status = "failed";
    info.end_utc = utc_now_iso8601();
    info.runs.ran = report.ran;
    info.runs.ran_failed = report.failed;
    info.wall_s = seconds_since(wall_start);
    // Each on its own: a journal that cannot be written (a full disk) must not keep the manifest
    // from saying "failed". The first error is the one to report.
    try {
      pipeline.flush();
    } catch (...) {  // NOLINT(bugprone-empty-catch)
    }
    record_failed_manifest(manifest_path, manifest_of(plan, info, report));
    throw;
  }

  // 3. Counts, the searches, the manifest, the aggregation.
  report.skipped = pipeline.finish();
  report.interrupted = stop_requested.load() && report.skipped + report.ran < report.total;
  report.wall_s = seconds_since(wall_start);
  report.runs_per_s = report.wall_s > 0 ? static_cast<double>(report.ran) / report.wall_s : 0.0;
  record_end(report, resumed, info);
  if (!report.interrupted && !plan.search_units().empty()) {
    run_searches(plan, options, threads, manifest_path, wall_start, info, report);
  }
  signals.reset();
  write_manifest(manifest_path, manifest_of(plan, info, report));

  if (!report.interrupted && options.shard_count == 1) aggregate(dir, {});
  return report;
}

}  // namespace sweep
}  // namespace fsweep
