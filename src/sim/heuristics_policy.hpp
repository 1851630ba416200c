#pragma once
/// @file heuristics_policy.hpp
/// The heuristics part of a Simulation (src/strategies/heuristics.hpp; the rules in
/// simulation.hpp): which heuristics are on, and the state of `seg` (the segmentation of the
/// known map, recomputed as the map grows, and the mask of the robot's segment). A value.

#include <cstdint>
#include <memory>
#include <vector>

#include "sim/heuristics.hpp"
#include "world/frontiers.hpp"
#include "world/known_map.hpp"
#include "world/segmentation.hpp"

namespace fsweep {
inline namespace sim {

/// What the `seg` heuristic did to one decision's candidates.
struct SegmentRestriction {
  /// One flag per cell of the robot's segment, for Observation::segment_mask; null when
  /// nothing was restricted. Valid until the next restrict_to_segment().
  const std::vector<std::uint8_t>* mask = nullptr;
  /// The clusters whose representative lies in that segment; null when nothing was
  /// restricted. Valid until the next restrict_to_segment().
  const std::vector<FrontierCluster>* clusters = nullptr;
  /// Time spent segmenting the known map for this decision (seconds; 0 when the cached
  /// segmentation was still current).
  double segmentation_time_s = 0.0;
};

class HeuristicsPolicy {
 public:
  HeuristicsPolicy() = default;
  explicit HeuristicsPolicy(const Heuristics& heuristics) : heuristics_(heuristics) {}

  [[nodiscard]] const Heuristics& heuristics() const { return heuristics_; }

  /// `seg`: when the robot's segment is a room holding the representative of some cluster,
  /// returns such clusters of `clusters` and the segment's mask; otherwise nothing (null mask
  /// and clusters). Segments `known` again when it changed since the last call. Without
  /// `seg`: nothing.
  SegmentRestriction restrict_to_segment(const KnownMap& known, Cell robot,
                                         const std::vector<FrontierCluster>& clusters);

  /// `rr`: whether a journey to `goal` should go on, on the current map (the rule in
  /// simulation.hpp). `goal_was_frontier`: the goal was a frontier cell when chosen.
  /// `range_cells`: the sensor range in cells.
  [[nodiscard]] static bool goal_still_open(const KnownMap& known, const FrontierMap& frontiers, Cell goal,
                                            bool goal_was_frontier, double range_cells);

 private:
  Heuristics heuristics_;
  /// The last segmentation (null before the first) and KnownMap::known_count() when it was
  /// made. Shared between forks until one of them segments again: never changed in place.
  std::shared_ptr<const Segmentation> segmentation_;
  int segmented_known_count_ = -1;
  std::vector<std::uint8_t> segment_mask_;
  std::vector<FrontierCluster> segment_clusters_;
};

}  // namespace sim
}  // namespace fsweep
