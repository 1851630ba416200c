#pragma once
/// @file jump_points.hpp
/// What `jps` (jps_planner.hpp) and `jps+` (jps_plus_planner.hpp) share: the directions a jump
/// point search follows from a state (its pruning rules under either corner rule), and the
/// query's search over jump points with the cells between them filled in.

#include <algorithm>
#include <cstdlib>
#include <optional>
#include <vector>

#include "planners/search_result.hpp"
#include "search/grid_search.hpp"
#include "world/grid.hpp"
#include "world/known_map.hpp"
#include "world/motion.hpp"

namespace fsweep {
inline namespace planners {
namespace jump_points {

/// Calls add(dx, dy) for each direction a jump point search follows from `at`, reached from
/// `from` (nullopt: the start, every direction in grid.hpp's order). After a straight move:
/// ahead, and the forced neighbours on each side; after a diagonal one: ahead, its two straight
/// components and (corner cutting only) the forced neighbours. `kCut` is
/// PlanRequest::allow_corner_cutting (the rules of jps_planner.hpp's file comment); `is_free(x,
/// y)`: known free and inside the grid.
template <bool kCut, typename IsFree, typename Add>
void pruned_directions(Cell at, std::optional<Cell> from, const IsFree& is_free, Add&& add) {
  if (!from) {
    for (const Cell d : kDirections) add(d.x, d.y);
    return;
  }
  // The direction of the last step: a segment between jump points runs diagonally first, then
  // straight along its longer axis (`jps`'s successors past a diagonal), so that axis alone when
  // the two differ.
  const int across = std::abs(at.x - from->x);
  const int along = std::abs(at.y - from->y);
  const int dx = across >= along ? sign_of(at.x - from->x) : 0;
  const int dy = along >= across ? sign_of(at.y - from->y) : 0;
  add(dx, dy);
  if (dx == 0 || dy == 0) {
    for (const Cell q : {Cell{dy, dx}, Cell{-dy, -dx}}) {
      if constexpr (kCut) {
        if (!is_free(at.x + q.x, at.y + q.y) && is_free(at.x + dx + q.x, at.y + dy + q.y))
          add(dx + q.x, dy + q.y);
      } else {
        if (is_free(at.x + q.x, at.y + q.y) && !is_free(at.x - dx + q.x, at.y - dy + q.y)) {
          add(q.x, q.y);
          add(dx + q.x, dy + q.y);
        }
      }
    }
    return;
  }
  add(dx, 0);
  add(0, dy);
  if constexpr (kCut) {
    if (!is_free(at.x - dx, at.y) && is_free(at.x - dx, at.y + dy)) add(-dx, dy);
    if (!is_free(at.x, at.y - dy) && is_free(at.x + dx, at.y - dy)) add(dx, -dy);
  }
}

/// Every cell of a chain of jump points, each consecutive pair on one straight or diagonal line,
/// or joined by a diagonal run and then a straight one (for_each_jump_run(), world/motion.hpp).
[[nodiscard]] inline std::vector<Cell> fill_segments(const std::vector<Cell>& jump_points) {
  std::vector<Cell> cells;
  if (jump_points.empty()) return cells;
  std::size_t count = 1;  // the cells of each segment past its first: its Chebyshev length
  for (std::size_t i = 1; i < jump_points.size(); ++i) {
    const Cell a = jump_points[i - 1];
    const Cell b = jump_points[i];
    count += static_cast<std::size_t>(std::max(std::abs(b.x - a.x), std::abs(b.y - a.y)));
  }
  cells.reserve(count);
  cells.push_back(jump_points.front());
  for_each_jump_run(jump_points, [&cells](Cell step, int steps) {
    Cell c = cells.back();
    for (int k = steps; k > 0; --k) cells.push_back(c = Cell{c.x + step.x, c.y + step.y});
  });
  return cells;
}

/// One query's search over the jump point environment `env`: the filled-in cells from
/// `request`'s start to its goal and their motion cost (measured from the jump points), or the
/// failure.
template <typename Env>
[[nodiscard]] SearchResult search_jumps(OctileSearch& search, Env env, const KnownMap& known,
                                        const PlanRequest& request, const StopCondition& stop) {
  SearchLimits limits;
  limits.stop = stop;
  const SearchOutcome outcome = search.run(env, known.index(request.start), limits);
  SearchResult result = search_result(search, outcome, [&known](int s) { return known.cell(s); });
  if (result.status != PlanStatus::Success) return result;
  result.motion =
      measure_jump_points(result.path, request.start_heading, request.energy, known.resolution_m());
  result.path = fill_segments(result.path);
  return result;
}

}  // namespace jump_points
}  // namespace planners
}  // namespace fsweep
