#pragma once
/// @file done_runs.hpp
/// The runs already in a sweep's runs.csv, as (run_key, run_index) pairs (sweep_runner.hpp).

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace fsweep {
inline namespace sweep {

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

/// Reads a run_key (16 hex digits); nullopt for anything else.
[[nodiscard]] std::optional<std::uint64_t> parse_run_key(std::string_view s);
/// Reads a run_index (decimal digits); nullopt for anything else.
[[nodiscard]] std::optional<std::uint64_t> parse_run_index(std::string_view s);

}  // namespace sweep
}  // namespace fsweep
