#pragma once
/// @file trajectory_image.hpp
/// A PNG picture of a run: ground truth, what was explored, the path coloured by time, the
/// dock and the frontier cells left.

#include <cstdint>
#include <string>
#include <vector>

#include "sim/run_result.hpp"
#include "sim/run_spec.hpp"
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
/// scale (0: automatic), with its title and legend, exceeds kMaxTrajectoryImageSide pixels per side or
/// kMaxTrajectoryImagePixels in all; the message gives the size and the limits. Sizes are
/// computed in 64 bits. Call it before writing anything that the picture belongs with.
void check_trajectory_image(const WorldMap& map, int scale, const std::string& option);

/// What the picture's title names besides the run's outcome (ASCII; other bytes are drawn as '?').
struct TrajectoryTitle {
  std::string map;       ///< the map: its label or SPEC
  std::string strategy;  ///< the strategy and its parameters
};

/// The title of a run of `spec`: `map` (a label, or spec.map's source when empty), and the
/// strategy's name with its parameters (trajectory_strategy_text()).
[[nodiscard]] TrajectoryTitle trajectory_title(const RunSpec& spec, const std::string& map = {});

/// "energy_aware w1=10 w2=0 w3=9 w4=20": the strategy's name and its number and text parameters
/// as recorded (recorded_strategy_params()), or `weights` given for `weight_names` instead of those.
[[nodiscard]] std::string trajectory_strategy_text(const RunSpec& spec,
                                                   const std::vector<std::string>& weight_names = {},
                                                   const std::vector<double>& weights = {});

/// The picture as PNG file bytes: a title (the map, the strategy, how the run ended, its distance
/// and coverage), the map with the run on it, and a legend with a scale bar in metres. Colours:
/// unexplored free = light grey, unexplored occupied = mid grey, explored free = white, explored
/// occupied = black, path = blue (start) to red (end), recharge points = green discs, the dock =
/// a larger green disc ringed white (at least 1/120 of the picture's longer side, so it shows at
/// any map size), frontier cells left = magenta. Each cell is `scale` x `scale` pixels; scale 0
/// picks one so the longer side is about 800 pixels; the picture is at least 400 pixels wide,
/// the map centred. Throws ConfigError (check_trajectory_image(), option "scale") for a negative
/// scale or a picture over the limits.
[[nodiscard]] std::string trajectory_png(const WorldMap& map, const RunResult& result, int scale = 0,
                                         const TrajectoryTitle& title = {});

/// trajectory_png() written to `path` (temp file and rename). Throws IoError naming the file
/// if writing fails.
void write_trajectory_png(const std::string& path, const WorldMap& map, const RunResult& result,
                          int scale = 0, const TrajectoryTitle& title = {});

}  // namespace sim
}  // namespace fsweep
