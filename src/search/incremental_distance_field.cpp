#include "search/incremental_distance_field.hpp"

#include "search/octile_grid.hpp"

namespace fsweep {
inline namespace search {

void IncrementalDistanceField::reset(const KnownMap& known, Cell source, bool allow_corner_cutting) {
  resolution_m_ = known.resolution_m();
  allow_corner_cutting_ = allow_corner_cutting;
  // A source that is not known free runs from no state: every distance reads as infinite.
  const OctileFieldEnvironment env(known, allow_corner_cutting_);
  expansions_ = search_.run(env, known.is_free(source) ? known.index(source) : -1).expansions;
}

void IncrementalDistanceField::update(const KnownMap& known, std::span<const int> revealed) {
  const OctileFieldEnvironment env(known, allow_corner_cutting_);
  search_.reopen();
  const int w = known.width();
  const int h = known.height();
  // 1. Every new move has a revealed free cell r as an end, or is a diagonal between two
  //    orthogonal neighbours a, b of r whose corner r (with the cell c across from it) had to
  //    be free (only without corner cutting). Relax r from its neighbours (its moves out are
  //    followed when the search expands it) and a, b from each other, opening the cells whose
  //    distance drops (each lowered at once, so later ones read it).
  const CellState* state = known.cells().data().data();
  const auto free_at = [&](int x, int y) {
    return x >= 0 && y >= 0 && x < w && y < h && state[y * w + x] == CellState::Free;
  };
  constexpr OctileCost kDiagonal = octile_step<OctileCost>(true);
  const auto relax_across = [&](int to, int from) {
    if (search_.reached(from)) (void)search_.lower_cost(env, to, search_.cost(from) + kDiagonal, from);
  };
  for (const int r : revealed) {
    if (state[r] != CellState::Free) continue;
    const bool reached = search_.reached(r);
    OctileCost best = reached ? search_.cost(r) : OctileCost{};
    int from = -1;
    for_each_octile_neighbour<OctileCost>(known, r, allow_corner_cutting_, [&](int m, OctileCost cost) {
      if (!search_.reached(m)) return;
      const OctileCost d = search_.cost(m) + cost;
      if ((!reached && from < 0) || d.value() < best.value()) {
        best = d;
        from = m;
      }
    });
    if (from >= 0) (void)search_.lower_cost(env, r, best, from);
    if (allow_corner_cutting_) continue;
    const int rx = r % w;
    const int ry = r / w;
    for (const int dx : {-1, 1}) {
      for (const int dy : {-1, 1}) {
        // a = r + (dx, 0), b = r + (0, dy), c = r + (dx, dy): the move a-b needs r and c free.
        if (!free_at(rx + dx, ry) || !free_at(rx, ry + dy) || !free_at(rx + dx, ry + dy)) continue;
        const int a_cell = r + dx;
        const int b_cell = r + dy * w;
        relax_across(a_cell, b_cell);
        relax_across(b_cell, a_cell);
      }
    }
  }
  // 2. Propagate the decreases (ties: smaller cell index first).
  expansions_ = search_.resume(env).expansions;
}

}  // namespace search
}  // namespace fsweep
