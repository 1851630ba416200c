#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <set>
#include <utility>
#include <vector>

#include "core/random.hpp"
#include "search/dijkstra_list.hpp"
#include "world/grid.hpp"

namespace fsweep {
namespace test_dijkstra_list {

/// An octile-like cost: a + b sqrt(2) cells, so costs share buckets in varied ways, some exact
/// integers.
double octile_like(Rng& rng, int max_steps) {
  return static_cast<double>(uniform_below(rng, static_cast<std::uint64_t>(max_steps))) +
         static_cast<double>(uniform_below(rng, static_cast<std::uint64_t>(max_steps))) * kSqrt2;
}

/// Pushes and pops as a Dijkstra run makes them (every push at least one cell past the last
/// pop, some from seeds added before the first pop), and also the pushes the search never makes
/// but the lists accept: a zero-cost edge (in the bucket being popped) and an entry below it.
/// Both lists must pop what a sorted set of (g, state) pops.
template <typename List>
void pops_in_order(const char* name) {
  List list;
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    Rng rng = make_rng(seed, name);
    list.clear();
    std::set<std::pair<double, int>> reference;
    int next_state = 0;
    const auto push = [&](double g, bool seed_entry) {
      const DijkstraItem item{g, next_state++};
      if (seed_entry) {
        list.add(item);
      } else {
        list.push(item);
      }
      reference.emplace(item.g, item.state);
    };
    const int seeds = static_cast<int>(uniform_below(rng, 20));
    for (int i = 0; i < seeds; ++i) push(octile_like(rng, 30), true);
    list.start();
    double last = 0.0;
    for (int op = 0; op < 3000; ++op) {
      const std::uint64_t kind = uniform_below(rng, 20);
      if (kind < 8 && !reference.empty()) {
        ASSERT_FALSE(list.empty());
        const DijkstraItem top = list.pop();
        ASSERT_EQ(std::make_pair(top.g, top.state), *reference.begin())
            << name << " seed " << seed << " op " << op;
        reference.erase(reference.begin());
        last = top.g;
      } else if (kind < 18) {  // an edge of 1 to a few cells
        push(last + 1.0 + octile_like(rng, 3), false);
      } else if (kind == 18) {  // a zero-cost edge: into the bucket being popped
        push(last, false);
      } else {  // below it (a seed opened after the first pop)
        push(std::max(0.0, last - octile_like(rng, 5)), false);
      }
      ASSERT_EQ(list.empty(), reference.empty());
    }
    while (!reference.empty()) {
      const DijkstraItem top = list.pop();
      ASSERT_EQ(std::make_pair(top.g, top.state), *reference.begin()) << name << " seed " << seed;
      reference.erase(reference.begin());
    }
    EXPECT_TRUE(list.empty());
  }
}

TEST(DijkstraList, BucketsPopInTheOrderOfGThenState) { pops_in_order<DijkstraBuckets>("buckets"); }

TEST(DijkstraList, HeapPopsInTheOrderOfGThenState) { pops_in_order<DijkstraHeap>("heap"); }

TEST(DijkstraList, BucketsCanBeClearedMidRunAndReused) {
  DijkstraBuckets list;
  for (int i = 0; i < 50; ++i) list.push(DijkstraItem{10.0 + i * kSqrt2, i});
  (void)list.pop();
  list.clear();  // entries left in many buckets
  EXPECT_TRUE(list.empty());
  list.push(DijkstraItem{3.5, 7});
  list.push(DijkstraItem{3.5, 2});
  list.push(DijkstraItem{1.0, 9});
  EXPECT_EQ(list.pop().state, 9);
  EXPECT_EQ(list.pop().state, 2);
  EXPECT_EQ(list.pop().state, 7);
  EXPECT_TRUE(list.empty());
}

}  // namespace test_dijkstra_list
}  // namespace fsweep
