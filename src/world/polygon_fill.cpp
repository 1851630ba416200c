#include "world/polygon_fill.hpp"

#include <algorithm>
#include <cstdlib>
#include <utility>

namespace fsweep {
inline namespace world {
namespace {

constexpr int kFixedShift = 16;  // OpenCV's XY_SHIFT
constexpr long long kOne = 1LL << kFixedShift;

void set_cell(Grid<std::uint8_t>& grid, int x, int y, std::uint8_t value) {
  if (grid.in_bounds(Cell{x, y})) grid.at(Cell{x, y}) = value;
}

/// The 8-connected line of cv::LineIterator (connectivity 8, left to right).
void draw_line(Grid<std::uint8_t>& grid, Cell a, Cell b, std::uint8_t value) {
  if (b.x < a.x) std::swap(a, b);
  const int dx = b.x - a.x;
  const int step_y = b.y < a.y ? -1 : 1;
  const int dy = std::abs(b.y - a.y);
  const bool steep = dy > dx;
  const long long major = steep ? dy : dx;
  const long long minor = steep ? dx : dy;
  long long err = major - 2 * minor;
  int x = a.x;
  int y = a.y;
  for (long long k = 0; k <= major; ++k) {
    set_cell(grid, x, y, value);
    const bool both = err < 0;
    err += both ? 2 * major - 2 * minor : -2 * minor;
    if (steep) {
      y += step_y;
      if (both) ++x;
    } else {
      ++x;
      if (both) y += step_y;
    }
  }
}

/// A non-horizontal edge: rows y0 <= y < y1, crossing x (16.16 fixed point) at row y0 and its
/// change per row.
struct Edge {
  int y0 = 0;
  int y1 = 0;
  long long x0 = 0;
  long long dx = 0;
  [[nodiscard]] long long x_at(int y) const { return x0 + static_cast<long long>(y - y0) * dx; }
};

}  // namespace

void fill_polygon(Grid<std::uint8_t>& grid, const std::vector<Cell>& vertices, std::uint8_t value) {
  if (vertices.empty()) return;
  std::vector<Edge> edges;
  Cell previous = vertices.back();
  for (const Cell& current : vertices) {
    draw_line(grid, previous, current, value);
    if (previous.y != current.y) {
      const auto [top, bottom] =
          previous.y < current.y ? std::pair{previous, current} : std::pair{current, previous};
      Edge e;
      e.y0 = top.y;
      e.y1 = bottom.y;
      e.x0 = static_cast<long long>(top.x) * kOne;
      // (x1 - x0) << 16 over the rows, truncated toward zero as OpenCV's integer division.
      e.dx = static_cast<long long>(current.x - previous.x) * kOne /
             static_cast<long long>(current.y - previous.y);
      edges.push_back(e);
    }
    previous = current;
  }
  if (edges.empty()) return;
  int y_min = edges.front().y0;
  int y_max = edges.front().y1;
  for (const Edge& e : edges) {
    y_min = std::min(y_min, e.y0);
    y_max = std::max(y_max, e.y1);
  }
  y_min = std::max(y_min, 0);
  y_max = std::min(y_max, grid.height());
  std::vector<long long> crossings;
  for (int y = y_min; y < y_max; ++y) {
    crossings.clear();
    for (const Edge& e : edges) {
      if (e.y0 <= y && y < e.y1) crossings.push_back(e.x_at(y));
    }
    std::sort(crossings.begin(), crossings.end());
    for (std::size_t k = 0; k + 1 < crossings.size(); k += 2) {
      // The left crossing rounded up, the right one down (arithmetic shifts), clipped to the grid.
      const int from = static_cast<int>(std::max<long long>((crossings[k] + kOne - 1) >> kFixedShift, 0));
      const int to = static_cast<int>(std::min<long long>(crossings[k + 1] >> kFixedShift, grid.width() - 1));
      for (int x = from; x <= to; ++x) grid.at(Cell{x, y}) = value;
    }
  }
}

}  // namespace world
}  // namespace fsweep
