#pragma once
/// @file weight_search_runner.hpp
/// Runs a sweep's exact weight searches (strategy entries with "search", sweep_plan.hpp) and
/// writes their files (docs/dev/architecture.md, "The exact weight search"; docs/weight-search.md documents
/// the columns). One search per SearchUnit (entry x map class x planner x robot variant), its
/// instances (the class's maps x repetitions) searched jointly by exact_search(). A behaviour's
/// objective is the mean of the objective over its instances (the class mean); every statistic
/// weighs a behaviour by its number of weight vectors, so it is the statistic over all vectors.
///
/// Resume: every finished behaviour (mode best: every one that was at most the best known
/// when it finished) is appended to `search_journal.jsonl` (weightsearch/search_journal.hpp),
/// and so is every finished subtree of the region tree, each at once. A rerun reads the lines
/// of its search's key (instances, box, objective, mode and journal format), keeps those
/// behaviours and skips the journaled subtrees and behaviours where its tree reaches them
/// (exact_search's `journal`; mode best starts with the best of them as its incumbent): the
/// CSV files are the same as an uninterrupted search's. A line that does not parse (torn by a
/// kill) and every line after it are dropped (stderr says so) and the file is cut there.
///
/// Files, written after the search through temp files (a killed search leaves none of them
/// half written):
/// - `searches.json`: per search, its id, entry label, map class, planner, robot, instances,
///   the box, mode, counts (vectors, behaviours, splits, forks), wall seconds, and per instance
///   every resolved parameter (SweepPlan::search_instance_json()).
/// - `behaviours.csv`: `search_id, behaviour_id, vectors`, the representative (the
///   lexicographically smallest vector, one column per weight), `<w>.min, <w>.max` per weight
///   (the bounding box of its vectors), `objective` (the class mean), then one row per
///   instance: `instance, map, seed` and the metric columns of runs.csv (effort metrics left
///   empty: they measured the shared search), `optimal_distance_m, competitive_ratio`.
///   Behaviours are numbered from 0 in the order of their representatives.
/// - `search_summary.csv` (searches of mode "all"): per search: `search_id, strategy_label, map_class,
/// planner, robot,
///   instances, vectors, behaviours`, `end.<reason>` (vectors x instances that ended so), then
///   per metric M `M.mean, M.std, M.min, M.q05, M.q25, M.median, M.q75, M.q95, M.max` over all
///   vectors x instances (type 7 quantiles of the counted values, core/statistics.hpp).
/// - `search_best.csv`: per search, its behaviours ranked by the objective (ties by
///   behaviour_id; no value last): `search_id, rank, behaviour_id, vectors, vectors_better,
///   objective`, the representative. `rank` = 1 + vectors_better (vectors strictly better).
///   In mode "best" only the optimal behaviours.
/// - `search_ranks.csv` (mode "all"): per search and vector of its "rank" list: `search_id`, the vector,
///   `behaviour_id, objective, rank, vectors_better, vectors_tied` (equal objective, itself
///   included), `percentile` = 100 x vectors_better / vectors.
/// - `search_heatmaps.csv` (mode "all"): per search and pair of weights (a, b), for every pair
///   of their values, the best objective of any vector with those two values:
///   `search_id, weight_a, weight_b, value_a, value_b, best_objective, behaviour_id`.
/// - `vectors.csv` (write_vectors): `search_id`, one column per weight, `behaviour_id`, every
///   vector of the box in lexicographic order.

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/memory_limit.hpp"
#include "core/shard_dirs.hpp"
#include "sweep/sweep_plan.hpp"

namespace fsweep {
inline namespace sweep {

/// The searches' memory guard (docs/weight-search.md, "Memory"): while a search runs (and while
/// it reads its journal to resume) the memory in use is read every few tens of milliseconds and
/// every 16 behaviours; once it reaches core/memory_watch.hpp's kMemorySafetyShare of `limit`,
/// the search stops as at a Ctrl-C, its journal whole.
struct SearchMemoryGuard {
  /// The limit; nullopt: no guard.
  std::optional<MemoryLimit> limit;
  /// The memory in use; empty: the process's resident set (resident_memory_bytes()).
  std::function<std::optional<std::uint64_t>()> resident;
};

/// Why the memory guard stopped a search.
struct MemoryStop {
  std::size_t search_id = 0;
  MemoryLimit limit;
  /// The memory in use when it reached the guard's threshold.
  std::uint64_t in_use_bytes = 0;
  /// Behaviours the search held then (mode all holds every one it found or read back).
  std::uint64_t held_behaviours = 0;
  /// Mode best: branches still waiting or running then.
  std::size_t open_branches = 0;
  /// Stage Writing: what formatting the files was estimated to need beyond `in_use_bytes`
  /// (kFormattingBytesPerRow a row of behaviours.csv); 0 when the formatting itself reached it.
  std::uint64_t needed_bytes = 0;
  /// When: before the search read or searched anything (the process was already past the
  /// threshold), while it read its journal back to resume (nothing searched), while searching, or
  /// once it finished, formatting its files (the journal then holds the whole search: a rerun
  /// with the memory reads it back and writes them).
  /// Merging: `fsweep merge` reading the shards' journals back, or formatting the merged files
  /// (nothing is written then).
  enum class Stage { Starting, Resuming, Searching, Writing, Merging };
  Stage stage = Stage::Searching;
  /// What happened and what to do: the limit, the memory in use, the behaviours held, and the
  /// ways on (a larger --max-memory, mode best, shards).
  std::string message;
};

struct SearchRunReport {
  std::size_t searches = 0;
  std::uint64_t vectors = 0;
  /// Behaviours found by searches of mode "all", optimal ones found by those of mode "best".
  std::uint64_t behaviours = 0;
  std::uint64_t optimal = 0;
  double wall_s = 0.0;
  /// The files written, in the order above.
  std::vector<std::string> files;
  /// Stopped by `stop` before every search finished: no file but the journal and the stopped
  /// search's anytime status (search_anytime.hpp) was written.
  bool interrupted = false;
  /// Of a stopped search of mode best: where it stands (describe_search_status()), naming its
  /// status file.
  std::vector<std::string> standings;
  /// Set when the memory guard stopped the search (`interrupted` is set too).
  std::optional<MemoryStop> memory_stop;
};

/// Runs every search of `plan` (none: returns at once, writing nothing) on `threads` worker
/// threads (>= 1) and writes the files above into `out_dir`. `progress`: share of weight vectors
/// resolved, with ETA, on stderr.
///
/// Shard `shard_index` of `shard_count` > 1 searches only its part of each box
/// (WeightGrid::shard(): contiguous runs of blocks, deterministic) and writes only its journal
/// and a searches.json of its records (with "shard"); merge_weight_searches() joins the shards.
///
/// `stop` (e.g. set by SIGINT): once it is true the search in progress ends at the next decision
/// of each branch (exact_search), nothing else is searched or written, and the report says
/// `interrupted`. What finished is in the journal, flushed line by line, so a rerun resumes.
/// `memory`: the guard, which stops a search the same way (within 50 ms of the memory reaching
/// its threshold) and says so in the report's `memory_stop`.
SearchRunReport run_weight_searches(const SweepPlan& plan, const std::string& out_dir, int threads,
                                    bool progress, std::uint64_t shard_index = 0,
                                    std::uint64_t shard_count = 1, const std::atomic<bool>* stop = nullptr,
                                    const SearchMemoryGuard& memory = {});

/// Joins the searches of `plan` run as `shards` (each with its searches.json, whose records name
/// the shard its directory is, and a journal without a damaged line that holds what the shard
/// found, check_shard_journal(); else ConfigError naming the file or line; the shards' files
/// are only read) and writes the files above into `out_dir`: the behaviours of the
/// shards with one trace (Behaviour::trace) are one behaviour, so every CSV file is the one an
/// unsharded search writes. In searches.json the counts of work (splits, forks, wall_s, the
/// certificate's pruned regions) are the shards' sums and `merged_from_shards` keeps each
/// shard's record (for mode best, its certificate).
///
/// `memory`: the guard, watching while the shards' journals are read back and checking before the
/// files are formatted; past its threshold the merge stops with report.memory_stop (stage
/// Merging) and writes nothing.
SearchRunReport merge_weight_searches(const SweepPlan& plan, const std::string& out_dir,
                                      const std::vector<ShardDir>& shards,
                                      const SearchMemoryGuard& memory = {});

/// Per search of `plan`, in search order: its weight vectors and its blocks of 8^4 (WeightGrid),
/// which `fsweep run --shard i/N` divides among the shards (a shard of no block has nothing to
/// search).
std::vector<std::pair<std::uint64_t, std::uint64_t>> weight_search_blocks(const SweepPlan& plan);

/// For a merge that cannot go on (a shard directory missing): writes each search of mode best's
/// joint status so far as merge_weight_searches() does for a shard that did not finish, a shard
/// in `shard_dirs` without a status counting as unknown, and returns the note that says where
/// they stand ("" when the sweep has no search of mode best).
std::string join_search_statuses(const SweepPlan& plan, const std::string& out_dir,
                                 const std::vector<std::string>& shard_dirs);

/// The key of the lines of `plan`'s search `search_id` in a journal of `format`
/// (SearchJournal::format_for() of its instance count; kPreviousFormat for a class's lines an
/// older build wrote): what a reader of
/// the journal matches lines by. ConfigError as run_weight_searches() for a bad plan;
/// std::out_of_range for an id past the plan's searches.
[[nodiscard]] std::string weight_search_journal_key(const SweepPlan& plan, std::size_t search_id,
                                                    std::string_view format);

}  // namespace sweep
}  // namespace fsweep
