#include "core/statistics.hpp"

#include <cmath>
#include <stdexcept>

namespace fsweep {
inline namespace core {

double quantile_sorted(const std::vector<double>& sorted, double q) {
  if (sorted.empty()) throw std::invalid_argument("quantile_sorted: no values");
  if (!(q >= 0.0 && q <= 1.0)) throw std::invalid_argument("quantile_sorted: q outside [0, 1]");
  // Hyndman and Fan (1996) type 7: h = (n - 1) q, interpolate between x[floor h] and x[floor h + 1].
  const double h = static_cast<double>(sorted.size() - 1) * q;
  const auto lo = static_cast<std::size_t>(std::floor(h));
  const double frac = h - static_cast<double>(lo);
  if (frac == 0.0 || lo + 1 >= sorted.size() || sorted[lo] == sorted[lo + 1]) return sorted[lo];
  return sorted[lo] + frac * (sorted[lo + 1] - sorted[lo]);
}

}  // namespace core
}  // namespace fsweep
