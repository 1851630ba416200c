#pragma once
/// @file sensing_region.hpp
/// The frontier cells inside and outside the robot's current sensing region, shared by the
/// two target-selection rules of Mei 2006 (orientation, section IV-B; widest frontier,
/// section V-C).

#include <vector>

#include "strategies/strategy.hpp"

namespace fsweep {
inline namespace strategies {

/// Frontier cells of one decision split by the sensing region (cell indices, ascending).
struct SensingRegion {
  /// Reachable frontier cells whose centre lies within d_s of the robot's centre (Euclidean,
  /// inclusive), d_s = sensor.range_m / resolution_m in cells. The robot's own cell included.
  std::vector<int> inside;
  /// Frontier cells beyond d_s (reachability not checked: see closest_outside()).
  std::vector<int> outside;
};

/// The frontier cells a strategy may choose: the members of obs.clusters, i.e. every frontier
/// cell of obs.frontiers except those the engine has dropped as unobservable or unreachable
/// goals (clusters are a partition of exactly those cells). Ascending cell indices.
[[nodiscard]] std::vector<int> open_frontier_cells(const Observation& obs);

/// Splits open_frontier_cells(obs) by the sensing region (Mei 2006 section IV-B step 1).
/// In-region cells that the robot cannot reach over known free space (obs.distances, no
/// bound) are treated as absent: they are in neither list.
[[nodiscard]] SensingRegion split_by_sensing_region(const Observation& obs);

/// Mei 2006 section IV-B steps 4 and 5 (and the same rule in section V-C): the frontier cell of
/// `outside` nearest to the robot by path length (obs.distances.nearest_from_robot; ties: the
/// lowest index), or Decision::finish() when none is reachable.
[[nodiscard]] Decision closest_outside(const Observation& obs, const std::vector<int>& outside);

/// For the sensing-region rules of orientation and widest_frontier (which read frontier cells
/// rather than obs.clusters): when obs.segment_mask is set (the `seg` heuristic restricts this
/// decision, src/sim/heuristics.hpp), keeps in `region.inside` and `region.outside` only the
/// cells of the robot's segment, unless none of either list is in it; then, and when the mask
/// is null, leaves `region` unchanged. Order is kept.
void restrict_to_segment(const Observation& obs, SensingRegion& region);

}  // namespace strategies
}  // namespace fsweep
