#pragma once
/// @file search_probes.hpp
/// The probes a search of mode `best` ran (`search_probes.jsonl`, beside the journal): one JSON
/// line per finished probe, `{"key", "at" (its grid point's indices, as
/// Behaviour::representative), "objective" (the class objective its runs gave; null: none, as
/// when a run never reached a coverage target)}`, written as each finishes. A resumed search
/// takes them up instead of running them again: their best is its first incumbent at once, where
/// running them again would take as long as the first time, with a worse best meanwhile. A
/// probe is no region of the box, so the journal, the certificate and `merge` do not read them;
/// a line of another search's key is skipped, one that does not parse is skipped with a note.

#include <array>
#include <string>
#include <vector>

#include "core/append_file.hpp"
#include "weightsearch/weight_grid.hpp"

namespace fsweep {
inline namespace weightsearch {

class SearchProbeLog {
 public:
  using Point = std::array<int, WeightGrid::kMaxWeights>;
  struct Probe {
    Point at{};
    double objective = 0.0;  ///< NaN: none
  };

  /// The probes of search `key` in the log at `path` (none when it is missing), `weights`
  /// indices each.
  [[nodiscard]] static std::vector<Probe> read(const std::string& path, const std::string& key, int weights);

  /// Opens the log at `path` for appending (created if missing); throws IoError as
  /// SearchJournal does.
  explicit SearchProbeLog(std::string path) : file_(std::move(path)) { file_.open(); }
  /// Appends search `key`'s probe at `at` (its first `weights` indices) with its `objective`.
  void append(const std::string& key, const Point& at, int weights, double objective);

 private:
  AppendFile file_;
};

}  // namespace weightsearch
}  // namespace fsweep
