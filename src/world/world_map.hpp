#pragma once
/// @file world_map.hpp
/// Ground truth: which cells are free and which are occupied.

#include <cstdint>
#include <string>

#include "world/grid.hpp"

namespace fsweep {
inline namespace world {

/// Ground-truth occupancy of one map. Cells outside the grid count as occupied.
struct WorldMap {
  /// 1 = occupied, 0 = free.
  Grid<std::uint8_t> occupied;
  /// Edge length of one square cell (metres), > 0.
  double resolution_m = 1.0;
  /// Where the robot starts and (by default) where the dock is. Always a free cell.
  Cell start{0, 0};
  /// Human-readable origin: a file path or a generator spec.
  std::string source;

  [[nodiscard]] int width() const { return occupied.width(); }
  [[nodiscard]] int height() const { return occupied.height(); }
  [[nodiscard]] bool is_free(Cell c) const { return occupied.in_bounds(c) && occupied.at(c) == 0; }
  [[nodiscard]] bool is_free(int index) const { return occupied[index] == 0; }
  /// Number of free cells in the whole grid.
  [[nodiscard]] int free_count() const;
};

/// FNV-1a 64 (core/random.hpp) of what a run sees of the map: the text "W H RESOLUTION X Y"
/// (size, resolution_m with 17 significant digits, start), then one byte per cell, row-major
/// (1 = occupied). Not the source: the same grid from another file or spec hashes the same, an
/// edited file differently. Run keys cover it (sweep_plan.hpp).
[[nodiscard]] std::uint64_t content_hash(const WorldMap& map);

/// Free cells reachable from `from` by 8-connected moves (no corner cutting unless
/// `allow_corner_cutting`). Result: 1 for reachable cells, 0 otherwise. `from` must be free
/// (an occupied or outside `from` gives an all-zero grid).
[[nodiscard]] Grid<std::uint8_t> reachable_free(const WorldMap& map, Cell from,
                                                bool allow_corner_cutting = false);

/// The largest region of free cells connected by 8-connected moves (the motion rule of
/// reachable_free()); of equal regions, the one holding the lowest cell index. 1 for its cells.
/// All zero on a map without free cells.
[[nodiscard]] Grid<std::uint8_t> largest_free_region(const WorldMap& map, bool allow_corner_cutting = false);

/// A cell drawn uniformly from the cells of `region` that are 1 (row-major order; the k-th of
/// them for k drawn from stream "map/start" of `seed`, core/random.hpp). {-1, -1} when none is.
/// A map's `start: "random"` (map_spec.hpp) draws with the run seed from largest_free_region().
[[nodiscard]] Cell draw_region_cell(const Grid<std::uint8_t>& region, std::uint64_t seed);

/// The cell of `region` (cells that are 1) nearest (Euclidean) the centroid of its cells, the
/// mean of their x and of their y; of equally near cells the lowest index (row, then column).
/// Exact: distances are compared as integers scaled by the cell count. A region that bends
/// around its centroid (an L, a ring) gets a cell of its own, not the centroid's. {-1, -1} when
/// no cell is 1. HouseExpo plans start here in their largest free region (load_houseexpo()).
[[nodiscard]] Cell region_centre_cell(const Grid<std::uint8_t>& region);

/// The first free cell in row-major order nearest (Euclidean, ties by index) to `near`;
/// used by generators that must guarantee a free start. Returns {-1,-1} when no cell is free.
[[nodiscard]] Cell nearest_free_cell(const WorldMap& map, Cell near);

}  // namespace world
}  // namespace fsweep
