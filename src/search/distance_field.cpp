#include "search/distance_field.hpp"

#include <algorithm>

#include "search/octile_grid.hpp"

namespace fsweep {
inline namespace search {
namespace {

/// Rounding allowed when comparing path lengths in cells (a length is a + b*sqrt(2) summed in
/// different orders, so equal lengths may differ in the last bits).
constexpr double kSlackCells = 1e-9;

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

  [[nodiscard]] int state_count() const { return known_.size(); }
  static constexpr bool kZeroHeuristic = true;
  [[nodiscard]] static double heuristic(int /*state*/) { return 0.0; }

  /// Settles states in cost order; once the first target is settled at d*, keeps settling
  /// states up to d* (ties, so every target at d* is exact) and stops at the first beyond.
  Visit visit(int state, double g) {
    if (remaining_targets_ > 0) {
      const bool target = target_stamp_[static_cast<std::size_t>(state)] == target_generation_;
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
    for_each_octile_neighbour(known_, state, allow_corner_cutting_, sink);
  }

 private:
  const KnownMap& known_;
  bool allow_corner_cutting_;
  const std::uint32_t* target_stamp_;  // null: no early stop
  std::uint32_t target_generation_;
  double nearest_target_g_ = -1.0;  // cells; < 0 until the first target is settled
  int remaining_targets_ = 0;       // settle-all mode: distinct targets not yet settled
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
    for (const int t : target_list) {
      if (t < 0 || t >= known.size()) continue;
      auto& stamp = target_stamp_[static_cast<std::size_t>(t)];
      if (stamp != target_generation_) ++distinct_targets;
      stamp = target_generation_;
    }
    targets = target_stamp_.data();
  }

  // 2. Bound in cells, inclusive up to rounding: a cell exactly at max_distance_m is reached.
  SearchLimits limits;
  limits.g_limit = query.max_distance_m / resolution_m_ * (1.0 + 1e-12) + kSlackCells;
  limits.stop = query.stop;

  // 3. Dijkstra from the source; a non-free source runs from no state, leaving the field empty.
  if (targets == nullptr) distinct_targets = 0;
  FieldEnvironment env(known, query.allow_corner_cutting, targets, target_generation_,
                       settle_all ? std::max(distinct_targets, 1) : 0);
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

}  // namespace search
}  // namespace fsweep
