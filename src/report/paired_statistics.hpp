#pragma once
/// @file paired_statistics.hpp
/// The statistics of paired differences behind `fsweep paired` (paired.hpp): Wilcoxon's
/// signed-rank test, Holm's step-down adjustment of several p-values, and a bootstrap interval
/// of the mean difference that resamples clusters (map instances) rather than pairs.
///
/// The signed-rank test follows R's `wilcox.test(x, mu = 0, paired, exact = NULL, correct =
/// TRUE)` step by step, so its p-values can be checked against R: zero differences are dropped
/// first; the exact null distribution is used when fewer than 50 differences remain and none is
/// zero and no two absolute differences tie, the normal approximation with the tie and
/// continuity corrections otherwise. The exact distribution is computed here (neither
/// Boost.Math nor GSL has it); the normal tail comes from Boost.Math.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "core/random.hpp"

namespace fsweep {
inline namespace report {

/// Below this many non-zero differences, a test without zeros or ties is exact (R's default).
inline constexpr std::size_t kSignedRankExactBelow = 50;

/// How a signed-rank p-value was computed.
enum class SignedRankMethod {
  Exact,   ///< the exact null distribution of V (no zeros, no ties, n < 50)
  Normal,  ///< normal approximation with tie and continuity corrections
  None,    ///< every difference is zero: no test (p = 1)
};

/// "exact", "normal" or "none".
[[nodiscard]] std::string_view to_string(SignedRankMethod method);

/// The outcome of a two-sided signed-rank test.
struct SignedRankTest {
  double v = 0.0;         ///< R's V: the sum of the ranks of the positive differences
  std::size_t n = 0;      ///< non-zero differences (the test's n)
  std::size_t zeros = 0;  ///< differences dropped as zero
  bool ties = false;      ///< two non-zero absolute differences are equal
  double p_value = 1.0;   ///< two-sided, in [0, 1]
  SignedRankMethod method = SignedRankMethod::None;
};

/// The two-sided Wilcoxon signed-rank test of `differences` against 0 (file comment). A
/// difference is zero when it is exactly 0: round near-ties to 0 before calling. Ranks of
/// equal absolute differences are their mean rank. NaN differences are a std::invalid_argument.
[[nodiscard]] SignedRankTest wilcoxon_signed_rank(const std::vector<double>& differences);

/// P(V <= v) under the null hypothesis for n differences without ties (R's psignrank(v, n)):
/// each of the 2^n sign patterns equally likely. 0 for v < 0, 1 for v >= n (n + 1) / 2.
/// n at most 1000 (the counts are exact up to n = 62, doubles beyond), else std::invalid_argument.
[[nodiscard]] double signed_rank_cdf(double v, std::size_t n);

/// Holm's step-down adjustment (R's p.adjust(p, "holm")): with the m values present sorted
/// ascending, the i-th (from 1) becomes max over j <= i of min(1, (m - j + 1) p_(j)). Absent
/// values (nullopt) stay absent and do not count in m.
[[nodiscard]] std::vector<std::optional<double>> holm_adjust(const std::vector<std::optional<double>>& p);

/// A two-sided interval.
struct Interval {
  double lo = 0.0;
  double hi = 0.0;
};

/// The percentile bootstrap interval at `level` (e.g. 0.95) of the mean of the values of
/// `clusters` pooled, resampling whole clusters: each of `resamples` draws takes as many
/// clusters as there are, uniformly with replacement (`rng`), and computes the mean of every
/// value of the drawn clusters (a cluster drawn twice counts twice); the interval is the
/// (1 - level) / 2 and (1 + level) / 2 type-7 quantiles of those means. The values of one
/// cluster (the repetitions on one map instance) stay together, as the cluster is the unit of
/// independence. nullopt with fewer than 2 non-empty clusters (nothing to resample: an interval
/// over one map says nothing about other maps) or no resamples. level in (0, 1).
[[nodiscard]] std::optional<Interval> cluster_bootstrap_mean(const std::vector<std::vector<double>>& clusters,
                                                             std::uint64_t resamples, double level, Rng& rng);

}  // namespace report
}  // namespace fsweep
