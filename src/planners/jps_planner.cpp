#include "planners/jps_planner.hpp"

#include <array>
#include <bit>
#include <cstdint>
#include <optional>
#include <vector>

#include "planners/jump_points.hpp"

namespace fsweep {
inline namespace planners {
namespace {

/// A unit step (dx, dy), each in -1..1, not both 0.
struct Step {
  int dx = 0;
  int dy = 0;
};

using jump_points::sign_of;

/// Search environment of one JPS query (the BestFirstSearch contract of grid_search.hpp): states
/// are cell indices, but only jump points are ever opened; a successor is the jump point found
/// from a state in one of its pruned directions, at the octile length of the segment between
/// them. `kCut` is PlanRequest::allow_corner_cutting (the rules of the file comment of
/// jps_planner.hpp). The direction a state was reached in comes from its parent in `search`,
/// which runs this environment (a settled state's parent is final).
template <bool kCut>
class JumpEnvironment {
 public:
  using Cost = OctileCost;
  JumpEnvironment(const KnownMap& known, Cell goal, const OctileSearch& search)
      : known_(known),
        cells_(known.cells().data().data()),
        width_(known.width()),
        height_(known.height()),
        goal_(goal),
        search_(search) {}

  [[nodiscard]] int state_count() const { return width_ * height_; }
  [[nodiscard]] Cost heuristic(int state) const { return octile_cost(cell_of(state), goal_); }
  Visit visit(int state, double /*g*/) const {
    return state == index_of(goal_) ? Visit::Goal : Visit::Expand;
  }

  template <typename Sink>
  void for_each_successor(int state, Sink&& sink) const {
    const Cell at = cell_of(state);
    std::array<Step, 8> steps{};
    int count = 0;
    const auto add = [&](int dx, int dy) { steps[static_cast<std::size_t>(count++)] = Step{dx, dy}; };
    const int parent = search_.parent(state);
    jump_points::pruned_directions<kCut>(
        at, parent < 0 ? std::nullopt : std::optional<Cell>(cell_of(parent)),
        [this](int x, int y) { return is_free(x, y); }, add);
    for (int k = 0; k < count; ++k) {
      const Step s = steps[static_cast<std::size_t>(k)];
      const int found = s.dx == 0 || s.dy == 0 ? jump_straight(at, s) : jump_diagonal(at, s);
      if (found >= 0) sink(found, octile_cost(at, cell_of(found)));
    }
  }

 private:
  [[nodiscard]] Cell cell_of(int state) const { return Cell{state % width_, state / width_}; }
  [[nodiscard]] int index_of(Cell c) const { return c.y * width_ + c.x; }
  /// Known free and inside the grid.
  [[nodiscard]] bool is_free(int x, int y) const {
    return x >= 0 && y >= 0 && x < width_ && y < height_ && cells_[y * width_ + x] == CellState::Free;
  }
  /// The diagonal step from `c` by `s` is allowed (octile_grid.hpp's rule).
  [[nodiscard]] bool diagonal_allowed(Cell c, Step s) const {
    return is_free(c.x + s.dx, c.y + s.dy) &&
           (kCut || (is_free(c.x + s.dx, c.y) && is_free(c.x, c.y + s.dy)));
  }
  /// The first jump point from `c` along the straight direction `s` (the goal or a cell with a
  /// forced neighbour), or -1 if a blocked cell comes first. Scans the row (or column) a word of
  /// 64 cells at a time (Harabor & Grastien, "Improving Jump Point Search", ICAPS 2014): the
  /// first cell past `c` that is blocked or has a forced neighbour, from the bits of its line
  /// and of the two lines beside it (KnownMap::free_row(), free_column()).
  [[nodiscard]] int jump_straight(Cell c, Step s) const {
    const bool across = s.dy == 0;  // along a row
    const int line = across ? c.y : c.x;
    const int from = across ? c.x : c.y;
    const int dir = across ? s.dx : s.dy;
    const int length = across ? width_ : height_;
    const int words = across ? known_.row_words() : known_.column_words();
    // Lines -1 and `lines` are KnownMap's clear guard lines.
    const auto bits = [&](int l) { return across ? known_.free_row(l) : known_.free_column(l); };
    const LineScan scan{bits(line), bits(line - 1), bits(line + 1), words};
    const int stop = dir > 0 ? scan.first_after(from) : scan.last_before(from);
    // The goal on this line before the stop (the stop is blocked or a jump point itself).
    const int goal_line = across ? goal_.y : goal_.x;
    const int goal_at = across ? goal_.x : goal_.y;
    if (goal_line == line && (goal_at - from) * dir > 0 && (stop - goal_at) * dir >= 0)
      return index_of(goal_);
    if (stop < 0 || stop >= length || !scan.free(stop)) return -1;
    return across ? index_of(Cell{stop, line}) : index_of(Cell{line, stop});
  }

  /// One line of cells (a row or column) and the lines on either side as free bits, for
  /// jump_straight(): where a straight jump along it stops.
  struct LineScan {
    const std::uint64_t* line;
    const std::uint64_t* side_a;
    const std::uint64_t* side_b;
    int words;

    /// Words -1 and `words` of every line are KnownMap's clear guards: no bounds checks.
    [[nodiscard]] bool free(int p) const { return ((line[p / 64] >> (p % 64)) & 1U) != 0; }
    /// Word w of a side's bits shifted so that bit i holds cell i - 1 (`previous`) or i + 1.
    [[nodiscard]] static std::uint64_t previous(const std::uint64_t* side, int w) {
      return (side[w] << 1U) | (side[w - 1] >> 63U);
    }
    [[nodiscard]] static std::uint64_t next(const std::uint64_t* side, int w) {
      return (side[w] >> 1U) | (side[w + 1] << 63U);
    }
    /// Word w of the cells where a jump in direction `dir` stops: blocked, or with a forced
    /// neighbour (jps_planner.hpp's rules). Without corner cutting, side cell p is free and the
    /// one behind it (p - dir) is not; with it, side cell p is blocked and the one ahead free.
    [[nodiscard]] std::uint64_t stops(int w, int dir) const {
      std::uint64_t forced = 0;
      for (const std::uint64_t* side : {side_a, side_b}) {
        const std::uint64_t here = side[w];
        if constexpr (kCut) {
          forced |= ~here & (dir > 0 ? next(side, w) : previous(side, w));
        } else {
          forced |= here & ~(dir > 0 ? previous(side, w) : next(side, w));
        }
      }
      return ~line[w] | forced;
    }
    /// The first stop after cell `from` (cells past the line's end are blocked).
    [[nodiscard]] int first_after(int from) const {
      const int start = from + 1;
      for (int w = start / 64; w < words; ++w) {
        std::uint64_t m = stops(w, +1);
        if (w == start / 64) m &= ~std::uint64_t{0} << static_cast<unsigned>(start % 64);
        if (m != 0) return w * 64 + std::countr_zero(m);
      }
      return words * 64;
    }
    /// The last stop before cell `from` (-1: the line's start is passed).
    [[nodiscard]] int last_before(int from) const {
      const int start = from - 1;
      for (int w = start / 64; start >= 0 && w >= 0; --w) {
        std::uint64_t m = stops(w, -1);
        if (w == start / 64) m &= ~std::uint64_t{0} >> static_cast<unsigned>(63 - start % 64);
        if (m != 0) return w * 64 + 63 - std::countl_zero(m);
      }
      return -1;
    }
  };
  /// The first jump point from `c` along the diagonal `s`: the goal, a cell with a forced
  /// neighbour (corner cutting only), or a cell from which jump_straight() along (dx, 0) or
  /// (0, dy) finds one; -1 if a disallowed step comes first.
  [[nodiscard]] int jump_diagonal(Cell c, Step s) const {
    while (diagonal_allowed(c, s)) {
      c = Cell{c.x + s.dx, c.y + s.dy};
      if (c == goal_) return index_of(c);
      if constexpr (kCut) {
        if ((!is_free(c.x - s.dx, c.y) && is_free(c.x - s.dx, c.y + s.dy)) ||
            (!is_free(c.x, c.y - s.dy) && is_free(c.x + s.dx, c.y - s.dy))) {
          return index_of(c);
        }
      }
      if (jump_straight(c, Step{s.dx, 0}) >= 0 || jump_straight(c, Step{0, s.dy}) >= 0) return index_of(c);
    }
    return -1;
  }

  const KnownMap& known_;
  const CellState* cells_;
  int width_;
  int height_;
  Cell goal_;
  const OctileSearch& search_;
};

}  // namespace

std::unique_ptr<Planner> JpsPlanner::clone() const { return std::make_unique<JpsPlanner>(params_); }

SearchResult JpsPlanner::search(const KnownMap& known, const PlanRequest& request,
                                const StopCondition& stop) {
  // Start == goal settles the start as the goal (a one-cell path).
  if (request.allow_corner_cutting) {
    return jump_points::search_jumps(search_, JumpEnvironment<true>(known, request.goal, search_), known,
                                     request.start, stop);
  }
  return jump_points::search_jumps(search_, JumpEnvironment<false>(known, request.goal, search_), known,
                                   request.start, stop);
}

}  // namespace planners
}  // namespace fsweep
