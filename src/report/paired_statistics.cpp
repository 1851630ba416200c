/// @file paired_statistics.cpp
/// Signed-rank test, Holm adjustment and cluster bootstrap (paired_statistics.hpp).

#include "report/paired_statistics.hpp"

#include <algorithm>
#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "core/statistics.hpp"

namespace fsweep {
inline namespace report {
namespace {

/// The largest n signed_rank_cdf() takes (its table has n (n + 1) / 2 + 1 entries, built in
/// n^3 / 2 steps).
constexpr std::size_t kMaxExactN = 200;

/// Mean ranks (from 1) of `values` (ties share their mean rank), and whether any tie.
std::pair<std::vector<double>, bool> mean_ranks(const std::vector<double>& values) {
  std::vector<std::size_t> order(values.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
  std::vector<double> ranks(values.size());
  bool ties = false;
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i;
    while (j < order.size() && values[order[j]] == values[order[i]]) ++j;
    ties = ties || j - i > 1;
    const double rank = (static_cast<double>(i + 1) + static_cast<double>(j)) / 2.0;
    for (std::size_t k = i; k < j; ++k) ranks[order[k]] = rank;
    i = j;
  }
  return {ranks, ties};
}

/// The sum over groups of equal ranks of t^3 - t (t: the group's size).
double tie_term(std::vector<double> ranks) {
  std::sort(ranks.begin(), ranks.end());
  double sum = 0.0;
  for (std::size_t i = 0; i < ranks.size();) {
    std::size_t j = i;
    while (j < ranks.size() && ranks[j] == ranks[i]) ++j;
    const auto t = static_cast<double>(j - i);
    sum += t * t * t - t;
    i = j;
  }
  return sum;
}

}  // namespace

std::string_view to_string(SignedRankMethod method) {
  switch (method) {
    case SignedRankMethod::Exact:
      return "exact";
    case SignedRankMethod::Normal:
      return "normal";
    case SignedRankMethod::None:
      break;
  }
  return "none";
}

double signed_rank_cdf(double v, std::size_t n) {
  if (n > kMaxExactN) throw std::invalid_argument("signed_rank_cdf: n above " + std::to_string(kMaxExactN));
  const std::size_t total = n * (n + 1) / 2;
  if (v < 0.0) return 0.0;
  if (v >= static_cast<double>(total)) return 1.0;
  // P(V = s) over the sign patterns of ranks 1..k, k = 1..n: adding rank k either leaves the sum
  // or adds k, each with probability 1/2 (dyadic rationals: exact in doubles for small n).
  std::vector<double> p(total + 1, 0.0);
  p[0] = 1.0;
  for (std::size_t k = 1; k <= n; ++k) {
    const std::size_t top = k * (k + 1) / 2;
    for (std::size_t s = top; s >= k; --s) p[s] = 0.5 * (p[s] + p[s - k]);
    for (std::size_t s = 0; s < k; ++s) p[s] *= 0.5;
  }
  const auto last = static_cast<std::size_t>(std::floor(v));
  double cdf = 0.0;
  for (std::size_t s = 0; s <= last; ++s) cdf += p[s];
  return std::min(cdf, 1.0);
}

SignedRankTest wilcoxon_signed_rank(const std::vector<double>& differences) {
  SignedRankTest t;
  std::vector<double> x;
  x.reserve(differences.size());
  for (const double d : differences) {
    if (std::isnan(d)) throw std::invalid_argument("wilcoxon_signed_rank: a difference is NaN");
    if (d == 0.0) {
      ++t.zeros;
    } else {
      x.push_back(d);
    }
  }
  t.n = x.size();
  if (t.n == 0) return t;  // every difference zero: method None, p = 1
  std::vector<double> magnitude(x.size());
  std::transform(x.begin(), x.end(), magnitude.begin(), [](double d) { return std::abs(d); });
  const auto [ranks, ties] = mean_ranks(magnitude);
  t.ties = ties;
  for (std::size_t i = 0; i < x.size(); ++i) t.v += x[i] > 0.0 ? ranks[i] : 0.0;
  const auto n = static_cast<double>(t.n);
  const double centre = n * (n + 1.0) / 4.0;
  if (t.n < kSignedRankExactBelow && !t.ties && t.zeros == 0) {
    t.method = SignedRankMethod::Exact;
    const double one_side = t.v > centre ? 1.0 - signed_rank_cdf(t.v - 1.0, t.n) : signed_rank_cdf(t.v, t.n);
    t.p_value = std::min(1.0, 2.0 * one_side);
    return t;
  }
  t.method = SignedRankMethod::Normal;
  const double sigma = std::sqrt(n * (n + 1.0) * (2.0 * n + 1.0) / 24.0 - tie_term(ranks) / 48.0);
  double z = t.v - centre;
  const double correction = z > 0.0 ? 0.5 : z < 0.0 ? -0.5 : 0.0;
  z = (z - correction) / sigma;
  const boost::math::normal standard;
  const double lower = boost::math::cdf(standard, z);
  const double upper = boost::math::cdf(boost::math::complement(standard, z));
  t.p_value = std::min(1.0, 2.0 * std::min(lower, upper));
  return t;
}

std::vector<std::optional<double>> holm_adjust(const std::vector<std::optional<double>>& p) {
  std::vector<std::size_t> present;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p[i]) present.push_back(i);
  }
  std::stable_sort(present.begin(), present.end(),
                   [&](std::size_t a, std::size_t b) { return *p[a] < *p[b]; });
  std::vector<std::optional<double>> adjusted(p.size());
  const auto m = static_cast<double>(present.size());
  double running = 0.0;
  for (std::size_t j = 0; j < present.size(); ++j) {
    running = std::max(running, std::min(1.0, (m - static_cast<double>(j)) * *p[present[j]]));
    adjusted[present[j]] = running;
  }
  return adjusted;
}

std::optional<Interval> cluster_bootstrap_mean(const std::vector<std::vector<double>>& clusters,
                                               std::uint64_t resamples, double level, Rng& rng) {
  if (!(level > 0.0 && level < 1.0))
    throw std::invalid_argument("cluster_bootstrap_mean: level not in (0, 1)");
  // Each cluster as its sum and count: a resample's mean is the drawn sums over the drawn counts.
  std::vector<std::pair<double, double>> sums;
  for (const auto& c : clusters) {
    if (!c.empty())
      sums.emplace_back(std::accumulate(c.begin(), c.end(), 0.0), static_cast<double>(c.size()));
  }
  if (sums.size() < 2 || resamples == 0) return std::nullopt;
  std::vector<double> means;
  means.reserve(resamples);
  for (std::uint64_t r = 0; r < resamples; ++r) {
    double sum = 0.0;
    double count = 0.0;
    for (std::size_t k = 0; k < sums.size(); ++k) {
      const auto& [s, c] = sums[uniform_below(rng, sums.size())];
      sum += s;
      count += c;
    }
    means.push_back(sum / count);
  }
  std::sort(means.begin(), means.end());
  return Interval{quantile_sorted(means, (1.0 - level) / 2.0), quantile_sorted(means, (1.0 + level) / 2.0)};
}

}  // namespace report
}  // namespace fsweep
