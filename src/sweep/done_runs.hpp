#pragma once
/// @file done_runs.hpp
/// The runs already in a sweep's runs.csv, as (run_key, run_index) pairs (sweep_runner.hpp).

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace fsweep {
inline namespace sweep {

/// A sorted set of done runs: 16 bytes per row plus one bit, so a resumed sweep of 10^8 done
/// runs needs 1.6 GB rather than a hash set of strings.
class DoneRuns {
 public:
  /// Adds a row (call before seal()).
  void add(std::uint64_t key, std::uint64_t index);
  /// Sorts; call once after the last add().
  void seal();

  /// True when a row with this key and index was added (progress.csv filtering).
  [[nodiscard]] bool contains(std::uint64_t key, std::uint64_t index) const;
  /// Consumes one not yet consumed row with this key; false when there is none (the run is
  /// not done). Each row skips one run, so duplicated configurations keep their count.
  bool take(std::uint64_t key);

  [[nodiscard]] std::size_t size() const { return rows_.size(); }
  /// Rows not consumed by take() yet (0: no later run can be done, stop looking).
  [[nodiscard]] std::size_t untaken() const { return rows_.size() - taken_count_; }
  [[nodiscard]] bool empty() const { return rows_.empty(); }

 private:
  struct Row {
    std::uint64_t key = 0;
    std::uint64_t index = 0;
    auto operator<=>(const Row&) const = default;
  };
  std::vector<Row> rows_;
  std::vector<bool> taken_;
  std::size_t taken_count_ = 0;
};

/// Reads a run_key (16 hex digits); nullopt for anything else.
[[nodiscard]] std::optional<std::uint64_t> parse_run_key(std::string_view s);
/// Reads a run_index (decimal digits); nullopt for anything else.
[[nodiscard]] std::optional<std::uint64_t> parse_run_index(std::string_view s);

}  // namespace sweep
}  // namespace fsweep
