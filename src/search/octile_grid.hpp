#pragma once
/// @file octile_grid.hpp
/// The 8-connected move rule over known-free cells, shared by the grid planners and the
/// distance field (and by their tests):
/// - a move goes to one of the 8 neighbours, which must be known free (unknown and occupied
///   cells, and cells outside the grid, block);
/// - orthogonal moves cost 1 cell, diagonal moves sqrt(2) cells;
/// - without corner cutting (the default, MovingAI's rule) a diagonal move also needs both
///   orthogonal cells it passes between to be known free;
/// - with corner cutting a diagonal move only needs its target cell free, so it may pass one
///   blocked corner or squeeze between two diagonally touching blocked cells (a point robot
///   touches the shared corner point either way).

#include <type_traits>

#include "search/cell_indexer.hpp"
#include "search/grid_search.hpp"
#include "world/grid.hpp"
#include "world/known_map.hpp"

namespace fsweep {
inline namespace search {

/// True if the single step a -> b (8-neighbours) is allowed on `known` by the rule above.
[[nodiscard]] inline bool octile_step_allowed(const KnownMap& known, Cell a, Cell b,
                                              bool allow_corner_cutting) {
  const int dx = b.x - a.x;
  const int dy = b.y - a.y;
  if ((dx == 0 && dy == 0) || dx < -1 || dx > 1 || dy < -1 || dy > 1) return false;
  if (!known.is_free(a) || !known.is_free(b)) return false;
  if (dx == 0 || dy == 0 || allow_corner_cutting) return true;
  return known.is_free(Cell{a.x + dx, a.y}) && known.is_free(Cell{a.x, a.y + dy});
}

/// The cost of one straight (1 cell) or diagonal (sqrt(2) cells) step as a `Cost`: double or
/// the exact OctileCost of grid_search.hpp.
template <typename Cost>
constexpr Cost octile_step(bool diagonal) {
  if constexpr (std::is_same_v<Cost, double>) {
    return diagonal ? kSqrt2 : 1.0;
  } else {
    return diagonal ? Cost{0, 1} : Cost{1, 0};
  }
}

/// Calls `sink(next_index, cost_cells)` for every allowed move out of cell `index`, in heading
/// order (see grid.hpp), with costs of type `Cost` (octile_step). `index` must be in the grid;
/// its own state is not checked. The allowed moves are gathered into a mask first (without
/// branches away from the border), then each is one call with its constant offset: measured
/// 2-5% faster per grid search than one call site in a loop over the mask's bits.
template <typename Cost = double, typename Sink>
inline void for_each_octile_neighbour(const KnownMap& known, int index, bool allow_corner_cutting,
                                      Sink&& sink) {
  constexpr Cost kStraight = octile_step<Cost>(false);
  constexpr Cost kDiagonal = octile_step<Cost>(true);
  const int w = known.width();
  const int h = known.height();
  const int x = index % w;
  const int y = index / w;
  const CellState* cells = known.cells().data().data();
  const auto free_at = [cells](int i) { return static_cast<unsigned>(cells[i] == CellState::Free); };

  const unsigned cut = allow_corner_cutting ? 1U : 0U;
  // Bit k: the move of heading k (E, SE, S, SW, W, NW, N, NE), odd headings diagonal.
  unsigned moves = 0;
  if (static_cast<unsigned>(x - 1) < static_cast<unsigned>(w - 2) &&
      static_cast<unsigned>(y - 1) < static_cast<unsigned>(h - 2)) {
    // Not on the border: all eight neighbours are in the grid, so every cell is read and the
    // mask is formed without a branch.
    const unsigned e = free_at(index + 1);
    const unsigned s = free_at(index + w);
    const unsigned wst = free_at(index - 1);
    const unsigned n = free_at(index - w);
    moves = e | (free_at(index + w + 1) & (cut | (e & s))) << 1U | s << 2U |
            (free_at(index + w - 1) & (cut | (wst & s))) << 3U | wst << 4U |
            (free_at(index - w - 1) & (cut | (wst & n))) << 5U | n << 6U |
            (free_at(index - w + 1) & (cut | (e & n))) << 7U;
  } else {
    const bool has_e = x + 1 < w;
    const bool has_s = y + 1 < h;
    const bool has_w = x > 0;
    const bool has_n = y > 0;
    const bool e = has_e && free_at(index + 1);
    const bool s = has_s && free_at(index + w);
    const bool wst = has_w && free_at(index - 1);
    const bool n = has_n && free_at(index - w);
    moves =
        static_cast<unsigned>(e) |
        static_cast<unsigned>(has_e && has_s && (cut != 0 || (e && s)) && free_at(index + w + 1)) << 1U |
        static_cast<unsigned>(s) << 2U |
        static_cast<unsigned>(has_w && has_s && (cut != 0 || (wst && s)) && free_at(index + w - 1)) << 3U |
        static_cast<unsigned>(wst) << 4U |
        static_cast<unsigned>(has_w && has_n && (cut != 0 || (wst && n)) && free_at(index - w - 1)) << 5U |
        static_cast<unsigned>(n) << 6U |
        static_cast<unsigned>(has_e && has_n && (cut != 0 || (e && n)) && free_at(index - w + 1)) << 7U;
  }
  // One call per allowed move, in heading order, each with its constant offset and cost.
  if ((moves & 1U) != 0) sink(index + 1, kStraight);
  if ((moves & 2U) != 0) sink(index + w + 1, kDiagonal);
  if ((moves & 4U) != 0) sink(index + w, kStraight);
  if ((moves & 8U) != 0) sink(index + w - 1, kDiagonal);
  if ((moves & 16U) != 0) sink(index - 1, kStraight);
  if ((moves & 32U) != 0) sink(index - w - 1, kDiagonal);
  if ((moves & 64U) != 0) sink(index - w, kStraight);
  if ((moves & 128U) != 0) sink(index - w + 1, kDiagonal);
}

/// The states and successors of a search environment over known free space (the contract of
/// grid_search.hpp): cells are states, the moves above at exact costs (OctileCost). The
/// environments below, and the distance fields' own (distance_field.cpp), add their heuristic
/// and stop rule to it.
class OctileMoves {
 public:
  using Cost = OctileCost;

  OctileMoves(const KnownMap& known, bool allow_corner_cutting)
      : known_(known), allow_corner_cutting_(allow_corner_cutting) {}

  [[nodiscard]] int state_count() const { return known_.size(); }
  template <typename Sink>
  void for_each_successor(int state, Sink&& sink) const {
    for_each_octile_neighbour<Cost>(known_, state, allow_corner_cutting_, sink);
  }

 private:
  const KnownMap& known_;
  bool allow_corner_cutting_;
};

/// The Dijkstra environment of a field over known free space: the moves above, no heuristic,
/// every settled cell expanded. Run from one cell or from several (a multi-source field).
class OctileFieldEnvironment : public OctileMoves {
 public:
  static constexpr bool kZeroHeuristic = true;
  using OctileMoves::OctileMoves;
  [[nodiscard]] static Cost heuristic(int /*state*/) { return {}; }
  static Visit visit(int /*state*/, double /*g*/) { return Visit::Expand; }
};

/// The search environment of one query to a goal cell over known free space: the moves above,
/// the goal ends the search; the heuristic is the octile length to the goal for A* (exact and
/// consistent) and 0 for Dijkstra (declared, so the search uses its Dijkstra open list).
template <bool kAStar>
class OctileGoalEnvironment : public OctileMoves {
 public:
  static constexpr bool kZeroHeuristic = !kAStar;

  OctileGoalEnvironment(const KnownMap& known, Cell goal, bool allow_corner_cutting)
      : OctileMoves(known, allow_corner_cutting),
        goal_(goal),
        goal_index_(known.index(goal)),
        cells_(known.width()) {}

  [[nodiscard]] Cost heuristic(int state) const {
    if constexpr (kAStar) {
      return octile_cost(cells_.cell(state), goal_);
    } else {
      return Cost{};
    }
  }
  [[nodiscard]] Visit visit(int state, double /*g*/) const {
    return state == goal_index_ ? Visit::Goal : Visit::Expand;
  }

 private:
  Cell goal_;
  int goal_index_;
  CellIndexer cells_;
};

}  // namespace search
}  // namespace fsweep
