#include "core/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
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

Statistics describe(std::vector<double>& values) {
  Statistics s;
  s.fill(std::numeric_limits<double>::quiet_NaN());
  if (values.empty()) return s;
  std::sort(values.begin(), values.end());
  double sum = 0.0;
  for (const double v : values) sum += v;
  const double n = static_cast<double>(values.size());
  const double mean = sum / n;
  double squares = 0.0;
  for (const double v : values) squares += (v - mean) * (v - mean);
  s = {mean,
       values.size() > 1 ? std::sqrt(squares / (n - 1.0)) : 0.0,
       values.front(),
       quantile_sorted(values, 0.05),
       quantile_sorted(values, 0.25),
       quantile_sorted(values, 0.5),
       quantile_sorted(values, 0.75),
       quantile_sorted(values, 0.95),
       values.back()};
  return s;
}

Statistics describe_counted(std::vector<CountedValue>& values) {
  Statistics s;
  s.fill(std::numeric_limits<double>::quiet_NaN());
  std::sort(values.begin(), values.end(),
            [](const CountedValue& a, const CountedValue& b) { return a.value < b.value; });
  if (values.empty()) return s;
  double n = 0.0;
  double mean = 0.0;
  double m2 = 0.0;  // weighted Welford
  for (const CountedValue& v : values) {
    const auto c = static_cast<double>(v.count);
    n += c;
    const double delta = v.value - mean;
    mean += delta * c / n;
    m2 += c * delta * (v.value - mean);
  }
  s = {mean,
       n > 1.0 ? std::sqrt(m2 / (n - 1.0)) : 0.0,
       values.front().value,
       counted_quantile_sorted(values, 0.05),
       counted_quantile_sorted(values, 0.25),
       counted_quantile_sorted(values, 0.5),
       counted_quantile_sorted(values, 0.75),
       counted_quantile_sorted(values, 0.95),
       values.back().value};
  return s;
}

}  // namespace core
}  // namespace fsweep
