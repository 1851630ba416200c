#pragma once
/// @file trajectory_image.hpp
/// A PNG picture of a run: ground truth, what was explored, the path coloured by time, the
/// dock and the frontier cells left.

#include <string>

#include "sim/run_result.hpp"
#include "world/world_map.hpp"

namespace fsweep {
inline namespace sim {

/// The picture as PNG file bytes. Colours: unexplored free = light grey, unexplored occupied = mid grey,
/// explored free = white, explored occupied = black, path = blue (start) to red (end), recharge points and
/// the dock = green, frontier cells left = magenta. Each cell is `scale` x `scale` pixels; scale 0 picks one
/// so the longer side is about 800 pixels.
[[nodiscard]] std::string trajectory_png(const WorldMap& map, const RunResult& result, int scale = 0);

/// trajectory_png() written to `path` (temp file and rename). Throws ConfigError naming the
/// file if writing fails.
void write_trajectory_png(const std::string& path, const WorldMap& map, const RunResult& result,
                          int scale = 0);

}  // namespace sim
}  // namespace fsweep
