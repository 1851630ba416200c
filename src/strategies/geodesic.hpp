#pragma once
/// @file geodesic.hpp
/// Geodesic distances on the grid and the geodesic Hausdorff distance (Arvanitakis,
/// Giannousakis, Tzes, "Mobile Robot Navigation in Unknown Environment based on Exploration
/// Principles", section II-A, Definition 1), for the `target_seeking` strategy.
///
/// A geodesic here is a shortest 8-connected cell path inside a set of cells (a flag per cell),
/// with octile step costs (1 cell orthogonally, sqrt(2) diagonally). A diagonal step needs at
/// least one of the two cells beside it in the set: a path never squeezes between two cells
/// outside the set. (For the unknown region this is the frontier rule of frontiers.hpp: a
/// diagonal between two unknown cells is sealed only when both cells beside it are known
/// occupied, because a known free cell beside it would be a frontier cell and so in the set.)

#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "world/frontiers.hpp"
#include "world/grid.hpp"
#include "world/known_map.hpp"

namespace fsweep {
inline namespace strategies {

/// Geodesic distances (metres) from the nearest of `sources` (cell indices of `inside`) to
/// every cell, through the cells flagged non-zero in `inside`; +infinity for cells not flagged
/// or not connected. Sources outside the grid or not flagged are ignored. Dijkstra (the generic
/// search of src/search/grid_search.hpp), O(n log n) in the flagged cells.
[[nodiscard]] std::vector<double> geodesic_distances(const Grid<std::uint8_t>& inside,
                                                     std::span<const int> sources, double resolution_m);

/// Geodesic distances with, per cell, the source it is nearest to.
struct GeodesicField {
  /// Metres; +infinity where not connected (as geodesic_distances()).
  std::vector<double> distance_m;
  /// The cell index of the nearest source; -1 where not connected. Ties between sources go to
  /// the one whose path reaches the cell first in the search (BestFirstSearch settles by
  /// distance, then cell index; a cell keeps the first parent that reached it at its final cost).
  std::vector<int> nearest_source;
};

/// geodesic_distances() plus the nearest source of every cell.
[[nodiscard]] GeodesicField geodesic_field(const Grid<std::uint8_t>& inside, std::span<const int> sources,
                                           double resolution_m);

/// The region the paper calls A-bar (section III-B): the complement of the known area plus its
/// free boundary, i.e. every unknown cell and every frontier cell, flagged 1.
[[nodiscard]] Grid<std::uint8_t> unknown_region(const KnownMap& known, const FrontierMap& frontiers);

/// The known free cells, flagged 1: the paper's explored space A, where the robot moves.
[[nodiscard]] Grid<std::uint8_t> known_free_cells(const KnownMap& known);

/// Definition 1: H_g(p, B) = min over q in B of d_g(p, q), read from `field` (the output of
/// geodesic_distances() with source p): the smallest field[q] over the cell indices q in `set`.
/// +infinity for an empty set or when no member is connected.
[[nodiscard]] double geodesic_hausdorff(std::span<const double> field, std::span<const int> set);

}  // namespace strategies
}  // namespace fsweep
