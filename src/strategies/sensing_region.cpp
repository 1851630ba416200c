#include "strategies/sensing_region.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fsweep {
inline namespace strategies {

std::vector<int> open_frontier_cells(const Observation& obs) {
  std::vector<int> cells;
  for (const auto& c : obs.clusters) cells.insert(cells.end(), c.cells.begin(), c.cells.end());
  std::sort(cells.begin(), cells.end());
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  return cells;
}

SensingRegion split_by_sensing_region(const Observation& obs) {
  SensingRegion r;
  const double d_s = obs.sensor.range_m / obs.known.resolution_m();
  const double d_s2 = d_s * d_s + 1e-9;  // inclusive boundary, as the sensor's (sensor.hpp)
  std::vector<int> near;
  for (const int i : open_frontier_cells(obs)) {
    const Cell c = obs.known.cell(i);
    const double dx = c.x - obs.robot.x;
    const double dy = c.y - obs.robot.y;
    (dx * dx + dy * dy <= d_s2 ? near : r.outside).push_back(i);
  }
  if (near.empty()) return r;
  const std::vector<double> d = obs.distances.from_robot(near, std::numeric_limits<double>::infinity());
  for (std::size_t k = 0; k < near.size(); ++k) {
    if (std::isfinite(d[k])) r.inside.push_back(near[k]);
  }
  return r;
}

Decision closest_outside(const Observation& obs, const std::vector<int>& outside) {
  const int best = obs.distances.nearest_from_robot(outside);
  if (best < 0) return Decision::finish();
  return Decision::go_to(obs.known.cell(outside[static_cast<std::size_t>(best)]));
}

void restrict_to_segment(const Observation& obs, SensingRegion& region) {
  if (obs.segment_mask == nullptr) return;
  const auto& mask = *obs.segment_mask;
  const auto in_segment = [&](int i) { return mask[static_cast<std::size_t>(i)] != 0; };
  if (std::none_of(region.inside.begin(), region.inside.end(), in_segment) &&
      std::none_of(region.outside.begin(), region.outside.end(), in_segment)) {
    return;
  }
  std::erase_if(region.inside, [&](int i) { return !in_segment(i); });
  std::erase_if(region.outside, [&](int i) { return !in_segment(i); });
}

}  // namespace strategies
}  // namespace fsweep
