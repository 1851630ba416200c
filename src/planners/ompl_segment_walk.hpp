#pragma once
/// @file ompl_segment_walk.hpp
/// Exact grid geometry behind the OMPL planners: which cells a straight segment in the plane
/// crosses (a supercover walk), whether the segment is collision-free under the move rule of
/// src/search/octile_grid.hpp, and the 8-connected cell chain of a polyline.
///
/// Coordinates are in cells: cell (x, y) is the square [x, x+1) x [y, y+1), its centre is
/// (x + 0.5, y + 0.5). A point belongs to the cell floor(x), floor(y).

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "world/grid.hpp"
#include "world/known_map.hpp"

namespace fsweep {
inline namespace planners {

/// A point in the plane, in cell units (see the file comment).
struct PlanePoint {
  double x = 0.0;
  double y = 0.0;
};

/// The cell containing `p` (floor of both coordinates). `p` must be finite.
[[nodiscard]] inline Cell cell_of(PlanePoint p) {
  return Cell{static_cast<int>(std::floor(p.x)), static_cast<int>(std::floor(p.y))};
}

/// Centre of cell `c`.
[[nodiscard]] inline PlanePoint centre_of(Cell c) { return PlanePoint{c.x + 0.5, c.y + 0.5}; }

/// Segment parameters closer than this to each other count as one grid-vertex crossing when
/// corner cutting is off (so the stricter diagonal rule applies to near-vertex crossings).
inline constexpr double kVertexTieT = 1e-9;

/// Walks the cells the segment a -> b crosses, in order, and calls `step(from, to, t)` for each
/// move from one cell to the next; `t` in [0, 1] is the segment parameter where it leaves
/// `from`. Moves are orthogonal except where the segment passes through a grid vertex, which
/// is one diagonal move. A crossing exactly through a vertex is a vertex crossing; one within
/// kVertexTieT of it counts as a vertex crossing too unless `allow_corner_cutting` (then it
/// is an orthogonal move through the cell the segment clips, which is the stricter reading in
/// that mode). `step` returns false to stop the walk. Returns false if stopped.
template <typename Step>
bool walk_segment_cells(PlanePoint a, PlanePoint b, bool allow_corner_cutting, Step&& step) {
  Cell c = cell_of(a);
  const Cell end = cell_of(b);
  const double dx = b.x - a.x;
  const double dy = b.y - a.y;
  const int sx = end.x > c.x ? 1 : (end.x < c.x ? -1 : 0);
  const int sy = end.y > c.y ? 1 : (end.y < c.y ? -1 : 0);
  int nx = sx * (end.x - c.x);
  int ny = sy * (end.y - c.y);
  constexpr double kInf = std::numeric_limits<double>::infinity();
  // Segment parameter of the next vertical (x) and horizontal (y) grid line.
  const auto next_t_x = [&]() { return sx == 0 ? kInf : ((sx > 0 ? c.x + 1 : c.x) - a.x) / dx; };
  const auto next_t_y = [&]() { return sy == 0 ? kInf : ((sy > 0 ? c.y + 1 : c.y) - a.y) / dy; };
  while (nx > 0 || ny > 0) {
    const double tx = next_t_x();
    const double ty = next_t_y();
    const Cell from = c;
    double t = 0.0;
    if (nx > 0 && ny > 0 && (tx == ty || (!allow_corner_cutting && std::abs(tx - ty) <= kVertexTieT))) {
      c.x += sx;
      c.y += sy;
      --nx;
      --ny;
      t = std::min(tx, ty);
    } else if (ny == 0 || (nx > 0 && tx < ty)) {
      c.x += sx;
      --nx;
      t = tx;
    } else {
      c.y += sy;
      --ny;
      t = ty;
    }
    if (!step(from, c, std::clamp(t, 0.0, 1.0))) return false;
  }
  return true;
}

/// Outcome of checking one segment.
struct SegmentCheck {
  /// True if the start cell is known free and every move of walk_segment_cells() is allowed
  /// by octile_step_allowed() (so every crossed cell is known free, and a vertex crossing
  /// between two blocked cells happens only with corner cutting).
  bool free = false;
  /// Segment parameter in [0, 1] where the first forbidden move starts (1 when `free`, 0 when
  /// the start cell itself is blocked).
  double blocked_t = 1.0;
};

/// Checks segment a -> b on `known` (outside the grid counts as occupied).
[[nodiscard]] SegmentCheck check_segment(const KnownMap& known, PlanePoint a, PlanePoint b,
                                         bool allow_corner_cutting);

/// The 8-connected cell chain of the polyline `points` (at least one point): the cells of
/// every segment in walk order, joined, then orthogonal corner pairs a -> b -> c replaced by
/// the diagonal a -> c wherever octile_step_allowed() permits it (left to right, greedy).
/// Consecutive cells of the result are 8-neighbours. If every segment passes check_segment(),
/// every move of the result is allowed by octile_step_allowed().
[[nodiscard]] std::vector<Cell> polyline_cell_chain(const KnownMap& known,
                                                    const std::vector<PlanePoint>& points,
                                                    bool allow_corner_cutting);

}  // namespace planners
}  // namespace fsweep
