#include "search/incremental_distance_field.hpp"

#include <algorithm>

#include "search/octile_grid.hpp"

namespace fsweep {
inline namespace search {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace

void IncrementalDistanceField::reset(const KnownMap& known, Cell source, bool allow_corner_cutting) {
  resolution_m_ = known.resolution_m();
  allow_corner_cutting_ = allow_corner_cutting;
  dist_.assign(static_cast<std::size_t>(known.size()), kInf);
  heap_.clear();
  expansions_ = 0;
  if (!known.is_free(source)) return;
  const int s = known.index(source);
  dist_[static_cast<std::size_t>(s)] = 0.0;
  heap_.push_back(Item{0.0, s});
  propagate(known);
}

void IncrementalDistanceField::update(const KnownMap& known, std::span<const int> revealed) {
  expansions_ = 0;
  const int w = known.width();
  const int h = known.height();
  // 1. Every new move has a revealed free cell as an end, or is a diagonal between two
  //    neighbours of one (its corner cell was revealed): re-relax the 3x3 block around each
  //    revealed free cell from its neighbours (moves are symmetric).
  for (const int r : revealed) {
    if (!known.is_free(r)) continue;
    const int rx = r % w;
    const int ry = r / w;
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const int x = rx + dx;
        const int y = ry + dy;
        if (x < 0 || y < 0 || x >= w || y >= h) continue;
        const int n = y * w + x;
        if (!known.is_free(n)) continue;
        double best = dist_[static_cast<std::size_t>(n)];
        for_each_octile_neighbour(known, n, allow_corner_cutting_, [&](int m, double cost) {
          best = std::min(best, dist_[static_cast<std::size_t>(m)] + cost);
        });
        if (best < dist_[static_cast<std::size_t>(n)]) {
          dist_[static_cast<std::size_t>(n)] = best;
          heap_.push_back(Item{best, n});  // propagate() heapifies
        }
      }
    }
  }
  // 2. Propagate the decreases.
  propagate(known);
}

void IncrementalDistanceField::propagate(const KnownMap& known) {
  const auto later = [](const Item& a, const Item& b) {
    return a.d > b.d || (a.d == b.d && a.index > b.index);
  };
  std::make_heap(heap_.begin(), heap_.end(), later);
  while (!heap_.empty()) {
    std::pop_heap(heap_.begin(), heap_.end(), later);
    const Item top = heap_.back();
    heap_.pop_back();
    if (top.d > dist_[static_cast<std::size_t>(top.index)]) continue;  // stale entry
    ++expansions_;
    for_each_octile_neighbour(known, top.index, allow_corner_cutting_, [&](int m, double cost) {
      const double d = top.d + cost;
      if (d < dist_[static_cast<std::size_t>(m)]) {
        dist_[static_cast<std::size_t>(m)] = d;
        heap_.push_back(Item{d, m});
        std::push_heap(heap_.begin(), heap_.end(), later);
      }
    });
  }
}

}  // namespace search
}  // namespace fsweep
