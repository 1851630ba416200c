#include "world/frontiers.hpp"

#include <algorithm>
#include <array>
#include <cmath>
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
  // their 8-neighbours can change.
  for (const int r : revealed) {
    const int rx = r % w;
    const int ry = r / w;
    const int x0 = std::max(rx - 1, 0);
    const int x1 = std::min(rx + 1, w - 1);
    const int y0 = std::max(ry - 1, 0);
    const int y1 = std::min(ry + 1, h - 1);
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) set(y * w + x, frontier_at(s, w, h, x, y));
    }
  }
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
  std::vector<FrontierCluster> result;
  if (flags_.size() != static_cast<std::size_t>(known.size()) || width_ != known.width()) {
    throw std::invalid_argument(
        "FrontierMap::clusters: the known map's size differs from the frontier map's");
  }
  if (!excluded.empty() && excluded.size() != flags_.size()) {
    throw std::invalid_argument("FrontierMap::clusters: excluded has " + std::to_string(excluded.size()) +
                                " flags for " + std::to_string(flags_.size()) + " cells");
  }
  if (count_ == 0) return result;
  normalise();
  const int w = known.width();
  const int h = known.height();
  const double resolution_m = known.resolution_m();
  const CellState* state = known.cells().data().data();
  std::uint8_t* flags = flags_.data();
  const std::uint8_t* skip = excluded.empty() ? nullptr : excluded.data();

  // Scratch marks live in flags_ and are cleared on every exit (also by an exception).
  struct ClearMarks {
    const std::vector<int>& list;
    std::uint8_t* flags;
    ~ClearMarks() {
      for (const int i : list) flags[i] &= static_cast<std::uint8_t>(~kPlaced);
    }
  } const clear_marks{list_, flags};

  // 1. Piece size in cells: floor(max_length_m / resolution_m), at least 1 (with slack for
  //    ratios such as 3.0 / 0.3 that round just below an integer); no splitting when <= 0.
  std::size_t cap = std::max<std::size_t>(static_cast<std::size_t>(count_), 1);
  if (max_length_m > 0.0) {
    const double ratio = std::floor(max_length_m / resolution_m * (1.0 + 1e-9));
    cap = ratio < 1.0 ? 1 : static_cast<std::size_t>(std::min(ratio, static_cast<double>(cap)));
  }

  // A cell in a walk, with its coordinates (carried along to avoid divisions).
  struct Node {
    int i;
    int x;
    int y;
  };
  // Calls visit(node) for every neighbour of `c` linked to it by the motion rule that is a
  // frontier cell, not excluded and not yet placed, in heading order. `c` is a copy: visit()
  // may grow the vector it came from. Unrolled over the eight headings.
  const auto for_each_link = [&](const Node c, auto&& visit) {
    const bool interior = c.x > 0 && c.y > 0 && c.x < w - 1 && c.y < h - 1;
    const auto step = [&]<std::size_t K>(std::integral_constant<std::size_t, K>) {
      constexpr int kDx = kDirections[K].x;
      constexpr int kDy = kDirections[K].y;
      const int nx = c.x + kDx;
      const int ny = c.y + kDy;
      if (!interior && (nx < 0 || ny < 0 || nx >= w || ny >= h)) return;
      const int n = c.i + kDy * w + kDx;
      if ((flags[n] & (kFrontier | kPlaced)) != kFrontier) return;
      if (skip != nullptr && skip[n] != 0) return;
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
  };

  // Appends the cluster of `members` (reordered by index here).
  const auto add_piece = [&](std::vector<Node>& members) {
    std::sort(members.begin(), members.end(), [](const Node& a, const Node& b) { return a.i < b.i; });
    FrontierCluster cl;
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
    result.push_back(std::move(cl));
  };

  // 2. Pieces, by walks over the cells not yet placed, each from the lowest-index one left.
  //    Links never join two components, so a walk stays inside the component of its start
  //    cell, and the pieces of each component come out exactly as the per-component rule in
  //    frontiers.hpp makes them (the lowest cell left overall is the lowest left in its
  //    component). Without splitting a walk takes the whole component. Every piece starts at
  //    its lowest member, so pieces come out ordered by lowest member.
  std::vector<Node> piece;
  piece.reserve(std::min(cap, list_.size()));
  result.reserve(list_.size() / cap + 16);
  for (const int start : list_) {
    if ((flags[start] & kPlaced) != 0 || (skip != nullptr && skip[start] != 0)) continue;
    piece.clear();
    flags[start] |= kPlaced;
    piece.push_back(Node{start, start % w, start / w});
    for (std::size_t head = 0; head < piece.size() && piece.size() < cap; ++head) {
      for_each_link(piece[head], [&](const Node& n) {
        if (piece.size() == cap) return;
        flags[n.i] |= kPlaced;
        piece.push_back(n);
      });
    }
    add_piece(piece);
  }
  return result;
}

}  // namespace world
}  // namespace fsweep
