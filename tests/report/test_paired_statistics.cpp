/// Tests of paired_statistics.hpp against values computed independently: R 4.2.2's
/// wilcox.test, psignrank and p.adjust (tests/report/reference/wilcoxon_reference.R made them;
/// its output is wilcoxon_reference.txt beside it), and a printed table of critical values.

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "report/paired_statistics.hpp"

namespace fsweep {
namespace {

/// The test vectors of wilcoxon_reference.R, built the same way.
std::vector<double> sine_cases(int n) {
  std::vector<double> x;
  for (int i = 1; i <= n; ++i) x.push_back(std::sin(static_cast<double>(i)) * 10.0 + 0.7);
  return x;
}

struct Reference {
  const char* name;
  std::vector<double> x;
  double v;
  double p;
  SignedRankMethod method;
};

std::vector<Reference> references() {
  const std::vector<double> a{1.83, 0.50, 1.62, 2.48, 1.68, 1.88, 1.55, 3.06, 1.30};
  const std::vector<double> b{0.878, 0.647, 0.598, 2.05, 1.06, 1.29, 1.06, 3.14, 1.29};
  std::vector<double> depression;
  for (std::size_t i = 0; i < a.size(); ++i) depression.push_back(a[i] - b[i]);
  std::vector<double> all_negative;
  for (int i = 1; i <= 10; ++i) all_negative.push_back(-i);
  std::vector<double> n80_ties;
  for (int i = 1; i <= 80; ++i) n80_ties.push_back(std::round(std::cos(static_cast<double>(i)) * 4.0) + 0.5);
  return {
      {"depression", depression, 40, 0.0390625, SignedRankMethod::Exact},
      {"single", {2.5}, 1, 1, SignedRankMethod::Exact},
      {"all_negative", all_negative, 0, 0.001953125, SignedRankMethod::Exact},
      {"ties", {1, 1, 2, -3, 4, 4, 5}, 24, 0.1070579459659193, SignedRankMethod::Normal},
      {"zeros", {0, 1.5, -2, 3, 0, 4.5, 6}, 13, 0.17752985241215349, SignedRankMethod::Normal},
      {"ties_and_zeros",
       {0, -1, -1, 2, -2, -3, 0, -4, 5, -6, -6},
       10.5,
       0.17193836605810284,
       SignedRankMethod::Normal},
      {"n49", sine_cases(49), 709, 0.34271842733243224, SignedRankMethod::Exact},
      {"n50", sine_cases(50), 733, 0.35911042772086338, SignedRankMethod::Normal},
      {"n80_ties", n80_ties, 1926, 0.14038118224113841, SignedRankMethod::Normal},
  };
}

TEST(PairedStatistics, SignedRankMatchesR) {
  for (const Reference& r : references()) {
    const SignedRankTest t = wilcoxon_signed_rank(r.x);
    EXPECT_EQ(t.v, r.v) << r.name;
    EXPECT_NEAR(t.p_value, r.p, 1e-12 * r.p) << r.name;
    EXPECT_EQ(t.method, r.method) << r.name;
  }
}

TEST(PairedStatistics, SignedRankCountsZerosAndTies) {
  const SignedRankTest t = wilcoxon_signed_rank({0, -1, -1, 2, -2, -3, 0, -4, 5, -6, -6});
  EXPECT_EQ(t.zeros, 2U);
  EXPECT_EQ(t.n, 9U);
  EXPECT_TRUE(t.ties);
  EXPECT_FALSE(wilcoxon_signed_rank({1, 2, -3}).ties);
}

TEST(PairedStatistics, AllZeroDifferencesAreNoTest) {
  const SignedRankTest t = wilcoxon_signed_rank({0, 0, 0});
  EXPECT_EQ(t.method, SignedRankMethod::None);
  EXPECT_EQ(t.p_value, 1.0);
  EXPECT_EQ(t.zeros, 3U);
  EXPECT_EQ(wilcoxon_signed_rank({}).method, SignedRankMethod::None);
  EXPECT_THROW((void)wilcoxon_signed_rank({1.0, std::nan("")}), std::invalid_argument);
}

TEST(PairedStatistics, SignedRankCdfMatchesR) {
  EXPECT_DOUBLE_EQ(signed_rank_cdf(0, 5), 0.03125);
  EXPECT_DOUBLE_EQ(signed_rank_cdf(7, 5), 0.5);
  EXPECT_DOUBLE_EQ(signed_rank_cdf(15, 10), 0.1162109375);
  EXPECT_DOUBLE_EQ(signed_rank_cdf(27, 10), 0.5);
  EXPECT_NEAR(signed_rank_cdf(100, 20), 0.43474388122558594, 1e-15);
  EXPECT_NEAR(signed_rank_cdf(600, 49), 0.45292177859757571, 1e-14);
  EXPECT_EQ(signed_rank_cdf(-1, 5), 0.0);
  EXPECT_EQ(signed_rank_cdf(15, 5), 1.0);
}

TEST(PairedStatistics, SignedRankCdfGivesTheTablesCriticalValues) {
  // Printed tables of the signed-rank test (e.g. Siegel & Castellan, Table H; Zar, Table B.12):
  // two-sided alpha 0.05 critical T: n = 10 -> 8, n = 20 -> 52, n = 30 -> 137. The critical value
  // is the largest T with P(V <= T) <= 0.025.
  for (const auto& [n, critical] : {std::pair{10U, 8.0}, std::pair{20U, 52.0}, std::pair{30U, 137.0}}) {
    EXPECT_LE(signed_rank_cdf(critical, n), 0.025) << n;
    EXPECT_GT(signed_rank_cdf(critical + 1, n), 0.025) << n;
  }
}

TEST(PairedStatistics, HolmMatchesR) {
  const auto adjusted = holm_adjust({0.01, 0.04, std::nullopt, 0.03, 0.005, 0.5});
  const std::vector<std::optional<double>> expected{0.04, 0.09, std::nullopt, 0.09, 0.025, 0.5};
  ASSERT_EQ(adjusted.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    ASSERT_EQ(adjusted[i].has_value(), expected[i].has_value()) << i;
    if (expected[i]) {
      EXPECT_NEAR(*adjusted[i], *expected[i], 1e-15) << i;
    }
  }
  EXPECT_TRUE(holm_adjust({}).empty());
}

TEST(PairedStatistics, BootstrapResamplesWholeClusters) {
  // Two instances: every resample draws (A, A), (A, B), (B, A) or (B, B), so its mean is 2, 6.5
  // or 11; in 10,000 resamples each extreme is drawn about 2,500 times, so the 2.5% and 97.5%
  // quantiles are exactly the instances' means. A bootstrap over the six pairs would put them
  // near 4 and 9.
  Rng rng = make_rng(1, "test");
  const auto ci = cluster_bootstrap_mean({{1, 2, 3}, {10, 11, 12}}, 10000, 0.95, rng);
  ASSERT_TRUE(ci);
  EXPECT_EQ(ci->lo, 2.0);
  EXPECT_EQ(ci->hi, 11.0);
}

TEST(PairedStatistics, BootstrapWeighsClustersByTheirPairs) {
  // A cluster of 3 pairs with mean 0 and one of 1 pair with mean 4: the pooled mean of (A, B) is
  // 1, not the 2 of a mean of cluster means.
  Rng rng = make_rng(2, "test");
  const auto ci = cluster_bootstrap_mean({{0, 0, 0}, {4}}, 20000, 0.2, rng);
  ASSERT_TRUE(ci);
  EXPECT_EQ(ci->lo, 1.0);
  EXPECT_EQ(ci->hi, 1.0);
}

TEST(PairedStatistics, BootstrapNeedsTwoClustersAndIsSeeded) {
  Rng rng = make_rng(3, "test");
  EXPECT_FALSE(cluster_bootstrap_mean({{1, 2, 3}}, 1000, 0.95, rng));
  EXPECT_FALSE(cluster_bootstrap_mean({{1, 2, 3}, {}}, 1000, 0.95, rng));
  EXPECT_FALSE(cluster_bootstrap_mean({{1}, {2}}, 0, 0.95, rng));
  const std::vector<std::vector<double>> clusters{{1.5, 2}, {-1}, {4, 4.5, 5}, {0.25}, {3}};
  Rng a = make_rng(9, "bootstrap");
  Rng b = make_rng(9, "bootstrap");
  const auto x = cluster_bootstrap_mean(clusters, 2000, 0.95, a);
  const auto y = cluster_bootstrap_mean(clusters, 2000, 0.95, b);
  ASSERT_TRUE(x && y);
  EXPECT_EQ(x->lo, y->lo);
  EXPECT_EQ(x->hi, y->hi);
  EXPECT_LT(x->lo, 17.25 / 8.0);  // the pooled mean lies inside
  EXPECT_GT(x->hi, 17.25 / 8.0);
}

}  // namespace
}  // namespace fsweep
