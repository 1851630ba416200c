#pragma once
/// @file loader_support.hpp
/// Private to the map loaders (map_loaders.cpp, image_map_loaders.cpp): message helpers and the
/// checks every loader shares.

#include <cmath>
#include <cstdint>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <string>

#include "core/config_error.hpp"
#include "world/world_map.hpp"

namespace fsweep {
inline namespace world {
namespace loader_detail {

/// The most cells a loaded map may have (MovingAI maps, images, resampled bitmaps; as generated
/// maps): checked against the header's declared size before anything is allocated.
inline constexpr std::int64_t kMaxMapCells = 100'000'000;

/// A number for messages: shortest form with up to 10 significant digits (0.05, not 0.050000).
inline std::string number_text(double v) {
  std::ostringstream out;
  out << std::setprecision(10) << v;
  return out.str();
}

/// The bytes of the file at `path`; a ConfigError(path, `cannot_open`) if it cannot be opened.
inline std::string read_whole_file(const std::string& path, const std::string& cannot_open) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ConfigError(path, cannot_open);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

/// "path:line" for messages (line counted from 1).
inline std::string at_line(const std::string& path, int line) { return path + ":" + std::to_string(line); }

/// Throws at `where` unless a declared width x height (both > 0) fits kMaxMapCells.
inline void require_map_size(std::int64_t width, std::int64_t height, const std::string& where) {
  if (width > 0 && height > 0 && width > kMaxMapCells / height) {
    throw ConfigError(where, "width " + std::to_string(width) + " x height " + std::to_string(height) +
                                 " is more than 100000000 cells; allowed: at most 100000000 cells");
  }
}

/// Throws unless the cell size is a finite number of metres > 0.
inline void require_positive_resolution(double resolution_m, const std::string& where) {
  if (!(resolution_m > 0.0) || !std::isfinite(resolution_m)) {
    throw ConfigError(where, "resolution " + number_text(resolution_m) +
                                 " m per cell is not allowed; it must be a finite number > 0");
  }
}

/// Sets the start to the first free cell in row-major order; a map without free cells is an error.
inline void set_first_free_start(WorldMap& map) {
  for (int i = 0; i < map.occupied.size(); ++i) {
    if (map.is_free(i)) {
      map.start = map.occupied.cell(i);
      return;
    }
  }
  throw ConfigError(map.source, "the map has no free cell, so there is no start cell");
}

}  // namespace loader_detail
}  // namespace world
}  // namespace fsweep
