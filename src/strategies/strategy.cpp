#include "strategies/strategy.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace fsweep {
inline namespace strategies {

void DistanceOracle::watch_from_robot(std::span<const int> cells, double bound_m, SettleWatcher& watcher) {
  const std::vector<double> d = from_robot(cells, bound_m);
  std::vector<std::size_t> order;
  for (std::size_t k = 0; k < d.size(); ++k) {
    if (std::isfinite(d[k])) order.push_back(k);
  }
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return d[a] < d[b]; });
  for (const std::size_t k : order) watcher.settled(k, d[k]);
}

std::optional<double> DistanceOracle::probe_from_robot(int cell, double bound_m, long /*max_expansions*/) {
  const std::array<int, 1> one{cell};
  return from_robot(one, bound_m).front();
}

int argmin_linear(const Candidates& c, std::span<const double> weights) {
  const auto k = static_cast<std::size_t>(c.feature_count);
  int best = -1;
  double best_cost = 0.0;
  for (std::size_t i = 0; i < c.cells.size(); ++i) {
    const double cost = linear_cost(weights, std::span(c.features).subspan(i * k, k));
    // Strict '<': on equal cost the lowest candidate index wins (documented tie rule).
    if (best < 0 || cost < best_cost) {
      best = static_cast<int>(i);
      best_cost = cost;
    }
  }
  return best;
}

}  // namespace strategies
}  // namespace fsweep
