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

/// a_k <= (f_j - f_i) - 4.5e-16 (|f_j| + |f_i|) for each feature k, so a . w > 0 at a weight
/// vector w proves that f_j costs more there (costs_more_at_every_direction()). False when the
/// sizes do not fit or a feature is not finite.
bool margin_differences(std::span<const double> f_j, std::span<const double> f_i,
                        std::array<double, WeightDirections::kMaxWeights>& a) {
  const std::size_t n = f_j.size();
  if (f_i.size() != n || n > WeightDirections::kMaxWeights) return false;
  constexpr double kMargin = 1e-12;
  for (std::size_t k = 0; k < n; ++k) {
    if (!std::isfinite(f_j[k]) || !std::isfinite(f_i[k])) return false;
    a[k] = (f_j[k] - f_i[k]) - kMargin * (std::abs(f_j[k]) + std::abs(f_i[k]));
  }
  return true;
}

}  // namespace

bool costs_more_at_every_weight(std::span<const double> f_j, std::span<const double> f_i,
                                std::span<const double> lo, std::span<const double> hi) {
  std::array<double, WeightDirections::kMaxWeights> a{};
  if (!margin_differences(f_j, f_i, a) || lo.size() != f_j.size() || hi.size() != f_j.size()) return false;
  // The lowest a . w over the box, at the corner with lo_k where a_k >= 0 and hi_k elsewhere,
  // positive beyond its own rounding.
  double lowest = 0.0;
  double size = 0.0;
  for (std::size_t k = 0; k < f_j.size(); ++k) {
    const double w = a[k] >= 0.0 ? lo[k] : hi[k];
    lowest += a[k] * w;
    size += std::abs(a[k]) * w;
  }
  return lowest > 2e-15 * size;
}

bool costs_more_at_every_direction(std::span<const double> f_j, std::span<const double> f_i,
                                   const WeightDirections& directions, double extra) {
  const std::size_t n = f_j.size();
  std::array<double, WeightDirections::kMaxWeights> a{};
  if (!margin_differences(f_j, f_i, a)) return false;
  // Directions sum to 1, so for any lambda, a . u = lambda + sum_k (a_k - lambda) u_k, which
  // is at least lambda + sum_k (a_k - lambda) * (lo_k or hi_k, whichever is lower): a lower
  // bound of the minimum over the box's directions, which one of lambda = 0, a_1, ..., a_n
  // attains (the breakpoint where the box's mass runs out). Each bound must be positive beyond
  // its own rounding (at most a few 1e-16 of the sum of its terms' sizes).
  const auto proven_with = [&](double lambda) {
    double lowest = lambda;
    double size = std::abs(lambda);
    for (std::size_t k = 0; k < n; ++k) {
      const double c = a[k] - lambda;
      const double u = c >= 0.0 ? directions.lo[k] : directions.hi[k];
      lowest += c * u;
      size += std::abs(c) * u;
    }
    return lowest > 2e-15 * size + extra;
  };
  if (proven_with(0.0)) return true;
  for (std::size_t k = 0; k < n; ++k) {
    if (proven_with(a[k])) return true;
  }
  return false;
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
