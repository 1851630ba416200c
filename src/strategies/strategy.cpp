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

namespace {

/// The argmin over the candidates `index(0..n-1)` (ascending indices): argmin_linear()'s rule.
template <typename Index>
int argmin_over(const Candidates& c, std::span<const double> weights, std::size_t n, Index index) {
  const auto k = static_cast<std::size_t>(c.feature_count);
  int best = -1;
  double best_cost = 0.0;
  for (std::size_t j = 0; j < n; ++j) {
    const auto i = static_cast<std::size_t>(index(j));
    const double cost = linear_cost(weights, std::span(c.features).subspan(i * k, k));
    // Strict '<': on equal cost the lowest candidate index wins (documented tie rule).
    if (best < 0 || cost < best_cost) {
      best = static_cast<int>(i);
      best_cost = cost;
    }
  }
  return best;
}

}  // namespace

int argmin_linear(const Candidates& c, std::span<const double> weights) {
  return argmin_over(c, weights, c.cells.size(), [](std::size_t j) { return j; });
}

int argmin_linear_among(const Candidates& c, std::span<const double> weights, std::span<const int> among) {
  return argmin_over(c, weights, among.size(), [among](std::size_t j) { return among[j]; });
}

}  // namespace strategies
}  // namespace fsweep
