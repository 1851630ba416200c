#include "strategies/sensing_region.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <unordered_set>

#include "world/sensor.hpp"

namespace fsweep {
inline namespace strategies {

std::vector<int> open_frontier_cells(const Observation& obs) {
  std::vector<int> cells;
  for (const auto& c : obs.clusters) cells.insert(cells.end(), c.cells.begin(), c.cells.end());
  std::sort(cells.begin(), cells.end());
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  return cells;
}

namespace {

/// Whether unknown cells belong to enclosed pockets of at most `limit` cells, memoised per
/// component for one decision.
class PocketTest {
 public:
  PocketTest(const KnownMap& known, int limit) : known_(known), limit_(limit) {}

  /// True when unknown cell `index` lies in an 8-connected component of unknown cells of at
  /// most limit_ cells (a walk that stops once it has found more).
  bool small(int index) {
    if (const auto it = pocket_of_.find(index); it != pocket_of_.end()) return it->second;
    std::vector<int> component{index};
    std::unordered_set<int> seen{index};
    bool small = true;
    for (std::size_t k = 0; k < component.size() && small; ++k) {
      const Cell c = known_.cell(component[k]);
      for (const Cell d : kDirections) {
        const Cell n{c.x + d.x, c.y + d.y};
        if (!known_.in_bounds(n) || known_.state(n) != CellState::Unknown) continue;
        const int ni = known_.index(n);
        if (!seen.insert(ni).second) continue;
        component.push_back(ni);
        if (static_cast<int>(component.size()) > limit_) {
          small = false;
          break;
        }
      }
    }
    // A walk cut short has not seen its whole component: remember only the cells it saw.
    for (const int i : component) pocket_of_[i] = small;
    return small;
  }

 private:
  const KnownMap& known_;
  int limit_;
  std::unordered_map<int, bool> pocket_of_;
};

/// True when every unknown 8-neighbour of frontier cell `index` lies in a small pocket.
bool borders_only_pockets(const KnownMap& known, int index, PocketTest& pockets) {
  const Cell c = known.cell(index);
  for (const Cell d : kDirections) {
    const Cell n{c.x + d.x, c.y + d.y};
    if (known.in_bounds(n) && known.state(n) == CellState::Unknown && !pockets.small(known.index(n))) {
      return false;
    }
  }
  return true;
}

}  // namespace

SensingRegion split_by_sensing_region(const Observation& obs, const SensingRegionRule& rule) {
  SensingRegion r;
  const double d_s = obs.sensor.range_m / obs.known.resolution_m();
  const double d_s2 = d_s * d_s + 1e-9;  // inclusive boundary, as the sensor's (sensor.hpp)
  const bool in_view_only = rule.region == "visible";
  PocketTest pockets(obs.known, rule.pocket_cells);
  std::vector<int> near;
  for (const int i : open_frontier_cells(obs)) {
    const Cell c = obs.known.cell(i);
    const double dx = c.x - obs.robot.x;
    const double dy = c.y - obs.robot.y;
    const bool in_region = dx * dx + dy * dy <= d_s2 &&
                           (!in_view_only || centre_ray_clear(obs.known, obs.robot, c)) &&
                           (rule.pocket_cells == 0 || !borders_only_pockets(obs.known, i, pockets));
    (in_region ? near : r.outside).push_back(i);
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
