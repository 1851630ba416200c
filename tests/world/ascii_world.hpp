#pragma once
/// @file ascii_world.hpp
/// Tiny hand-drawn maps for tests, independent of the map loaders.

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/random.hpp"
#include "world/known_map.hpp"
#include "world/world_map.hpp"

namespace fsweep::test {

/// A WorldMap from rows of `.` (free), `#` (occupied) and `S` (free start cell). Row 0 is the
/// top (y = 0), column 0 the left (x = 0). Without `S` the start is the first free cell in
/// row-major order. All rows must have the same length.
inline WorldMap ascii_world(const std::vector<std::string>& rows, double resolution_m = 1.0) {
  if (rows.empty() || rows.front().empty()) throw std::invalid_argument("ascii_world: empty map");
  const int width = static_cast<int>(rows.front().size());
  const int height = static_cast<int>(rows.size());
  WorldMap map;
  map.occupied = Grid<std::uint8_t>(width, height, 0);
  map.resolution_m = resolution_m;
  map.source = "ascii";
  bool has_start = false;
  bool has_free = false;
  for (int y = 0; y < height; ++y) {
    const std::string& row = rows[static_cast<std::size_t>(y)];
    if (static_cast<int>(row.size()) != width) throw std::invalid_argument("ascii_world: ragged rows");
    for (int x = 0; x < width; ++x) {
      const char c = row[static_cast<std::size_t>(x)];
      if (c != '.' && c != '#' && c != 'S') throw std::invalid_argument("ascii_world: bad character");
      map.occupied.at(Cell{x, y}) = c == '#' ? 1 : 0;
      if (c == 'S') {
        map.start = Cell{x, y};
        has_start = true;
      }
      if (c != '#' && !has_free) {
        has_free = true;
        if (!has_start) map.start = Cell{x, y};
      }
    }
  }
  return map;
}

/// A KnownMap from rows of `?` (unknown), `.` (free) and `#` (occupied).
inline KnownMap ascii_known(const std::vector<std::string>& rows, double resolution_m = 1.0) {
  if (rows.empty() || rows.front().empty()) throw std::invalid_argument("ascii_known: empty map");
  const int width = static_cast<int>(rows.front().size());
  const int height = static_cast<int>(rows.size());
  KnownMap known(width, height, resolution_m);
  for (int y = 0; y < height; ++y) {
    const std::string& row = rows[static_cast<std::size_t>(y)];
    if (static_cast<int>(row.size()) != width) throw std::invalid_argument("ascii_known: ragged rows");
    for (int x = 0; x < width; ++x) {
      const char c = row[static_cast<std::size_t>(x)];
      if (c == '?') continue;
      if (c != '.' && c != '#') throw std::invalid_argument("ascii_known: bad character");
      known.reveal(known.index(Cell{x, y}), c == '#');
    }
  }
  return known;
}

/// A `width` x `height` known map drawn cell by cell (row-major, one uniform01 draw each) from
/// `rng`: free with probability `p_free`, occupied with `p_occupied`, unknown otherwise.
inline KnownMap random_partly_known(int width, int height, double p_free, double p_occupied, Rng& rng,
                                    double resolution_m = 1.0) {
  KnownMap known(width, height, resolution_m);
  for (int i = 0; i < known.size(); ++i) {
    const double u = uniform01(rng);
    if (u < p_free + p_occupied) known.reveal(i, u >= p_free);
  }
  return known;
}

}  // namespace fsweep::test
