#pragma once
/// @file grid.hpp
/// Flat row-major grids and the 8-connected cell geometry shared by every layer.
///
/// Conventions (docs/dev/architecture.md, "World conventions"): (0,0) is the top-left cell, x is the column
/// and grows to the right, y is the row and grows downward, `index = y * width + x`. Distances inside this
/// file are in cells unless a name says metres.

#include <array>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <vector>

namespace fsweep {
inline namespace world {

/// A grid cell by column `x` and row `y` (cells).
struct Cell {
  int x = 0;
  int y = 0;
  friend constexpr bool operator==(Cell a, Cell b) = default;
};

inline constexpr double kSqrt2 = 1.41421356237309504880;

/// The 8 neighbour offsets in heading order: heading h points along kDirections[h].
/// Heading 0 is east (+x); headings advance clockwise on screen (y grows downward), so
/// heading 2 is south (+y), 4 west, 6 north. Odd headings are diagonal.
inline constexpr std::array<Cell, 8> kDirections{Cell{1, 0},  Cell{1, 1},   Cell{0, 1},  Cell{-1, 1},
                                                 Cell{-1, 0}, Cell{-1, -1}, Cell{0, -1}, Cell{1, -1}};

/// Length of one step in heading h (cells): 1 orthogonally, sqrt(2) diagonally.
constexpr double step_length(int heading) { return (heading & 1) != 0 ? kSqrt2 : 1.0; }

/// Heading index (0..7) of a unit step (dx, dy), each in {-1, 0, 1}, not both 0; -1 for (0, 0)
/// or a longer step. A table read (it runs once per path step in measure_path()).
constexpr int heading_of(int dx, int dy) {
  constexpr std::array<int, 9> kHeadingOfStep{5, 6, 7, 4, -1, 0, 3, 2, 1};  // at (dy + 1) * 3 + dx + 1
  if (dx < -1 || dx > 1 || dy < -1 || dy > 1) return -1;
  const int at = (dy + 1) * 3 + dx + 1;
  return kHeadingOfStep[static_cast<std::size_t>(at)];
}
static_assert([] {
  for (int h = 0; h < 8; ++h) {
    if (heading_of(kDirections[static_cast<std::size_t>(h)].x, kDirections[static_cast<std::size_t>(h)].y) !=
        h)
      return false;
  }
  return heading_of(0, 0) == -1 && heading_of(2, 0) == -1;
}());

/// Smallest number of 45-degree steps between two headings (0..4).
constexpr int heading_difference(int a, int b) {
  const int d = (a - b) & 7;  // (a - b) mod 8 in 0..7, negative differences included
  return d > 4 ? 8 - d : d;
}

/// -1, 0 or 1: the sign of v.
constexpr int sign_of(int v) { return (v > 0) - (v < 0); }

/// Angle of heading h in radians, measured clockwise on screen from +x (= atan2(dy, dx)).
inline double heading_angle(int heading) { return heading * (M_PI / 4.0); }

/// Octile distance between two cells (cells): the 8-connected shortest length on an empty grid.
inline double octile_distance(Cell a, Cell b) {
  const int dx = std::abs(a.x - b.x);
  const int dy = std::abs(a.y - b.y);
  const int lo = dx < dy ? dx : dy;
  const int hi = dx < dy ? dy : dx;
  return (hi - lo) + kSqrt2 * lo;
}

/// Euclidean distance between two cell centres (cells).
inline double euclidean_distance(Cell a, Cell b) {
  return std::hypot(static_cast<double>(a.x - b.x), static_cast<double>(a.y - b.y));
}

/// Dense 2D array stored row-major, `index = y * width + x`.
template <typename T>
class Grid {
 public:
  Grid() = default;
  Grid(int width, int height, T fill = T{})
      : width_(width),
        height_(height),
        data_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), fill) {}

  [[nodiscard]] int width() const { return width_; }
  [[nodiscard]] int height() const { return height_; }
  [[nodiscard]] int size() const { return width_ * height_; }
  [[nodiscard]] bool in_bounds(Cell c) const { return c.x >= 0 && c.y >= 0 && c.x < width_ && c.y < height_; }
  [[nodiscard]] int index(Cell c) const { return c.y * width_ + c.x; }
  [[nodiscard]] Cell cell(int index) const { return Cell{index % width_, index / width_}; }

  T& operator[](int i) { return data_[static_cast<std::size_t>(i)]; }
  const T& operator[](int i) const { return data_[static_cast<std::size_t>(i)]; }
  T& at(Cell c) { return data_[static_cast<std::size_t>(index(c))]; }
  const T& at(Cell c) const { return data_[static_cast<std::size_t>(index(c))]; }

  void fill(T value) { std::fill(data_.begin(), data_.end(), value); }
  [[nodiscard]] const std::vector<T>& data() const { return data_; }
  [[nodiscard]] std::vector<T>& data() { return data_; }

  friend bool operator==(const Grid&, const Grid&) = default;

 private:
  int width_ = 0;
  int height_ = 0;
  std::vector<T> data_;
};

}  // namespace world
}  // namespace fsweep
