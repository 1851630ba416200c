#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

#include "core/random.hpp"
#include "search/grid_search.hpp"
#include "search/indexed_heap.hpp"

namespace fsweep {
namespace test_indexed_heap {

/// An entry keyed by a small integer (many ties), then by state.
struct Item {
  int key;
  int state;
  [[nodiscard]] int id() const { return state; }
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
      // Insert, or re-key up or down (a state already in the heap): a smaller key for a state
      // in the heap half of the time by decrease(), which may only move it up.
      const int state = static_cast<int>(uniform_below(rng, kStates));
      const int key = static_cast<int>(uniform_below(rng, 40));
      int& old = key_of[static_cast<std::size_t>(state)];
      const bool smaller = old >= 0 && key < old;
      if (old >= 0) reference.erase({old, state});
      old = key;
      reference.insert({key, state});
      if (smaller && op % 2 == 0) {
        heap.decrease(Item{key, state});
      } else {
        heap.push_or_update(Item{key, state});
      }
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

/// The order A*'s list had before its entries were packed: f, then the larger g, then the
/// smaller state, comparing the costs' doubles.
bool before_as_doubles(OctileCost f1, OctileCost g1, int s1, OctileCost f2, OctileCost g2, int s2) {
  if (f1.value() != f2.value()) return f1.value() < f2.value();
  if (g1.value() != g2.value()) return g1.value() > g2.value();
  return s1 < s2;
}

TEST(PackedOctileItem, OrdersAsTheCostsDoublesWithTiesAndLongPaths) {
  // Small counts (many equal f and g, and near-equal ones such as 29 sqrt(2) against 41) and
  // counts up to 2^20, where distinct lengths come closest; the largest state id.
  for (const int range : {60, 1 << 20}) {
    Rng rng = make_rng(static_cast<std::uint64_t>(range), "packed_octile_item");
    const auto draw = [&](int limit) {
      return static_cast<int>(uniform_below(rng, static_cast<std::uint64_t>(limit)));
    };
    struct Entry {
      OctileCost f, g;
      int state;
      PackedOctileItem item;
    };
    std::vector<Entry> entries;
    for (int i = 0; i < 400; ++i) {
      const OctileCost g{draw(range), draw(range)};
      const OctileCost f = g + OctileCost{draw(range), draw(range)};
      const int state = i % 7 == 0 ? std::numeric_limits<int>::max() - draw(3) : draw(1000);
      entries.push_back({f, g, state, PackedOctileItem::make(f, g, state)});
    }
    entries.push_back(entries[5]);  // the same entry twice
    for (const Entry& a : entries) {
      ASSERT_EQ(a.item.id(), a.state);
      for (const Entry& b : entries) {
        ASSERT_EQ(PackedOctileItem::before(a.item, b.item),
                  before_as_doubles(a.f, a.g, a.state, b.f, b.g, b.state))
            << "f " << a.f.straight << "+" << a.f.diagonal << "r2, g " << a.g.straight << "+" << a.g.diagonal
            << "r2, state " << a.state << " against f " << b.f.straight << "+" << b.f.diagonal << "r2, g "
            << b.g.straight << "+" << b.g.diagonal << "r2, state " << b.state;
      }
    }
  }
  // 29 sqrt(2) = 41.012...: f just above 41 straight steps, with equal g, comes after.
  EXPECT_TRUE(PackedOctileItem::before(PackedOctileItem::make({41, 0}, {1, 0}, 9),
                                       PackedOctileItem::make({0, 29}, {1, 0}, 2)));
}

TEST(PackedOctileItem, RefusesACostOf2To24CellsOrMore) {
  EXPECT_NO_THROW((void)PackedOctileItem::make({(1 << 24) - 1, 0}, {0, 0}, 0));
  EXPECT_THROW((void)PackedOctileItem::make({1 << 24, 0}, {0, 0}, 0), std::overflow_error);
  EXPECT_THROW((void)PackedOctileItem::make({0, 1 << 24}, {0, 1 << 24}, 0), std::overflow_error);
}

}  // namespace test_indexed_heap
}  // namespace fsweep
