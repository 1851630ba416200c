// The exact weight search's proofs by direction: costs_more_at_every_direction() claims that one
// candidate costs more than another at every weight vector of a set of directions, as
// linear_cost() computes both; WeightGrid::directions() bounds the directions of a region's
// points; WeightGrid::sole_choice() names the candidate argmin_linear() chooses at every point
// of a region. Each claim is checked at the vectors it speaks of, with near-ties whose order
// rounding decides.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "core/random.hpp"
#include "strategies/weight_grid.hpp"

namespace fsweep {
namespace {

using Point = std::array<int, WeightGrid::kMaxWeights>;
using Row = std::array<double, 4>;

/// The directions of the integer vectors of [lo, hi] (per weight) whose direction lies in the
/// box `d`, visited by `f(w)`.
template <typename F>
void for_each_vector_in(const WeightDirections& d, int lo, int hi, F&& f) {
  for (int a = lo; a <= hi; ++a) {
    for (int b = lo; b <= hi; ++b) {
      for (int c = lo; c <= hi; ++c) {
        for (int e = lo; e <= hi; ++e) {
          const Row w{double(a), double(b), double(c), double(e)};
          const double sum = w[0] + w[1] + w[2] + w[3];
          if (sum == 0.0) continue;
          bool inside = true;
          for (std::size_t k = 0; k < 4; ++k)
            inside = inside && d.lo[k] <= w[k] / sum && w[k] / sum <= d.hi[k];
          if (inside) f(w);
        }
      }
    }
  }
}

TEST(WeightDirections, ANearTieIsNeverClaimed) {
  // 0.1 w1 + 0.2 w2 against 0.3 w1 at w1 = w2: equal in exact arithmetic, ordered by rounding
  // (0.1 + 0.2 > 0.3 in doubles) and differently at different scales.
  WeightDirections diagonal;
  diagonal.lo = {0.5 - 1e-14, 0.5 - 1e-14, 0.0, 0.0};
  diagonal.hi = {0.5 + 1e-14, 0.5 + 1e-14, 0.0, 0.0};
  diagonal.zero = false;
  const Row a{0.1, 0.2, 0.0, 0.0};
  const Row b{0.3, 0.0, 0.0, 0.0};
  EXPECT_FALSE(costs_more_at_every_direction(a, b, diagonal));
  EXPECT_FALSE(costs_more_at_every_direction(b, a, diagonal));
  int a_above = 0;
  int b_above = 0;
  for (int t = 1; t <= 250; ++t) {
    const Row w{double(t), double(t), 0.0, 0.0};
    a_above += linear_cost(w, a) > linear_cost(w, b) ? 1 : 0;
    b_above += linear_cost(w, b) > linear_cost(w, a) ? 1 : 0;
  }
  // A real near-tie: rounding puts either above, or ties them, depending on the scale.
  EXPECT_GT(a_above, 0);
  EXPECT_GT(b_above, 0);
  EXPECT_GT(250 - a_above - b_above, 0);
  // A clear gap along the same directions is proven.
  EXPECT_TRUE(costs_more_at_every_direction(Row{0.1, 0.2001, 0.0, 0.0}, b, diagonal));
}

/// Features of both signs for a claim test; every fourth pair (by `trial`) nearly tied: the
/// second a rounding away, or a sum of fractions that ties in exact arithmetic on w0 = w1.
void random_pair(Rng& rng, int trial, Row& fi, Row& fj) {
  for (std::size_t k = 0; k < 4; ++k) {
    fi[k] = (static_cast<double>(uniform_below(rng, 2001)) - 1000.0) / 7.0;
    fj[k] = (static_cast<double>(uniform_below(rng, 2001)) - 1000.0) / 7.0;
  }
  if (trial % 4 == 1) {
    fj = fi;
    const std::size_t k = uniform_below(rng, 4);
    fj[k] = std::nextafter(fj[k], 1e300);
  } else if (trial % 4 == 3) {
    fj = fi;
    fj[0] = fi[0] + fi[1];
    fj[1] = 0.0;
  }
}

TEST(WeightDirections, AClaimHoldsAtEveryVectorOfTheDirections) {
  Rng rng = make_rng(11, "weight_directions");
  int claims = 0;
  int refusals = 0;
  for (int trial = 0; trial < 400; ++trial) {
    // A random direction box, narrow or wide.
    WeightDirections d;
    d.zero = false;
    const double width = trial % 2 == 0 ? 0.05 : 0.4;
    for (std::size_t k = 0; k < 4; ++k) {
      d.lo[k] = static_cast<double>(uniform_below(rng, 100)) / 100.0 * (1.0 - width);
      d.hi[k] = d.lo[k] + width;
    }
    Row fi{};
    Row fj{};
    random_pair(rng, trial, fi, fj);
    if (!costs_more_at_every_direction(fj, fi, d)) {
      ++refusals;
      continue;
    }
    ++claims;
    for_each_vector_in(d, 0, 12, [&](const Row& w) {
      ASSERT_GT(linear_cost(w, fj), linear_cost(w, fi)) << "trial " << trial;
    });
  }
  EXPECT_GT(claims, 40);  // the test checks claims, not only refusals
  EXPECT_GT(refusals, 40);
}

TEST(WeightDirections, AClaimOverABoxHoldsAtEveryVectorOfIt) {
  // costs_more_at_every_weight() over random integer boxes, narrow and wide, some holding the
  // zero vector: every claim is checked at every integer vector of its box.
  Rng rng = make_rng(14, "weight_directions");
  int claims = 0;
  int refusals = 0;
  for (int trial = 0; trial < 800; ++trial) {
    Row lo{};
    Row hi{};
    const int width = trial % 2 == 0 ? 2 : 9;
    for (std::size_t k = 0; k < 4; ++k) {
      lo[k] = static_cast<double>(trial % 8 == 0 ? 0 : uniform_below(rng, 12));
      hi[k] = lo[k] + static_cast<double>(uniform_below(rng, static_cast<std::uint64_t>(width) + 1));
    }
    Row fi{};
    Row fj{};
    random_pair(rng, trial, fi, fj);
    if (!costs_more_at_every_weight(fj, fi, lo, hi)) {
      ++refusals;
      continue;
    }
    ++claims;
    EXPECT_FALSE(lo == Row{}) << "a box with the zero vector, where every cost is 0, was claimed";
    for (double a = lo[0]; a <= hi[0]; ++a) {
      for (double b = lo[1]; b <= hi[1]; ++b) {
        for (double c = lo[2]; c <= hi[2]; ++c) {
          for (double e = lo[3]; e <= hi[3]; ++e) {
            const Row w{a, b, c, e};
            ASSERT_GT(linear_cost(w, fj), linear_cost(w, fi)) << "trial " << trial;
          }
        }
      }
    }
  }
  EXPECT_GT(claims, 80);
  EXPECT_GT(refusals, 80);
  // The near-tie along the diagonal is never claimed, however narrow the box around it.
  for (double t = 1; t <= 250; t += 7) {
    const Row at{t, t, 0.0, 0.0};
    EXPECT_FALSE(costs_more_at_every_weight(Row{0.1, 0.2, 0, 0}, Row{0.3, 0, 0, 0}, at, at));
    EXPECT_FALSE(costs_more_at_every_weight(Row{0.3, 0, 0, 0}, Row{0.1, 0.2, 0, 0}, at, at));
    EXPECT_TRUE(costs_more_at_every_weight(Row{0.1, 0.2001, 0, 0}, Row{0.3, 0, 0, 0}, at, at));
  }
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(
      costs_more_at_every_weight(Row{inf, 1, 1, 1}, Row{0, 0, 0, 0}, Row{1, 1, 1, 1}, Row{2, 2, 2, 2}));
}

TEST(WeightDirections, NonFiniteFeaturesAreNeverClaimed) {
  const WeightDirections every;
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(costs_more_at_every_direction(Row{inf, 1, 1, 1}, Row{0, 0, 0, 0}, every));
  EXPECT_FALSE(costs_more_at_every_direction(Row{1, 1, 1, 1}, Row{0, 0, 0, std::nan("")}, every));
  EXPECT_TRUE(costs_more_at_every_direction(Row{1, 1, 1, 1}, Row{0, 0, 0, 0}, every));
}

/// A 4-weight grid of `n` values each: 0, 1, ..., n - 1.
WeightGrid integer_grid(int n) {
  std::vector<double> v;
  for (int i = 0; i < n; ++i) v.push_back(i);
  return WeightGrid({v, v, v, v});
}

/// Random candidates: continuous features of both signs, sometimes a duplicate row or a row
/// tied with another along a direction.
Candidates random_candidates(Rng& rng) {
  Candidates c;
  c.feature_count = 4;
  const auto n = 2 + static_cast<int>(uniform_below(rng, 8));
  for (int i = 0; i < n; ++i) {
    c.cells.push_back(Cell{i, 0});
    for (int k = 0; k < 4; ++k)
      c.features.push_back((static_cast<double>(uniform_below(rng, 401)) - 100.0) / 3.0);
  }
  if (uniform_below(rng, 3) == 0) {  // a copy of row 0 at the end (an exact tie)
    c.cells.push_back(Cell{n, 0});
    for (int k = 0; k < 4; ++k) c.features.push_back(c.features[static_cast<std::size_t>(k)]);
  }
  return c;
}

TEST(WeightGrid, DirectionsBoundEveryPointsDirection) {
  Rng rng = make_rng(12, "weight_directions");
  const WeightGrid grid = integer_grid(13);
  for (int trial = 0; trial < 30; ++trial) {
    for (const WeightGrid::Share& share : grid.split(grid.everything(), random_candidates(rng))) {
      const WeightDirections d = grid.directions(share.region);
      bool zero = false;
      bool nonzero = false;
      grid.for_each_point(share.region, [&](const Point& at) {
        const std::vector<double> w = grid.weights_at(at);
        const double sum = w[0] + w[1] + w[2] + w[3];
        if (sum == 0.0) {
          zero = true;
          return;
        }
        nonzero = true;
        for (std::size_t k = 0; k < 4; ++k) {
          EXPECT_LE(d.lo[k], w[k] / sum) << "trial " << trial;
          EXPECT_GE(d.hi[k], w[k] / sum) << "trial " << trial;
        }
      });
      EXPECT_EQ(d.zero, zero) << "trial " << trial;
      EXPECT_EQ(d.nonzero, nonzero) << "trial " << trial;
    }
  }
}

TEST(WeightGrid, SoleChoiceIsArgminLinearsChoiceAtEveryPoint) {
  // Regions as the search makes them (shares of shares), asked about fresh candidates: when
  // sole_choice() names a candidate, argmin_linear() chooses it at every point.
  Rng rng = make_rng(13, "weight_directions");
  const WeightGrid grid = integer_grid(16);
  int named = 0;
  int one_share = 0;
  for (int trial = 0; trial < 40; ++trial) {
    for (const WeightGrid::Share& first : grid.split(grid.everything(), random_candidates(rng))) {
      for (const WeightGrid::Share& share : grid.split(first.region, random_candidates(rng))) {
        const WeightDirections d = grid.directions(share.region);
        for (int ask = 0; ask < 3; ++ask) {
          const Candidates c = random_candidates(rng);
          const int sole = grid.sole_choice(d, c);
          const bool single = grid.split(share.region, c).size() == 1;
          one_share += single ? 1 : 0;
          if (sole < 0) continue;
          ++named;
          EXPECT_TRUE(single) << "trial " << trial;
          grid.for_each_point(share.region, [&](const Point& at) {
            ASSERT_EQ(argmin_linear(c, grid.weights_at(at)), sole) << "trial " << trial;
          });
        }
      }
    }
  }
  EXPECT_GT(named, 30);         // narrow regions are proven whole
  EXPECT_GT(one_share, named);  // ... but not every region with one choice
}

TEST(WeightGrid, SplitOfNarrowRegionsWithNearTiesIsArgminLinearsChoice) {
  // Narrow regions far from the origin (shares of shares), where split() decides partial blocks
  // by comparing candidates over their points' span, asked about candidates that nearly tie
  // there (features a rounding apart, and sums of fractions equal in exact arithmetic on
  // w0 = w1): every point goes to argmin_linear()'s choice.
  Rng rng = make_rng(15, "weight_directions");
  std::vector<double> v;
  for (int i = 0; i < 24; ++i) v.push_back(40 + i);
  const WeightGrid grid({v, v, v, v});
  int points = 0;
  for (int trial = 0; trial < 12; ++trial) {
    for (const WeightGrid::Share& first : grid.split(grid.everything(), random_candidates(rng))) {
      for (const WeightGrid::Share& share : grid.split(first.region, random_candidates(rng))) {
        Candidates c = random_candidates(rng);
        const std::size_t n = c.cells.size();
        Row fi{};
        Row fj{};
        random_pair(rng, 1 + 2 * static_cast<int>(uniform_below(rng, 2)), fi, fj);
        for (const Row& f : {fi, fj, Row{0.1, 0.2, fi[2], fi[3]}, Row{0.3, 0.0, fi[2], fi[3]}}) {
          c.cells.push_back(Cell{static_cast<int>(c.cells.size()), 0});
          c.features.insert(c.features.end(), f.begin(), f.end());
        }
        std::vector<int> owner(static_cast<std::size_t>(grid.size()), -1);
        const auto slot = [](const Point& at) { return ((at[0] * 24 + at[1]) * 24 + at[2]) * 24 + at[3]; };
        for (const WeightGrid::Share& s : grid.split(share.region, c)) {
          grid.for_each_point(
              s.region, [&](const Point& at) { owner[static_cast<std::size_t>(slot(at))] = s.candidate; });
        }
        grid.for_each_point(share.region, [&](const Point& at) {
          ++points;
          ASSERT_EQ(owner[static_cast<std::size_t>(slot(at))], argmin_linear(c, grid.weights_at(at)))
              << "trial " << trial << ", " << n << " random candidates";
        });
      }
    }
  }
  EXPECT_GT(points, 1000000);
}

TEST(WeightGrid, SoleChoiceAtTheZeroVectorIsTheFirstCandidate) {
  const WeightGrid grid = integer_grid(3);
  WeightDirections only_zero;
  only_zero.zero = true;
  only_zero.nonzero = false;
  Candidates c;
  c.feature_count = 4;
  c.cells = {Cell{0, 0}, Cell{1, 0}};
  c.features = {5, 5, 5, 5, 1, 1, 1, 1};
  EXPECT_EQ(grid.sole_choice(only_zero, c), 0);  // every cost is 0: the first wins the tie
  EXPECT_EQ(argmin_linear(c, std::vector<double>{0, 0, 0, 0}), 0);
  // The whole grid holds the zero vector, and candidate 1 wins everywhere else: no sole choice.
  EXPECT_EQ(grid.sole_choice(grid.directions(grid.everything()), c), -1);
  c.features = {1, 1, 1, 1, 5, 5, 5, 5};
  EXPECT_EQ(grid.sole_choice(grid.directions(grid.everything()), c), 0);
}

}  // namespace
}  // namespace fsweep
