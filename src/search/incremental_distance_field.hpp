#pragma once
/// @file incremental_distance_field.hpp
/// Shortest path lengths from a fixed source over known free space, kept up to date as the
/// map grows. Revealing cells only adds free cells and moves (a known cell never changes), so
/// path lengths only decrease: an update relaxes the cells around the revealed ones and
/// propagates the decreases (the generic search of grid_search.hpp, continued from its last run
/// by BestFirstSearch::reopen / lower_cost / resume), instead of recomputing. Moves follow
/// octile_grid.hpp. Used for the dock, which never moves.

#include <limits>
#include <span>
#include <vector>

#include "search/grid_search.hpp"
#include "world/grid.hpp"
#include "world/known_map.hpp"

namespace fsweep {
inline namespace search {

/// The field, kept in its search storage (reused by every update; not thread-safe).
class IncrementalDistanceField {
 public:
  IncrementalDistanceField() = default;

  /// Computes the field from scratch on `known` (a source that is not known free gives an
  /// empty field until it becomes free and reset() is called again).
  void reset(const KnownMap& known, Cell source, bool allow_corner_cutting);

  /// Brings the field up to date after `revealed` cells became known on `known`.
  void update(const KnownMap& known, std::span<const int> revealed);

  /// Path length (metres) from the source to `index`; +infinity if unreachable.
  [[nodiscard]] double distance_m(int index) const { return search_.g(index) * resolution_m_; }
  /// Cells settled by the last reset() or update().
  [[nodiscard]] long expansions() const { return expansions_; }

 private:
  OctileDistanceSearch search_;  // its exact costs (cells) are the field; +infinity where unreachable
  double resolution_m_ = 1.0;
  bool allow_corner_cutting_ = false;
  long expansions_ = 0;
};

}  // namespace search
}  // namespace fsweep
