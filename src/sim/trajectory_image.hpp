#pragma once
/// @file trajectory_image.hpp
/// A PNG picture of a run: ground truth, what was explored, the path coloured by time, the
/// dock and the frontier cells left.

#include <cstdint>
#include <string>

#include "sim/run_result.hpp"
#include "world/world_map.hpp"

namespace fsweep {
inline namespace sim {

/// The largest picture drawn: at most this many pixels per side...
inline constexpr std::int64_t kMaxTrajectoryImageSide = 16384;
/// ... and at most this many pixels in all (100 megapixels, 300 MB of RGB).
inline constexpr std::int64_t kMaxTrajectoryImagePixels = 100'000'000;

/// The pixels per cell trajectory_png() draws `map` with: `scale`, or for 0 the automatic one
/// (the longer side about 800 pixels, 1 to 16 pixels per cell).
[[nodiscard]] int trajectory_scale(const WorldMap& map, int scale);

/// Throws ConfigError naming `option` if `scale` is negative, or if the picture of `map` at that
/// scale (0: automatic) exceeds kMaxTrajectoryImageSide pixels per side or
/// kMaxTrajectoryImagePixels in all; the message gives the size and the limits. Sizes are
/// computed in 64 bits. Call it before writing anything that the picture belongs with.
void check_trajectory_image(const WorldMap& map, int scale, const std::string& option);

/// The picture as PNG file bytes. Colours: unexplored free = light grey, unexplored occupied = mid grey,
/// explored free = white, explored occupied = black, path = blue (start) to red (end), recharge points and
/// the dock = green, frontier cells left = magenta. Each cell is `scale` x `scale` pixels; scale 0 picks one
/// so the longer side is about 800 pixels. Throws ConfigError (check_trajectory_image(), option "scale")
/// for a negative scale or a picture over the limits.
[[nodiscard]] std::string trajectory_png(const WorldMap& map, const RunResult& result, int scale = 0);

/// trajectory_png() written to `path` (temp file and rename). Throws ConfigError naming the
/// file if writing fails.
void write_trajectory_png(const std::string& path, const WorldMap& map, const RunResult& result,
                          int scale = 0);

}  // namespace sim
}  // namespace fsweep
