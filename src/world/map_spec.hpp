#pragma once
/// @file map_spec.hpp
/// A map SPEC names a map source in one string, as on the command line:
/// - a file path: `.map` (MovingAI), `.yaml` (ROS map_server), `.png`/`.pgm` (bitmap),
///   `.txt` (ASCII), `.json` (a HouseExpo floor plan, map_loaders.hpp), optionally followed by
///   `:key=value,...` options
///   (`res=0.5`, `start=x;y`, bitmap: `threshold=127`, `mpp=0.05` or `size=40x18`);
/// - a generator: `KIND:key=value,...`, e.g. `rooms:w=120,h=80,door=3,seed=4`
///   (keys: w, h, res, seed, border, p, door, min_room, wall, block, street, corridor,
///   squares, lane, start=x;y).
/// The same sources are accepted as JSON objects in sweeps: {"generator": "rooms", "w": 120}
/// or {"file": "maps/x.map", "res": 0.5}; there `start` may be [x, y] or "x;y", `size` [w, h]
/// or "WxH", `border` true/false (or 1/0).
///
/// Details:
/// - A source containing '.' or '/' is a file (paths must not contain ':'), else a generator kind.
/// - Keys each source accepts: generators w, h, res, seed, start plus their own (free: border,
///   wall; random: border, wall, p; rooms: door, min_room, wall; office: door, min_room, wall,
///   corridor; manhattan: block, street; oldtown: squares, lane); `.map`/`.txt`: res, start;
///   `.json`: res (default HouseExpo's 0.04 m), start;
///   `.yaml`/`.yml`: start (resolution from the YAML); `.png`/`.pgm`: res, start, threshold,
///   mpp, size. Integers must be integers; nothing is rounded or clamped.
/// - Bitmaps: threshold defaults to 127 (Stage). With `mpp` or `size`, `res` is the cell size
///   to resample to (max-pooling; omitted: one pixel per cell, pixels must be square). With
///   neither, one pixel is one cell of `res` metres (default 1).
/// - `start` overrides the source's start (generators: their default; HouseExpo plans: the cell
///   nearest the centre of their largest free region, load_houseexpo(); other files: the first
///   free cell in row-major order); it must be a free cell inside the grid, or "random" where
///   runs draw their own start (load_run_map_spec()).
/// - Errors from loaders and generators are rethrown with the spec (or JSON path) in front.

#include <nlohmann/json_fwd.hpp>
#include <string>

#include "world/world_map.hpp"

namespace fsweep {
inline namespace world {

/// Loads or generates the map a SPEC string names. Throws ConfigError naming the spec, the
/// bad key and the allowed keys/values; a start cell inside an obstacle is an error naming
/// the cell.
[[nodiscard]] WorldMap load_map_spec(const std::string& spec);

/// The JSON object form of a SPEC string, as load_map_spec() reads it: "file" (a source with '.'
/// or '/') or "generator" is the part before the first ':', then one key per key=value option,
/// its value an integer, a number, true/false or else the text. Throws ConfigError naming the
/// spec for an empty source, an option without '=' or a repeated or reserved key.
[[nodiscard]] nlohmann::json map_spec_object(const std::string& spec);

/// The same from a JSON object (sweep files); `where` is its JSON path for messages.
[[nodiscard]] WorldMap load_map_json(const nlohmann::json& j, const std::string& where);

/// A map as runs use it: the map, and whether each run draws its own start cell.
struct RunMap {
  WorldMap map;
  /// The source said `start: "random"` (`start=random` in a SPEC string): each run draws its
  /// start with draw_region_cell() from its run seed over largest_free_region() of its motion
  /// rule (world_map.hpp). map.start is then the loader's default start, unused by runs.
  bool random_start = false;
};

/// load_map_spec() and load_map_json() that also accept `start: "random"` (those two refuse it,
/// naming where random starts are allowed: sweeps and `fsweep sim`).
[[nodiscard]] RunMap load_run_map_spec(const std::string& spec);
[[nodiscard]] RunMap load_run_map_json(const nlohmann::json& j, const std::string& where);

}  // namespace world
}  // namespace fsweep
