#include "engine/world/frontiers.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

namespace fsweep {
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

/// Index of the first nonzero byte of `p[from, n)`, or `n`. Skips zero stretches eight bytes
/// at a time: frontier flags are sparse.
std::size_t next_set(const std::uint8_t* p, std::size_t n, std::size_t from) {
  std::size_t i = from;
  while (i + 8 <= n) {
    std::uint64_t word = 0;
    std::memcpy(&word, p + i, sizeof word);
    if (word != 0) break;
    i += 8;
  }
  while (i < n && p[i] == 0) ++i;
  return i;
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
  count_ = 0;
  const CellState* s = known.cells().data().data();
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (frontier_at(s, w, h, x, y)) {
        const int i = y * w + x;
        flags_[static_cast<std::size_t>(i)] = 1;
        ++count_;
      }
    }
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
      for (int x = x0; x <= x1; ++x) {
        const std::uint8_t now = frontier_at(s, w, h, x, y) ? 1 : 0;
        const int i = y * w + x;
        std::uint8_t& flag = flags_[static_cast<std::size_t>(i)];
        count_ += static_cast<int>(now) - static_cast<int>(flag);
        flag = now;
      }
    }
  }
}

std::vector<int> FrontierMap::cells() const {
  std::vector<int> out;
  out.reserve(static_cast<std::size_t>(count_));
  const std::size_t n = flags_.size();
  for (std::size_t i = next_set(flags_.data(), n, 0); i < n; i = next_set(flags_.data(), n, i + 1)) {
    out.push_back(static_cast<int>(i));
  }
  return out;
}

std::vector<FrontierCluster> FrontierMap::clusters(const KnownMap& known, double max_length_m,
                                                   std::span<const std::uint8_t> excluded) const {
  std::vector<FrontierCluster> result;
  if (flags_.size() != static_cast<std::size_t>(known.size()) || width_ != known.width()) {
    throw std::invalid_argument(
        "FrontierMap::clusters: the known map's size differs from the frontier map's");
  }
  if (count_ == 0) return result;
  const int w = known.width();
  const int h = known.height();
  const double resolution_m = known.resolution_m();

  // 1. Candidate cells: a copy of the flags without the excluded cells. The walk below clears
  //    each cell it visits, so the copy doubles as the "not yet visited" set.
  std::vector<std::uint8_t> remaining = flags_;
  const std::size_t n = remaining.size();
  if (!excluded.empty()) {
    if (excluded.size() != n) {
      throw std::invalid_argument("FrontierMap::clusters: excluded has " + std::to_string(excluded.size()) +
                                  " flags for " + std::to_string(n) + " cells");
    }
    for (std::size_t i = 0; i < n; ++i) remaining[i] &= static_cast<std::uint8_t>(excluded[i] == 0 ? 1 : 0);
  }

  // 2. Piece size in cells: floor(max_length_m / resolution_m), at least 1 (with slack for
  //    ratios such as 3.0 / 0.3 that round just below an integer); no splitting when <= 0.
  std::size_t cap = std::max<std::size_t>(static_cast<std::size_t>(count_), 1);
  if (max_length_m > 0.0) {
    const double ratio = std::floor(max_length_m / resolution_m * (1.0 + 1e-9));
    cap = ratio < 1.0 ? 1 : static_cast<std::size_t>(std::min(ratio, static_cast<double>(cap)));
  }

  // 3. One breadth-first walk per 8-connected component, from its lowest-index cell (the
  //    ascending scan meets it first), visiting neighbours in heading order; the visiting order
  //    is cut into consecutive pieces of `cap` cells.
  std::vector<int> queue;
  queue.reserve(static_cast<std::size_t>(count_));
  std::array<int, 8> offset{};  // index step of each heading
  for (std::size_t k = 0; k < offset.size(); ++k) offset[k] = kDirections[k].y * w + kDirections[k].x;
  const auto add_piece = [&](std::span<const int> members) {
    FrontierCluster cl;
    cl.cells.assign(members.begin(), members.end());
    std::sort(cl.cells.begin(), cl.cells.end());
    const auto n = static_cast<long long>(cl.cells.size());
    long long sx = 0;
    long long sy = 0;
    for (const int i : cl.cells) {
      sx += i % w;
      sy += i / w;
    }
    // Cell (x, y) has its centre at (x, y) in cell units (as in euclidean_distance()).
    cl.centroid_x = static_cast<double>(sx) / static_cast<double>(n);
    cl.centroid_y = static_cast<double>(sy) / static_cast<double>(n);
    cl.length_m = static_cast<double>(n) * resolution_m;
    // Representative: nearest to the centroid, compared exactly as
    // n^2 d^2 = (n x - sum x)^2 + (n y - sum y)^2; members are ascending and only a strictly
    // smaller distance wins, so ties keep the lowest index.
    Int128 best = -1;
    for (const int i : cl.cells) {
      const Int128 ex = static_cast<Int128>(n) * (i % w) - sx;
      const Int128 ey = static_cast<Int128>(n) * (i / w) - sy;
      const Int128 d = ex * ex + ey * ey;
      if (best < 0 || d < best) {
        best = d;
        cl.representative = i;
      }
    }
    result.push_back(std::move(cl));
  };

  for (std::size_t seed = next_set(remaining.data(), n, 0); seed < n;
       seed = next_set(remaining.data(), n, seed + 1)) {
    remaining[seed] = 0;
    queue.clear();
    queue.push_back(static_cast<int>(seed));
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const int c = queue[head];
      const int cx = c % w;
      const int cy = c / w;
      const bool interior = cx > 0 && cy > 0 && cx < w - 1 && cy < h - 1;
      for (std::size_t k = 0; k < kDirections.size(); ++k) {
        if (!interior) {
          const int nx = cx + kDirections[k].x;
          const int ny = cy + kDirections[k].y;
          if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
        }
        const int ni = c + offset[k];
        std::uint8_t& r = remaining[static_cast<std::size_t>(ni)];
        if (r == 0) continue;
        r = 0;
        queue.push_back(ni);
      }
    }
    for (std::size_t first = 0; first < queue.size(); first += cap) {
      add_piece(std::span<const int>(queue).subspan(first, std::min(cap, queue.size() - first)));
    }
  }

  // 4. Order by lowest member (pieces of one component interleave with other components).
  std::sort(result.begin(), result.end(), [](const FrontierCluster& a, const FrontierCluster& b) {
    return a.cells.front() < b.cells.front();
  });
  return result;
}

}  // namespace fsweep
