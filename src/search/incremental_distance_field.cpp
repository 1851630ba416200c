#include "search/incremental_distance_field.hpp"

#include "search/octile_grid.hpp"

namespace fsweep {
inline namespace search {
namespace {

/// Dijkstra environment of the field: cells are states, the octile moves of octile_grid.hpp, no
/// heuristic, every visited cell expanded.
class OctileMoves {
 public:
  OctileMoves(const KnownMap& known, bool allow_corner_cutting)
      : known_(known), allow_corner_cutting_(allow_corner_cutting) {}

  using Cost = OctileCost;
  [[nodiscard]] int state_count() const { return known_.size(); }
  static constexpr bool kZeroHeuristic = true;
  [[nodiscard]] static Cost heuristic(int /*state*/) { return {}; }
  static Visit visit(int /*state*/, double /*g*/) { return Visit::Expand; }
  template <typename Sink>
  void for_each_successor(int state, Sink&& sink) const {
    for_each_octile_neighbour<Cost>(known_, state, allow_corner_cutting_, sink);
  }

 private:
  const KnownMap& known_;
  bool allow_corner_cutting_;
};

}  // namespace

void IncrementalDistanceField::reset(const KnownMap& known, Cell source, bool allow_corner_cutting) {
  resolution_m_ = known.resolution_m();
  allow_corner_cutting_ = allow_corner_cutting;
  // A source that is not known free runs from no state: every distance reads as infinite.
  const OctileMoves env(known, allow_corner_cutting_);
  expansions_ = search_.run(env, known.is_free(source) ? known.index(source) : -1).expansions;
}

void IncrementalDistanceField::update(const KnownMap& known, std::span<const int> revealed) {
  const OctileMoves env(known, allow_corner_cutting_);
  search_.reopen();
  const int w = known.width();
  const int h = known.height();
  // 1. Every new move has a revealed free cell as an end, or is a diagonal between two
  //    neighbours of one (its corner cell was revealed): re-relax the 3x3 block around each
  //    revealed free cell from its neighbours (moves are symmetric), opening the cells whose
  //    distance drops (each lowered at once, so later blocks read it).
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
        const bool reached = search_.reached(n);
        OctileCost best = reached ? search_.cost(n) : OctileCost{};
        int from = -1;
        for_each_octile_neighbour<OctileCost>(known, n, allow_corner_cutting_, [&](int m, OctileCost cost) {
          if (!search_.reached(m)) return;
          const OctileCost d = search_.cost(m) + cost;
          if ((!reached && from < 0) || d.value() < best.value()) {
            best = d;
            from = m;
          }
        });
        if (from >= 0) (void)search_.lower_cost(env, n, best, from);
      }
    }
  }
  // 2. Propagate the decreases (ties: smaller cell index first).
  expansions_ = search_.resume(env).expansions;
}

}  // namespace search
}  // namespace fsweep
