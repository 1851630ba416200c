/// @file town_generators.cpp
/// The outdoor generators: `manhattan` (street grid) and `oldtown` (winding lanes and squares).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

#include "world/generator_canvas.hpp"

namespace fsweep {
inline namespace world {
namespace generator_detail {

/// Manhattan: a periodic street grid (period block + street) whose central street crossing
/// sits at the map centre; blocks at the edges are clipped. Blocks are drawn in row-major order.
Occupancy make_manhattan(const GeneratorParams& p, Rng& rng) {
  Occupancy g(p.width, p.height, kFree);
  const int b = p.block;
  const int s = p.street;
  const int period = b + s;
  const int alley = std::max(1, s / 2);
  // Block starts along one axis: origin + k * period with origin = centre - s/2 + s, all k whose
  // block [start, start + b) overlaps [0, extent).
  const auto block_starts = [&](int extent) {
    const int origin = extent / 2 - s / 2 + s;
    const int k_min = -(origin / period) - 2;
    std::vector<int> starts;
    for (int k = k_min;; ++k) {
      const int start = origin + k * period;
      if (start >= extent) break;
      if (start + b > 0) starts.push_back(start);
    }
    return starts;
  };
  const std::vector<int> xs = block_starts(p.width);
  const std::vector<int> ys = block_starts(p.height);
  for (const int y0 : ys) {
    for (const int x0 : xs) {
      const Rect r{x0, y0, x0 + b, y0 + b};
      const double kind = uniform01(rng);
      if (kind < p.park_share) continue;
      fill_rect(g, r, kWall);
      if (kind < p.park_share + p.alley_share && b >= alley + 2) {
        const bool vertical = uniform_below(rng, 2) == 0;
        const int k = uniform_int(rng, 1, b - alley - 1);
        fill_rect(g,
                  vertical ? Rect{x0 + k, y0, x0 + k + alley, r.y1} : Rect{x0, y0 + k, r.x1, y0 + k + alley},
                  kFree);
      }
    }
  }
  return g;
}

namespace {

/// The old town's lanes: a lane "stamp" is the l x l square whose top-left corner is the point;
/// it must fit inside the one-cell frame: x in [1, width - 1 - l].
struct Lanes {
  Occupancy& g;
  int l;
  int max_x;
  int max_y;

  [[nodiscard]] Cell clamped(Cell c) const {
    return Cell{std::clamp(c.x, 1, max_x), std::clamp(c.y, 1, max_y)};
  }
  void stamp(Cell c) const { fill_rect(g, Rect{c.x, c.y, c.x + l, c.y + l}, kFree); }

  /// A 4-connected stroke of stamps from `c` to `e`: each step along the axis whose next
  /// crossing of the ideal line comes first.
  void stroke(Cell c, Cell e) const {
    const int dx = std::abs(e.x - c.x);
    const int dy = std::abs(e.y - c.y);
    const int sx = e.x > c.x ? 1 : -1;
    const int sy = e.y > c.y ? 1 : -1;
    stamp(c);
    for (int ix = 0, iy = 0; ix < dx || iy < dy;) {
      if ((1LL + 2LL * ix) * dy < (1LL + 2LL * iy) * dx) {
        c.x += sx;
        ++ix;
      } else {
        c.y += sy;
        ++iy;
      }
      stamp(c);
    }
  }
};

/// Waypoints on a jittered grid: one uniformly placed in each spacing x spacing tile of the
/// interior, spacing = 6l (grown so that there are at most 2,000: the spanning tree is quadratic
/// in their number).
void add_waypoints(const GeneratorParams& p, const Lanes& lanes, Rng& rng, std::vector<Cell>& anchors) {
  constexpr int kSpacingLanes = 6;           // waypoint tile edge, in lanes
  constexpr long long kMaxWaypoints = 2000;  // Prim below is quadratic in their number
  const int inner_w = p.width - 2;
  const int inner_h = p.height - 2;
  int spacing = kSpacingLanes * lanes.l;
  while (static_cast<long long>(std::max(1, inner_w / spacing)) * std::max(1, inner_h / spacing) >
         kMaxWaypoints) {
    spacing += lanes.l;
  }
  const int tiles_x = std::max(1, inner_w / spacing);
  const int tiles_y = std::max(1, inner_h / spacing);
  for (int ty = 0; ty < tiles_y; ++ty) {
    for (int tx = 0; tx < tiles_x; ++tx) {
      // Tile [x0, x1) x [y0, y1): the interior split evenly.
      const int x0 = 1 + tx * inner_w / tiles_x;
      const int x1 = 1 + (tx + 1) * inner_w / tiles_x;
      const int y0 = 1 + ty * inner_h / tiles_y;
      const int y1 = 1 + (ty + 1) * inner_h / tiles_y;
      anchors.push_back(lanes.clamped(Cell{uniform_int(rng, x0, x1 - 1), uniform_int(rng, y0, y1 - 1)}));
    }
  }
}

/// The lanes' edges between anchors: Prim's minimum spanning tree (squared Euclidean, ties by
/// lowest index), then for each anchor, with probability 1/4, an edge to its nearest anchor not
/// yet joined to it (loops, so that lanes form a network).
std::vector<std::pair<std::size_t, std::size_t>> town_edges(const std::vector<Cell>& anchors, Rng& rng) {
  constexpr double kLoopProbability = 0.25;  // extra edge per waypoint
  const std::size_t n = anchors.size();
  const auto d2 = [&](std::size_t a, std::size_t b) {
    const long long dx = anchors[a].x - anchors[b].x;
    const long long dy = anchors[a].y - anchors[b].y;
    return dx * dx + dy * dy;
  };
  std::vector<std::pair<std::size_t, std::size_t>> edges;
  std::vector<std::vector<bool>> joined(n, std::vector<bool>(n, false));
  std::vector<bool> in_tree(n, false);
  std::vector<long long> best(n, std::numeric_limits<long long>::max());
  std::vector<std::size_t> parent(n, 0);
  best[0] = 0;
  for (std::size_t step = 0; step < n; ++step) {
    std::size_t u = n;
    for (std::size_t v = 0; v < n; ++v) {
      if (!in_tree[v] && (u == n || best[v] < best[u])) u = v;
    }
    in_tree[u] = true;
    if (step > 0) {
      edges.emplace_back(parent[u], u);
      joined[parent[u]][u] = joined[u][parent[u]] = true;
    }
    for (std::size_t v = 0; v < n; ++v) {
      if (!in_tree[v] && d2(u, v) < best[v]) {
        best[v] = d2(u, v);
        parent[v] = u;
      }
    }
  }
  for (std::size_t a = 0; a < n; ++a) {
    std::size_t nearest = n;
    for (std::size_t b = 0; b < n; ++b) {
      if (b != a && !joined[a][b] && (nearest == n || d2(a, b) < d2(a, nearest))) nearest = b;
    }
    if (nearest < n && uniform01(rng) < kLoopProbability) {
      edges.emplace_back(a, nearest);
      joined[a][nearest] = joined[nearest][a] = true;
    }
  }
  return edges;
}

/// An edge from `a` to `b` as a polyline by midpoint displacement (perpendicular offset up to
/// 0.2 of the segment length) until segments are at most 4l long. Points are clamped into the
/// frame, so strokes between them stay connected.
std::vector<Cell> winding_line(Cell a, Cell b, const Lanes& lanes, Rng& rng) {
  constexpr double kDisplacement = 0.2;  // largest midpoint offset / segment length
  constexpr double kSegmentLanes = 4.0;  // segments longer than this (in lanes) are split
  std::vector<Cell> line{a, b};
  for (int round = 0; round < 8; ++round) {
    std::vector<Cell> finer{line.front()};
    bool split = false;
    for (std::size_t k = 1; k < line.size(); ++k) {
      const Cell s = line[k - 1];
      const Cell e = line[k];
      const double dx = e.x - s.x;
      const double dy = e.y - s.y;
      const double len = std::sqrt(dx * dx + dy * dy);
      if (len > kSegmentLanes * lanes.l) {
        const double offset = (2.0 * uniform01(rng) - 1.0) * kDisplacement;  // times len, along (-dy, dx)
        const double mx = (s.x + e.x) / 2.0 - dy * offset;
        const double my = (s.y + e.y) / 2.0 + dx * offset;
        finer.push_back(lanes.clamped(
            Cell{static_cast<int>(std::floor(mx + 0.5)), static_cast<int>(std::floor(my + 0.5))}));
        split = true;
      }
      finer.push_back(e);
    }
    line = std::move(finer);
    if (!split) break;
  }
  return line;
}

}  // namespace

/// Old town: winding lanes along a spanning tree (plus loops) over squares and waypoints.
Occupancy make_oldtown(const GeneratorParams& p, Rng& rng) {
  Occupancy g(p.width, p.height, kWall);
  const Lanes lanes{g, p.lane, p.width - 1 - p.lane, p.height - 1 - p.lane};
  const int l = p.lane;
  std::vector<Cell> anchors;
  // 1. Squares, sides in [3l, 6l] clipped to the interior.
  for (int i = 0; i < p.squares; ++i) {
    const int sw = std::min(uniform_int(rng, 3 * l, 6 * l), p.width - 2);
    const int sh = std::min(uniform_int(rng, 3 * l, 6 * l), p.height - 2);
    const int x = uniform_int(rng, 1, p.width - 1 - sw);
    const int y = uniform_int(rng, 1, p.height - 1 - sh);
    fill_rect(g, Rect{x, y, x + sw, y + sh}, kFree);
    anchors.push_back(lanes.clamped(Cell{x + sw / 2, y + sh / 2}));
  }
  // 2. Waypoints, 3. edges, 4. each edge a winding line of strokes.
  add_waypoints(p, lanes, rng, anchors);
  for (const auto& [a, b] : town_edges(anchors, rng)) {
    const std::vector<Cell> line = winding_line(anchors[a], anchors[b], lanes, rng);
    for (std::size_t k = 1; k < line.size(); ++k) lanes.stroke(line[k - 1], line[k]);
  }
  return g;
}

}  // namespace generator_detail
}  // namespace world
}  // namespace fsweep
