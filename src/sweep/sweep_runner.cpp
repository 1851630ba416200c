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
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <thread>

#include "core/config_error.hpp"
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
    "vectors.csv",        "search_journal.jsonl", "results.sqlite",   kOptimaFile};

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
  const ShardOf shard{options.shard_index, options.shard_count};
  SweepTable table(plan);
  nlohmann::json sessions = nlohmann::json::array();
  if (options.fresh) {
    for (const char* f : kOutputFiles) fs::remove(dir + "/" + f);
  } else if (const auto old = read_manifest(manifest_path)) {
    sessions = manifest_sessions(*old);
    const std::string old_hash = (*old)["sweep_hash"].get<std::string>();
    if (old_hash != hash) {
      report.kept = extend_outputs(plan, shard, table, dir, *old);  // refuses unless it only adds runs
      report.extended_from = old_hash;
    } else if (!old->contains("maps") && has_rows(dir + "/runs.csv")) {
      throw ConfigError(dir,
                        "holds the results of an older fsweep: its manifest.json does not record the maps' "
                        "content, and its run keys differ from this version's; use --fresh to start over, or "
                        "another output directory");
    } else if (const auto changed = changed_maps(*old, plan);
               !changed.empty() && has_rows(dir + "/runs.csv")) {
      std::string list;
      for (const std::string& c : changed) list += (list.empty() ? "" : "; ") + c;
      throw ConfigError(dir, "holds the results of other maps than this sweep's (" + list +
                                 "); use --fresh to start over, or another output directory");
    }
  }

  CsvJournal runs(dir + "/runs.csv", table.header());
  CsvJournal progress(dir + "/progress.csv", SweepTable::progress_header());
  Resumed resumed = repair_outputs(plan, shard, table, runs, progress);

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
  write_manifest(manifest_path, manifest_json(plan, info));
  report.total = info.runs.total;

  // The offline optima of the runs on competitive maps, once per key before the runs (so the
  // workers only read them), from optima.csv or computed; none when every run is done.
  if (plan.competitive() && resumed.done.size() < info.runs.total) {
    table.use_optima(std::make_shared<const OptimumTable>(
        OptimumTable::prepare(plan, dir, options.shard_index, options.shard_count,
                              std::min(threads, tbb::info::default_concurrency()), report.optima)));
  }

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
  // A run below the largest run_index in the files (a gap a dropped row left, a new run of an
  // extended sweep) is appended like any other; both files are put in run order (temp file and
  // rename) once the runs end, also when interrupted.
  const std::size_t index_col = table.column(kRunIndexColumn);
  const std::size_t progress_index_col = SweepTable::progress_column(kRunIndexColumn);
  std::optional<std::uint64_t> last_index = resumed.last_index;
  bool reorder = !resumed.in_order;
  const auto put_in_order = [&] {
    if (!reorder) return;
    progress.rewrite_in_order(progress_index_col);  // progress first, as always
    runs.rewrite_in_order(index_col);
    reorder = false;
  };
  auto write = [&](const Job& job) {
    ++report.ran;
    if (job.rows.failed) ++report.failed;
    if (last_index && job.index < *last_index) reorder = true;
    last_index = std::max(last_index.value_or(0), job.index);
    progress.append(job.rows.progress_rows);
    runs.append(job.rows.run_row);
    flush_both();  // two write(2) calls per run: nothing next to a simulation
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
    info.runs.ran = report.ran;
    info.runs.ran_failed = report.failed;
    info.wall_s = std::chrono::duration<double>(Clock::now() - wall_start).count();
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
  info.runs.ran_failed = report.failed;
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
