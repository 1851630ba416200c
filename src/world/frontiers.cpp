#include "world/frontiers.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

namespace fsweep {
inline namespace world {
namespace {

/// 128-bit integer for exact centroid distances (GCC/Clang extension).
__extension__ typedef __int128 Int128;

/// Frontier test of cell (x, y) on raw known-map storage `s` of size `w` x `h`
/// (the definition in frontiers.hpp).
inline bool frontier_at(const CellState* s, int w, int h, int x, int y) {
  const int i = y * w + x;
  if (s[i] != CellState::Free) return false;
  constexpr CellState kUnknown = CellState::Unknown;
  constexpr CellState kOccupied = CellState::Occupied;
  if (x > 0 && y > 0 && x < w - 1 && y < h - 1) {  // all eight neighbours on the map
    if (s[i - 1] == kUnknown || s[i + 1] == kUnknown || s[i - w] == kUnknown || s[i + w] == kUnknown) {
      return true;
    }
    // A diagonal neighbour counts unless both cells beside it are occupied.
    const bool west = s[i - 1] == kOccupied;
    const bool east = s[i + 1] == kOccupied;
    const bool north = s[i - w] == kOccupied;
    const bool south = s[i + w] == kOccupied;
    return (s[i - w - 1] == kUnknown && !(west && north)) || (s[i - w + 1] == kUnknown && !(east && north)) ||
           (s[i + w - 1] == kUnknown && !(west && south)) || (s[i + w + 1] == kUnknown && !(east && south));
  }
  for (const Cell d : kDirections) {
    const int nx = x + d.x;
    const int ny = y + d.y;
    if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
    if (s[ny * w + nx] != CellState::Unknown) continue;
    if (d.x == 0 || d.y == 0) return true;
    // Diagonal: sealed when both cells beside it are occupied. Both are on the map because
    // the diagonal neighbour is.
    if (s[y * w + nx] != CellState::Occupied || s[ny * w + x] != CellState::Occupied) return true;
  }
  return false;
}

/// FrontierMap::flags_ bit besides kFrontier and kListed: tested during this update() (clear
/// between calls).
constexpr std::uint8_t kTested = 4;

}  // namespace

bool is_frontier_cell(const KnownMap& known, int index) {
  const Cell c = known.cell(index);
  return frontier_at(known.cells().data().data(), known.width(), known.height(), c.x, c.y);
}

FrontierMap::FrontierMap(const KnownMap& known) { rebuild(known); }

void FrontierMap::rebuild(const KnownMap& known) {
  const int w = known.width();
  const int h = known.height();
  width_ = w;
  flags_.assign(static_cast<std::size_t>(known.size()), 0);
  list_.clear();
  count_ = 0;
  stale_ = 0;
  const CellState* s = known.cells().data().data();
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (frontier_at(s, w, h, x, y)) {
        const int i = y * w + x;
        flags_[static_cast<std::size_t>(i)] = kFrontier | kListed;
        list_.push_back(i);
      }
    }
  }
  count_ = static_cast<int>(list_.size());
  sorted_ = list_.size();
}

void FrontierMap::set(int i, bool frontier) {
  std::uint8_t& flag = flags_[static_cast<std::size_t>(i)];
  const bool was = (flag & kFrontier) != 0;
  if (was == frontier) return;
  if (frontier) {
    ++count_;
    if ((flag & kListed) != 0) {
      --stale_;  // revived while still listed
    } else {
      list_.push_back(i);
    }
    flag = kFrontier | kListed;
  } else {
    --count_;
    ++stale_;
    flag = kListed;
  }
}

void FrontierMap::update(const KnownMap& known, std::span<const int> revealed) {
  if (flags_.size() != static_cast<std::size_t>(known.size()) || width_ != known.width()) {
    rebuild(known);
    return;
  }
  const int w = known.width();
  const int h = known.height();
  const CellState* s = known.cells().data().data();
  // A cell's status depends only on its 3x3 neighbourhood, so only the revealed cells and
  // their 8-neighbours can change; each of them is tested once (flagged kTested meanwhile:
  // neighbourhoods of cells revealed together overlap).
  static_assert((kTested & (kFrontier | kListed)) == 0);
  const auto each_neighbourhood = [&](auto&& visit) {
    for (const int r : revealed) {
      const int rx = r % w;
      const int ry = r / w;
      const int x0 = std::max(rx - 1, 0);
      const int x1 = std::min(rx + 1, w - 1);
      for (int y = std::max(ry - 1, 0); y <= std::min(ry + 1, h - 1); ++y) {
        for (int x = x0; x <= x1; ++x) visit(y * w + x, x, y);
      }
    }
  };
  each_neighbourhood([&](int i, int x, int y) {
    if ((flags_[static_cast<std::size_t>(i)] & kTested) != 0) return;
    set(i, frontier_at(s, w, h, x, y));
    flags_[static_cast<std::size_t>(i)] |= kTested;
  });
  each_neighbourhood(
      [&](int i, int, int) { flags_[static_cast<std::size_t>(i)] &= static_cast<std::uint8_t>(~kTested); });
  // Keep the list within a constant factor of the frontier count.
  if (stale_ > 64 && stale_ > static_cast<std::size_t>(count_)) normalise();
}

void FrontierMap::normalise() const {
  if (stale_ == 0 && sorted_ == list_.size()) return;
  std::size_t kept = 0;
  std::size_t kept_sorted = 0;
  for (std::size_t k = 0; k < list_.size(); ++k) {
    const int i = list_[k];
    std::uint8_t& flag = flags_[static_cast<std::size_t>(i)];
    if ((flag & kFrontier) != 0) {
      list_[kept++] = i;
      if (k < sorted_) kept_sorted = kept;
    } else {
      flag = 0;  // stale: no longer listed
    }
  }
  list_.resize(kept);
  stale_ = 0;
  const auto middle = list_.begin() + static_cast<std::ptrdiff_t>(kept_sorted);
  std::sort(middle, list_.end());
  std::inplace_merge(list_.begin(), middle, list_.end());
  sorted_ = list_.size();
}

std::vector<int> FrontierMap::cells() const {
  normalise();
  return list_;
}

std::vector<FrontierCluster> FrontierMap::clusters(const KnownMap& known, double max_length_m,
                                                   bool allow_corner_cutting,
                                                   std::span<const std::uint8_t> excluded) const {
  if (flags_.size() != static_cast<std::size_t>(known.size()) || width_ != known.width()) {
    throw std::invalid_argument(
        "FrontierMap::clusters: the known map's size differs from the frontier map's");
  }
  FrontierClusters from_scratch(known, max_length_m, allow_corner_cutting);
  return from_scratch.clusters(known, *this, excluded);
}

namespace {

/// FrontierClusters::owner_ marks besides a lowest member index.
constexpr int kNone = -1;         // not in a cluster
constexpr int kInComponent = -2;  // in the component being split into pieces (scratch)

/// A cell in a walk, with its coordinates.
using Node = FrontierClusters::PieceCell;

/// The cluster of `members` (ascending by index): centroid, length and representative. Its
/// cell list is written into `storage` (a spare vector whose allocation it reuses).
FrontierCluster make_cluster(const std::vector<Node>& members, int w, int h, double resolution_m,
                             std::vector<int> storage) {
  FrontierCluster cl;
  cl.cells = std::move(storage);
  cl.cells.clear();
  cl.cells.reserve(members.size());
  const auto n = static_cast<long long>(members.size());
  long long sx = 0;
  long long sy = 0;
  for (const Node& m : members) {
    cl.cells.push_back(m.i);
    sx += m.x;
    sy += m.y;
  }
  // Cell (x, y) has its centre at (x, y) in cell units (as in euclidean_distance()).
  cl.centroid_x = static_cast<double>(sx) / static_cast<double>(n);
  cl.centroid_y = static_cast<double>(sy) / static_cast<double>(n);
  cl.length_m = static_cast<double>(n) * resolution_m;
  // Representative: nearest to the centroid, compared exactly as
  // n^2 d^2 = (n x - sum x)^2 + (n y - sum y)^2; members are ascending and only a strictly
  // smaller distance wins, so ties keep the lowest index. |n x - sum x| <= n * side, so
  // 64 bits suffice while 2 (n * side)^2 < 2^63; else 128.
  const auto nearest = [&]<typename T>(T best) {
    for (const Node& m : members) {
      const T ex = static_cast<T>(n) * m.x - sx;
      const T ey = static_cast<T>(n) * m.y - sy;
      const T d = ex * ex + ey * ey;
      if (best < 0 || d < best) {
        best = d;
        cl.representative = m.i;
      }
    }
  };
  if (n * std::max(w, h) < (1LL << 30)) {
    nearest(static_cast<long long>(-1));
  } else {
    nearest(static_cast<Int128>(-1));
  }
  return cl;
}

}  // namespace

/// What the walks of FrontierClusters read: the map, the frontier and exclusion flags, and the
/// owner marks.
struct FrontierClusters::Walk {
  int w;
  int h;
  const CellState* state;
  const FrontierMap& frontiers;
  const std::uint8_t* skip;  // null: nothing excluded
  int* owner;
  bool allow_corner_cutting;

  /// True when cell `i` may join a cluster: a frontier cell, not excluded.
  [[nodiscard]] bool open(int i) const {
    return frontiers.is_frontier(i) && (skip == nullptr || skip[i] == 0);
  }

  /// Calls visit(node) for every neighbour of `c` linked to it by the motion rule
  /// (FrontierMap::clusters) that may join a cluster and whose owner mark is `wanted(mark)`, in
  /// heading order. `c` is a copy: visit() may grow the vector it came from. Unrolled over the
  /// eight headings.
  template <typename Wanted, typename Visit>
  void for_each_link(const Node c, Wanted&& wanted, Visit&& visit) const {
    const bool interior = c.x > 0 && c.y > 0 && c.x < w - 1 && c.y < h - 1;
    const auto step = [&]<std::size_t K>(std::integral_constant<std::size_t, K>) {
      constexpr int kDx = kDirections[K].x;
      constexpr int kDy = kDirections[K].y;
      const int nx = c.x + kDx;
      const int ny = c.y + kDy;
      if (!interior && (nx < 0 || ny < 0 || nx >= w || ny >= h)) return;
      const int n = c.i + kDy * w + kDx;
      if (!wanted(owner[n]) || !open(n)) return;
      // Diagonal: both cells beside it must be known free.
      if constexpr (kDx != 0 && kDy != 0) {
        if (!allow_corner_cutting &&
            (state[c.i + kDx] != CellState::Free || state[c.i + kDy * w] != CellState::Free)) {
          return;
        }
      }
      visit(Node{n, nx, ny});
    };
    const auto steps = [&]<std::size_t... K>(std::index_sequence<K...>) {
      (step(std::integral_constant<std::size_t, K>{}), ...);
    };
    steps(std::make_index_sequence<kDirections.size()>{});
  }
};

FrontierClusters::FrontierClusters(const KnownMap& known, double max_length_m, bool allow_corner_cutting)
    : max_length_m_(max_length_m),
      allow_corner_cutting_(allow_corner_cutting),
      width_(known.width()),
      height_(known.height()),
      owner_(static_cast<std::size_t>(known.size()), kNone),
      flags_(static_cast<std::size_t>(known.size()), 0) {}

void FrontierClusters::revealed(std::span<const int> cells) {
  if (!everything_dirty_) revealed_.insert(revealed_.end(), cells.begin(), cells.end());
}

void FrontierClusters::exclusion_changed(int index) {
  if (!everything_dirty_) exclusion_changed_.push_back(index);
}

void FrontierClusters::mark(int key) {
  std::uint8_t& flag = flags_[static_cast<std::size_t>(key)];
  if ((flag & kWalkAgain) != 0) return;
  flag |= kWalkAgain;
  ++marked_;
  lowest_marked_ = std::min(lowest_marked_, key);
}

void FrontierClusters::mark_near(int x, int y, int after) {
  const int x0 = std::max(x - 1, 0);
  const int x1 = std::min(x + 1, width_ - 1);
  for (int ny = std::max(y - 1, 0); ny <= std::min(y + 1, height_ - 1); ++ny) {
    const int* row = owner_.data() + static_cast<std::ptrdiff_t>(ny) * width_;
    for (int nx = x0; nx <= x1; ++nx) {
      if (row[nx] > after) mark(row[nx]);  // else none (-1), or replayed already
    }
  }
}

void FrontierClusters::mark_near(int cell, int after) { mark_near(cell % width_, cell / width_, after); }

const std::vector<FrontierCluster>& FrontierClusters::clusters(const KnownMap& known,
                                                               const FrontierMap& frontiers,
                                                               std::span<const std::uint8_t> excluded) {
  if (owner_.size() != static_cast<std::size_t>(known.size()) || width_ != known.width()) {
    throw std::invalid_argument(
        "FrontierClusters::clusters: the known map's size differs from the clusters'");
  }
  if (!excluded.empty() && excluded.size() != owner_.size()) {
    throw std::invalid_argument("FrontierClusters::clusters: excluded has " +
                                std::to_string(excluded.size()) + " flags for " +
                                std::to_string(owner_.size()) + " cells");
  }
  const Walk walk{width_,
                  height_,
                  known.cells().data().data(),
                  frontiers,
                  excluded.empty() ? nullptr : excluded.data(),
                  owner_.data(),
                  allow_corner_cutting_};
  // Piece size in cells: floor(max_length_m / resolution_m), at least 1 (with slack for ratios
  // such as 3.0 / 0.3 that round just below an integer); no splitting when <= 0.
  std::size_t cap = std::numeric_limits<std::size_t>::max();
  if (max_length_m_ > 0.0) {
    const double ratio = std::floor(max_length_m_ / known.resolution_m() * (1.0 + 1e-9));
    cap = ratio < 1.0 ? 1 : static_cast<std::size_t>(std::min(ratio, 1e18));
  }
  if (!everything_dirty_ && revealed_.empty() && exclusion_changed_.empty()) return clusters_;
  find_starts(walk, frontiers);
  const Grow grow{walk, cap, known.resolution_m()};
  const std::size_t first = first_replayed();
  const std::size_t k = replay(grow, first);
  splice(first, k);
  return clusters_;
}

void FrontierClusters::find_starts(const Walk& walk, const FrontierMap& frontiers) {
  // 1. The cells to walk from besides the pieces' own starts: every frontier cell the first
  //    time; later the changed cells. Pieces within one cell of a changed cell must be walked
  //    again.
  starts_.clear();
  marked_ = 0;
  lowest_marked_ = std::numeric_limits<int>::max();
  if (everything_dirty_) {
    starts_ = frontiers.cells();  // ascending: already a min-heap
    everything_dirty_ = false;
  } else {
    const int w = width_;
    const int h = height_;
    dirty_cells_.clear();
    const auto dirty = [&](int cell) {
      std::uint8_t& flag = flags_[static_cast<std::size_t>(cell)];
      if ((flag & kChanged) != 0) return;
      flag |= kChanged;
      dirty_cells_.push_back(cell);
    };
    // A walk reads its cells' neighbours: whether they may join (frontier, not excluded) and
    // the known state of those beside a diagonal, which are orthogonal neighbours of its cells.
    // States change only at revealed cells; whether a cell may join only at a revealed cell's
    // 8-neighbours (and itself) or where the exclusion changed. A cell could join at the last
    // call exactly when it was in a piece then (every such cell is, and no other), so those
    // whose status changed are found by their owner mark.
    for (const int r : revealed_) {
      const int rx = r % w;
      const int ry = r / w;
      mark_near(rx, ry, -1);
      for (int y = std::max(ry - 1, 0); y <= std::min(ry + 1, h - 1); ++y) {
        for (int x = std::max(rx - 1, 0); x <= std::min(rx + 1, w - 1); ++x) dirty(y * w + x);
      }
    }
    for (const int e : exclusion_changed_) dirty(e);
    for (const int d : dirty_cells_) {
      flags_[static_cast<std::size_t>(d)] &= static_cast<std::uint8_t>(~kChanged);
      const bool open = walk.open(d);
      if (open == (owner_[static_cast<std::size_t>(d)] >= 0)) continue;  // unchanged
      mark_near(d, -1);
      if (open) starts_.push_back(d);
    }
    std::make_heap(starts_.begin(), starts_.end(), std::greater<>{});
  }
  revealed_.clear();
  exclusion_changed_.clear();
}

std::size_t FrontierClusters::first_replayed() const {
  const int lowest =
      std::min(lowest_marked_, starts_.empty() ? std::numeric_limits<int>::max() : starts_.front());
  return static_cast<std::size_t>(
      std::partition_point(clusters_.begin(), clusters_.end(),
                           [lowest](const FrontierCluster& c) { return c.cells.front() < lowest; }) -
      clusters_.begin());
}

// What must be walked again besides the pieces near changed cells: a piece's walk reads a
// neighbour's owner mark only as "placed by an earlier piece" or not, and the walk is the
// same as last time unless a cell it read as placed is not placed now. (A cell it read as
// not placed and did not take, it met only once the piece was full, or not at all: reading it
// as placed now changes nothing.) So a piece that loses a cell to an earlier one is walked
// again (grow() marks it), and so are the pieces near the cells a piece walked again leaves
// free (walk_again()); a cell taken by another piece needs nothing more.
bool FrontierClusters::grow(const Grow& g, int start, FrontierCluster* old) {
  piece_.clear();
  owner_[static_cast<std::size_t>(start)] = start;
  piece_.push_back(Node{start, start % width_, start / width_});
  const auto free_now = [start](int mark) { return mark < 0 || mark > start; };
  for (std::size_t head = 0; head < piece_.size() && piece_.size() < g.cap; ++head) {
    g.walk.for_each_link(piece_[head], free_now, [&](const Node& n) {
      if (piece_.size() == g.cap) return;
      const int taken_from = owner_[static_cast<std::size_t>(n.i)];
      if (taken_from > start) mark(taken_from);
      owner_[static_cast<std::size_t>(n.i)] = start;
      piece_.push_back(n);
    });
  }
  std::sort(piece_.begin(), piece_.end(), [](const Node& a, const Node& b) { return a.i < b.i; });
  if (old != nullptr && std::equal(piece_.begin(), piece_.end(), old->cells.begin(), old->cells.end(),
                                   [](const Node& a, int b) { return a.i == b; })) {
    next_.push_back(std::move(*old));
    return true;
  }
  std::vector<int> storage;
  if (!spare_.empty()) {
    storage = std::move(spare_.back());
    spare_.pop_back();
  }
  next_.push_back(make_cluster(piece_, width_, height_, g.resolution_m, std::move(storage)));
  return false;
}

std::size_t FrontierClusters::replay(const Grow& g, std::size_t first) {
  // 2. The loop of FrontierMap::clusters, replayed in increasing order of start cell over the
  //    last call's pieces and the cells in starts_. owner_ of a cell holds its piece's start:
  //    <= the current start once placed by this call, > it while still in a piece not yet
  //    replayed. Pieces before the first marked piece and the first cell in starts_ stay as
  //    they are, and so do those after the last piece that changes: the replay starts at the
  //    former and stops once no cell is left in starts_ and no marked piece lies ahead
  //    (marked_ counts those; every mark goes to a piece not yet replayed).
  next_.clear();
  std::size_t k = first;  // next piece of the last call
  while ((k < clusters_.size() && marked_ > 0) || !starts_.empty()) {
    if (!starts_.empty() && (k == clusters_.size() || starts_.front() < clusters_[k].cells.front())) {
      const int cell = starts_.front();
      std::pop_heap(starts_.begin(), starts_.end(), std::greater<>{});
      starts_.pop_back();
      // A walk from `cell` when it is open and not yet placed (there was no piece at `cell`).
      const int mark = owner_[static_cast<std::size_t>(cell)];
      if ((mark < 0 || mark > cell) && g.walk.open(cell)) (void)grow(g, cell, nullptr);
      continue;
    }
    // The last call's piece k, starting at s: kept when nothing near it changed (a piece built
    // by this call that took one of its cells marked it too).
    FrontierCluster& old = clusters_[k];
    const int s = old.cells.front();
    std::uint8_t& flag = flags_[static_cast<std::size_t>(s)];
    const bool intact = (flag & kWalkAgain) == 0;
    ++k;
    if (intact) {
      next_.push_back(std::move(old));
      continue;
    }
    flag &= static_cast<std::uint8_t>(~kWalkAgain);
    --marked_;
    walk_again(g, old);
  }
  return k;
}

void FrontierClusters::walk_again(const Grow& g, FrontierCluster& old) {
  // Walk again from s (when it is still open and free). The old cells it leaves free may
  // change what any later piece reads (those near them are marked), and are walked from in
  // turn.
  const int s = old.cells.front();
  for (const int c : old.cells) {
    if (owner_[static_cast<std::size_t>(c)] == s) owner_[static_cast<std::size_t>(c)] = kNone;
  }
  if (owner_[static_cast<std::size_t>(s)] == kNone && g.walk.open(s) && grow(g, s, &old)) return;  // the same
  for (const int c : old.cells) {
    if (owner_[static_cast<std::size_t>(c)] != kNone) continue;
    mark_near(c, s);
    if (c != s) {
      starts_.push_back(c);
      std::push_heap(starts_.begin(), starts_.end(), std::greater<>{});
    }
  }
  spare_.push_back(std::move(old.cells));
}

void FrontierClusters::splice(std::size_t first, std::size_t k) {
  // 3. The replayed pieces take the place of the last call's pieces [first, k).
  const auto at = [this](std::size_t i) { return clusters_.begin() + static_cast<std::ptrdiff_t>(i); };
  const std::size_t replaced = k - first;
  const std::size_t common = std::min(replaced, next_.size());
  std::move(next_.begin(), next_.begin() + static_cast<std::ptrdiff_t>(common), at(first));
  if (replaced > common) {
    clusters_.erase(at(first + common), at(k));
  } else {
    clusters_.insert(at(k), std::make_move_iterator(next_.begin() + static_cast<std::ptrdiff_t>(common)),
                     std::make_move_iterator(next_.end()));
  }
}

}  // namespace world
}  // namespace fsweep
