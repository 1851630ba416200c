#include "strategies/widest_frontier.hpp"

#include <algorithm>
#include <limits>
#include <nlohmann/json.hpp>

#include "core/config_error.hpp"
#include "strategies/sensing_region.hpp"

namespace fsweep {
inline namespace strategies {

std::vector<std::vector<int>> frontier_groups(const KnownMap& known, std::span<const int> cells) {
  std::vector<std::vector<int>> groups;
  std::vector<char> placed(cells.size(), 0);
  auto position = [&](int index) -> std::ptrdiff_t {
    const auto it = std::lower_bound(cells.begin(), cells.end(), index);
    return it != cells.end() && *it == index ? it - cells.begin() : -1;
  };
  for (std::size_t seed = 0; seed < cells.size(); ++seed) {
    if (placed[seed] != 0) continue;
    std::vector<int> group{cells[seed]};
    placed[seed] = 1;
    // Breadth-first over 8-neighbours that are in `cells`.
    for (std::size_t k = 0; k < group.size(); ++k) {
      const Cell c = known.cell(group[k]);
      for (const Cell d : kDirections) {
        const Cell n{c.x + d.x, c.y + d.y};
        if (!known.in_bounds(n)) continue;
        const std::ptrdiff_t p = position(known.index(n));
        if (p < 0 || placed[static_cast<std::size_t>(p)] != 0) continue;
        placed[static_cast<std::size_t>(p)] = 1;
        group.push_back(known.index(n));
      }
    }
    std::sort(group.begin(), group.end());
    groups.push_back(std::move(group));
  }
  return groups;
}

int middle_cell(const KnownMap& known, std::span<const int> group) {
  double cx = 0.0;
  double cy = 0.0;
  for (const int i : group) {
    cx += known.cell(i).x;
    cy += known.cell(i).y;
  }
  cx /= static_cast<double>(group.size());
  cy /= static_cast<double>(group.size());
  int best = -1;
  double best_d2 = std::numeric_limits<double>::infinity();
  for (const int i : group) {  // ascending: strict < keeps the lowest index on ties
    const double dx = known.cell(i).x - cx;
    const double dy = known.cell(i).y - cy;
    const double d2 = dx * dx + dy * dy;
    if (d2 < best_d2 - 1e-12) {
      best_d2 = d2;
      best = i;
    }
  }
  return best;
}

ParamDecl<WidestFrontierParams> widest_frontier_params() {
  ParamDecl<WidestFrontierParams> d;
  declare_sensing_region_params(d);
  return d;
}

Decision WidestFrontier::decide(const Observation& obs) {
  SensingRegion region = split_by_sensing_region(obs, params_);  // 1
  restrict_to_segment(obs, region);  // the `seg` heuristic, when on (src/sim/heuristics.hpp)
  if (region.inside.empty()) return closest_outside(obs, region.outside);  // 4
  const auto groups = frontier_groups(obs.known, region.inside);           // 2
  std::size_t widest = 0;
  for (std::size_t g = 1; g < groups.size(); ++g) {
    if (groups[g].size() > groups[widest].size()) widest = g;  // ties: the earlier group
  }
  return Decision::go_to(obs.known.cell(middle_cell(obs.known, groups[widest])));  // 3
}

}  // namespace strategies
}  // namespace fsweep
