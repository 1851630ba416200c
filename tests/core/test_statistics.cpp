// quantile_sorted (Hyndman-Fan type 7) and summary.csv's statistics against hand-computed values.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "core/statistics.hpp"

namespace fsweep {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Hand computation, type 7: h = 3q for n = 4; q05: h = 0.15 -> 1 + 0.15 * (2 - 1) = 1.15, etc.
TEST(Quantile, Type7MatchesHandComputation) {
  const std::vector<double> v{1, 2, 3, 4};
  EXPECT_NEAR(quantile_sorted(v, 0.05), 1.15, 1e-12);
  EXPECT_NEAR(quantile_sorted(v, 0.25), 1.75, 1e-12);
  EXPECT_NEAR(quantile_sorted(v, 0.5), 2.5, 1e-12);
  EXPECT_NEAR(quantile_sorted(v, 0.75), 3.25, 1e-12);
  EXPECT_NEAR(quantile_sorted(v, 0.95), 3.85, 1e-12);
  EXPECT_EQ(quantile_sorted(v, 0.0), 1.0);
  EXPECT_EQ(quantile_sorted(v, 1.0), 4.0);
}

TEST(Quantile, SingleValueIsEveryQuantile) {
  for (const double q : {0.0, 0.05, 0.5, 0.95, 1.0}) EXPECT_EQ(quantile_sorted({7.0}, q), 7.0);
}

// n = 2: h = q, so the quantile is 1 + 2q.
TEST(Quantile, TwoValuesInterpolateLinearly) {
  const std::vector<double> v{1, 3};
  EXPECT_NEAR(quantile_sorted(v, 0.05), 1.1, 1e-12);
  EXPECT_NEAR(quantile_sorted(v, 0.25), 1.5, 1e-12);
  EXPECT_NEAR(quantile_sorted(v, 0.5), 2.0, 1e-12);
  EXPECT_NEAR(quantile_sorted(v, 0.95), 2.9, 1e-12);
}

TEST(Quantile, RejectsNoValuesAndQOutsideUnitInterval) {
  EXPECT_THROW((void)quantile_sorted({}, 0.5), std::invalid_argument);
  EXPECT_THROW((void)quantile_sorted({1.0}, 1.5), std::invalid_argument);
  EXPECT_THROW((void)quantile_sorted({1.0}, std::nan("")), std::invalid_argument);
}

// n = 5, h = 4q: q = 0.1 -> h = 0.4 -> 10 + 0.4 * (20 - 10) = 14; q = 0.3 -> h = 1.2 ->
// 20 + 0.2 * (40 - 20) = 24; q = 0.9 -> h = 3.6 -> 80 + 0.6 * (160 - 80) = 128.
TEST(Quantile, Type7InterpolatesBetweenOrderStatistics) {
  const std::vector<double> v{10, 20, 40, 80, 160};
  EXPECT_NEAR(quantile_sorted(v, 0.1), 14.0, 1e-12);
  EXPECT_NEAR(quantile_sorted(v, 0.3), 24.0, 1e-12);
  EXPECT_EQ(quantile_sorted(v, 0.5), 40.0);  // h = 2: the order statistic itself
  EXPECT_NEAR(quantile_sorted(v, 0.9), 128.0, 1e-12);
}

// At an order statistic, or between equal neighbours, the value itself: inf - inf is never formed.
TEST(Quantile, InfiniteValuesStayInfinite) {
  EXPECT_EQ(quantile_sorted({1.0, kInf}, 1.0), kInf);
  EXPECT_EQ(quantile_sorted({1.0, kInf}, 0.5), kInf);
  EXPECT_EQ(quantile_sorted({kInf, kInf}, 0.5), kInf);
  EXPECT_EQ(quantile_sorted({-kInf, 1.0}, 0.0), -kInf);
  EXPECT_EQ(quantile_sorted({-kInf, 1.0, 2.0}, 0.5), 1.0);
}

// Counted values give the quantiles of their expansion, for every q on a fine grid.
TEST(Quantile, CountedValuesAreTheirExpansion) {
  const std::vector<CountedValue> counted{{-3.0, 2}, {1.5, 1}, {2.0, 5}, {7.25, 3}, {kInf, 1}};
  std::vector<double> expanded;
  for (const CountedValue& v : counted) expanded.insert(expanded.end(), v.count, v.value);
  for (int i = 0; i <= 1000; ++i) {
    const double q = i / 1000.0;
    EXPECT_EQ(counted_quantile_sorted(counted, q), quantile_sorted(expanded, q)) << "q = " << q;
  }
  EXPECT_EQ(counted_quantile_sorted({{4.0, 1'000'000'000'000}}, 0.3), 4.0);
  EXPECT_THROW((void)counted_quantile_sorted({}, 0.5), std::invalid_argument);
  EXPECT_THROW((void)counted_quantile_sorted({{1.0, 2}}, 2.0), std::invalid_argument);
}

// summary.csv's nine statistics by hand: 1, 2, 4, 8 has mean 3.75, std sqrt(28.75 / 3).
TEST(Statistics, DescribeGivesTheNineInColumnOrderAndNaNForNone) {
  std::vector<double> values{8.0, 1.0, 4.0, 2.0};
  const Statistics s = describe(values);
  EXPECT_EQ(kStatisticNames.front(), "mean");
  EXPECT_DOUBLE_EQ(s[0], 3.75);
  EXPECT_DOUBLE_EQ(s[1], std::sqrt(28.75 / 3.0));
  EXPECT_EQ(s[2], 1.0);
  EXPECT_DOUBLE_EQ(s[5], 3.0);  // median: 2 + 0.5 * (4 - 2)
  EXPECT_EQ(s[8], 8.0);
  std::vector<double> one{5.0};
  EXPECT_EQ(describe(one)[1], 0.0);
  std::vector<double> none;
  for (const double v : describe(none)) EXPECT_TRUE(std::isnan(v));
}

// The search's weighted statistics (each behaviour counted by its vectors) are those of the
// expanded values: quantiles, min and max exactly, mean and std up to rounding.
TEST(Statistics, CountedValuesDescribeAsTheirExpansion) {
  std::vector<CountedValue> counted{{7.25, 3}, {-3.0, 2}, {2.0, 5}, {1.5, 1}};
  std::vector<double> expanded;
  for (const CountedValue& v : counted) expanded.insert(expanded.end(), v.count, v.value);
  const Statistics c = describe_counted(counted);
  const Statistics e = describe(expanded);
  for (std::size_t k = 0; k < kStatisticNames.size(); ++k) {
    EXPECT_NEAR(c[k], e[k], 1e-12 * (1.0 + std::abs(e[k]))) << kStatisticNames[k];
  }
  for (const std::size_t k : {2, 3, 4, 5, 6, 7, 8}) EXPECT_EQ(c[k], e[k]) << kStatisticNames[k];
  std::vector<CountedValue> none;
  for (const double v : describe_counted(none)) EXPECT_TRUE(std::isnan(v));
}

}  // namespace
}  // namespace fsweep
