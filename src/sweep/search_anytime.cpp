#include "sweep/search_anytime.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <system_error>
#include <utility>

#include "core/config_error.hpp"
#include "core/csv_format.hpp"
#include "core/files.hpp"
#include "core/json_text.hpp"
#include "core/readable_number.hpp"
#include "report/search_schema.hpp"
#include "sweep/sweep_axes.hpp"

namespace fsweep {
inline namespace sweep {
namespace {

using nlohmann::json;

/// A finite number, or null.
json finite_or_null(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

/// The number at `key` of a status (NaN: null or missing).
double status_number(const json& status, const char* key) {
  const auto it = status.find(key);
  return it != status.end() && it->is_number() ? it->get<double>() : std::numeric_limits<double>::quiet_NaN();
}

/// Fills best, bound, gap and relative_gap of `status` from the signed best and bound.
void put_gap(json& status, double signed_best, double signed_bound, double sign) {
  status["bound"] = finite_or_null(sign * signed_bound);
  const double gap = signed_best - signed_bound;
  const bool known = std::isfinite(signed_best) && std::isfinite(signed_bound);
  status["gap"] = known ? json(std::max(gap, 0.0)) : json(nullptr);
  status["relative_gap"] =
      known && signed_best != 0.0 ? json(std::max(gap, 0.0) / std::abs(signed_best)) : json(nullptr);
}

}  // namespace

namespace {
/// The longest time a resumed search takes from its status file (about 31 years).
constexpr double kMaxEarlierSeconds = 1e9;
}  // namespace

SearchAnytimeLog::SearchAnytimeLog(std::string dir, std::size_t id, std::string key, std::uint64_t vectors,
                                   double sign, std::vector<std::string> weights)
    : dir_(std::move(dir)),
      id_(id),
      key_(std::move(key)),
      vectors_(vectors),
      sign_(sign),
      weights_(std::move(weights)),
      curve_(dir_ + "/" + kSearchAnytimeFile) {
  const std::string path = dir_ + "/" + search_status_file(id_);
  if (const auto text = read_file(path)) {
    try {  // a damaged or foreign status only loses the earlier time
      const json earlier = parse_json_bounded(*text, path);
      const json& elapsed = earlier.value("elapsed_s", json());
      // Not a time a search can have taken (negative, 1e308): the earlier time is lost, not trusted.
      if (earlier.value("key", std::string()) == key_ && elapsed.is_number() &&
          elapsed.get<double>() >= 0.0 && elapsed.get<double>() < kMaxEarlierSeconds) {
        earlier_s_ = elapsed.get<double>();
      }
    } catch (const std::exception&) {
    }
  }
  const std::string header = csv_record(search_anytime_columns()) + '\n';
  const std::optional<std::string> curve = read_file(curve_.path());
  if (!curve || curve->empty() || header.starts_with(*curve)) {  // none, or a header cut short
    if (curve && !curve->empty()) std::filesystem::resize_file(curve_.path(), 0);
    curve_.write(header);
    return;
  }
  if (!curve->starts_with(header)) {
    throw ConfigError(curve_.path(), "not a search's curve (its first line is not the header " +
                                         header.substr(0, header.size() - 1) +
                                         "): move it away, and the search starts a new one");
  }
  // A row cut short by a stop mid-write: the rows after it start on a line of their own.
  if (curve->back() != '\n') std::filesystem::resize_file(curve_.path(), curve->rfind('\n') + 1);
}

void SearchAnytimeLog::record(const AnytimeState& state, std::uint64_t resolved,
                              std::span<const double> best_weights, std::string_view status) {
  const double elapsed =
      earlier_s_ + std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  json s{{"format", kSearchStatusFormat},
         {kSearchIdColumn, id_},
         {"key", key_},
         {"status", status},
         {"direction", sign_ > 0 ? "minimize" : "maximize"},
         {"elapsed_s", elapsed},
         {kVectorsColumn, vectors_},
         {"resolved_vectors", resolved},
         {"open_branches", state.open_branches},
         {"best", nullptr}};
  if (std::isfinite(state.best) && !best_weights.empty()) {
    json w = json::object();
    for (std::size_t k = 0; k < weights_.size() && k < best_weights.size(); ++k)
      w[weights_[k]] = best_weights[k];
    s["best"] = json{{"objective", sign_ * state.best}, {"weights", w}};
  }
  put_gap(s, state.best, state.lower, sign_);
  const auto cell = [&](const char* key) { return number_cell(status_number(s, key)); };
  const double best =
      std::isfinite(state.best) ? sign_ * state.best : std::numeric_limits<double>::quiet_NaN();
  curve_.write(
      csv_record({std::to_string(id_), format_number(elapsed), std::string(status), std::to_string(resolved),
                  std::to_string(vectors_), std::to_string(state.open_branches), number_cell(best),
                  cell("bound"), cell("gap"), cell("relative_gap")}) +
      '\n');
  write_file_atomically(dir_ + "/" + search_status_file(id_), s.dump(2) + '\n');
  last_ = std::move(s);
}

json join_search_status(std::span<const json> shards, std::uint64_t vectors, double sign) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  double best = kInf;
  json best_entry = nullptr;
  double bound = kInf;
  bool bound_known = true;
  bool finished = true;
  std::uint64_t resolved = 0;
  for (const json& shard : shards) {
    if (shard.is_null()) {
      bound_known = false;
      finished = false;
      continue;
    }
    const bool shard_finished = shard.value("status", std::string()) == "finished";
    finished = finished && shard_finished;
    resolved += shard.value("resolved_vectors", std::uint64_t{0});
    const json& b = shard.at("best");
    if (!b.is_null() && sign * b.at("objective").get<double>() < best) {
      best = sign * b.at("objective").get<double>();
      best_entry = b;
    }
    // A finished shard leaves nothing unresolved: its bound is its own optimum, no better than its
    // best, and none at all when it holds no vector (a shard past the box's blocks) or no vector
    // of it has a value, so it bounds nothing the best does not.
    if (shard_finished) continue;
    const double shard_bound = status_number(shard, "bound");
    if (std::isnan(shard_bound)) {
      bound_known = false;
    } else {
      bound = std::min(bound, sign * shard_bound);
    }
  }
  json s{{"format", kSearchStatusFormat},
         {"status", finished ? "finished" : "stopped"},
         {"direction", sign > 0 ? "minimize" : "maximize"},
         {kVectorsColumn, vectors},
         {"resolved_vectors", resolved},
         {"shards", shards.size()},
         {"best", best_entry}};
  put_gap(s, best, bound_known ? std::min(bound, best) : -kInf, sign);
  return s;
}

std::string describe_search_status(const json& status, std::string_view unit) {
  const std::string with_unit = unit.empty() ? std::string() : " " + std::string(unit);
  std::string out;
  const json& best = status.at("best");
  if (best.is_null()) {
    out = "no behaviour finished yet";
  } else {
    out = "best so far " + readable_number(best.at("objective").get<double>(), 6) + with_unit + " at (";
    bool first = true;
    for (const auto& [name, value] : best.at("weights").items()) {
      out += (first ? "" : ", ") + name + "=" + readable_number(value.get<double>(), 6);
      first = false;
    }
    out += ")";
  }
  const double bound = status_number(status, "bound");
  const bool minimised = status.value("direction", std::string("minimize")) == "minimize";
  out += std::isnan(bound) ? std::string("; no bound on the optimum yet")
                           : std::string("; the optimum is at ") + (minimised ? "least " : "most ") +
                                 readable_number(bound, 6) + with_unit;
  const double relative = status_number(status, "relative_gap");
  if (!std::isnan(relative)) out += " (gap " + readable_number(100.0 * relative, 3) + "%)";
  out += "; " + sweep_detail::with_thousands(status.value("resolved_vectors", std::uint64_t{0})) + " of " +
         sweep_detail::with_thousands(status.value(kVectorsColumn, std::uint64_t{0})) +
         " weight vectors resolved";
  return out;
}

}  // namespace sweep
}  // namespace fsweep
