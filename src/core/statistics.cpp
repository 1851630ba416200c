#include "core/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fsweep {
inline namespace core {

namespace {

/// Hyndman and Fan (1996) type 7 over n sorted values, value i being at(i): h = (n - 1) q,
/// interpolate between x[floor h] and x[floor h + 1].
template <typename At>
double type7(std::uint64_t n, double q, At&& at) {
  if (n == 0) throw std::invalid_argument("quantile_sorted: no values");
  if (!(q >= 0.0 && q <= 1.0)) throw std::invalid_argument("quantile_sorted: q outside [0, 1]");
  const double h = static_cast<double>(n - 1) * q;
  const auto lo = static_cast<std::uint64_t>(std::floor(h));
  const double frac = h - static_cast<double>(lo);
  const double x = at(lo);
  if (frac == 0.0 || lo + 1 >= n) return x;
  const double next = at(lo + 1);
  if (x == next) return x;
  return x + frac * (next - x);
}

}  // namespace

double quantile_sorted(const std::vector<double>& sorted, double q) {
  return type7(sorted.size(), q, [&](std::uint64_t i) { return sorted[static_cast<std::size_t>(i)]; });
}

double counted_quantile_sorted(const std::vector<CountedValue>& sorted, double q) {
  std::vector<std::uint64_t> ends;  // ends[k]: values up to and including entry k
  ends.reserve(sorted.size());
  std::uint64_t n = 0;
  for (const CountedValue& v : sorted) ends.push_back(n += v.count);
  return type7(n, q, [&](std::uint64_t i) {
    return sorted[static_cast<std::size_t>(std::upper_bound(ends.begin(), ends.end(), i) - ends.begin())]
        .value;
  });
}

}  // namespace core
}  // namespace fsweep
