#include "sim/heuristics_policy.hpp"

#include <algorithm>
#include <chrono>
#include <iterator>

namespace fsweep {
inline namespace sim {

SegmentRestriction HeuristicsPolicy::restrict_to_segment(const KnownMap& known, Cell robot,
                                                         const std::vector<FrontierCluster>& clusters) {
  SegmentRestriction out;
  if (!heuristics_.segment) return out;
  if (known.known_count() != segmented_known_count_) {
    const auto t0 = std::chrono::steady_clock::now();
    segmentation_ = std::make_shared<const Segmentation>(segment_free_space(known));
    segmented_known_count_ = known.known_count();
    out.segmentation_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  const Segmentation& s = *segmentation_;
  const int mine = s.label[static_cast<std::size_t>(known.index(robot))];
  const auto in_mine = [&](int i) { return s.label[static_cast<std::size_t>(i)] == mine; };
  // The candidate of a cluster is its representative (the goal strategies choose).
  const auto inside = [&](const FrontierCluster& c) { return in_mine(c.representative); };
  // Only inside a room: the corridors of a building form one left-over segment, and keeping
  // the robot in it would explore every corridor before any room (section IV-D2 wants rooms
  // one by one).
  if (mine < 0 || s.room[static_cast<std::size_t>(mine)] == 0 ||
      std::none_of(clusters.begin(), clusters.end(), inside)) {
    return out;
  }
  segment_clusters_.clear();
  std::copy_if(clusters.begin(), clusters.end(), std::back_inserter(segment_clusters_), inside);
  out.clusters = &segment_clusters_;
  segment_mask_.assign(s.label.size(), 0);
  for (std::size_t i = 0; i < segment_mask_.size(); ++i) segment_mask_[i] = s.label[i] == mine ? 1 : 0;
  out.mask = &segment_mask_;
  return out;
}

bool HeuristicsPolicy::goal_still_open(const KnownMap& known, const FrontierMap& frontiers, Cell goal,
                                       bool goal_was_frontier, double range_cells) {
  if (goal_was_frontier) return frontiers.is_frontier(known.index(goal));
  const double r2 = range_cells * range_cells * (1.0 + 1e-9) + 1e-9;  // inclusive, as the sensor's range
  for (const int i : frontiers.cells()) {
    const Cell c = known.cell(i);
    const double dx = c.x - goal.x;
    const double dy = c.y - goal.y;
    if (dx * dx + dy * dy <= r2) return true;
  }
  return false;
}

}  // namespace sim
}  // namespace fsweep
