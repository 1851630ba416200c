#pragma once
/// @file done_runs.hpp
/// The runs already in a sweep's output directory (sweep_runner.hpp): as (run_key, run_index)
/// pairs, read back from runs.csv and progress.csv by a resume (repair_outputs()), and moved to
/// their places in a changed sweep that only adds runs (extend_outputs()).

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fsweep {
inline namespace sweep {

class CsvJournal;
class SweepPlan;
class SweepTable;

/// The done runs of a resumed sweep, sorted by run_index: 16 bytes per row, so a resumed sweep
/// of 10^8 done runs needs 1.6 GB rather than a hash set of strings. Each run_index is added at
/// most once (the runner drops a repeated row while repairing runs.csv).
class DoneRuns {
 public:
  struct Row {
    std::uint64_t index = 0;
    std::uint64_t key = 0;
    auto operator<=>(const Row&) const = default;
  };

  /// Adds a row (call before seal()).
  void add(std::uint64_t key, std::uint64_t index);
  /// Sorts by run_index; call once after the last add().
  void seal();

  /// True when the row of run `index` has this key (progress.csv filtering).
  [[nodiscard]] bool contains(std::uint64_t key, std::uint64_t index) const;
  /// True when run `index` has a row: the run is done and is skipped.
  [[nodiscard]] bool has(std::uint64_t index) const;

  /// The rows, by run_index (after seal()).
  [[nodiscard]] const std::vector<Row>& rows() const { return rows_; }
  [[nodiscard]] std::size_t size() const { return rows_.size(); }
  [[nodiscard]] bool empty() const { return rows_.empty(); }

 private:
  std::vector<Row> rows_;
};

/// Where the done runs of an earlier version of a sweep file go in its new plan (an extended
/// sweep, sweep_runner.hpp): each to a run of the new plan with its run key. The new plan's runs
/// are offered in ascending run_index order, and each takes the first done row with its key not
/// placed yet (by earlier run_index), so rows of one key (a configuration two strategy entries
/// reach) keep their order. 40 bytes per done row.
class RunPlacement {
 public:
  /// Nothing of `done` (sealed) placed yet.
  explicit RunPlacement(const DoneRuns& done);

  /// Offers run `index` of the new plan, whose run key is `key` (ascending `index`, before seal()).
  void offer(std::uint64_t index, std::uint64_t key);
  /// True when every done row has its place.
  [[nodiscard]] bool complete() const { return placed_ == rows_.size(); }
  /// Call once after the last offer().
  void seal();

  /// The new run_index of the done row (key, index); also `index` itself when a done row of
  /// this key was placed there (a row already renumbered). Nullopt otherwise (after seal()).
  [[nodiscard]] std::optional<std::uint64_t> new_index(std::uint64_t key, std::uint64_t index) const;
  /// The done rows that found no place, by run_index (after seal()).
  [[nodiscard]] std::vector<DoneRuns::Row> unplaced() const;
  /// Done rows placed.
  [[nodiscard]] std::size_t placed() const { return placed_; }

 private:
  static constexpr std::uint64_t kNowhere = UINT64_MAX;
  struct Move {
    std::uint64_t key = 0;
    std::uint64_t from = 0;  ///< run_index in the done rows
    std::uint64_t to = kNowhere;
  };
  std::vector<Move> rows_;              ///< by (key, from) until seal(), then by from
  std::vector<DoneRuns::Row> arrived_;  ///< (to, key) of the placed rows, by `to` (after seal())
  std::size_t placed_ = 0;
};

/// The shard a runner writes: runs i with i % count == index (sweep_runner.hpp, Sharding).
struct ShardOf {
  std::uint64_t index = 0;
  std::uint64_t count = 1;
};

/// What survives of earlier invocations: the done runs, after repairing both files.
struct Resumed {
  DoneRuns done;
  std::uint64_t failed = 0;  ///< done rows whose end_reason is `error`
  /// The largest run_index of a done row; runs below it that are not done fill gaps.
  std::optional<std::uint64_t> last_index;
  bool in_order = true;  ///< the done rows are in ascending run_index order
};

/// Repairs `runs` and `progress` (the journals of `plan`'s runs.csv and progress.csv, of
/// `table`'s header) for a resume (sweep_runner.hpp, Resume): drops, naming each on stderr, a
/// torn last record, malformed rows, rows of a bad run_key or run_index, of a run_index beyond the
/// sweep or of another shard, repeated runs, and progress rows of runs without a complete runs.csv
/// row. Throws ConfigError before runs.csv is touched when a row's run_key is not the key `plan`
/// gives its run_index (its inputs changed).
[[nodiscard]] Resumed repair_outputs(const SweepPlan& plan, ShardOf shard, const SweepTable& table,
                                     CsvJournal& runs, CsvJournal& progress);

/// Moves the outputs in `dir` of another version of the sweep file, whose manifest is `old`, to
/// their places in `plan`'s run order (of `table`'s header) when `plan` only adds runs to it
/// (sweep_runner.hpp, Extending), and returns the finished runs kept; the caller then resumes
/// `plan` as usual. Otherwise throws ConfigError before any file is touched.
[[nodiscard]] std::uint64_t extend_outputs(const SweepPlan& plan, ShardOf shard, const SweepTable& table,
                                           const std::string& dir, const nlohmann::json& old);

/// True when the CSV file at `path` has a line after its header.
[[nodiscard]] bool has_rows(const std::string& path);

/// Reads a run_key (16 hex digits); nullopt for anything else.
[[nodiscard]] std::optional<std::uint64_t> parse_run_key(std::string_view s);
/// Reads a run_index (decimal digits); nullopt for anything else.
[[nodiscard]] std::optional<std::uint64_t> parse_run_index(std::string_view s);

}  // namespace sweep
}  // namespace fsweep
