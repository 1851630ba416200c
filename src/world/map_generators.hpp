#pragma once
/// @file map_generators.hpp
/// Seeded, deterministic map generators. Every generated map has a free start cell; all sizes
/// are in cells, and the resolution is set by the caller.
///
/// Randomness comes only from `make_rng(seed, "map")` through `uniform01` / `uniform_below`
/// and integer or correctly rounded arithmetic (no std distributions, no sin/cos/hypot), so a
/// (params, seed) pair gives the same map bit for bit on every platform.
///
/// Kinds and the parameters each reads (besides width, height, resolution_m, seed, start):
/// - `free`: no obstacles; with `border` an occupied frame `wall` cells thick.
/// - `random`: every cell independently occupied with probability `obstacle_probability`
///   (drawn in row-major order over the whole grid), then the `border` frame of `wall` cells.
///   No connectivity is guaranteed; the default start lies in the largest free component.
/// - `rooms`: recursive division. An occupied frame `wall` thick encloses one room; a room is
///   split by a wall `wall` thick (across its longer side; random side on squares) at a random
///   position that leaves at least `min_room` cells on both sides, and the wall gets one door
///   of `door` cells at a random place. A wall never ends at an existing door. Leaf rooms have
///   sides >= min_room (and < 2 * min_room + wall unless doors block every split position).
///   Needs 1 <= door <= min_room and width, height >= min_room + 2 * wall.
/// - `office`: horizontal corridors `corridor` wide across the map, each with a band of rooms
///   above and below (depth >= `min_room`; widths drawn in [min_room, 2 * min_room], the last
///   room of a row taking the rest, < 2 * min_room + wall; walls `wall` thick); every room has
///   one door of `door` cells onto its corridor; one vertical corridor (at a random column)
///   joins all corridors. Needs height >= 2 * min_room + corridor + 4 * wall,
///   width >= 2 * min_room + corridor + 4 * wall, 1 <= door <= min_room.
/// - `manhattan`: a street grid: square blocks `block` cells wide separated by streets `street`
///   cells wide, with a street crossing at the map centre; blocks at the map edges are clipped.
///   Each block is a park (free) with probability `parks` (default 0.1), a building cut
///   through by an alley max(1, street / 2) wide (random direction and offset) with probability
///   `alleys` (default 0.35; when block >= alley + 2, else a plain building), else a plain
///   building. Needs width, height >= block + 2 * street and parks + alleys <= 1. Every block
///   draws the same random numbers whatever the shares, so maps of one seed differ only where
///   the shares make them differ.
/// - `oldtown`: inside a one-cell occupied frame, `squares` open squares (sides in
///   [3 * lane, 6 * lane], clipped to the map) and one waypoint per tile of a jittered grid
///   (tiles 6 * lane wide, grown to keep at most 2000 waypoints); a Euclidean minimum spanning
///   tree over square centres and waypoints, plus extra edges for loops (each waypoint joins
///   its nearest not yet joined one with probability 0.25), is carved as winding lanes `lane`
///   cells wide (random midpoint displacement up to 0.2 of a segment's length down to segments
///   of 4 * lane, drawn as 4-connected strokes). Needs width, height >= 3 * lane + 2.
///
/// Connectivity guarantee (8-connected moves without corner cutting): for rooms, office,
/// manhattan, oldtown and free every free cell is reachable from the start. For random none.
/// Default start (start_x, start_y < 0): the free cell nearest the centre (width / 2,
/// height / 2), ties by lowest index, among the cells of the largest free component.

#include <cstdint>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/registry.hpp"
#include "world/world_map.hpp"

namespace fsweep {
inline namespace world {

/// Parameters common to all generators plus each generator's own (unused ones are ignored by
/// the generators that do not read them; map_spec validates which keys a kind accepts).
struct GeneratorParams {
  std::string kind = "free";  // free | random | rooms | office | manhattan | oldtown
  int width = 100;            // cells
  int height = 100;           // cells
  double resolution_m = 1.0;  // metres per cell
  std::uint64_t seed = 0;
  bool border = true;                 // occupied frame around the map (free, random)
  double obstacle_probability = 0.2;  // random: each cell occupied with this probability
  int door = 3;                       // rooms, office: door width (cells)
  int min_room = 12;                  // rooms: rooms are not split below this size; office: room depth
                                      // and least room width (cells)
  int wall = 1;                       // wall thickness (cells): free/random frame, rooms, office
  int block = 20;                     // manhattan: building block edge (cells)
  int street = 6;                     // manhattan: street width (cells)
  double park_share = 0.1;            // manhattan: probability that a block is a park
  double alley_share = 0.35;          // manhattan: probability that a block is a building with an alley
  int corridor = 4;                   // office: corridor width (cells)
  int squares = 4;                    // oldtown: number of open squares
  int lane = 3;                       // oldtown: narrow street width (cells)
  /// Start cell; negative: the generator's default (documented per kind, centre for free space).
  int start_x = -1;
  int start_y = -1;
};

/// Generates a map. Throws ConfigError for out-of-range parameters (message naming the
/// parameter by its spec key and the allowed range), for an unknown kind (listing the kinds),
/// for an explicit start outside the grid or on an occupied cell (naming the cell) and when no
/// cell is free. Dimensions: 1..65536 cells each, at most 10^8 cells in all.
[[nodiscard]] WorldMap generate_map(const GeneratorParams& params);

/// The generator kinds generate_map accepts, in documentation order.
[[nodiscard]] std::vector<std::string> generator_kinds();

/// The generators as plugins (core/registry.hpp): each kind with its declared map-spec keys
/// (w, h, res, seed, start and the kind's own); the maker calls generate_map().
using GeneratorRegistry = Registry<WorldMap>;
[[nodiscard]] const GeneratorRegistry& generator_registry();

/// A cell from [x, y] or "x;y" (non-negative integers up to 10^9); nothing for anything else.
[[nodiscard]] std::optional<Cell> parse_cell_pair(const nlohmann::json& v);

}  // namespace world
}  // namespace fsweep
