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

/// Dijkstra environment of one compute(): cells are states, octile moves, no heuristic, and the
/// early-stop rule of DistanceQuery::stop_at_first_of in visit().
class FieldEnvironment {
 public:
  /// `all_targets` > 0: settle-all mode (stop once that many distinct targets are settled);
  /// 0: nearest-target mode.
  FieldEnvironment(const KnownMap& known, bool allow_corner_cutting, const std::uint32_t* target_stamp,
                   std::uint32_t target_generation, int all_targets)
      : known_(known),
        allow_corner_cutting_(allow_corner_cutting),
        target_stamp_(target_stamp),
        target_generation_(target_generation),
        remaining_targets_(all_targets) {}

  /// Settle-all mode only: reports settled targets to `watcher` and lets it stop the search.
  /// `first_position` / `next_position`: the targets' positions (DistanceField's members).
  void watch(SettleWatcher* watcher, const int* first_position, const int* next_position,
             double resolution_m) {
    watcher_ = watcher;
    first_position_ = first_position;
    next_position_ = next_position;
    resolution_m_ = resolution_m;
  }

  using Cost = OctileCost;
  [[nodiscard]] int state_count() const { return known_.size(); }
  static constexpr bool kZeroHeuristic = true;
  [[nodiscard]] static Cost heuristic(int /*state*/) { return {}; }

  /// Settles states in cost order; once the first target is settled at d*, keeps settling
  /// states up to d* (ties, so every target at d* is exact) and stops at the first beyond.
  Visit visit(int state, double g) {
    if (remaining_targets_ > 0) {
      const bool target = target_stamp_[static_cast<std::size_t>(state)] == target_generation_;
      if (watcher_ != nullptr && !watched(state, g, target)) return Visit::Stop;
      return target && --remaining_targets_ == 0 ? Visit::Goal : Visit::Expand;
    }
    if (nearest_target_g_ >= 0.0 && g > nearest_target_g_ + kSlackCells) return Visit::Stop;
    if (nearest_target_g_ < 0.0 && target_stamp_ != nullptr &&
        target_stamp_[static_cast<std::size_t>(state)] == target_generation_) {
      nearest_target_g_ = g;
    }
    return Visit::Expand;
  }

  template <typename Sink>
  void for_each_successor(int state, Sink&& sink) const {
    for_each_octile_neighbour<Cost>(known_, state, allow_corner_cutting_, sink);
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
      for (int p = first_position_[state]; p >= 0; p = next_position_[p])
        watcher_->settled(static_cast<std::size_t>(p), radius_m);
      go_on_until_m_ = -std::numeric_limits<double>::infinity();  // ask again before the next cell
    }
    return true;
  }

  const KnownMap& known_;
  bool allow_corner_cutting_;
  const std::uint32_t* target_stamp_;  // null: no early stop
  std::uint32_t target_generation_;
  double nearest_target_g_ = -1.0;  // cells; < 0 until the first target is settled
  int remaining_targets_ = 0;       // settle-all mode: distinct targets not yet settled
  SettleWatcher* watcher_ = nullptr;
  const int* first_position_ = nullptr;
  const int* next_position_ = nullptr;
  double resolution_m_ = 1.0;
  /// The watcher is asked before settling a cell farther than this (metres).
  double go_on_until_m_ = -std::numeric_limits<double>::infinity();
};

}  // namespace

void DistanceField::compute(const KnownMap& known, Cell source, const DistanceQuery& query) {
  width_ = known.width();
  resolution_m_ = known.resolution_m();
  source_ = source;

  // 1. Mark the stop targets with a fresh generation stamp (no clearing between queries).
  const std::uint32_t* targets = nullptr;
  const bool settle_all = query.stop_at_first_of.empty() && !query.stop_when_all_settled.empty();
  const std::span<const int> target_list = settle_all ? query.stop_when_all_settled : query.stop_at_first_of;
  int distinct_targets = 0;
  if (!target_list.empty()) {
    const auto n = static_cast<std::size_t>(known.size());
    if (target_stamp_.size() != n) {
      target_stamp_.assign(n, 0);
      target_generation_ = 0;
    }
    if (++target_generation_ == 0) {
      std::fill(target_stamp_.begin(), target_stamp_.end(), 0U);
      target_generation_ = 1;
    }
    const bool watched = settle_all && query.watcher != nullptr;
    if (watched) {
      first_position_.resize(n);
      next_position_.assign(target_list.size(), -1);
    }
    // Backwards, so that each cell's position chain runs in increasing order.
    for (std::size_t p = target_list.size(); p-- > 0;) {
      const int t = target_list[p];
      if (t < 0 || t >= known.size()) continue;
      auto& stamp = target_stamp_[static_cast<std::size_t>(t)];
      if (stamp != target_generation_) {
        ++distinct_targets;
        if (watched) first_position_[static_cast<std::size_t>(t)] = -1;
      }
      stamp = target_generation_;
      if (watched) {
        next_position_[p] = first_position_[static_cast<std::size_t>(t)];
        first_position_[static_cast<std::size_t>(t)] = static_cast<int>(p);
      }
    }
    targets = target_stamp_.data();
  }

  // 2. Bound in cells.
  SearchLimits limits;
  limits.g_limit = limit_cells(query, resolution_m_);
  limits.stop = query.stop;

  // 3. Dijkstra from the source; a non-free source runs from no state, leaving the field empty.
  if (targets == nullptr) distinct_targets = 0;
  FieldEnvironment env(known, query.allow_corner_cutting, targets, target_generation_,
                       settle_all ? std::max(distinct_targets, 1) : 0);
  if (settle_all && targets != nullptr && query.watcher != nullptr)
    env.watch(query.watcher, first_position_.data(), next_position_.data(), resolution_m_);
  const int start = known.is_free(source) ? known.index(source) : -1;
  const SearchOutcome outcome = search_.run(env, start, limits);
  expansions_ = outcome.expansions;
  stopped_ = outcome.stopped;
}

double DistanceField::distance_m(int index) const {
  return search_.settled(index) ? search_.g(index) * resolution_m_ : std::numeric_limits<double>::infinity();
}

std::vector<Cell> DistanceField::path_to(int index) const {
  std::vector<Cell> path;
  if (!search_.settled(index)) return path;
  const std::vector<int> states = search_.path_to(index);
  path.reserve(states.size());
  for (const int s : states) path.push_back(Cell{s % width_, s / width_});
  return path;
}

std::optional<double> PointDistance::compute(const KnownMap& known, Cell source, Cell goal,
                                             const DistanceQuery& query) {
  expansions_ = 0;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  if (!known.is_free(source) || !known.is_free(goal)) return kInf;  // as an empty or unreached field
  SearchLimits limits;
  limits.g_limit = limit_cells(query, known.resolution_m());
  limits.stop = query.stop;
  const OctileGoalEnvironment<true> env(known, goal, query.allow_corner_cutting);
  const SearchOutcome outcome = search_.run(env, known.index(source), limits);
  expansions_ = outcome.expansions;
  if (outcome.goal >= 0) return search_.g(outcome.goal) * known.resolution_m();
  if (outcome.stopped) return std::nullopt;
  return kInf;
}

}  // namespace search
}  // namespace fsweep
