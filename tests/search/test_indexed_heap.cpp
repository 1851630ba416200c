#include <gtest/gtest.h>

#include <cstdint>
#include <set>
#include <utility>
#include <vector>

#include "core/random.hpp"
#include "search/indexed_heap.hpp"

namespace fsweep {
namespace test_indexed_heap {

/// An entry keyed by a small integer (many ties), then by state.
struct Item {
  int key;
  int state;
  static bool before(const Item& a, const Item& b) {
    if (a.key != b.key) return a.key < b.key;
    return a.state < b.state;
  }
};

TEST(IndexedHeap, PopsInKeyOrderThroughPushesAndReKeysBothWays) {
  constexpr int kStates = 300;
  IndexedHeap<Item> heap;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    Rng rng = make_rng(seed, "indexed_heap");
    heap.reset(kStates);
    std::set<std::pair<int, int>> reference;  // (key, state): the same order
    std::vector<int> key_of(kStates, -1);     // -1: not in the heap
    for (int op = 0; op < 5000; ++op) {
      if (uniform_below(rng, 3) == 0 && !reference.empty()) {
        const Item top = heap.pop();
        ASSERT_EQ(std::make_pair(top.key, top.state), *reference.begin()) << "seed " << seed << " op " << op;
        reference.erase(reference.begin());
        key_of[static_cast<std::size_t>(top.state)] = -1;
        continue;
      }
      // Insert, or re-key up or down (a state already in the heap).
      const int state = static_cast<int>(uniform_below(rng, kStates));
      const int key = static_cast<int>(uniform_below(rng, 40));
      int& old = key_of[static_cast<std::size_t>(state)];
      if (old >= 0) reference.erase({old, state});
      old = key;
      reference.insert({key, state});
      heap.push_or_update(Item{key, state});
      ASSERT_EQ(heap.size(), reference.size());
    }
    if (seed % 2 == 0) continue;  // leave entries behind: reset() must forget them
    while (!reference.empty()) {
      const Item top = heap.pop();
      ASSERT_EQ(std::make_pair(top.key, top.state), *reference.begin());
      reference.erase(reference.begin());
    }
    EXPECT_TRUE(heap.empty());
  }
}

TEST(IndexedHeap, ClearForgetsEntriesSoTheyComeBackAsNew) {
  IndexedHeap<Item> heap;
  heap.reset(4);
  heap.push_or_update(Item{5, 1});
  heap.push_or_update(Item{3, 2});
  heap.clear();
  EXPECT_TRUE(heap.empty());
  heap.push_or_update(Item{7, 2});  // a new entry, not a re-key of the cleared one
  heap.push_or_update(Item{6, 1});
  EXPECT_EQ(heap.size(), 2U);
  EXPECT_EQ(heap.pop().state, 1);
  EXPECT_EQ(heap.pop().state, 2);
  EXPECT_TRUE(heap.empty());
}

}  // namespace test_indexed_heap
}  // namespace fsweep
