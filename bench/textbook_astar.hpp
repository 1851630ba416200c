#pragma once
/// @file textbook_astar.hpp
/// The yardstick of BM_TextbookAstar: a compact, standalone octile A* on a fully known MovingAI
/// map, written the way a tuned research code base writes it (Warthog's A*: an indexed binary
/// heap with decrease-key whose position lives in the search node, f and g kept with the node),
/// with no environment, planner or stop-condition layers:
/// - the map is copied into a byte grid with a blocked border, so moves need no bounds checks;
/// - moves are MovingAI's: 8-connected, no corner cutting, 1 and sqrt(2) per step; costs are
///   exact (counts of straight and diagonal steps, compared as count_s + count_d * sqrt(2));
/// - the open list is an indexed 4-ary heap of (f, g, cell) entries, one per open cell, ordered
///   by smaller f, then larger g, then smaller cell (the order of BestFirstSearchT, so both
///   expand the same cells: bench_planners.cpp checks it), compared without branches;
/// - node data is stamped per query instead of cleared;
/// - the relaxation is inlined at each of the eight moves (FSWEEP_ALWAYS_INLINE; as a call it
///   took 3-7% longer, measured 2026-12-03: the same change as in grid_search.hpp's search).
/// It answers length and path cells only (no energy or turn accounting).

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/always_inline.hpp"
#include "world/grid.hpp"
#include "world/known_map.hpp"

namespace fsweep::textbook {

/// One query's answer: the optimal length (cells; < 0: no path), the cells expanded and the
/// path's cell count (start and goal included).
struct TextbookResult {
  double length = -1.0;
  long expansions = 0;
  std::size_t path_cells = 0;
};

/// Octile A* over one fully known map (see the file comment). Not thread-safe.
class TextbookAStar {
 public:
  explicit TextbookAStar(const KnownMap& known)
      : stride_(known.width() + 2),
        free_(static_cast<std::size_t>(stride_ * (known.height() + 2)), 0),
        nodes_(free_.size()) {
    for (int y = 0; y < known.height(); ++y) {
      for (int x = 0; x < known.width(); ++x) free_[at(x + 1, y + 1)] = known.is_free(Cell{x, y}) ? 1 : 0;
    }
  }

  /// The shortest path from `start` to `goal` (free cells of the map).
  TextbookResult search(Cell start, Cell goal) {
    TextbookResult result;
    ++query_;
    open_.clear();
    goal_x_ = goal.x + 1;
    goal_y_ = goal.y + 1;
    const int target = (goal.y + 1) * stride_ + goal.x + 1;
    relax(-1, (start.y + 1) * stride_ + start.x + 1, 0, 0, start.x + 1, start.y + 1);
    const std::uint8_t* free = free_.data();
    while (!open_.empty()) {
      const int c = pop();
      Node& node = nodes_[static_cast<std::size_t>(c)];
      node.closed = query_;
      ++result.expansions;
      if (c == target) {
        result.length = length(node.gs, node.gd);
        path_.clear();
        for (int p = c; p >= 0; p = nodes_[static_cast<std::size_t>(p)].parent) path_.push_back(p);
        std::reverse(path_.begin(), path_.end());
        result.path_cells = path_.size();
        return result;
      }
      // One division per expansion; the neighbours' coordinates follow from it.
      const int x = c % stride_;
      const int y = c / stride_;
      const int gs = node.gs;
      const int gd = node.gd;
      const bool east = free[c + 1] != 0;
      const bool south = free[c + stride_] != 0;
      const bool west = free[c - 1] != 0;
      const bool north = free[c - stride_] != 0;
      if (east) relax(c, c + 1, gs + 1, gd, x + 1, y);
      if (east && south && free[c + stride_ + 1] != 0) relax(c, c + stride_ + 1, gs, gd + 1, x + 1, y + 1);
      if (south) relax(c, c + stride_, gs + 1, gd, x, y + 1);
      if (west && south && free[c + stride_ - 1] != 0) relax(c, c + stride_ - 1, gs, gd + 1, x - 1, y + 1);
      if (west) relax(c, c - 1, gs + 1, gd, x - 1, y);
      if (west && north && free[c - stride_ - 1] != 0) relax(c, c - stride_ - 1, gs, gd + 1, x - 1, y - 1);
      if (north) relax(c, c - stride_, gs + 1, gd, x, y - 1);
      if (east && north && free[c - stride_ + 1] != 0) relax(c, c - stride_ + 1, gs, gd + 1, x + 1, y - 1);
    }
    return result;
  }

 private:
  /// Search data of a cell: g as step counts, parent, slot in open_, query stamps.
  struct Node {
    std::int32_t gs = 0;
    std::int32_t gd = 0;
    std::int32_t parent = -1;
    std::uint32_t slot = 0;
    std::uint32_t reached = 0;
    std::uint32_t closed = 0;
  };
  struct Entry {
    double f;
    double g;
    std::int32_t cell;
  };
  static constexpr std::size_t kArity = 4;

  [[nodiscard]] std::size_t at(int x, int y) const { return static_cast<std::size_t>(y * stride_ + x); }
  static double length(int straight, int diagonal) { return straight + diagonal * kSqrt2; }
  /// a before b: smaller f, larger g, smaller cell, as one branch-free expression.
  static bool first(const Entry& a, const Entry& b) {
    const unsigned on_g = static_cast<unsigned>(a.g > b.g) |
                          (static_cast<unsigned>(a.g == b.g) & static_cast<unsigned>(a.cell < b.cell));
    return static_cast<bool>(static_cast<unsigned>(a.f < b.f) | (static_cast<unsigned>(a.f == b.f) & on_g));
  }

  /// Opens `cell` (at x, y) at g = (gs, gd) from `parent` if that is shorter than its path so far.
  FSWEEP_ALWAYS_INLINE void relax(int parent, int cell, int gs, int gd, int x, int y) {
    Node& n = nodes_[static_cast<std::size_t>(cell)];
    if (n.closed == query_) return;
    const double g = length(gs, gd);
    const bool seen = n.reached == query_;
    if (seen && length(n.gs, n.gd) <= g) return;
    n.gs = gs;
    n.gd = gd;
    n.parent = parent;
    n.reached = query_;
    const int dx = x > goal_x_ ? x - goal_x_ : goal_x_ - x;
    const int dy = y > goal_y_ ? y - goal_y_ : goal_y_ - y;
    const int diagonal = dx < dy ? dx : dy;
    const Entry e{length(gs + (dx + dy - 2 * diagonal), gd + diagonal), g, cell};
    if (seen) {
      up(n.slot, e);  // decrease-key: f drops with g (h is fixed)
    } else {
      open_.push_back(e);
      up(open_.size() - 1, e);
    }
  }
  /// Moves `e` from slot `i` towards the root.
  void up(std::size_t i, const Entry& e) {
    for (std::size_t p = (i - 1) / kArity; i > 0 && first(e, open_[p]); i = p, p = (i - 1) / kArity) {
      open_[i] = open_[p];
      nodes_[static_cast<std::size_t>(open_[i].cell)].slot = static_cast<std::uint32_t>(i);
    }
    open_[i] = e;
    nodes_[static_cast<std::size_t>(e.cell)].slot = static_cast<std::uint32_t>(i);
  }
  /// Removes the root and returns its cell.
  int pop() {
    const int top = open_.front().cell;
    const Entry e = open_.back();
    open_.pop_back();
    const std::size_t n = open_.size();
    if (n == 0) return top;
    std::size_t i = 0;
    for (std::size_t c = 1; c < n; c = i * kArity + 1) {
      const std::size_t last = std::min(c + kArity, n);
      std::size_t m = c;
      for (std::size_t k = c + 1; k < last; ++k) m = first(open_[k], open_[m]) ? k : m;
      if (!first(open_[m], e)) break;
      open_[i] = open_[m];
      nodes_[static_cast<std::size_t>(open_[i].cell)].slot = static_cast<std::uint32_t>(i);
      i = m;
    }
    open_[i] = e;
    nodes_[static_cast<std::size_t>(e.cell)].slot = static_cast<std::uint32_t>(i);
    return top;
  }

  int stride_;
  std::vector<std::uint8_t> free_;
  std::vector<Node> nodes_;
  std::vector<Entry> open_;
  std::vector<int> path_;
  std::uint32_t query_ = 0;
  int goal_x_ = 0;
  int goal_y_ = 0;
};

}  // namespace fsweep::textbook
