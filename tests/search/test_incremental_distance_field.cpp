#include <gtest/gtest.h>

#include <cmath>

#include "core/random.hpp"
#include "search/distance_field.hpp"
#include "search/incremental_distance_field.hpp"

namespace fsweep {
namespace {

// Reveals a random 60x60 world (25% obstacles) in random batches and checks after every batch
// that the incrementally updated field equals a from-scratch Dijkstra, bit for bit.
void check_matches_scratch(bool corner_cutting, std::uint64_t seed) {
  const int w = 60;
  const int h = 60;
  Rng rng = make_rng(seed, "test");
  std::vector<bool> occupied(static_cast<std::size_t>(w * h));
  for (auto&& o : occupied) o = uniform01(rng) < 0.25;
  const Cell source{30, 30};
  occupied[static_cast<std::size_t>(source.y * w + source.x)] = false;

  KnownMap known(w, h, 0.5);
  known.reveal(known.index(source), false);
  IncrementalDistanceField inc;
  inc.reset(known, source, corner_cutting);

  std::vector<int> order(static_cast<std::size_t>(w * h));
  for (int i = 0; i < w * h; ++i) order[static_cast<std::size_t>(i)] = i;
  for (std::size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[uniform_below(rng, i)]);

  DistanceField scratch;
  DistanceQuery q;
  q.allow_corner_cutting = corner_cutting;
  for (std::size_t start = 0; start < order.size(); start += 97) {
    std::vector<int> batch;
    for (std::size_t k = start; k < std::min(order.size(), start + 97); ++k) {
      const int i = order[k];
      if (known.reveal(i, occupied[static_cast<std::size_t>(i)])) batch.push_back(i);
    }
    inc.update(known, batch);
    scratch.compute(known, source, q);
    for (int i = 0; i < w * h; ++i) {
      ASSERT_EQ(std::isinf(inc.distance_m(i)), std::isinf(scratch.distance_m(i))) << "cell " << i;
      if (!std::isinf(inc.distance_m(i))) {
        // Exact costs: the same length bit for bit, however the update reached it.
        ASSERT_EQ(inc.distance_m(i), scratch.distance_m(i)) << "cell " << i << " after " << start;
      }
    }
  }
}

TEST(IncrementalDistanceField, MatchesScratchAsTheMapGrows) { check_matches_scratch(false, 1); }
TEST(IncrementalDistanceField, MatchesScratchWithCornerCutting) { check_matches_scratch(true, 2); }

TEST(IncrementalDistanceField, UnknownSourceGivesEmptyField) {
  KnownMap known(5, 5, 1.0);
  IncrementalDistanceField inc;
  inc.reset(known, Cell{2, 2}, false);
  EXPECT_TRUE(std::isinf(inc.distance_m(known.index(Cell{2, 2}))));
}

}  // namespace
}  // namespace fsweep
