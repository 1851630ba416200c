// The Choquet integral (Holz 2010 equation 6) and the fuzzy-measure axioms, against hand
// computations.
#include <gtest/gtest.h>

#include <array>
#include <stdexcept>
#include <vector>

#include "core/random.hpp"
#include "strategies/choquet.hpp"

namespace fsweep {
namespace {

// Criteria in bit order L (bit 0), I (bit 1), O (bit 2). Holz 2010 Table I.
const std::vector<double> kTableI = {0.0, 0.2, 0.4, 0.9, 0.4, 0.6, 0.8, 1.0};

TEST(Choquet, TableIByHand) {
  // u = (L 0.6, I 0.3, O 0.9). Sorted: I 0.3 <= L 0.6 <= O 0.9.
  //   (0.3 - 0) mu({L, I, O}) = 0.3 * 1.0 = 0.30
  //   (0.6 - 0.3) mu({L, O})  = 0.3 * 0.6 = 0.18
  //   (0.9 - 0.6) mu({O})     = 0.3 * 0.4 = 0.12
  //   sum 0.60 (the additive weighted average with weights .2 .4 .4 would be 0.6*.2 + 0.3*.4 +
  //   0.9*.4 = 0.60 too, by coincidence; the next case differs)
  EXPECT_NEAR(choquet_integral(std::vector<double>{0.6, 0.3, 0.9}, kTableI), 0.60, 1e-12);
  // u = (L 1, I 1, O 0): sorted O 0 <= L 1 = I 1:
  //   0 * mu(LIO) + (1 - 0) mu({L, I}) = 0.9 (synergy of L and I: the weighted average of the
  //   singletons would give 0.2 + 0.4 = 0.6).
  EXPECT_NEAR(choquet_integral(std::vector<double>{1.0, 1.0, 0.0}, kTableI), 0.9, 1e-12);
  // u = (L 0.2, I 0.8, O 0.5): sorted L 0.2 <= O 0.5 <= I 0.8:
  //   0.2 * 1.0 + 0.3 * mu({I, O}) + 0.3 * mu({I}) = 0.2 + 0.24 + 0.12 = 0.56
  EXPECT_NEAR(choquet_integral(std::vector<double>{0.2, 0.8, 0.5}, kTableI), 0.56, 1e-12);
}

TEST(Choquet, AdditiveMeasureIsTheWeightedAverage) {
  // mu(A) = sum of the weights in A: the integral is sum_j w_j u_j (Holz 2010 section IV-C).
  const std::array<double, 4> w = {0.1, 0.2, 0.3, 0.4};
  std::vector<double> mu(16, 0.0);
  for (unsigned s = 0; s < 16; ++s) {
    for (unsigned j = 0; j < 4; ++j) {
      if ((s >> j) & 1U) mu[s] += w[j];
    }
  }
  mu[15] = 1.0;  // exactly, not the rounded sum
  Rng rng = make_rng(1, "choquet-test");
  for (int k = 0; k < 50; ++k) {
    std::vector<double> u(4);
    double average = 0.0;
    for (std::size_t j = 0; j < 4; ++j) {
      u[j] = uniform01(rng);
      average += w[j] * u[j];
    }
    EXPECT_NEAR(choquet_integral(u, mu), average, 1e-12);
  }
  // By hand: u = (1, 0, 0.5, 0.5): 0.1 + 0.15 + 0.2 = 0.45.
  EXPECT_NEAR(choquet_integral(std::vector<double>{1.0, 0.0, 0.5, 0.5}, mu), 0.45, 1e-12);
}

TEST(Choquet, TiesDoNotDependOnOrderAndBoundsHold) {
  // Equal utilities: the integral is that value times mu(all) = the value.
  EXPECT_NEAR(choquet_integral(std::vector<double>{0.7, 0.7, 0.7}, kTableI), 0.7, 1e-12);
  EXPECT_DOUBLE_EQ(choquet_integral(std::vector<double>{0, 0, 0}, kTableI), 0.0);
  EXPECT_DOUBLE_EQ(choquet_integral(std::vector<double>{1, 1, 1}, kTableI), 1.0);
  // Two tied criteria: (0.5, 0.5, 0): 0.5 mu({L, I}) = 0.45 whichever of L, I sorts first.
  EXPECT_NEAR(choquet_integral(std::vector<double>{0.5, 0.5, 0.0}, kTableI), 0.45, 1e-12);
  // Between min and max of the utilities (a property of any fuzzy measure).
  Rng rng = make_rng(2, "choquet-test");
  for (int k = 0; k < 50; ++k) {
    const std::vector<double> u = {uniform01(rng), uniform01(rng), uniform01(rng)};
    const double v = choquet_integral(u, kTableI);
    EXPECT_GE(v, std::min({u[0], u[1], u[2]}) - 1e-12);
    EXPECT_LE(v, std::max({u[0], u[1], u[2]}) + 1e-12);
  }
}

TEST(Choquet, OneCriterionAndSizeErrors) {
  EXPECT_DOUBLE_EQ(choquet_integral(std::vector<double>{0.25}, std::vector<double>{0.0, 1.0}), 0.25);
  EXPECT_THROW((void)choquet_integral(std::vector<double>{0.1, 0.2}, kTableI), std::invalid_argument);
  EXPECT_THROW((void)choquet_integral(std::vector<double>{0.1}, std::vector<double>{0.0, 0.5, 1.0}),
               std::invalid_argument);
  EXPECT_THROW((void)fuzzy_measure_violations(std::vector<double>{}), std::invalid_argument);
}

TEST(FuzzyMeasure, TableIIsValid) { EXPECT_TRUE(fuzzy_measure_violations(kTableI).empty()); }

TEST(FuzzyMeasure, ReportsEveryViolationWithItsPair) {
  // mu(L) = 0.7 > mu(LI) = 0.5; mu(empty) = 0.1; mu(O) = 1.2 (out of range, and above
  // mu(LO) = 0.8 and mu(IO) = 0.8; O < LIO is not a one-criterion step, so not checked).
  const std::vector<double> mu = {0.1, 0.7, 0.4, 0.5, 1.2, 0.8, 0.8, 1.0};
  const auto v = fuzzy_measure_violations(mu);
  using K = MeasureViolation::Kind;
  std::vector<std::array<unsigned, 3>> got;
  got.reserve(v.size());
  for (const auto& x : v) got.push_back({static_cast<unsigned>(x.kind), x.subset, x.superset});
  const std::vector<std::array<unsigned, 3>> expected = {
      {static_cast<unsigned>(K::OutOfRange), 4, 4},   // O = 1.2
      {static_cast<unsigned>(K::Boundary), 0, 0},     // mu(empty) = 0.1
      {static_cast<unsigned>(K::NotMonotone), 1, 3},  // L 0.7 > LI 0.5
      {static_cast<unsigned>(K::NotMonotone), 4, 5},  // O 1.2 > LO 0.8
      {static_cast<unsigned>(K::NotMonotone), 4, 6},  // O 1.2 > IO 0.8
  };
  EXPECT_EQ(got, expected);
  EXPECT_EQ(subset_name(5, "LIO"), "LO");
  EXPECT_EQ(subset_name(0, "LIO"), "{}");
  // mu(all) != 1.
  const std::vector<double> short_top = {0.0, 0.2, 0.4, 0.9, 0.4, 0.6, 0.8, 0.95};
  const auto t = fuzzy_measure_violations(short_top);
  ASSERT_EQ(t.size(), 1U);
  EXPECT_EQ(t[0].kind, K::Boundary);
  EXPECT_EQ(t[0].subset, 7U);
}

}  // namespace
}  // namespace fsweep
