#pragma once
/// @file indexed_heap.hpp
/// The open list of BestFirstSearchT (grid_search.hpp): a 4-ary min-heap holding at most one
/// entry per state, with the state's position kept so that a cheaper path re-keys its entry in
/// place (decrease-key, as Warthog's pqueue) instead of pushing a duplicate. Popping runs the
/// entries in the order of `Item::before`, which must be a strict total order (the search's
/// key ends on the state id), so the pops are the same whatever the heap's shape.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace fsweep {
inline namespace search {

/// `Item` has `int id() const`, its state in [0, state count), and a static `bool before(const
/// Item&, const Item&)`: a strict total order, true when the first comes out first.
template <typename Item>
class IndexedHeap {
 public:
  /// Children per node: 4 halves the depth of a binary heap for one more comparison a level,
  /// and the four children of a node are adjacent in memory.
  static constexpr std::size_t kArity = 4;

  /// Empties the heap and sizes the positions for states 0..state_count-1.
  void reset(std::size_t state_count) {
    items_.clear();
    if (position_.size() != state_count) position_.assign(state_count, 0);
  }
  /// Empties the heap (in constant time: positions are checked against the entries, not
  /// cleared).
  void clear() { items_.clear(); }
  [[nodiscard]] bool empty() const { return items_.empty(); }
  [[nodiscard]] std::size_t size() const { return items_.size(); }

  /// Inserts `item`, whose state the heap must not hold (below reset()'s state count).
  void push(const Item& item) {
    items_.push_back(item);
    sift_up(items_.size() - 1, item);
  }
  /// Inserts `item`, or replaces the entry of `item.id()` if the heap holds one (its key may
  /// move either way). The state must be below reset()'s state count.
  void push_or_update(const Item& item) {
    const std::uint32_t at = position_[idx(item.id())];
    if (at >= items_.size() || items_[at].id() != item.id()) {
      push(item);
    } else if (at > 0 && Item::before(item, items_[(at - 1) / kArity])) {
      sift_up(at, item);
    } else {
      sift_down(at, item);
    }
  }
  /// Re-keys the entry of `item.id()`, which the heap must hold, to `item`, which must come
  /// before it (a decrease-key): it can only move up.
  void decrease(const Item& item) { sift_up(position_[idx(item.id())], item); }
  /// Removes and returns the first entry; the heap must not be empty.
  Item pop() {
    const Item top = items_.front();
    const Item last = items_.back();
    items_.pop_back();
    if (!items_.empty()) sift_down(0, last);
    return top;
  }

 private:
  static std::size_t idx(int state) { return static_cast<std::size_t>(state); }

  /// Puts `item` at `at` and records its position.
  void place(std::size_t at, const Item& item) {
    items_[at] = item;
    position_[idx(item.id())] = static_cast<std::uint32_t>(at);
  }
  /// Moves `item`, meant for slot `at`, up past the entries it comes before.
  void sift_up(std::size_t at, const Item& item) {
    while (at > 0) {
      const std::size_t up = (at - 1) / kArity;
      if (!Item::before(item, items_[up])) break;
      place(at, items_[up]);
      at = up;
    }
    place(at, item);
  }
  /// Moves `item`, meant for slot `at`, down past the children that come before it.
  void sift_down(std::size_t at, const Item& item) {
    const std::size_t n = items_.size();
    for (;;) {
      const std::size_t first = at * kArity + 1;
      if (first >= n) break;
      const std::size_t end = first + kArity < n ? first + kArity : n;
      std::size_t best = first;
      for (std::size_t c = first + 1; c < end; ++c) best = Item::before(items_[c], items_[best]) ? c : best;
      if (!Item::before(items_[best], item)) break;
      place(at, items_[best]);
      at = best;
    }
    place(at, item);
  }

  std::vector<Item> items_;
  /// Slot of each state's entry in items_ while it has one; else stale (a slot past the end or
  /// holding another state), which is how push_or_update() tells that it has none.
  std::vector<std::uint32_t> position_;
};

}  // namespace search
}  // namespace fsweep
