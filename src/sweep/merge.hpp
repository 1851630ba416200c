#pragma once
/// @file merge.hpp
/// `fsweep merge DIR`: joins the shard outputs `DIR/shard-i-of-n/` of one sweep (sweep_runner.hpp,
/// Sharding) into DIR/runs.csv, DIR/progress.csv and DIR/manifest.json, then aggregates them as
/// `fsweep aggregate` does (summary.csv, progress_summary.csv, best.csv).

#include <cstdint>
#include <string>
#include <vector>

#include "core/shard_dirs.hpp"
#include "sweep/weight_search_runner.hpp"

namespace fsweep {
inline namespace sweep {

/// What merge_shards found and did.
struct MergeReport {
  std::uint64_t shard_count = 0;  ///< n of the shard directories
  std::uint64_t total = 0;        ///< runs of the whole sweep
  std::uint64_t rows = 0;         ///< runs.csv rows read over all shards
  /// Problems that make the merge incomplete: missing shard directories, missing runs
  /// ("run_index I (run_key K)"; the key when the sweep plan could be rebuilt), duplicates.
  /// Empty on success.
  std::vector<std::string> problems;
  bool written = false;  ///< merged files and aggregates written (problems is empty)
  /// With problems and exact weight searches of mode best: where they stand over the shards
  /// there are (join_search_statuses(), which wrote DIR/search_status_<id>.json); else empty.
  std::string search_status;
  /// Exact weight searches merged (merge_weight_searches(), weight_search_runner.hpp).
  std::size_t searches = 0;
  /// Set when the memory guard stopped the searches' merge: what it says (MemoryStop::message).
  /// Nothing is written then.
  std::string memory_stop;
};

/// Merges the shards under `dir`. Every shard directory (name `shard-<i>-of-<n>`) must have the
/// same n, a manifest.json with the same sweep_hash and runs.csv / progress.csv with equal
/// headers, and a manifest.json already in `dir` (an earlier merge or an unsharded run) must have
/// that sweep_hash too, or that of a sweep a session of the shards ran (the shards extended it,
/// sweep_runner.hpp); otherwise (or with no shard directory, or malformed files) throws
/// ConfigError naming the directories (and both sweeps) or the file and line, before anything is
/// written (exit code 2 in the CLI). The sweep's run count and run
/// keys come from the sweep plan rebuilt from the manifest's `sweep` (if that fails, e.g. a map
/// file is not reachable from the current directory, the total is the sum of the shard
/// manifests' `runs.total` and keys are not checked). Missing shard directories, run indices
/// 0..total-1 without a row, indices outside that range, and a run_index or run_key in more than
/// one row are listed in `problems`; then nothing is written but the searches' joint status
/// files (MergeReport::search_status). Otherwise writes DIR/runs.csv and
/// DIR/progress.csv (rows ordered by run_index, a run's progress rows in their shard's order),
/// DIR/manifest.json (the first shard's, with shard {index 0, count 1}, runs summed, every shard's
/// sessions by start time, start_utc the first session's, status
/// "complete") atomically, and runs aggregate(dir, {objective}). A sweep with exact weight
/// searches has them merged first (merge_weight_searches(): every shard needs its
/// searches.json, else ConfigError and nothing is written), under the memory guard `memory`
/// (no guard by default): past its threshold, report.memory_stop says so and nothing is written.
[[nodiscard]] MergeReport merge_shards(const std::string& dir, const std::string& objective = {},
                                       const SearchMemoryGuard& memory = {});

}  // namespace sweep
}  // namespace fsweep
