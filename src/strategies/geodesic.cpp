#include "strategies/geodesic.hpp"

#include <limits>

#include "search/grid_search.hpp"

namespace fsweep {
inline namespace strategies {

namespace {

/// Dijkstra environment of geodesic_field(): the cells flagged in `inside` are states, the 8
/// moves between them at octile costs (a diagonal needs one of the two cells beside it in the
/// set), a zero heuristic. Settling a cell writes its distance and its nearest source: its
/// parent's (the settled cell its final cost came from first), or itself for a source.
class GeodesicRegion {
 public:
  GeodesicRegion(const Grid<std::uint8_t>& inside, double resolution_m, const BestFirstSearch& search,
                 GeodesicField& out)
      : inside_(inside), resolution_m_(resolution_m), search_(search), out_(out) {}

  [[nodiscard]] int state_count() const { return inside_.size(); }
  static constexpr bool kZeroHeuristic = true;
  [[nodiscard]] static double heuristic(int /*state*/) { return 0.0; }
  Visit visit(int state, double g) {
    const auto s = static_cast<std::size_t>(state);
    const int parent = search_.parent(state);
    out_.distance_m[s] = g * resolution_m_;
    out_.nearest_source[s] = parent < 0 ? state : out_.nearest_source[static_cast<std::size_t>(parent)];
    return Visit::Expand;
  }
  template <typename Sink>
  void for_each_successor(int state, Sink&& sink) const {
    const Cell c = inside_.cell(state);
    for (int h = 0; h < 8; ++h) {
      const Cell step = kDirections[static_cast<std::size_t>(h)];
      const Cell n{c.x + step.x, c.y + step.y};
      if (!in_set(n)) continue;
      // A diagonal needs one of the two cells beside it in the set.
      if ((h & 1) != 0 && !in_set(Cell{c.x + step.x, c.y}) && !in_set(Cell{c.x, c.y + step.y})) continue;
      sink(inside_.index(n), step_length(h));
    }
  }

 private:
  [[nodiscard]] bool in_set(Cell c) const { return inside_.in_bounds(c) && inside_.at(c) != 0; }

  const Grid<std::uint8_t>& inside_;
  double resolution_m_;
  const BestFirstSearch& search_;
  GeodesicField& out_;
};

}  // namespace

std::vector<double> geodesic_distances(const Grid<std::uint8_t>& inside, std::span<const int> sources,
                                       double resolution_m) {
  return geodesic_field(inside, sources, resolution_m).distance_m;
}

GeodesicField geodesic_field(const Grid<std::uint8_t>& inside, std::span<const int> sources,
                             double resolution_m) {
  GeodesicField out;
  out.distance_m.assign(static_cast<std::size_t>(inside.size()), std::numeric_limits<double>::infinity());
  out.nearest_source.assign(static_cast<std::size_t>(inside.size()), -1);
  // 1. Every flagged source at distance 0 (a source listed twice counts once).
  std::vector<SearchSeed> seeds;
  seeds.reserve(sources.size());
  for (const int s : sources) {
    if (s >= 0 && s < inside.size() && inside[s] != 0) seeds.push_back(SearchSeed{s, 0.0});
  }
  // 2. Dijkstra through the set (ties: smaller cell index first); settling fills `out`.
  BestFirstSearch search;
  GeodesicRegion region(inside, resolution_m, search, out);
  (void)search.run(region, seeds);
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
