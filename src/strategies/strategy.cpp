#include "strategies/strategy.hpp"

namespace fsweep {
inline namespace strategies {

int argmin_linear(const Candidates& c, std::span<const double> weights) {
  const auto k = static_cast<std::size_t>(c.feature_count);
  int best = -1;
  double best_cost = 0.0;
  for (std::size_t i = 0; i < c.cells.size(); ++i) {
    double cost = 0.0;
    for (std::size_t f = 0; f < k; ++f) cost += weights[f] * c.features[i * k + f];
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
