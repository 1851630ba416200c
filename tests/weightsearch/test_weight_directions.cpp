// The exact weight search's proofs by direction: costs_more_at_every_direction() claims that one
// candidate costs more than another at every weight vector of a set of directions, as
// linear_cost() computes both; WeightGrid::directions() bounds the directions of a region's
// points; WeightGrid::sole_choice() names the candidate argmin_linear() chooses at every point
// of a region. Each claim is checked at the vectors it speaks of, with near-ties whose order
// rounding decides.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "core/random.hpp"
#include "weightsearch/weight_grid.hpp"

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

/// Random candidates whose third feature is `sign` times the second (the energy-aware
/// strategy's d_gbe = -d_gb above half charge, +d_gb below): lengths of an 8-connected grid of
/// 10 m cells (10 a + 10 sqrt(2) b), theta_rel in eighths; some rows repeat another's lengths
/// with another theta_rel, one in three repeats a row whole (an exact tie).
Candidates random_tied_candidates(Rng& rng, int sign) {
  Candidates c;
  c.feature_count = 4;
  const auto length = [&] {
    return 10.0 * static_cast<double>(uniform_below(rng, 9)) +
           10.0 * std::sqrt(2.0) * static_cast<double>(uniform_below(rng, 6));
  };
  const auto n = 2 + static_cast<int>(uniform_below(rng, 10));
  for (int i = 0; i < n; ++i) {
    c.cells.push_back(Cell{i, 0});
    double g = length();
    double gb = length();
    if (i > 0 && uniform_below(rng, 4) == 0) {  // another's lengths, another turn
      g = c.features[0];
      gb = c.features[1];
    }
    const double theta = static_cast<double>(uniform_below(rng, 9)) / 8.0;
    for (const double f : {g, gb, sign * gb, theta}) c.features.push_back(f);
  }
  if (uniform_below(rng, 3) == 0) {
    c.cells.push_back(Cell{n, 0});
    for (int k = 0; k < 4; ++k) c.features.push_back(c.features[static_cast<std::size_t>(k)]);
  }
  return c;
}

/// v of WeightGrid::tied_directions(): (w1, max(w2 - w3, 0), max(w3 - w2, 0), w4) for sign -1,
/// (w1, w2 + w3, 0, w4) for +1.
Row tied_coordinates(const std::vector<double>& w, int sign) {
  const double u = w[1] - w[2];
  return sign < 0 ? Row{w[0], std::max(u, 0.0), std::max(-u, 0.0), w[3]} : Row{w[0], w[1] + w[2], 0.0, w[3]};
}

TEST(WeightGrid, TiedSignSeesTheThirdFeatureAsTheSecondSigned) {
  Rng rng = make_rng(21, "weight_directions");
  EXPECT_EQ(WeightGrid::tied_sign(random_tied_candidates(rng, -1)), -1);
  EXPECT_EQ(WeightGrid::tied_sign(random_tied_candidates(rng, 1)), 1);
  Candidates c = random_tied_candidates(rng, -1);
  c.features[6] = std::nextafter(c.features[6], 1e9);  // row 1's third feature, one ulp off
  EXPECT_EQ(WeightGrid::tied_sign(c), 0);
  Candidates zeros;
  zeros.feature_count = 4;
  zeros.cells = {Cell{0, 0}};
  zeros.features = {3, 0, 0, 1};  // 0 = -0 and 0 = +0: either sign is right; -1 is said
  EXPECT_EQ(WeightGrid::tied_sign(zeros), -1);
}

TEST(WeightGrid, TiedRatioBoundsTheSmallerOfW2AndW3OverTheOtherTerms) {
  // At every point where w1 + |w2 - w3| + w4 > 0, min(w2, w3) over it is at most tied_ratio().
  for (const std::vector<double>& values :
       {std::vector<double>{0, 1, 2, 3, 4, 5, 6, 7}, std::vector<double>{0, 0.25, 3, 7.5},
        std::vector<double>{40, 41, 47}}) {
    const WeightGrid grid({values, values, values, values});
    double worst = 0.0;
    grid.for_each_point(grid.everything(), [&](const Point& at) {
      const std::vector<double> w = grid.weights_at(at);
      const double others = w[0] + std::abs(w[1] - w[2]) + w[3];
      if (others > 0.0) worst = std::max(worst, std::min(w[1], w[2]) / others);
    });
    EXPECT_GE(grid.tied_ratio(), worst);
    EXPECT_GT(worst, 0.0);
  }
  EXPECT_NEAR(integer_grid(251).tied_ratio(), 250.0, 1e-9);
}

TEST(WeightGrid, TiedDirectionsBoundEveryPointsDirectionInTheirCoordinates) {
  Rng rng = make_rng(22, "weight_directions");
  const WeightGrid grid = integer_grid(13);
  for (int trial = 0; trial < 30; ++trial) {
    const int sign = trial % 2 == 0 ? -1 : 1;
    for (const WeightGrid::Share& share : grid.split(grid.everything(), random_tied_candidates(rng, sign))) {
      const WeightDirections d = grid.tied_directions(share.region, sign);
      bool zero = false;
      grid.for_each_point(share.region, [&](const Point& at) {
        const Row v = tied_coordinates(grid.weights_at(at), sign);
        const double sum = v[0] + v[1] + v[2] + v[3];
        if (sum == 0.0) {
          zero = true;
          return;
        }
        EXPECT_TRUE(d.nonzero);
        for (std::size_t k = 0; k < 4; ++k) {
          EXPECT_LE(d.lo[k], v[k] / sum) << "trial " << trial;
          EXPECT_GE(d.hi[k], v[k] / sum) << "trial " << trial;
        }
      });
      if (zero) {
        EXPECT_TRUE(d.zero) << "trial " << trial;
      }
    }
  }
}

TEST(WeightGrid, SoleChoiceTiedIsArgminLinearsChoiceAtEveryPoint) {
  // Regions as the search makes them from tied candidates (shares of shares: slabs along
  // (0, 1, -sign, 0)), asked about fresh tied candidates, some with near-ties one rounding
  // apart: when sole_choice_tied() names a candidate, argmin_linear() chooses it at every
  // point, including the line w1 = w4 = 0, w2 = w3 where the costs cancel to 0. It proves many
  // regions that sole_choice() by the directions of w does not.
  Rng rng = make_rng(23, "weight_directions");
  int named = 0;
  int only_tied = 0;
  for (const int first_value : {0, 40}) {
    std::vector<double> v;
    for (int i = 0; i < 16; ++i) v.push_back(first_value + i);
    const WeightGrid grid({v, v, v, v});
    for (int trial = 0; trial < 24; ++trial) {
      const int sign = trial % 3 == 0 ? 1 : -1;
      for (const WeightGrid::Share& first :
           grid.split(grid.everything(), random_tied_candidates(rng, sign))) {
        for (const WeightGrid::Share& share : grid.split(first.region, random_tied_candidates(rng, sign))) {
          const WeightDirections plain = grid.directions(share.region);
          const WeightDirections tied = grid.tied_directions(share.region, sign);
          for (int ask = 0; ask < 3; ++ask) {
            Candidates c = random_tied_candidates(rng, sign);
            if (ask == 2) {  // a row a rounding away from row 0 in its first feature
              c.cells.push_back(Cell{static_cast<int>(c.cells.size()), 0});
              for (int k = 0; k < 4; ++k) {
                const double f = c.features[static_cast<std::size_t>(k)];
                c.features.push_back(k == 0 ? std::nextafter(f, 1e9) : f);
              }
            }
            const int sole = grid.sole_choice_tied(tied, sign, c);
            if (sole < 0) continue;
            ++named;
            only_tied += grid.sole_choice(plain, c) < 0 ? 1 : 0;
            grid.for_each_point(share.region, [&](const Point& at) {
              ASSERT_EQ(argmin_linear(c, grid.weights_at(at)), sole)
                  << "values from " << first_value << ", trial " << trial << ", sign " << sign;
            });
          }
        }
      }
    }
  }
  EXPECT_GT(named, 100);
  EXPECT_GT(only_tied, named / 4);
}

TEST(WeightGrid, SplitByTiedDirectionsIsArgminLinearsChoice) {
  // split() given the region's tied directions rules out candidates per block in those
  // coordinates too: every point still goes to argmin_linear()'s choice, near-ties included, on
  // slabs near the origin (the line w1 = w4 = 0, w2 = w3 included) and far from it.
  Rng rng = make_rng(24, "weight_directions");
  long points = 0;
  for (const int first_value : {0, 40}) {
    std::vector<double> v;
    for (int i = 0; i < 16; ++i) v.push_back(first_value + i);
    const WeightGrid grid({v, v, v, v});
    std::vector<int> owner(static_cast<std::size_t>(grid.size()), -1);
    const auto slot = [](const Point& at) { return ((at[0] * 16 + at[1]) * 16 + at[2]) * 16 + at[3]; };
    for (int trial = 0; trial < 12; ++trial) {
      const int sign = trial % 3 == 0 ? 1 : -1;
      for (const WeightGrid::Share& first :
           grid.split(grid.everything(), random_tied_candidates(rng, sign))) {
        for (const WeightGrid::Share& share : grid.split(first.region, random_tied_candidates(rng, sign))) {
          const WeightDirections tied = grid.tied_directions(share.region, sign);
          Candidates c = random_tied_candidates(rng, sign);
          c.cells.push_back(Cell{static_cast<int>(c.cells.size()), 0});
          for (int k = 0; k < 4; ++k) {  // a row a rounding away from row 0
            const double f = c.features[static_cast<std::size_t>(k)];
            c.features.push_back(k == 0 ? std::nextafter(f, -1e9) : f);
          }
          for (const WeightGrid::Share& s : grid.split(share.region, c, &tied)) {
            grid.for_each_point(
                s.region, [&](const Point& at) { owner[static_cast<std::size_t>(slot(at))] = s.candidate; });
          }
          grid.for_each_point(share.region, [&](const Point& at) {
            ++points;
            ASSERT_EQ(owner[static_cast<std::size_t>(slot(at))], argmin_linear(c, grid.weights_at(at)))
                << "values from " << first_value << ", trial " << trial << ", sign " << sign;
          });
        }
      }
    }
  }
  EXPECT_GT(points, 1000000);
}

TEST(WeightGrid, SoleChoiceTiedKeepsTheMarginOfTheCostsAsComputed) {
  // The tied coordinates drop min(w2, w3): at w = (0, 1e8 + 1, 1e8, 0), v = (0, 1, 0, 0), but
  // the costs add two products near 1e8 f2 whose rounding dwarfs a difference of f2 in the 11th
  // digit. Candidate 1 costs more than candidate 0 in exact arithmetic, by more than the margin
  // of v alone, yet argmin_linear() chooses it there. The extra margin (tied_ratio() is 1e8 on
  // this grid) refuses the claim.
  const WeightGrid grid({{0.0}, {1e8, 1e8 + 1}, {1e8}, {0.0}});
  EXPECT_GE(grid.tied_ratio(), 1e8);
  const double g = 10.0 / 7.0;
  const double g1 = g * (1 + 1e-11);
  Candidates c;
  c.feature_count = 4;
  c.cells = {Cell{0, 0}, Cell{1, 0}};
  c.features = {0, g, -g, 0, 0, g1, -g1, 0};
  ASSERT_EQ(WeightGrid::tied_sign(c), -1);
  EXPECT_EQ(argmin_linear(c, std::vector<double>{0, 1e8 + 1, 1e8, 0}), 1);  // rounding decides
  EXPECT_EQ(argmin_linear(c, std::vector<double>{0, 1e8, 1e8, 0}), 0);      // v = 0: every cost 0
  const WeightDirections tied = grid.tied_directions(grid.everything(), -1);
  EXPECT_EQ(grid.sole_choice_tied(tied, -1, c), -1);
  // Without the extra margin the claim would pass: the difference is above v's own margin.
  EXPECT_TRUE(costs_more_at_every_direction(std::span<const double>(c.features).subspan(4, 4),
                                            std::span<const double>(c.features).first(4), tied));
  EXPECT_FALSE(costs_more_at_every_direction(
      std::span<const double>(c.features).subspan(4, 4), std::span<const double>(c.features).first(4), tied,
      grid.tied_extra(-1, std::span<const double>(c.features).subspan(4, 4),
                      std::span<const double>(c.features).first(4))));
  // split() with the tied directions still gives each point its argmin.
  for (const WeightGrid::Share& share : grid.split(grid.everything(), c, &tied)) {
    grid.for_each_point(share.region, [&](const Point& at) {
      EXPECT_EQ(argmin_linear(c, grid.weights_at(at)), share.candidate);
    });
  }
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
