#pragma once
/// @file map_loaders.hpp
/// Reading ground-truth maps and MovingAI scenario files. Every loader throws ConfigError
/// naming the file (and line or pixel where it applies) on bad input.

#include <string>
#include <vector>

#include "world/world_map.hpp"

namespace fsweep {
inline namespace world {

/// MovingAI `.map` (`type octile`, `height H`, `width W`, `map`, H rows of W chars).
/// `.` `G` `S` are free; `@` `O` `T` `W` are occupied. Resolution 1 m per cell unless given.
/// The start is the first free cell in row-major order (override it in the map spec).
[[nodiscard]] WorldMap load_movingai_map(const std::string& path, double resolution_m = 1.0);

/// ASCII test map: one row per line, `.` free, `#` occupied, `S` free start cell (optional;
/// default the first free cell). All rows must have equal length.
[[nodiscard]] WorldMap parse_ascii_map(const std::string& text, double resolution_m = 1.0,
                                       const std::string& source = "ascii");
[[nodiscard]] WorldMap load_ascii_map(const std::string& path, double resolution_m = 1.0);

/// ROS map_server YAML + PGM/PNG image: honours `image` (relative to the YAML), `resolution`,
/// `negate`, `occupied_thresh`, `free_thresh` (trinary mode). Unknown pixels count as
/// occupied. Row 0 of the image is the top row of the grid (the map frame's y is flipped).
/// Details: p = (255 - v) / 255 (v / 255 with `negate`), free iff p < free_thresh; `mode` may be
/// trinary or scale (thresholded alike; raw is an error); `negate` is 0/1 or true/false;
/// other keys (origin, ...) are ignored. Colour pixels use the mean of R, G, B (alpha ignored).
/// The start is the first free cell in row-major order.
[[nodiscard]] WorldMap load_ros_map(const std::string& yaml_path);

/// Scale of a bitmap: either metres per pixel, or the whole image's width and height in metres
/// (Stage's `size [40 18]`), which may differ per axis.
struct BitmapScale {
  double metres_per_pixel = 0.0;  // > 0 to use
  double width_m = 0.0;           // with height_m, > 0 to use
  double height_m = 0.0;
};

/// PNG or PGM bitmap: a pixel with grey value > `threshold` (0..255) is free, otherwise
/// occupied (Stage's rule with threshold 127). The image is resampled to square cells of
/// `resolution_m`; a cell is occupied if any pixel it covers is occupied (max-pooling, so thin
/// walls never leak). With resolution_m <= 0 one pixel is one cell (scale must be square).
/// The grid is ceil(image extent / resolution_m) cells per axis (a last partial cell pools the
/// pixels it covers), at most 10^8 cells. Colour pixels use the mean of R, G, B. The start is
/// the first free cell in row-major order.
[[nodiscard]] WorldMap load_bitmap(const std::string& path, const BitmapScale& scale, int threshold,
                                   double resolution_m);

/// HouseExpo's own resolution: PseudoSLAM draws its plans at 25 pixels per metre.
inline constexpr double kHouseExpoResolution = 0.04;

/// HouseExpo floor plan (JSON; keys `verts`, `id`, `bbox`, `room_category`, `room_num`): the
/// `verts` contour (metres) is the free space, everything else is wall. Drawn as PseudoSLAM's
/// jsonReader draws it: every vertex scaled by 1 / `resolution_m` (rounded to the nearest
/// integer when within 1e-9 of it, as PseudoSLAM's integer `meter2pixel`) and truncated toward
/// zero (numpy's astype(int), so 1.16 m is cell 28 at 25 cells per metre: 1.16 * 25 rounds
/// below 29), shifted so the smallest x and y are 0, then filled as cv2.drawContours fills
/// (polygon_fill.hpp). The map is the contour's bounding box plus a border of one wall cell
/// (PseudoSLAM pads 25 pixels; outside the grid is a wall here anyway). Other keys are not
/// read. A plan has no start; the map's start is region_centre_cell() of largest_free_region()
/// without corner cutting (the default motion rule, whose regions are the 4-connected ones): the
/// cell nearest the centroid of the largest free region, ties to the lowest row, then column.
/// Errors name the file and the JSON path (a vertex that is not two finite numbers, fewer than 3
/// vertices, a grid over 10^8 cells) or a plan without free cells.
[[nodiscard]] WorldMap load_houseexpo(const std::string& path, double resolution_m = kHouseExpoResolution);

/// One MovingAI scenario query.
struct ScenarioQuery {
  int bucket = 0;
  std::string map_name;  // the file's map field, as written
  int map_width = 0;
  int map_height = 0;
  Cell start;
  Cell goal;
  /// Optimal octile length (no corner cutting); 0 in GPPC files means unreachable.
  double optimal_length = 0.0;
};

/// Reads a `.scen` file (`version 1` header, 9 tab-separated fields per row).
[[nodiscard]] std::vector<ScenarioQuery> load_scenario(const std::string& path);

}  // namespace world
}  // namespace fsweep
