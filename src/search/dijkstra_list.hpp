#pragma once
/// @file dijkstra_list.hpp
/// The open lists of BestFirstSearchT's Dijkstra runs (grid_search.hpp, a zero heuristic): both
/// take a duplicate entry when a state's cost drops (the search skips stale entries when popped)
/// and pop the entries in the order of (g, state), smaller first. That order is total (a state is
/// opened again only at a strictly lower g), so the two lists pop the same sequence and a run is
/// the same whichever the search uses.
///
/// - DijkstraHeap: a binary heap (std::push_heap / pop_heap), for any costs >= 0.
/// - DijkstraBuckets: for costs counted in cells with every edge at least one cell long (OctileCost:
///   1 or sqrt(2) a step). Entries go to bucket floor(kPerCell g), kPerCell buckets a cell; an edge
///   of at least one cell takes an entry popped from bucket k to a later one (about k + kPerCell;
///   rounding may make it k + kPerCell - 1), so a bucket is complete when the search reaches it,
///   and sorting it then gives the exact order. A
///   push costs an append instead of a sift, a pop a read instead of a sift down; each entry is
///   sorted once among the few of its bucket (a sixteenth of a cell of the search's wave front).
///   An entry in the bucket being popped (a zero-cost edge) or below it (a seed opened after the
///   first pop) is still put in its place, by a sorted insertion or by taking its bucket as the
///   one to pop.
///   Against the heap, side by side: a Dijkstra over den312d 0.70-0.82x the time, the
///   Manhattan class's [0, 3]^4 weight search with a coverage target 0.82-0.93x (one bucket a
///   cell); the same memory. Sixteen buckets a cell against one: the weight search 0.93x (most
///   of its buckets' sorting goes; 64 a cell was 1.08x slower than 16, the empty buckets' turn).
///
/// Memory: DijkstraBuckets keeps its buckets in a ring as long as the span of the costs it holds
/// at once (about 24 buckets for an octile search from one cell; wider for seeds of many costs), so
/// it holds about as much as the heap would.

#include <algorithm>
#include <cstddef>
#include <vector>

namespace fsweep {
inline namespace search {

/// An open-list entry of a Dijkstra run: the cost so far (as cost_value(), cells for the grid
/// searches) and the state.
struct DijkstraItem {
  double g;
  int state;
  [[nodiscard]] int id() const { return state; }
  /// The pop order: smaller g, then smaller state.
  friend bool operator<(const DijkstraItem& a, const DijkstraItem& b) {
    return a.g < b.g || (a.g == b.g && a.state < b.state);
  }
};

/// The binary-heap list.
class DijkstraHeap {
 public:
  void clear() { heap_.clear(); }
  [[nodiscard]] bool empty() const { return heap_.empty(); }
  /// Adds an entry before start(), unordered.
  void add(const DijkstraItem& item) { heap_.push_back(item); }
  /// Orders the entries add() gave.
  void start() { std::make_heap(heap_.begin(), heap_.end(), Later{}); }
  void push(const DijkstraItem& item) {
    heap_.push_back(item);
    std::push_heap(heap_.begin(), heap_.end(), Later{});
  }
  /// Removes and returns the first entry; the list must not be empty.
  DijkstraItem pop() {
    std::pop_heap(heap_.begin(), heap_.end(), Later{});
    const DijkstraItem top = heap_.back();
    heap_.pop_back();
    return top;
  }

 private:
  /// The std heap comparator: true when `a` comes out after `b`. A function object so that the
  /// heap algorithms inline it.
  struct Later {
    bool operator()(const DijkstraItem& a, const DijkstraItem& b) const { return b < a; }
  };
  std::vector<DijkstraItem> heap_;
};

/// The bucket list (costs in cells, edges of at least one cell; see the file comment).
class DijkstraBuckets {
 public:
  /// Empties the list.
  void clear() {
    // Only [current_, high_) may hold entries (the current one its popped ones too): pop()
    // empties each bucket it leaves behind, so a wide ring is not walked whole.
    for (std::size_t b = current_; b < high_; ++b) at(b).clear();
    current_ = 0;
    high_ = 0;
    next_ = 0;
    sorted_ = false;
    size_ = 0;
  }
  [[nodiscard]] bool empty() const { return size_ == 0; }
  void add(const DijkstraItem& item) { push(item); }
  void start() {}
  void push(const DijkstraItem& item) {
    const std::size_t b = bucket_of(item.g);
    if (b > current_ && b - current_ < ring_.size() && size_ != 0) {  // the usual case: a bucket ahead
      at(b).push_back(item);
      high_ = std::max(high_, b + 1);
      ++size_;
      return;
    }
    push_elsewhere(item, b);
  }
  /// Removes and returns the first entry; the list must not be empty.
  DijkstraItem pop() {
    while (next_ == at(current_).size()) {  // this bucket is done: on to the next one
      at(current_).clear();
      ++current_;
      next_ = 0;
      sorted_ = false;
    }
    std::vector<DijkstraItem>& bucket = at(current_);
    if (!sorted_) {
      std::sort(bucket.begin() + static_cast<std::ptrdiff_t>(next_), bucket.end());
      sorted_ = true;
    }
    --size_;
    return bucket[next_++];
  }

 private:
  static std::size_t bucket_of(double g) { return static_cast<std::size_t>(g * kPerCell); }
  /// Bucket b (current_ <= b < current_ + ring size) in the ring.
  std::vector<DijkstraItem>& at(std::size_t b) { return ring_[b & (ring_.size() - 1)]; }

  /// push() of an entry into bucket `b` when it is not one ahead of the current bucket.
  void push_elsewhere(const DijkstraItem& item, std::size_t b) {
    if (size_ == 0 || b < current_) {
      // The first entry, or one below the bucket being popped: its bucket is popped next, and
      // the rest of the current one (its popped entries dropped) waits unsorted.
      if (!ring_.empty()) {
        std::vector<DijkstraItem>& current = at(current_);
        current.erase(current.begin(), current.begin() + static_cast<std::ptrdiff_t>(next_));
      }
      if (size_ == 0) high_ = b;
      fit(b, std::max(high_, b + 1));
      current_ = b;
      next_ = 0;
      sorted_ = false;
    } else {
      fit(current_, std::max(high_, b + 1));
    }
    std::vector<DijkstraItem>& bucket = at(b);
    if (b == current_ && sorted_) {  // into the sorted rest, at its place
      bucket.insert(std::upper_bound(bucket.begin() + static_cast<std::ptrdiff_t>(next_), bucket.end(), item),
                    item);
    } else {
      bucket.push_back(item);
    }
    high_ = std::max(high_, b + 1);
    ++size_;
  }
  /// Grows the ring (doubling) until it holds the buckets [low, high), moving the buckets held
  /// now ([current_, high_) when not empty) to their new places.
  void fit(std::size_t low, std::size_t high) {
    std::size_t n = ring_.empty() ? kFirstRing : ring_.size();
    while (high - low > n) n *= 2;
    if (n == ring_.size()) return;
    std::vector<std::vector<DijkstraItem>> grown(n);
    if (size_ != 0) {
      for (std::size_t b = current_; b < high_; ++b) grown[b & (n - 1)] = std::move(at(b));
    }
    ring_ = std::move(grown);
  }

  /// Buckets a cell of cost: a power of two, so that g * kPerCell is exact.
  static constexpr double kPerCell = 16.0;
  /// Buckets a new ring holds: the live entries of an octile search span about 24.
  static constexpr std::size_t kFirstRing = 64;
  /// The buckets [current_, high_) in a ring of a power of two size, bucket b at b mod size: the
  /// capacities of the few buckets a search keeps at once are reused, so the memory follows the
  /// wave front, not the cells reached.
  std::vector<std::vector<DijkstraItem>> ring_;
  std::size_t current_ = 0;  ///< the bucket being popped: none below it holds an entry
  std::size_t high_ = 0;     ///< past the last bucket that may hold an entry
  std::size_t next_ = 0;     ///< the current bucket's next entry to pop (those before are popped)
  bool sorted_ = false;      ///< its entries from next_ on are sorted
  std::size_t size_ = 0;     ///< entries held
};

}  // namespace search
}  // namespace fsweep
