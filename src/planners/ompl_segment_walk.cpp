#include "planners/ompl_segment_walk.hpp"

#include "search/octile_grid.hpp"

namespace fsweep {
inline namespace planners {

SegmentCheck check_segment(const KnownMap& known, PlanePoint a, PlanePoint b, bool allow_corner_cutting) {
  if (!known.is_free(cell_of(a))) return SegmentCheck{false, 0.0};
  SegmentCheck check{true, 1.0};
  walk_segment_cells(a, b, allow_corner_cutting, [&](Cell from, Cell to, double t) {
    if (octile_step_allowed(known, from, to, allow_corner_cutting)) return true;
    check = SegmentCheck{false, t};
    return false;
  });
  return check;
}

std::vector<Cell> polyline_cell_chain(const KnownMap& known, const std::vector<PlanePoint>& points,
                                      bool allow_corner_cutting) {
  std::vector<Cell> walked;
  if (points.empty()) return walked;
  walked.push_back(cell_of(points.front()));
  for (std::size_t i = 1; i < points.size(); ++i) {
    // 1. Each segment starts in the cell the previous one ended in (shared vertex).
    walk_segment_cells(points[i - 1], points[i], allow_corner_cutting,
                       [&](Cell /*from*/, Cell to, double /*t*/) {
                         walked.push_back(to);
                         return true;
                       });
  }
  // 2. Greedy diagonal shortcuts of orthogonal corners a -> b -> c (b is dropped).
  std::vector<Cell> chain;
  chain.reserve(walked.size());
  for (const Cell c : walked) {
    if (!chain.empty() && chain.back() == c) continue;  // a segment of zero cells
    if (chain.size() >= 2) {
      const Cell a = chain[chain.size() - 2];
      const Cell b = chain.back();
      const bool orthogonal_ab = (a.x == b.x) != (a.y == b.y);
      const bool orthogonal_bc = (b.x == c.x) != (b.y == c.y);
      const bool diagonal_ac = std::abs(a.x - c.x) == 1 && std::abs(a.y - c.y) == 1;
      if (orthogonal_ab && orthogonal_bc && diagonal_ac &&
          octile_step_allowed(known, a, c, allow_corner_cutting)) {
        chain.back() = c;
        continue;
      }
    }
    chain.push_back(c);
  }
  return chain;
}

}  // namespace planners
}  // namespace fsweep
