// WeightGrid and WeightRegion against plain enumeration: split() gives every point to the
// candidate argmin_linear() chooses there (blocks decided whole by their corners or point by
// point, regions holding whole and partial blocks, features of both signs, ties, non-finite
// features), and count, lexmin, bounds, contains and for_each_point agree with the points.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/random.hpp"
#include "weightsearch/weight_grid.hpp"

namespace fsweep {
namespace {

using Point = std::array<int, WeightGrid::kMaxWeights>;

/// Every point of `region`, by for_each_point.
std::vector<Point> points_of(const WeightGrid& grid, const WeightRegion& region) {
  std::vector<Point> out;
  grid.for_each_point(region, [&out](const Point& at) { out.push_back(at); });
  return out;
}

/// Checks count, lexmin, bounds and contains of a non-empty `region` against its points.
void expect_consistent(const WeightGrid& grid, const WeightRegion& region, const std::string& what) {
  const std::vector<Point> points = points_of(grid, region);
  ASSERT_FALSE(points.empty()) << what;
  EXPECT_EQ(grid.count(region), points.size()) << what;
  EXPECT_EQ(grid.lexmin(region), *std::min_element(points.begin(), points.end())) << what;
  const auto box = grid.bounds(region);
  for (std::size_t k = 0; k < WeightGrid::kMaxWeights; ++k) {
    int lo = points.front()[k];
    int hi = lo;
    for (const Point& p : points) {
      lo = std::min(lo, p[k]);
      hi = std::max(hi, p[k]);
    }
    EXPECT_EQ(box[k][0], lo) << what << " weight " << k;
    EXPECT_EQ(box[k][1], hi) << what << " weight " << k;
  }
  for (const Point& p : points) EXPECT_TRUE(grid.contains(region, p)) << what;
  // index_boxes(): disjoint boxes of exactly the region's points.
  std::vector<Point> boxed;
  for (const WeightGrid::IndexBox& b : grid.index_boxes(region)) {
    Point at{};
    for (at[0] = b.lo[0]; at[0] <= b.hi[0]; ++at[0]) {
      for (at[1] = b.lo[1]; at[1] <= b.hi[1]; ++at[1]) {
        for (at[2] = b.lo[2]; at[2] <= b.hi[2]; ++at[2]) {
          for (at[3] = b.lo[3]; at[3] <= b.hi[3]; ++at[3]) boxed.push_back(at);
        }
      }
    }
  }
  std::vector<Point> sorted = points;
  std::sort(sorted.begin(), sorted.end());
  std::sort(boxed.begin(), boxed.end());
  EXPECT_EQ(boxed, sorted) << what << ": index_boxes()";
}

/// Random candidates over `weights` features: small integers of both signs (so costs tie often)
/// and, when `infinite`, one feature +infinity.
Candidates random_candidates(Rng& rng, int weights, bool infinite) {
  Candidates c;
  c.feature_count = weights;
  const auto n = 2 + static_cast<int>(uniform_below(rng, 6));
  for (int i = 0; i < n; ++i) {
    c.cells.push_back(Cell{i, 0});
    for (int k = 0; k < weights; ++k) c.features.push_back(static_cast<double>(uniform_below(rng, 9)) - 3.0);
  }
  if (uniform_below(rng, 4) == 0) {  // a duplicate row: an exact tie everywhere
    c.cells.push_back(Cell{n, 0});
    const std::vector<double> row(c.features.begin(), c.features.begin() + weights);
    c.features.insert(c.features.end(), row.begin(), row.end());
  }
  if (infinite)
    c.features[static_cast<std::size_t>(uniform_below(rng, c.features.size()))] =
        std::numeric_limits<double>::infinity();
  return c;
}

/// split(region, c) against argmin_linear at every point of `region`; returns the shares.
std::vector<WeightGrid::Share> expect_split_is_argmin(const WeightGrid& grid, const WeightRegion& region,
                                                      const Candidates& c, const std::string& what) {
  std::vector<WeightGrid::Share> shares = grid.split(region, c);
  std::map<Point, int> owner;
  for (std::size_t s = 0; s < shares.size(); ++s) {
    if (s > 0) {
      EXPECT_LT(shares[s - 1].candidate, shares[s].candidate) << what;
    }
    expect_consistent(grid, shares[s].region, what);
    for (const Point& p : points_of(grid, shares[s].region)) {
      EXPECT_TRUE(owner.emplace(p, shares[s].candidate).second) << what << ": a point in two shares";
    }
  }
  const std::vector<Point> all = points_of(grid, region);
  EXPECT_EQ(owner.size(), all.size()) << what;
  for (const Point& p : all) {
    const auto it = owner.find(p);
    EXPECT_TRUE(it != owner.end() && it->second == argmin_linear(c, grid.weights_at(p))) << what;
  }
  return shares;
}

TEST(WeightGrid, SplitGivesEveryPointArgminLinearsChoice) {
  Rng rng = make_rng(3, "weight_grid");
  // Grids of 1 to 4 weights whose sizes are and are not multiples of the block edge.
  // The last has 3 x 1 x 3 x 2 blocks: boxes of blocks halved down to single blocks.
  const std::vector<std::vector<int>> shapes{{20},          {9, 17},       {8, 3, 11},
                                             {5, 9, 4, 10}, {16, 1, 8, 9}, {24, 3, 17, 10}};
  int shares_seen = 0;
  for (const std::vector<int>& shape : shapes) {
    std::vector<std::vector<double>> values;
    for (const int n : shape) {
      std::vector<double> v;
      for (int i = 0; i < n; ++i) v.push_back(i * 1.5 + (i > 2 ? 1.0 : 0.0));  // uneven steps
      values.push_back(v);
    }
    const WeightGrid grid(values);
    const int weights = static_cast<int>(shape.size());
    for (int trial = 0; trial < 12; ++trial) {
      const std::string what = std::to_string(weights) + " weights, trial " + std::to_string(trial);
      const Candidates first = random_candidates(rng, weights, trial % 4 == 3);
      const std::vector<WeightGrid::Share> shares =
          expect_split_is_argmin(grid, grid.everything(), first, what);
      shares_seen += static_cast<int>(shares.size());
      // Split each share again: regions of partial blocks.
      for (const WeightGrid::Share& share : shares) {
        (void)expect_split_is_argmin(grid, share.region, random_candidates(rng, weights, trial % 4 == 1),
                                     what + " again");
      }
    }
  }
  EXPECT_GT(shares_seen, 100);  // the candidates do divide the grids
}

TEST(WeightGrid, EverythingHoldsEveryPoint) {
  const WeightGrid grid({{0, 1, 2}, {5, 6, 7, 8, 9, 10, 11, 12, 13}});
  expect_consistent(grid, grid.everything(), "everything");
  EXPECT_EQ(grid.size(), 27U);
  EXPECT_FALSE(grid.contains(grid.everything(), Point{3, 0, 0, 0}));
  EXPECT_EQ(grid.weights_at(Point{2, 8, 0, 0}), (std::vector<double>{2, 13}));
}

TEST(WeightGrid, HoldsOnlyRegionsOfItsOwnBlocksAndPoints) {
  // 3 x 9 values: blocks (0, 0) and (0, 1), the second holding weight 1's last value only.
  const WeightGrid grid({{0, 1, 2}, {5, 6, 7, 8, 9, 10, 11, 12, 13}});
  EXPECT_TRUE(grid.holds(grid.everything()));
  Rng rng = make_rng(7, "holds");
  for (int trial = 0; trial < 20; ++trial) {
    for (const WeightGrid::Share& share : grid.split(grid.everything(), random_candidates(rng, 2, false))) {
      EXPECT_TRUE(grid.holds(share.region));
    }
  }
  const auto part = [](std::uint32_t block, int bit) {
    WeightRegion::Part p;
    p.block = block;
    p.bits[static_cast<std::size_t>(bit) / 64] |= std::uint64_t{1} << (bit % 64);
    return p;
  };
  const auto with_parts = [](std::vector<WeightRegion::Part> parts) {
    WeightRegion r;
    r.parts = std::move(parts);
    return r;
  };
  EXPECT_TRUE(grid.holds(with_parts({part(0, 0), part(1, 0)})));
  EXPECT_FALSE(grid.holds(with_parts({part(2, 0)}))) << "no block 2";
  EXPECT_FALSE(grid.holds(with_parts({part(1, 64)}))) << "block 1 has no second value of weight 1";
  EXPECT_FALSE(grid.holds(with_parts({part(0, 3 * 512)}))) << "weight 0 has 3 values";
  EXPECT_FALSE(grid.holds(with_parts({part(1, 0), part(0, 0)}))) << "out of order";
  EXPECT_FALSE(grid.holds(with_parts({part(0, 0), part(0, 1)}))) << "a block twice";
  EXPECT_FALSE(grid.holds(with_parts({WeightRegion::Part{}}))) << "a part without points";
  const auto with_box = [](std::array<std::uint32_t, 4> lo, std::array<std::uint32_t, 4> hi) {
    WeightRegion r;
    r.whole.push_back(WeightRegion::Box{lo, hi});
    return r;
  };
  EXPECT_TRUE(grid.holds(with_box({0, 0, 0, 0}, {1, 2, 1, 1})));
  EXPECT_FALSE(grid.holds(with_box({0, 1, 0, 0}, {1, 1, 1, 1}))) << "an empty box";
  EXPECT_FALSE(grid.holds(with_box({0, 0, 0, 0}, {1, 3, 1, 1}))) << "weight 1 has 2 blocks";
  EXPECT_FALSE(grid.holds(with_box({0, 0, 0, 0}, {1, 1, 2, 1}))) << "an unused weight has 1 block";
}

TEST(WeightGrid, ShardsAreDisjointAndCoverTheGridInAFewBoxes) {
  // Grids of 1 to 4 weights whose block counts are not multiples of the shard counts, and more
  // shards than blocks (some empty).
  const auto values = [](int n) {
    std::vector<double> v;
    for (int i = 0; i < n; ++i) v.push_back(i);
    return v;
  };
  for (const std::vector<int>& shape :
       std::vector<std::vector<int>>{{20}, {17, 30}, {9, 25, 3}, {24, 3, 17, 10}}) {
    std::vector<std::vector<double>> lists;
    for (const int n : shape) lists.push_back(values(n));
    const WeightGrid grid(lists);
    for (const std::uint64_t count : {1U, 2U, 3U, 7U, 40U}) {
      const std::string what =
          std::to_string(shape.size()) + " weights, " + std::to_string(count) + " shards";
      std::map<Point, std::uint64_t> owner;
      WeightRegion all;
      for (std::uint64_t i = 0; i < count; ++i) {
        const WeightRegion shard = grid.shard(i, count);
        EXPECT_LE(shard.whole.size(), 4U * 2U * 4U) << what;
        for (const Point& p : points_of(grid, shard)) {
          EXPECT_TRUE(owner.emplace(p, i).second) << what << ": a point in two shards";
        }
        if (!shard.empty()) expect_consistent(grid, shard, what);
        all = WeightGrid::united(all, shard);
      }
      EXPECT_EQ(owner.size(), grid.size()) << what;
      EXPECT_EQ(grid.count(all), grid.size()) << what;
      if (count == 1) {
        EXPECT_EQ(grid.count(grid.shard(0, 1)), grid.size());
      }
    }
  }
  const WeightGrid grid({values(3)});
  EXPECT_THROW((void)grid.shard(2, 2), std::invalid_argument);
  EXPECT_THROW((void)grid.shard(0, 0), std::invalid_argument);
}

TEST(WeightGrid, PointRunsGiveBackTheirBits) {
  // Blocks of every density, empty and full, and the first and last bits alone.
  Rng rng = make_rng(5, "point_runs");
  std::vector<BlockBits> blocks;
  BlockBits all{};
  all.fill(~std::uint64_t{0});
  BlockBits first{};
  first[0] = 1;
  BlockBits last{};
  last[63] = std::uint64_t{1} << 63U;
  blocks.insert(blocks.end(), {BlockBits{}, all, first, last});
  for (int trial = 0; trial < 200; ++trial) {
    BlockBits b{};
    const std::uint64_t density = uniform_below(rng, 65);
    for (int bit = 0; bit < 4096; ++bit) {
      if (uniform_below(rng, 64) < density) {
        b[static_cast<std::size_t>(bit) / 64] |= std::uint64_t{1} << (bit % 64);
      }
    }
    blocks.push_back(b);
  }
  for (const BlockBits& b : blocks) {
    const std::vector<std::uint32_t> runs = point_runs(b);
    ASSERT_EQ(runs.size() % 2, 0U);
    std::uint64_t in = 0;
    for (std::size_t r = 1; r < runs.size(); r += 2) in += runs[r];
    std::uint64_t bits = 0;
    for (const std::uint64_t word : b) bits += static_cast<std::uint64_t>(std::popcount(word));
    EXPECT_EQ(in, bits);
    EXPECT_EQ(bits_of_runs(runs), b);
  }
  EXPECT_EQ(point_runs(all), (std::vector<std::uint32_t>{0, 4096}));
  EXPECT_EQ(point_runs(last), (std::vector<std::uint32_t>{4095, 1}));
  EXPECT_TRUE(point_runs(BlockBits{}).empty());
  const auto refusal = [](std::vector<std::uint32_t> runs) {
    try {
      (void)bits_of_runs(runs);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  };
  EXPECT_EQ(refusal({3}), "an odd number of runs (the last must be of points in)");
  EXPECT_EQ(refusal({3, 0}), "a run of 0 points after the first");
  EXPECT_EQ(refusal({4000, 97}), "runs of more than 4096 points");
  EXPECT_EQ(refusal({4000, 90, 2, 5}), "runs of more than 4096 points");
  EXPECT_EQ(refusal({4000, 96}), "(accepted)");
}

TEST(WeightGrid, RefusesBadValueLists) {
  const auto refusal = [](std::vector<std::vector<double>> values) {
    try {
      const WeightGrid grid(std::move(values));
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  };
  EXPECT_EQ(refusal({}), "a weight grid has 1 to 4 weights, not 0");
  EXPECT_EQ(refusal({{0}, {0}, {0}, {0}, {0}}), "a weight grid has 1 to 4 weights, not 5");
  EXPECT_EQ(refusal({{0}, {}}), "weight 2 has no value");
  const std::string order = "the values of weight 1 must be finite, >= 0 and strictly ascending";
  EXPECT_EQ(refusal({{1, 1}}), order);
  EXPECT_EQ(refusal({{2, 1}}), order);
  EXPECT_EQ(refusal({{-1, 1}}), order);
  EXPECT_EQ(refusal({{0, std::numeric_limits<double>::infinity()}}), order);
  EXPECT_EQ(refusal({{0, std::numeric_limits<double>::quiet_NaN()}}), order);
  EXPECT_THROW((void)WeightGrid({{0, 1}}).split(WeightGrid({{0, 1}}).everything(), Candidates{}),
               std::invalid_argument);
}

}  // namespace
}  // namespace fsweep
