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

/// Search environment of one JPS query (the BestFirstSearch contract of grid_search.hpp): states
/// are cell indices, but only jump points are ever opened; a successor is the jump point found
/// from a state in one of its pruned directions, at the octile length of the segment between
/// them. `kCut` is PlanRequest::allow_corner_cutting (the rules of the file comment of
/// jps_planner.hpp). The direction a state was reached in comes from its parent in `search`,
/// which runs this environment (a settled state's parent is final).
///
/// Every cell test reads KnownMap's free bits (free_row(), free_column()), whose guard words
/// and guard lines are clear: a cell one step off the grid reads as blocked with no bounds
/// check. Each of the eight directions has its own jump (jump_straight<kDx, kDy>() or
/// jump_diagonal<kDx, kDy>(), as the ICAPS 2014 paper's jump functions), so that its shifts,
/// scan order and steps are constants.
template <bool kCut>
class JumpEnvironment {
 public:
  using Cost = OctileCost;
  JumpEnvironment(const KnownMap& known, Cell goal, const OctileSearch& search)
      : rows_(known.free_row(0)),
        row_stride_(known.row_words() + 2),
        row_words_(known.row_words()),
        columns_(known.free_column(0)),
        column_stride_(known.column_words() + 2),
        column_words_(known.column_words()),
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
    // The successors are handed to the sink a batch at a time, in the order found, each one's
    // search data prefetched when it is found: a diagonal jump finds many, and each relaxation
    // waited for its node (measured against handing each over at once: 0.95x the time on
    // den312d's and room-64-64-8's scenarios, no change on a 1,024 x 1,024 open map).
    std::size_t pending = 0;
    const auto flush = [&] {
      for (std::size_t i = 0; i < pending; ++i) sink(index_of(found_[i]), octile_cost(at, found_[i]));
      pending = 0;
    };
    const auto emit = [&](Cell c) {
      search_.prefetch(index_of(c));
      found_[pending++] = c;
      if (pending == kBatch) flush();
    };
    for (int k = 0; k < count; ++k) jump(at, steps[static_cast<std::size_t>(k)], emit);
    flush();
  }

 private:
  /// Successors handed to the sink together (for_each_successor()).
  static constexpr std::size_t kBatch = 16;
  [[nodiscard]] Cell cell_of(int state) const { return Cell{state % width_, state / width_}; }
  [[nodiscard]] int index_of(Cell c) const { return c.y * width_ + c.x; }
  /// Free bits of row y (-1 <= y <= height) and column x (-1 <= x <= width), guards included.
  [[nodiscard]] const std::uint64_t* row(int y) const {
    return rows_ + static_cast<std::ptrdiff_t>(y) * row_stride_;
  }
  [[nodiscard]] const std::uint64_t* column(int x) const {
    return columns_ + static_cast<std::ptrdiff_t>(x) * column_stride_;
  }
  /// Bit p of a line whose words -1.. are readable (p >= -64): arithmetic shifts, so p = -1
  /// reads the leading guard word.
  [[nodiscard]] static bool bit(const std::uint64_t* line, int p) {
    return ((line[p >> 6] >> static_cast<unsigned>(p & 63)) & 1U) != 0;
  }
  /// Known free; (x, y) inside the grid or one cell beyond an edge (blocked).
  [[nodiscard]] bool is_free(int x, int y) const { return bit(row(y), x); }

  /// Emits the successors of `c` along `s`: the jump of that direction.
  template <typename Emit>
  void jump(Cell c, Step s, const Emit& emit) const {
    const auto straight = [&](std::optional<Cell> found) {
      if (found) emit(*found);
    };
    switch ((s.dy + 1) * 3 + s.dx + 1) {
      case 0:
        return jump_diagonal<-1, -1>(c, emit);
      case 1:
        return straight(jump_straight<0, -1>(c));
      case 2:
        return jump_diagonal<1, -1>(c, emit);
      case 3:
        return straight(jump_straight<-1, 0>(c));
      case 5:
        return straight(jump_straight<1, 0>(c));
      case 6:
        return jump_diagonal<-1, 1>(c, emit);
      case 7:
        return straight(jump_straight<0, 1>(c));
      default:
        return jump_diagonal<1, 1>(c, emit);
    }
  }

  /// The first jump point from `c` along the straight direction (kDx, kDy) (the goal or a cell
  /// with a forced neighbour), or none if a blocked cell comes first. Scans the row (or column)
  /// a word of 64 cells at a time (Harabor & Grastien, "Improving Jump Point Search", ICAPS
  /// 2014): the first cell past `c` that is blocked or has a forced neighbour, from the bits of
  /// its line and of the two lines beside it (lines -1 and `lines` are KnownMap's clear guards).
  template <int kDx, int kDy>
  [[nodiscard]] std::optional<Cell> jump_straight(Cell c) const {
    constexpr bool kAcross = kDy == 0;  // along a row
    constexpr int kDir = kAcross ? kDx : kDy;
    const int line = kAcross ? c.y : c.x;
    const int from = kAcross ? c.x : c.y;
    const auto bits = [this](int l) {
      if constexpr (kAcross) {
        return row(l);
      } else {
        return column(l);
      }
    };
    const std::uint64_t* here = bits(line);
    const int stop =
        stop_after<kDir>(here, bits(line - 1), bits(line + 1), kAcross ? row_words_ : column_words_, from);
    // The goal on this line before the stop (the stop is blocked or a jump point itself).
    const int goal_line = kAcross ? goal_.y : goal_.x;
    const int goal_at = kAcross ? goal_.x : goal_.y;
    if (goal_line == line && (goal_at - from) * kDir > 0 && (stop - goal_at) * kDir >= 0) return goal_;
    if (!bit(here, stop)) return std::nullopt;
    return kAcross ? Cell{stop, line} : Cell{line, stop};
  }

  /// The first cell past `from` in direction kDir (+1 or -1) of a line of `words` words whose
  /// bits are `line`, with `side_a` and `side_b` the lines beside it, that is blocked or has a
  /// forced neighbour: without corner cutting, a side cell free and the one behind it (p - kDir)
  /// not; with it, a side cell blocked and the one ahead free. -1 when the scan passes the line's
  /// start, words * 64 when it passes its last word (cells past the line's end are blocked).
  template <int kDir>
  [[nodiscard]] static int stop_after(const std::uint64_t* line, const std::uint64_t* side_a,
                                      const std::uint64_t* side_b, int words, int from) {
    // Word w of a side's bits shifted so that bit i holds cell i - 1 (`previous`) or i + 1; a
    // line's words -1 and `words` are clear guards.
    const auto previous = [](const std::uint64_t* side, int w) {
      return (side[w] << 1U) | (side[w - 1] >> 63U);
    };
    const auto next = [](const std::uint64_t* side, int w) { return (side[w] >> 1U) | (side[w + 1] << 63U); };
    const auto stops = [&](int w) {
      std::uint64_t forced = 0;
      for (const std::uint64_t* side : {side_a, side_b}) {
        if constexpr (kCut) {
          forced |= ~side[w] & (kDir > 0 ? next(side, w) : previous(side, w));
        } else {
          forced |= side[w] & ~(kDir > 0 ? previous(side, w) : next(side, w));
        }
      }
      return ~line[w] | forced;
    };
    const int start = from + kDir;
    int w = start / 64;
    if constexpr (kDir > 0) {
      if (w >= words) return words * 64;
      std::uint64_t m = stops(w) & (~std::uint64_t{0} << static_cast<unsigned>(start % 64));
      while (m == 0) {
        if (++w == words) return words * 64;
        m = stops(w);
      }
      return w * 64 + std::countr_zero(m);
    } else {
      if (start < 0) return -1;
      std::uint64_t m = stops(w) & (~std::uint64_t{0} >> static_cast<unsigned>(63 - start % 64));
      while (m == 0) {
        if (--w < 0) return -1;
        m = stops(w);
      }
      return w * 64 + 63 - std::countl_zero(m);
    }
  }

  /// Emits the successors of `c` along the diagonal (kDx, kDy), stepping one cell at a time
  /// until a disallowed step: at each cell the jump points that jump_straight() along (kDx, 0)
  /// and (0, kDy) finds, reached through that cell (the ICAPS 2014 paper's online pruning: the
  /// cell itself is not opened, see the file comment of jps_planner.hpp). The goal, and (corner
  /// cutting only) a cell with a forced neighbour, is emitted itself and ends the jump.
  template <int kDx, int kDy, typename Emit>
  void jump_diagonal(Cell c, const Emit& emit) const {
    while (true) {
      // The step (octile_grid.hpp's rule): its target free and, without corner cutting, both
      // cells beside it.
      const std::uint64_t* ahead = row(c.y + kDy);
      if (!bit(ahead, c.x + kDx)) return;
      if constexpr (!kCut) {
        if (!bit(ahead, c.x) || !bit(row(c.y), c.x + kDx)) return;
      }
      c = Cell{c.x + kDx, c.y + kDy};
      if (c == goal_) return emit(c);
      if constexpr (kCut) {
        if ((!is_free(c.x - kDx, c.y) && is_free(c.x - kDx, c.y + kDy)) ||
            (!is_free(c.x, c.y - kDy) && is_free(c.x + kDx, c.y - kDy))) {
          return emit(c);
        }
      }
      if (const std::optional<Cell> across = jump_straight<kDx, 0>(c)) emit(*across);
      if (const std::optional<Cell> along = jump_straight<0, kDy>(c)) emit(*along);
    }
  }

  const std::uint64_t* rows_;
  std::ptrdiff_t row_stride_;
  int row_words_;
  const std::uint64_t* columns_;
  std::ptrdiff_t column_stride_;
  int column_words_;
  int width_;
  int height_;
  Cell goal_;
  const OctileSearch& search_;
  /// The batch of for_each_successor(), kept here: cleared once a query, not at every
  /// expansion (a 128-byte clear there took 5% of a den312d query's time).
  mutable std::array<Cell, kBatch> found_{};
};

}  // namespace

std::unique_ptr<Planner> JpsPlanner::clone() const { return std::make_unique<JpsPlanner>(params_); }

SearchResult JpsPlanner::search(const KnownMap& known, const PlanRequest& request,
                                const StopCondition& stop) {
  // Start == goal settles the start as the goal (a one-cell path).
  if (request.allow_corner_cutting) {
    return jump_points::search_jumps(search_, JumpEnvironment<true>(known, request.goal, search_), known,
                                     request, stop);
  }
  return jump_points::search_jumps(search_, JumpEnvironment<false>(known, request.goal, search_), known,
                                   request, stop);
}

}  // namespace planners
}  // namespace fsweep
