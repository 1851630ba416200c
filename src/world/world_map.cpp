#include "world/world_map.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string_view>
#include <vector>

#include "core/random.hpp"

namespace fsweep {
inline namespace world {

int WorldMap::free_count() const {
  return static_cast<int>(std::count(occupied.data().begin(), occupied.data().end(), std::uint8_t{0}));
}

std::uint64_t content_hash(const WorldMap& map) {
  char head[96];
  const int n = std::snprintf(head, sizeof(head), "%d %d %.17g %d %d", map.width(), map.height(),
                              map.resolution_m, map.start.x, map.start.y);
  const auto& cells = map.occupied.data();
  // NOLINTNEXTLINE(cppcoreguidelines-pro-type-reinterpret-cast): the cells' bytes, read as chars
  const std::string_view bytes(reinterpret_cast<const char*>(cells.data()), cells.size());
  return fnv1a(bytes, fnv1a(std::string_view(head, static_cast<std::size_t>(n))));
}

namespace {

/// Breadth-first search over free cells from `from` (free, not yet marked), marking every cell
/// it reaches with 1 in `reached` and appending its index to `queue`. A diagonal step from c to
/// c + (dx, dy) needs both orthogonal cells c + (dx, 0) and c + (0, dy) free unless corner
/// cutting is allowed (the MovingAI convention, docs/dev/architecture.md, "Robot, motion and
/// energy"); the rule is symmetric, so the cells reached form one connected region.
void flood_free(const WorldMap& map, Cell from, bool allow_corner_cutting, Grid<std::uint8_t>& reached,
                std::vector<int>& queue) {
  const std::size_t first = queue.size();
  reached.at(from) = 1;
  queue.push_back(map.occupied.index(from));
  for (std::size_t head = first; head < queue.size(); ++head) {
    const Cell c = map.occupied.cell(queue[head]);
    for (int h = 0; h < 8; ++h) {
      const Cell d = kDirections[static_cast<std::size_t>(h)];
      const Cell n{c.x + d.x, c.y + d.y};
      if (!map.is_free(n) || reached.at(n) != 0) continue;
      if ((h & 1) != 0 && !allow_corner_cutting &&
          (!map.is_free(Cell{c.x + d.x, c.y}) || !map.is_free(Cell{c.x, c.y + d.y}))) {
        continue;
      }
      reached.at(n) = 1;
      queue.push_back(map.occupied.index(n));
    }
  }
}

}  // namespace

Grid<std::uint8_t> reachable_free(const WorldMap& map, Cell from, bool allow_corner_cutting) {
  Grid<std::uint8_t> reached(map.width(), map.height(), 0);
  if (!map.is_free(from)) return reached;
  std::vector<int> queue;
  queue.reserve(static_cast<std::size_t>(map.occupied.size()));
  flood_free(map, from, allow_corner_cutting, reached, queue);
  return reached;
}

Grid<std::uint8_t> largest_free_region(const WorldMap& map, bool allow_corner_cutting) {
  Grid<std::uint8_t> seen(map.width(), map.height(), 0);
  std::vector<int> region;
  std::vector<int> best;
  for (int i = 0; i < map.occupied.size(); ++i) {
    if (!map.is_free(i) || seen[i] != 0) continue;
    region.clear();
    flood_free(map, map.occupied.cell(i), allow_corner_cutting, seen, region);
    if (region.size() > best.size()) best.swap(region);  // strict: the earliest region wins ties
  }
  Grid<std::uint8_t> out(map.width(), map.height(), 0);
  for (const int i : best) out[i] = 1;
  return out;
}

Cell draw_region_cell(const Grid<std::uint8_t>& region, std::uint64_t seed) {
  const auto cells = static_cast<std::uint64_t>(std::count(region.data().begin(), region.data().end(), 1));
  if (cells == 0) return Cell{-1, -1};
  Rng rng = make_rng(seed, "map/start");
  std::uint64_t k = uniform_below(rng, cells);
  for (int i = 0; i < region.size(); ++i) {
    if (region[i] == 0) continue;
    if (k == 0) return region.cell(i);
    --k;
  }
  return Cell{-1, -1};  // not reached: k < cells
}

Cell region_centre_cell(const Grid<std::uint8_t>& region) {
  // 1. The cell count n and the coordinate sums; the centroid is (sum_x / n, sum_y / n).
  std::int64_t n = 0;
  std::int64_t sum_x = 0;
  std::int64_t sum_y = 0;
  for (int i = 0; i < region.size(); ++i) {
    if (region[i] != 1) continue;
    const Cell c = region.cell(i);
    ++n;
    sum_x += c.x;
    sum_y += c.y;
  }
  if (n == 0) return Cell{-1, -1};
  // 2. The cell minimising n^2 |c - centroid|^2 = (n x - sum_x)^2 + (n y - sum_y)^2, in integers:
  // |n x - sum_x| < n * width <= 2^62 (a grid has fewer than 2^31 cells), its square below 2^124.
  __extension__ typedef unsigned __int128 Scaled;  // a typedef: __extension__ (for -Wpedantic) takes no alias
  const auto square = [](std::int64_t v) {
    const auto a = static_cast<Scaled>(v < 0 ? -v : v);
    return a * a;
  };
  Cell best{-1, -1};
  Scaled best_d2 = 0;
  for (int i = 0; i < region.size(); ++i) {
    if (region[i] != 1) continue;
    const Cell c = region.cell(i);
    const Scaled d2 = square(n * c.x - sum_x) + square(n * c.y - sum_y);
    if (best.x < 0 || d2 < best_d2) {  // strict: the lowest index wins ties
      best_d2 = d2;
      best = c;
    }
  }
  return best;
}

Cell nearest_free_cell(const WorldMap& map, Cell near) {
  Cell best{-1, -1};
  long long best_d2 = std::numeric_limits<long long>::max();
  for (int i = 0; i < map.occupied.size(); ++i) {
    if (!map.is_free(i)) continue;
    const Cell c = map.occupied.cell(i);
    const long long dx = c.x - near.x;
    const long long dy = c.y - near.y;
    const long long d2 = dx * dx + dy * dy;
    if (d2 < best_d2) {  // strict: the lowest index wins ties
      best_d2 = d2;
      best = c;
    }
  }
  return best;
}

}  // namespace world
}  // namespace fsweep
