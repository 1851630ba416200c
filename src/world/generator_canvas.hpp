#pragma once
/// @file generator_canvas.hpp
/// Private to the map generators (map_generators.cpp, building_generators.cpp,
/// town_generators.cpp): the drawing helpers they share and the per-kind functions. Each
/// `make_*` draws one kind on a fresh grid from already validated parameters; see
/// map_generators.hpp for what each kind does.

#include <algorithm>
#include <cstdint>

#include "core/random.hpp"
#include "world/grid.hpp"
#include "world/map_generators.hpp"

namespace fsweep {
inline namespace world {
namespace generator_detail {

/// Ground-truth occupancy being drawn: kWall (1) occupied, kFree (0) free.
using Occupancy = Grid<std::uint8_t>;
inline constexpr std::uint8_t kFree = 0;
inline constexpr std::uint8_t kWall = 1;

/// Half-open rectangle of cells [x0, x1) x [y0, y1).
struct Rect {
  int x0 = 0;
  int y0 = 0;
  int x1 = 0;
  int y1 = 0;
};

/// Sets every cell of `r` (clipped to the grid) to `value`.
inline void fill_rect(Occupancy& g, Rect r, std::uint8_t value) {
  r.x0 = std::max(r.x0, 0);
  r.y0 = std::max(r.y0, 0);
  r.x1 = std::min(r.x1, g.width());
  r.y1 = std::min(r.y1, g.height());
  for (int y = r.y0; y < r.y1; ++y) {
    for (int x = r.x0; x < r.x1; ++x) g.at(Cell{x, y}) = value;
  }
}

/// Occupied frame `thickness` cells wide along the grid's edges.
inline void frame(Occupancy& g, int thickness) {
  const int w = g.width();
  const int h = g.height();
  fill_rect(g, Rect{0, 0, w, thickness}, kWall);
  fill_rect(g, Rect{0, h - thickness, w, h}, kWall);
  fill_rect(g, Rect{0, 0, thickness, h}, kWall);
  fill_rect(g, Rect{w - thickness, 0, w, h}, kWall);
}

/// Uniform integer in [lo, hi] (lo <= hi), platform independent.
inline int uniform_int(Rng& rng, int lo, int hi) {
  return lo + static_cast<int>(uniform_below(rng, static_cast<std::uint64_t>(hi - lo) + 1U));
}

[[nodiscard]] Occupancy make_rooms(const GeneratorParams& p, Rng& rng);      // building_generators.cpp
[[nodiscard]] Occupancy make_office(const GeneratorParams& p, Rng& rng);     // building_generators.cpp
[[nodiscard]] Occupancy make_manhattan(const GeneratorParams& p, Rng& rng);  // town_generators.cpp
[[nodiscard]] Occupancy make_oldtown(const GeneratorParams& p, Rng& rng);    // town_generators.cpp

}  // namespace generator_detail
}  // namespace world
}  // namespace fsweep
