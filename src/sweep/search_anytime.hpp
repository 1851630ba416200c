#pragma once
/// @file search_anytime.hpp
/// Where a search of mode best stands while it runs (AnytimeState; docs/weight-search.md,
/// "Boxes out of reach"): the best objective finished so far with its weight vector, a certified
/// bound on the optimum over everything not yet resolved, and the gap between them. Kept as
///   - DIR/search_anytime.csv: the curve, a row per report (every few seconds, at a stop, at
///     the end), across the processes of a resumed search (elapsed_s goes on from the last);
///   - DIR/search_status_<id>.json: the latest report, rewritten atomically.
/// Both are in the objective's own direction: for a minimised objective `bound` is a lower bound
/// and gap = best - bound; for a maximised one an upper bound and gap = bound - best.
/// `fsweep merge` joins the shards' status files of a search (join_search_status()).

#include <chrono>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/append_file.hpp"
#include "weightsearch/exact_search.hpp"

namespace fsweep {
inline namespace sweep {

/// The format of a status file, its "format".
inline constexpr char kSearchStatusFormat[] = "fsweep weight search status 1";

class SearchAnytimeLog {
 public:
  /// The log of search `id` of `vectors` weight vectors (named `weights`) into `dir`; `key` its
  /// journal key (a status file of another search is not continued); `sign` as branch and bound
  /// minimises sign x the objective. Reads the elapsed time of an earlier process of the same
  /// search from its status file (one below 0 or above 10^9 s is not taken). An existing curve is
  /// continued: a last row cut short is cut off, and a file whose first line is not the curve's
  /// header is ConfigError (its content is never appended to or lost).
  SearchAnytimeLog(std::string dir, std::size_t id, std::string key, std::uint64_t vectors, double sign,
                   std::vector<std::string> weights);

  /// Appends a row to the curve and rewrites the status file. `state` signed as branch and
  /// bound minimises; `best_weights`: the weight vector of the best objective (empty: none yet);
  /// `status`: "running", "stopped" or "finished". Throws IoError naming a file it cannot write.
  void record(const AnytimeState& state, std::uint64_t resolved, std::span<const double> best_weights,
              std::string_view status);

  /// The status last recorded (null before the first).
  [[nodiscard]] const nlohmann::json& last() const { return last_; }

 private:
  std::string dir_;
  std::size_t id_;
  std::string key_;
  std::uint64_t vectors_;
  double sign_;
  std::vector<std::string> weights_;
  double earlier_s_ = 0.0;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  AppendFile curve_;
  nlohmann::json last_;
};

/// The status of a whole search from its shards' (each null when the shard has none, e.g. it
/// never started): the best of their best vectors and the weakest of the unfinished shards'
/// bounds (null when one of those is unknown; a finished shard bounds nothing its best does not,
/// and one holding no vector has no bound), the resolved vectors summed, status "finished" only
/// when every shard's is, the bound then the optimum. `vectors`: the whole box's; `sign` as SearchAnytimeLog.
[[nodiscard]] nlohmann::json join_search_status(std::span<const nlohmann::json> shards, std::uint64_t vectors,
                                                double sign);

/// One line for a person: best, bound and gap of a status (SearchAnytimeLog::last()), the
/// objective's values followed by `unit` ("m"; none when empty).
[[nodiscard]] std::string describe_search_status(const nlohmann::json& status, std::string_view unit = {});

}  // namespace sweep
}  // namespace fsweep
