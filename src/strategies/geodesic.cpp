#include "strategies/geodesic.hpp"

#include <functional>
#include <queue>
#include <utility>

namespace fsweep {
inline namespace strategies {

std::vector<double> geodesic_distances(const Grid<std::uint8_t>& inside, std::span<const int> sources,
                                       double resolution_m) {
  return geodesic_field(inside, sources, resolution_m).distance_m;
}

GeodesicField geodesic_field(const Grid<std::uint8_t>& inside, std::span<const int> sources,
                             double resolution_m) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  GeodesicField out;
  std::vector<double>& dist = out.distance_m;
  std::vector<int>& from = out.nearest_source;
  dist.assign(static_cast<std::size_t>(inside.size()), kInf);
  from.assign(static_cast<std::size_t>(inside.size()), -1);
  using Item = std::pair<double, int>;  // (distance in cells, index)
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  for (const int s : sources) {
    if (s < 0 || s >= inside.size() || inside[s] == 0) continue;
    if (dist[static_cast<std::size_t>(s)] == 0.0) continue;  // listed twice
    dist[static_cast<std::size_t>(s)] = 0.0;
    from[static_cast<std::size_t>(s)] = s;
    open.emplace(0.0, s);
  }
  const auto in_set = [&](Cell c) { return inside.in_bounds(c) && inside.at(c) != 0; };
  while (!open.empty()) {
    const auto [d, i] = open.top();
    open.pop();
    if (d > dist[static_cast<std::size_t>(i)]) continue;  // a stale entry
    const Cell c = inside.cell(i);
    for (int h = 0; h < 8; ++h) {
      const Cell step = kDirections[static_cast<std::size_t>(h)];
      const Cell n{c.x + step.x, c.y + step.y};
      if (!in_set(n)) continue;
      // A diagonal needs one of the two cells beside it in the set.
      if ((h & 1) != 0 && !in_set(Cell{c.x + step.x, c.y}) && !in_set(Cell{c.x, c.y + step.y})) continue;
      const double nd = d + step_length(h);
      const int ni = inside.index(n);
      if (nd < dist[static_cast<std::size_t>(ni)]) {
        dist[static_cast<std::size_t>(ni)] = nd;
        from[static_cast<std::size_t>(ni)] = from[static_cast<std::size_t>(i)];
        open.emplace(nd, ni);
      }
    }
  }
  for (double& v : dist) v *= resolution_m;  // infinity stays infinity
  return out;
}

Grid<std::uint8_t> unknown_region(const KnownMap& known, const FrontierMap& frontiers) {
  Grid<std::uint8_t> out(known.width(), known.height(), 0);
  for (int i = 0; i < known.size(); ++i) {
    if (known.is_unknown(i) || frontiers.is_frontier(i)) out[i] = 1;
  }
  return out;
}

Grid<std::uint8_t> known_free_cells(const KnownMap& known) {
  Grid<std::uint8_t> out(known.width(), known.height(), 0);
  for (int i = 0; i < known.size(); ++i) out[i] = known.is_free(i) ? 1 : 0;
  return out;
}

double geodesic_hausdorff(std::span<const double> field, std::span<const int> set) {
  double best = std::numeric_limits<double>::infinity();
  for (const int q : set) {
    if (q >= 0 && static_cast<std::size_t>(q) < field.size() && field[static_cast<std::size_t>(q)] < best) {
      best = field[static_cast<std::size_t>(q)];
    }
  }
  return best;
}

}  // namespace strategies
}  // namespace fsweep
