#pragma once
/// @file sweep_runner.hpp
/// Runs a SweepPlan in parallel (oneTBB) and writes its outputs, resumably.
///
/// Files in the output directory (the contract between runner, aggregation, merge and plots):
/// - `runs.csv`: header `run_index,run_key,map_class,strategy_label,<config columns>,seed,<metric columns>,
///   optimal_distance_m,competitive_ratio`; one row per run, in run-index order. `map_class` is
///   SweepMap::map_class, `strategy_label` the strategy entry's label followed by "+rr", "+seg"
///   for each heuristic the run uses (src/sim/heuristics.hpp; "cf+rr+seg"). Config columns
///   are the union over the sweep of runs_schema.hpp's config_columns() (a column a run does not
///   have is empty; see sweep_table.hpp); metric columns are runs_schema.hpp's metric_columns().
///   The last two columns are empty where no optimum is known: they hold the star-pattern
///   optimum d* = pi r^2 / (2 r_s) (competitive.hpp) and distance_m / d* for runs on a `free`
///   map with a finite battery, r = battery capacity / energy per metre of straight travel
///   (per_metre + per_cell / resolution), r_s = sensor range_m, when the map holds the disc of
///   radius r/2 + r_s around the dock and one cell more (sweep_table.hpp's star_optimum()). In a
///   sweep with a `free` map the last config column, `optimum_check`, says why per run: empty
///   (no free-space competitive setting), `ok`, or `clipped: half-width H < N cells`.
///   A run that fails (planner error, step cap, a plugin throwing ConfigError) is a row with its
///   end_reason and end_detail; an exception leaves the metric cells empty. It never stops the
///   sweep.
/// - `progress.csv`: `run_index,run_key,distance_m,explored_area_m2,coverage,energy`, the runs'
///   progress samples, grouped by run in run-index order. A run's progress rows reach the file
///   before its runs.csv row, so a run counts as done exactly when its runs.csv row is complete.
/// - `manifest.json` (manifest.hpp): the sweep file's contents and FNV-1a hash, run counts
///   (total, done, skipped as already done, ran, failed), git revision, compiler, library
///   versions, host, CPU model, threads, start and end time (UTC, ISO 8601), wall seconds,
///   runs/s, status ("running" while running, then "complete", "interrupted" or "failed"), and
///   `sessions`: one entry per invocation on the directory, oldest first (start, end, status,
///   sweep_hash, sweep file, version, host, threads, shard, runs simulated, wall seconds, runs/s),
///   so the history of a resumed or extended sweep is kept; the top-level timing fields are over
///   all sessions (manifest_json()). Written at the start and at the end, each time through a
///   temp file and rename; `fresh` starts the history over.
///   In a sweep with a competitive map (sweep_plan.hpp, `competitive`), runs.csv ends with
///   runs_schema.hpp's kCompetitiveColumns: the offline optimum's bounds of the run's map and
///   robot and distance_to_final_coverage_m over them (optimum_table.hpp, docs/results.md).
/// - `optima.csv` (competitive maps only): the cache of the offline optima (optimum_table.hpp),
///   computed before the runs for the keys the (shard's) runs need and missing from it.
/// - `summary.csv`, `progress_summary.csv`, `best.csv`: written by aggregate.hpp after a
///   complete, unsharded run.
/// - The exact weight searches' files (weight_search_runner.hpp: searches.json,
///   behaviours.csv, search_summary.csv, search_best.csv, search_ranks.csv,
///   search_heatmaps.csv, vectors.csv), after the runs of a complete run; skipped when
///   searches.json is already there (a finished search is not redone; --fresh redoes it). A
///   shard searches its part of each box and writes its journal and searches.json only; the
///   merge writes the files (merge.hpp).
/// - `results.sqlite`: the runs as an SQLite database (report/sqlite_export.hpp), written by the
///   CLI after a run that was not interrupted when asked (`fsweep run --sqlite`); `fresh` deletes it.
/// - `.fsweep.lock`: an flock held while running; a second runner on the same directory is
///   refused (the kernel drops the lock when the process dies, even by SIGKILL). Temp files a
///   killed runner left (`runs.csv.tmp.<pid>`, ...) are deleted on start.
///
/// Determinism: workers run whole runs; rows pass through a bounded reorder stage (a oneTBB
/// parallel_pipeline whose serial in-order output stage writes them) and are written in
/// run-index order, so the files are byte-identical for any thread count (timing columns
/// aside: `*_time_s` columns measure this machine and are excluded from comparisons). At most
/// 16 x threads runs are in flight or waiting to be written, whatever the sweep's size.
///
/// Durability: each run's rows are written (write(2), no fsync) as soon as the in-order writer
/// reaches it, its progress rows before its runs.csv row. SIGKILL at any moment loses only the
/// runs in flight and leaves at most a torn last record in each file.
///
/// Resume: on start, runs.csv must have this sweep's header (else ConfigError: use `fresh`);
/// a torn last record (no final newline), malformed records (what CsvReader refuses: a
/// carriage return inside a line, a stray quote) and records with the wrong field count or a
/// bad run_key or run_index are cut off, each named on stderr with its file, line(s) and
/// reason. The done runs are the (run_key, run_index) pairs of its rows, kept as 16 bytes per
/// row. progress.csv is cut the same way and loses the rows of runs without a runs.csv row
/// (truncated when they form its tail, rewritten through a temp file otherwise). Runs are then
/// dispatched in index order, skipping a run whose key is among the done ones (each done row
/// skips one run: a sweep listing the same configuration twice keeps both). A run below the
/// largest run_index in the files (a gap a dropped row left, a new run of an extended sweep) is
/// appended like any other, and once the runs end (also when interrupted) both files are
/// rewritten in run_index order (CsvJournal::rewrite_in_order(); progress.csv first, each
/// through a temp file and rename, so a kill meanwhile leaves complete files, out of order, that
/// the next run puts in order the same way). Done rows out of run_index order are put in order
/// the same way. So the resumed files are byte-identical to an uninterrupted run's (timing
/// columns aside).
///
/// Extending: when the sweep file's hash differs from the manifest's (and not `fresh`), the
/// outputs are of another version of the sweep file. It is an extension when every done row's
/// run_key is the key the changed sweep gives one of its runs (of the same shard): repetitions,
/// map seeds, values, maps or strategy entries added. The done rows are found by
/// RunPlacement (done_runs.hpp) from the changed plan's keys (computed in parallel until every
/// done row has its place), and both files are rewritten in the changed sweep's run order
/// (rewrite_in_order() again): progress rows renumbered, runs.csv rows under the changed
/// sweep's header with their cells up to end_reason described by it (SweepTable::describe():
/// run_index, labels, config columns) and their outcome and metric cells kept; then the run goes
/// on as a resume, so only the new runs are simulated. A place follows from the keys alone, so a
/// kill during the rewrite is repaired by the next run. Refused with a ConfigError before any
/// file is touched: done runs the changed sweep does not have (removed or changed: how many, and
/// one or two of them by map, strategy, parameters and repetition of the earlier sweep rebuilt
/// from the manifest), done runs of a shard directory that belong to other shards of the changed
/// sweep (run indices change with the plan), a map whose content changed (changed_map_contents()),
/// outcome or metric columns of another build, and sweeps with exact weight searches (before or
/// after: their files are of the earlier sweep's instances).
///
/// Memory: a weight search whose memory in use reaches 90% of RunnerOptions::max_memory is
/// stopped as by a signal (below) but the manifest says "failed" and the report has
/// searches.memory_stop (weight_search_runner.hpp). The limit is recorded in the manifest:
/// `max_memory` {bytes, source}, at the top level and in the session's entry (sweeps with searches).
///
/// Signals: SIGINT/SIGTERM stop dispatching new runs; runs in flight finish and are written,
/// the files are flushed, the manifest says "interrupted", and run_sweep returns with
/// `interrupted` set. During the exact weight searches they stop the search at each branch's
/// next decision (run_weight_searches' `stop`): its journal keeps what finished, no other search
/// file is written, and the same holds. A second SIGINT/SIGTERM kills the process (default action; the files
/// stay repairable). The previous handlers are restored on return. Not reentrant: one run_sweep per process
/// at a time.
///
/// Sharding (docs/dev/architecture.md, "Sweeps, keys, shards and the weight search"): shard i of n runs the
/// indices with index % n == i and writes to
/// `<out>/shard-i-of-n/` with the whole sweep's header, so shards concatenate row-wise; each
/// shard resumes on its own; aggregation is left to the merge.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "core/memory_limit.hpp"
#include "sweep/optimum_table.hpp"
#include "sweep/sweep_plan.hpp"
#include "sweep/weight_search_runner.hpp"

namespace fsweep {
inline namespace sweep {

/// The bound of RunnerOptions::threads: this many times the machine's hardware threads.
inline constexpr int kThreadsPerHardwareThread = 4;

/// std::thread::hardware_concurrency(), at least 1 (it may report 0 when unknown).
[[nodiscard]] int hardware_threads();

/// kThreadsPerHardwareThread x hardware_threads(): the most worker threads a sweep may ask for.
[[nodiscard]] int max_threads();

struct RunnerOptions {
  /// Worker threads; 0 = all cores (oneTBB's default concurrency). Negative or more than
  /// max_threads(): ConfigError.
  int threads = 0;
  /// Delete previous outputs (runs.csv, progress.csv, manifest.json, summary.csv,
  /// progress_summary.csv, best.csv; nothing else) and start over.
  bool fresh = false;
  /// Output directory; empty = the plan's. Created when missing.
  std::string out_dir;
  /// Path of the sweep file, recorded in the manifest (may be empty).
  std::string sweep_file;
  /// Progress on stderr: a bar with runs done, runs/s and ETA on a terminal, a line every few
  /// seconds otherwise; false = silent.
  bool progress = true;
  /// Shard i of n (docs/dev/architecture.md, "Sweeps, keys, shards and the weight search"): only runs with
  /// index % n == i. n = 1: all runs. n = 0 or i >= n: ConfigError.
  std::uint64_t shard_index = 0;
  std::uint64_t shard_count = 1;
  /// The memory limit of the exact weight searches' guard (weight_search_runner.hpp,
  /// SearchMemoryGuard; `fsweep run --max-memory`); nullopt: default_memory_limit() (the
  /// cgroup's limit, else the machine's memory). Recorded in the manifest as `max_memory`.
  std::optional<MemoryLimit> max_memory;
  /// What the guard reads as the memory in use; empty: the process's resident set. Tests give
  /// their own to stop a search at a point of their choosing.
  std::function<std::optional<std::uint64_t>()> resident_memory;
};

struct RunnerReport {
  std::uint64_t total = 0;    ///< runs in the sweep (or shard)
  std::uint64_t skipped = 0;  ///< already in the outputs
  std::uint64_t ran = 0;      ///< simulated now
  std::uint64_t failed = 0;   ///< of those simulated now, ended with EndReason::Error
  bool interrupted = false;   ///< stopped by a signal before every run was done
  int threads = 0;            ///< worker threads used
  double wall_s = 0.0;
  double runs_per_s = 0.0;  ///< ran / wall_s
  std::string out_dir;      ///< where the files are (with the shard subdirectory)
  /// The sweep_hash of the earlier version of the sweep file whose outputs this run extended
  /// (Extending, above); empty when the sweep file had not changed.
  std::string extended_from;
  /// Of those outputs, the finished runs kept (in the changed sweep's run order).
  std::uint64_t kept = 0;
  /// The sweep's exact weight searches, run after its runs (when those were not interrupted).
  /// A search the memory guard stopped sets searches.memory_stop, and `interrupted`.
  SearchRunReport searches;
  /// The guard's limit (RunnerOptions::max_memory or the default); nullopt when none could be read.
  std::optional<MemoryLimit> max_memory;
  /// Their files were already there (searches.json), so they were not run again.
  bool searches_done_before = false;
  /// The offline optima of the runs on competitive maps (optimum_table.hpp), prepared before the
  /// runs: all zero in a sweep without a competitive map or with every run already done.
  OptimumReport optima;
};

/// Runs the plan. Throws ConfigError for unusable outputs (another runner on the directory, a
/// sweep file changed since the outputs were made other than by adding runs, without `fresh`;
/// runs.csv with other columns) and for bad options. A file the machine does not let it write
/// (an unwritable directory, a full disk, a file size limit) throws IoError naming the file and
/// the OS error; every file is then left whole (the manifest says "failed" when the runs were
/// stopped by it), and the same call resumes once the file can be written.
[[nodiscard]] RunnerReport run_sweep(const SweepPlan& plan, const RunnerOptions& options);

}  // namespace sweep
}  // namespace fsweep
