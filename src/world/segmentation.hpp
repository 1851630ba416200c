#pragma once
/// @file segmentation.hpp
/// Room segmentation of the known free space, for the `seg` heuristic (Holz, Basilico, Amigoni
/// 2010, section IV-D2; src/sim/heuristics.hpp).
///
/// The paper splits the free space at critical points of its Voronoi diagram (Thrun 1998):
/// points of the medial axis where the clearance (distance to the nearest obstacle) has a
/// local minimum, i.e. doorways. This is the equivalent distance-transform form (Bormann et
/// al. 2016, "distance segmentation"): a door is a neck where the clearance drops below a
/// threshold t, so the free cells with clearance > t fall apart into one core per room; every
/// other free cell joins the core its clearance rises to. t is chosen per map, without
/// parameters, as the value that separates the most rooms. Precisely, on the cells of a
/// KnownMap (cells outside the grid count as occupied, unknown cells as not occupied):
///
/// 1. Clearance D(c) of every cell: Euclidean distance (cells) from its centre to the nearest
///    occupied cell centre (exact distance transform, Felzenszwalb & Huttenlocher 2012).
/// 2. Connectivity between known free cells: 8-neighbours, a diagonal one only when neither
///    cell beside the diagonal is occupied (the robot's motion rule without corner cutting).
/// 3. Cores at threshold t: the connected components of the known free cells with D > t. A
///    core is a room core when its peak clearance exceeds 1.5 t (a wall niche or the bulge of
///    a corridor in front of a door is not). For each integer t = 1 .. floor(max D) the room
///    cores are counted; t* is the t with the most (ties: the smallest t); none when no t has
///    any (then step 4 is skipped).
/// 4. Each room core at t* is a segment. The other known free cells, in order of decreasing
///    clearance (ties: ascending cell index), join the segment of their highest connected
///    neighbour earlier in that order (ties: a neighbour in a segment, then the lowest
///    index); a cell with no such neighbour in a segment is left over (it lies below a peak
///    that is no room: a corridor, a narrow passage). So doorways go to a room, not beyond.
/// 5. Left-over cells form connected components. A component of at least (2 t* + 1)^2 cells
///    (a corridor) becomes a segment of its own; smaller ones join the segments around them
///    (breadth-first from every labelled cell, in index order), and become segments of their
///    own when none touches them.
///
/// Segment ids are 0 .. count - 1 in order of creation (room cores by their peak in the order
/// of step 4, then left-over components by their lowest cell index). Deterministic.
/// Cost O(N log N) for N cells (a sort by clearance); recompute it as the map grows.

#include <cstdint>
#include <string>
#include <vector>

#include "world/known_map.hpp"

namespace fsweep {
inline namespace world {

/// A segmentation of a map's known free cells.
struct Segmentation {
  /// Per cell index: the segment id (0 .. count - 1) of a known free cell, -1 for other cells.
  std::vector<int> label;
  /// Number of segments.
  int count = 0;
  /// Per segment id: 1 for a room (grown from a room core, step 4), 0 for a left-over
  /// component (step 5: a corridor or passage, or a bit of space with no room core).
  std::vector<std::uint8_t> room;
  /// The threshold t* of step 3 (cells); 0 when there was no room core.
  int threshold_cells = 0;
};

/// Segments the known free cells of `known` (algorithm above).
[[nodiscard]] Segmentation segment_free_space(const KnownMap& known);

/// Writes a PNG picture of `s` over `known`: each room segment in its own colour (a hash of
/// its id), left-over segments in pale shades of grey-blue, occupied cells black, unknown cells
/// dark grey. Each cell is `scale` x `scale` pixels (>= 1). Throws IoError (core/io_error.hpp)
/// naming the file and the OS error when it cannot be written.
void write_segments_png(const std::string& path, const KnownMap& known, const Segmentation& s, int scale = 2);

/// Squared clearance of every cell of `known` (step 1, in cells^2; 0 on occupied cells).
[[nodiscard]] std::vector<long long> squared_clearance(const KnownMap& known);

}  // namespace world
}  // namespace fsweep
