#include "search/distance_field.hpp"

#include <algorithm>
#include <limits>

#include "search/octile_grid.hpp"

namespace fsweep {
inline namespace search {
namespace {

/// Rounding allowed when comparing path lengths in cells (a length is a + b*sqrt(2) summed in
/// different orders, so equal lengths may differ in the last bits).
constexpr double kSlackCells = 1e-9;

/// The search bound in cells of a query on cells of `resolution_m`: inclusive up to rounding, so
/// a cell exactly at max_distance_m is reached.
double limit_cells(const DistanceQuery& query, double resolution_m) {
  return query.max_distance_m / resolution_m * (1.0 + 1e-12) + kSlackCells;
}

/// Dijkstra environment of one compute(): the octile moves, no heuristic, and the early-stop rule
/// of DistanceQuery::stop_at_first_of in visit().
class FieldEnvironment : public OctileMoves {
 public:
  /// `all_targets` > 0: settle-all mode (stop once that many distinct targets are settled);
  /// 0: nearest-target mode. `is_target`: null for no early stop.
  FieldEnvironment(const KnownMap& known, bool allow_corner_cutting, const std::vector<bool>* is_target,
                   int all_targets)
      : OctileMoves(known, allow_corner_cutting), is_target_(is_target), remaining_targets_(all_targets) {}

  /// Settle-all mode only: reports settled targets to `watcher` and lets it stop the search.
  /// `positions`: (cell, position) of every target, sorted (DistanceField's member).
  void watch(SettleWatcher* watcher, const std::vector<std::pair<int, int>>* positions, double resolution_m) {
    watcher_ = watcher;
    positions_ = positions;
    resolution_m_ = resolution_m;
  }

  static constexpr bool kZeroHeuristic = true;
  [[nodiscard]] static Cost heuristic(int /*state*/) { return {}; }

  /// Settles states in cost order; once the first target is settled at d*, keeps settling
  /// states up to d* (ties, so every target at d* is exact) and stops at the first beyond.
  Visit visit(int state, double g) {
    if (remaining_targets_ > 0) {
      const bool target = (*is_target_)[static_cast<std::size_t>(state)];
      if (watcher_ != nullptr && !watched(state, g, target)) return Visit::Stop;
      return target && --remaining_targets_ == 0 ? Visit::Goal : Visit::Expand;
    }
    if (nearest_target_g_ >= 0.0 && g > nearest_target_g_ + kSlackCells) return Visit::Stop;
    if (nearest_target_g_ < 0.0 && is_target_ != nullptr && (*is_target_)[static_cast<std::size_t>(state)]) {
      nearest_target_g_ = g;
    }
    return Visit::Expand;
  }

 private:
  /// The watcher's part of visit(): false to stop before settling `state` at `g` (cells).
  bool watched(int state, double g, bool target) {
    // Metres as DistanceField::distance_m reads them, so the radius bounds every later reading.
    const double radius_m = g * resolution_m_;
    if (radius_m > go_on_until_m_) {
      go_on_until_m_ = watcher_->go_on_until(radius_m);
      if (go_on_until_m_ < radius_m) return false;
    }
    if (target) {
      const auto first = std::lower_bound(positions_->begin(), positions_->end(), std::pair{state, -1});
      for (auto it = first; it != positions_->end() && it->first == state; ++it)
        watcher_->settled(static_cast<std::size_t>(it->second), radius_m);
      go_on_until_m_ = -std::numeric_limits<double>::infinity();  // ask again before the next cell
    }
    return true;
  }

  const std::vector<bool>* is_target_;  // null: no early stop
  double nearest_target_g_ = -1.0;      // cells; < 0 until the first target is settled
  int remaining_targets_ = 0;           // settle-all mode: distinct targets not yet settled
  SettleWatcher* watcher_ = nullptr;
  const std::vector<std::pair<int, int>>* positions_ = nullptr;
  double resolution_m_ = 1.0;
  /// The watcher is asked before settling a cell farther than this (metres).
  double go_on_until_m_ = -std::numeric_limits<double>::infinity();
};

/// compute_to()'s A* in `search`: the goal's length in metres (+infinity when unreachable or
/// beyond the bound), nullopt when query.stop ended it first; `outcome` as the search ended.
template <Parents P>
std::optional<double> length_to(BestFirstSearchT<OctileCost, P>& search, const KnownMap& known, Cell source,
                                Cell goal, const DistanceQuery& query, SearchOutcome& outcome) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  outcome = SearchOutcome{};
  if (!known.is_free(source) || !known.is_free(goal)) {  // unreachable at once; the field reads empty
    FieldEnvironment empty(known, query.allow_corner_cutting, nullptr, 0);
    (void)search.run(empty, -1);
    return kInf;
  }
  SearchLimits limits;
  limits.g_limit = limit_cells(query, known.resolution_m());
  limits.stop = query.stop;
  const OctileGoalEnvironment<true> env(known, goal, query.allow_corner_cutting);
  outcome = search.run(env, known.index(source), limits);
  if (outcome.goal >= 0) return search.g(outcome.goal) * known.resolution_m();
  if (outcome.stopped) return std::nullopt;
  return kInf;
}

}  // namespace

void DistanceField::compute(const KnownMap& known, Cell source, const DistanceQuery& query) {
  resolution_m_ = known.resolution_m();
  source_ = source;

  // 1. Mark the stop targets (the marks are taken off again at the end).
  const bool settle_all = query.stop_at_first_of.empty() && !query.stop_when_all_settled.empty();
  const std::span<const int> target_list = settle_all ? query.stop_when_all_settled : query.stop_at_first_of;
  const bool watched = settle_all && query.watcher != nullptr;
  int distinct_targets = 0;
  if (!target_list.empty()) {
    is_target_.resize(static_cast<std::size_t>(known.size()));
    if (watched) target_positions_.clear();
    for (std::size_t p = 0; p < target_list.size(); ++p) {
      const int t = target_list[p];
      if (t < 0 || t >= known.size()) continue;
      if (!is_target_[static_cast<std::size_t>(t)]) ++distinct_targets;
      is_target_[static_cast<std::size_t>(t)] = true;
      if (watched) target_positions_.emplace_back(t, static_cast<int>(p));
    }
    if (watched) std::sort(target_positions_.begin(), target_positions_.end());
  }

  // 2. Bound in cells.
  SearchLimits limits;
  limits.g_limit = limit_cells(query, resolution_m_);
  limits.stop = query.stop;

  // 3. Dijkstra from the source; a non-free source runs from no state, leaving the field empty.
  FieldEnvironment env(known, query.allow_corner_cutting, target_list.empty() ? nullptr : &is_target_,
                       settle_all ? std::max(distinct_targets, 1) : 0);
  if (watched) env.watch(query.watcher, &target_positions_, resolution_m_);
  const int start = known.is_free(source) ? known.index(source) : -1;
  const SearchOutcome outcome = search_.run(env, start, limits);
  expansions_ = outcome.expansions;
  stopped_ = outcome.stopped;

  for (const int t : target_list) {
    if (t >= 0 && t < known.size()) is_target_[static_cast<std::size_t>(t)] = false;
  }
}

std::optional<double> DistanceField::compute_to(const KnownMap& known, Cell source, Cell goal,
                                                const DistanceQuery& query) {
  resolution_m_ = known.resolution_m();
  source_ = source;
  SearchOutcome outcome;
  const std::optional<double> length = length_to(search_, known, source, goal, query, outcome);
  expansions_ = outcome.expansions;
  stopped_ = outcome.stopped;
  return length;
}

std::optional<double> PathProbe::compute_to(const KnownMap& known, Cell source, Cell goal,
                                            const DistanceQuery& query) {
  SearchOutcome outcome;
  const std::optional<double> length = length_to(search_, known, source, goal, query, outcome);
  expansions_ = outcome.expansions;
  goal_ = outcome.goal;
  return length;
}

double DistanceField::distance_m(int index) const {
  return search_.settled(index) ? search_.g(index) * resolution_m_ : std::numeric_limits<double>::infinity();
}

}  // namespace search
}  // namespace fsweep
