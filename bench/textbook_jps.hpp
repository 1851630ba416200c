#pragma once
/// @file textbook_jps.hpp
/// The yardstick of `jps` (bench_jps.cpp): a compact, standalone jump point search on a fully known,
/// static map, written from Harabor and Grastien, "Improving Jump Point Search" (ICAPS 2014), its
/// block-based symmetry breaking, with no environment, planner or stop-condition layers:
/// - the map is copied once into its own bit rows and a transposed copy (bit columns), each padded
///   with a blocked border and a zero guard word at either end, so that a straight jump reads whole
///   words of its line and of the two lines beside it with no bounds checks, and vertical jumps run
///   the row code on the columns; a byte grid with the same border serves the diagonal steps;
/// - a straight jump finds in each word, by bit operations, the cells that are blocked or have a
///   forced neighbour and takes the first of them past its cell (count trailing zeros going up a
///   line, leading zeros going down), 64 cells a word;
/// - moves are MovingAI's (8-connected, no corner cutting: a diagonal step needs both orthogonal
///   cells beside it free), so diagonal moves have no forced neighbours, and a straight move from p
///   to x forces x + q (q perpendicular) when x + q is free and p + q is not (then x also branches
///   to x + q and x + d + q);
/// - a diagonal jump steps one cell at a time until a step is not allowed and at each cell runs the
///   two straight jumps along its components, opening the jump points they find as successors of
///   the cell jumped from, through the diagonal cell (the paper's online pruning: the cells of the
///   diagonal are not opened, only the goal if the diagonal reaches it); the direction of arrival
///   at a jump point is the last step's, along the longer axis from its parent, so the yardstick
///   expands the jump points `jps` expands;
/// - A* over the jump points: exact costs as counts of straight and diagonal steps, the octile
///   heuristic, an indexed binary heap with decrease-key ordered by smaller f, larger g, smaller
///   cell (the order of BestFirstSearchT; the padded cell index orders cells as the map's index does),
///   the successors of a jump point in `jps`'s order, node data stamped per query.
/// It answers as TextbookAStar does (TextbookResult: length, expansions, which here are jump points,
/// and the path's cell count), and the path's every cell when asked for.

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "textbook_astar.hpp"  // TextbookResult
#include "world/grid.hpp"
#include "world/known_map.hpp"
#include "world/world_map.hpp"

namespace fsweep::textbook {

/// Jump point search with block-based jumps over one static map (see the file comment). Not
/// thread-safe.
class TextbookJps {
 public:
  explicit TextbookJps(const KnownMap& known)
      : TextbookJps(known.width(), known.height(), [&known](int x, int y) {
          return known.is_free(Cell{x, y});
        }) {}
  explicit TextbookJps(const WorldMap& map)
      : TextbookJps(map.width(), map.height(), [&map](int x, int y) {
          return map.is_free(Cell{x, y});
        }) {}
  /// A width x height map whose cell (x, y) is free when `is_free(x, y)`.
  template <typename IsFree>
  TextbookJps(int width, int height, IsFree is_free)
      : stride_(width + 2),
        free_(static_cast<std::size_t>(stride_) * static_cast<std::size_t>(height + 2), 0),
        rows_(height + 2, stride_),
        columns_(stride_, height + 2),
        nodes_(free_.size()),
        open_(free_.size()) {
    for (int y = 1; y <= height; ++y) {
      for (int x = 1; x <= width; ++x) {
        if (!is_free(x - 1, y - 1)) continue;
        const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(stride_);
        free_[i + static_cast<std::size_t>(x)] = 1;
        rows_.set(y, x);
        columns_.set(x, y);
      }
    }
  }

  /// The shortest path from `start` to `goal` (free cells of the map); with `cells`, also its
  /// every cell from start to goal (cleared when there is none).
  TextbookResult search(Cell start, Cell goal, std::vector<Cell>* cells = nullptr) {
    TextbookResult result;
    query_ += 2;
    open_.clear();
    goal_x_ = goal.x + 1;
    goal_y_ = goal.y + 1;
    goal_ = goal_y_ * stride_ + goal_x_;
    relax(-1, (start.y + 1) * stride_ + start.x + 1, 0, 0, start.x + 1, start.y + 1);
    while (!open_.empty()) {
      const int c = open_.pop();
      Node& node = nodes_[static_cast<std::size_t>(c)];
      node.stamp = query_ + 1;
      ++result.expansions;
      if (c == goal_) {
        result.length = node.gs + node.gd * kSqrt2;
        result.path_cells = trace(c, cells);
        return result;
      }
      expand(c, node.parent);
    }
    if (cells != nullptr) cells->clear();
    return result;
  }

 private:
  /// Bit lines (rows, or the columns of the transposed copy) of the padded map: bit p of line l
  /// set when cell p of it is free; each line a zero guard word, `words` words, a zero guard word.
  class Lines {
   public:
    Lines(int lines, int cells)
        : words_((cells + 63) / 64 + 2),
          bits_(static_cast<std::size_t>(lines) * static_cast<std::size_t>(words_)) {}
    void set(int line, int p) { at(line)[p / 64] |= std::uint64_t{1} << static_cast<unsigned>(p % 64); }
    /// Word 0 of line l (word -1 is its leading guard word).
    [[nodiscard]] const std::uint64_t* at(int line) const {
      return bits_.data() + static_cast<std::ptrdiff_t>(line) * words_ + 1;
    }

   private:
    std::uint64_t* at(int line) { return bits_.data() + static_cast<std::ptrdiff_t>(line) * words_ + 1; }
    int words_;
    std::vector<std::uint64_t> bits_;
  };

  /// Search data of a cell (16 bytes): g as step counts, parent, and the query's stamp: query_
  /// when reached (open), query_ + 1 when settled, anything else stale.
  struct Node {
    std::int32_t gs = 0;
    std::int32_t gd = 0;
    std::int32_t parent = -1;
    std::uint32_t stamp = 0;
  };

  /// A*'s open list: a binary heap of (f, g, cell) entries, one per open cell, whose slots are
  /// kept per cell for decrease-key.
  class OpenList {
   public:
    struct Entry {
      double f;
      double g;
      std::int32_t cell;
    };
    explicit OpenList(std::size_t cells) : slot_of_(cells, 0) {}
    [[nodiscard]] bool empty() const { return heap_.empty(); }
    void clear() { heap_.clear(); }
    void push(const Entry& e) {
      heap_.push_back(e);
      rise(heap_.size() - 1, e);
    }
    /// `e` replaces the entry of its cell, which it must come before.
    void decrease(const Entry& e) { rise(slot_of_[static_cast<std::size_t>(e.cell)], e); }
    /// Removes the first entry and returns its cell.
    int pop() {
      const int top = heap_[0].cell;
      const Entry last = heap_.back();
      heap_.pop_back();
      if (!heap_.empty()) sink(last);
      return top;
    }

   private:
    /// Smaller f, then larger g, then smaller cell.
    static bool before(const Entry& a, const Entry& b) {
      if (a.f != b.f) return a.f < b.f;
      if (a.g != b.g) return a.g > b.g;
      return a.cell < b.cell;
    }
    void put(std::size_t slot, const Entry& e) {
      heap_[slot] = e;
      slot_of_[static_cast<std::size_t>(e.cell)] = static_cast<std::uint32_t>(slot);
    }
    /// Fills the hole at `slot` with `e`, moving the parents it comes before down.
    void rise(std::size_t slot, const Entry& e) {
      while (slot > 0 && before(e, heap_[(slot - 1) / 2])) {
        put(slot, heap_[(slot - 1) / 2]);
        slot = (slot - 1) / 2;
      }
      put(slot, e);
    }
    /// Fills the hole at the root with `e`, moving the smaller children up.
    void sink(const Entry& e) {
      const std::size_t n = heap_.size();
      std::size_t slot = 0;
      for (std::size_t child = 1; child < n; child = 2 * slot + 1) {
        if (child + 1 < n && before(heap_[child + 1], heap_[child])) ++child;
        if (!before(heap_[child], e)) break;
        put(slot, heap_[child]);
        slot = child;
      }
      put(slot, e);
    }
    std::vector<Entry> heap_;
    std::vector<std::uint32_t> slot_of_;
  };

  static int sign(int v) { return (v > 0) - (v < 0); }

  /// The first cell past `p` (going up the line) that is blocked or has a forced neighbour: a
  /// side cell free and the side cell behind it (p - 1) blocked. The padding stops it.
  static int first_stop_after(const std::uint64_t* line, const std::uint64_t* a, const std::uint64_t* b,
                              int p) {
    int w = (p + 1) / 64;
    std::uint64_t past = ~std::uint64_t{0} << static_cast<unsigned>((p + 1) % 64);
    for (;; ++w, past = ~std::uint64_t{0}) {
      const std::uint64_t behind_a = (a[w] << 1U) | (a[w - 1] >> 63U);
      const std::uint64_t behind_b = (b[w] << 1U) | (b[w - 1] >> 63U);
      const std::uint64_t stops = (~line[w] | (a[w] & ~behind_a) | (b[w] & ~behind_b)) & past;
      if (stops != 0) return w * 64 + std::countr_zero(stops);
    }
  }
  /// The same going down the line: the last such cell before `p` (behind a cell is p + 1).
  static int last_stop_before(const std::uint64_t* line, const std::uint64_t* a, const std::uint64_t* b,
                              int p) {
    int w = (p - 1) / 64;
    std::uint64_t past = ~std::uint64_t{0} >> static_cast<unsigned>(63 - (p - 1) % 64);
    for (;; --w, past = ~std::uint64_t{0}) {
      const std::uint64_t behind_a = (a[w] >> 1U) | (a[w + 1] << 63U);
      const std::uint64_t behind_b = (b[w] >> 1U) | (b[w + 1] << 63U);
      const std::uint64_t stops = (~line[w] | (a[w] & ~behind_a) | (b[w] & ~behind_b)) & past;
      if (stops != 0) return w * 64 + 63 - std::countl_zero(stops);
    }
  }
  /// The steps of the straight jump from cell `p` of line `l` in direction kDir (+1 or -1) to the
  /// goal (at `goal_p` of line `goal_l`) or a jump point; 0 if a blocked cell comes first.
  template <int kDir>
  static int jump_line(const Lines& lines, int l, int p, int goal_l, int goal_p) {
    const std::uint64_t* line = lines.at(l);
    int stop = 0;
    if constexpr (kDir > 0) {
      stop = first_stop_after(line, lines.at(l - 1), lines.at(l + 1), p);
    } else {
      stop = last_stop_before(line, lines.at(l - 1), lines.at(l + 1), p);
    }
    if (l == goal_l && (goal_p - p) * kDir > 0 && (stop - goal_p) * kDir >= 0) return (goal_p - p) * kDir;
    const bool free = ((line[stop / 64] >> static_cast<unsigned>(stop % 64)) & 1U) != 0;
    return free ? (stop - p) * kDir : 0;
  }
  /// The steps of the straight jump from (x, y) along (kDx, kDy) to the goal or a jump point; 0
  /// if a blocked cell comes first: along its row, or its column in the transposed copy.
  template <int kDx, int kDy>
  [[nodiscard]] int straight_steps(int x, int y) const {
    if constexpr (kDy == 0) {
      return jump_line<kDx>(rows_, y, x, goal_y_, goal_x_);
    } else {
      return jump_line<kDy>(columns_, x, y, goal_x_, goal_y_);
    }
  }
  /// Jumps from cell `c` at (x, y) along (kDx, kDy) and opens the jump points found. Straight:
  /// the jump point of the line. Diagonal: one step at a time until a step is not allowed,
  /// opening at each cell the jump points of the straight jumps along kDx and kDy from it, or
  /// the cell itself if it is the goal (then the jump ends); the cells of the diagonal are not
  /// opened (the paper's online pruning).
  template <int kDx, int kDy>
  void jump(int c, int x, int y) {
    const Node& from = nodes_[static_cast<std::size_t>(c)];
    const int gs = from.gs;
    const int gd = from.gd;
    if constexpr (kDx == 0 || kDy == 0) {
      const int steps = straight_steps<kDx, kDy>(x, y);
      if (steps != 0)
        relax(c, c + steps * (kDy * stride_ + kDx), gs + steps, gd, x + steps * kDx, y + steps * kDy);
    } else {
      const int vertical = kDy * stride_;
      const std::uint8_t* at = free_.data() + static_cast<std::ptrdiff_t>(y) * stride_ + x;
      int cell = c;
      for (int steps = 1;; ++steps) {
        if ((at[kDx] & at[vertical] & at[vertical + kDx]) == 0) return;
        at += vertical + kDx;
        cell += vertical + kDx;
        x += kDx;
        y += kDy;
        if (cell == goal_) return relax(c, cell, gs, gd + steps, x, y);
        if (const int across = straight_steps<kDx, 0>(x, y); across != 0) {
          relax(c, cell + across * kDx, gs + across, gd + steps, x + across * kDx, y);
        }
        if (const int along = straight_steps<0, kDy>(x, y); along != 0) {
          relax(c, cell + along * vertical, gs + along, gd + steps, x, y + along * kDy);
        }
      }
    }
  }
  /// jump<dx, dy>(): one specialisation per direction, as the paper's (and Warthog's) jump
  /// functions, so that each scans with its direction's shifts and counts.
  void jump(int c, int x, int y, int dx, int dy) {
    using Jump = void (TextbookJps::*)(int, int, int);
    static constexpr std::array<Jump, 9> kJumps{&TextbookJps::jump<-1, -1>,
                                                &TextbookJps::jump<0, -1>,
                                                &TextbookJps::jump<1, -1>,
                                                &TextbookJps::jump<-1, 0>,
                                                nullptr,
                                                &TextbookJps::jump<1, 0>,
                                                &TextbookJps::jump<-1, 1>,
                                                &TextbookJps::jump<0, 1>,
                                                &TextbookJps::jump<1, 1>};
    const int heading = (dy + 1) * 3 + dx + 1;
    (this->*kJumps[static_cast<std::size_t>(heading)])(c, x, y);
  }
  /// Jumps from the settled cell `c` (reached from `parent`, -1 for the start) in its pruned
  /// directions, in `jps`'s order.
  void expand(int c, int parent) {
    const int x = c % stride_;
    const int y = c / stride_;
    if (parent < 0) {
      for (const Cell d : kDirections) jump(c, x, y, d.x, d.y);
      return;
    }
    // The direction of the last step from the parent: along the longer axis (a diagonal run
    // comes before a straight one), diagonal if the axes are equal.
    const int across = std::abs(x - parent % stride_);
    const int down = std::abs(y - parent / stride_);
    const int dx = across >= down ? sign(x - parent % stride_) : 0;
    const int dy = down >= across ? sign(y - parent / stride_) : 0;
    jump(c, x, y, dx, dy);  // the natural neighbour ahead
    if (dx != 0 && dy != 0) {
      jump(c, x, y, dx, 0);
      jump(c, x, y, 0, dy);
      return;
    }
    const std::uint8_t* free = free_.data();
    for (const int side : {1, -1}) {  // q = (dy, dx) and (-dy, -dx): forced past a blocked p + q
      const int q = side * (dx * stride_ + dy);
      if (free[c + q] != 0 && free[c - dy * stride_ - dx + q] == 0) {
        jump(c, x, y, side * dy, side * dx);
        jump(c, x, y, dx + side * dy, dy + side * dx);
      }
    }
  }
  /// Opens `cell` (at x, y) at g = (gs, gd) from `parent` unless it is settled or has a path
  /// as short; f adds the octile distance to the goal.
  void relax(int parent, int cell, int gs, int gd, int x, int y) {
    Node& n = nodes_[static_cast<std::size_t>(cell)];
    const bool seen = n.stamp == query_;
    if (n.stamp == query_ + 1 || (seen && n.gs + n.gd * kSqrt2 <= gs + gd * kSqrt2)) return;
    n = Node{gs, gd, parent, query_};
    const int across = std::abs(x - goal_x_);
    const int down = std::abs(y - goal_y_);
    const int h_diagonal = std::min(across, down);
    const OpenList::Entry e{(gs + across + down - 2 * h_diagonal) + (gd + h_diagonal) * kSqrt2,
                            gs + gd * kSqrt2, cell};
    if (seen) {
      open_.decrease(e);  // a shorter g with the same h: a smaller f
    } else {
      open_.push(e);
    }
  }
  /// The path's cell count back from `goal` along the parents (jump points); with `cells`, its
  /// every cell, written from the back.
  std::size_t trace(int goal, std::vector<Cell>* cells) const {
    std::size_t count = 1;
    for (int p = goal, q = nodes_[static_cast<std::size_t>(p)].parent; q >= 0;
         p = q, q = nodes_[static_cast<std::size_t>(q)].parent) {
      count += static_cast<std::size_t>(
          std::max(std::abs(p % stride_ - q % stride_), std::abs(p / stride_ - q / stride_)));
    }
    if (cells == nullptr) return count;
    cells->resize(count);
    std::size_t i = count;
    int p = goal;
    for (int q = nodes_[static_cast<std::size_t>(p)].parent; q >= 0;
         p = q, q = nodes_[static_cast<std::size_t>(q)].parent) {
      // From p back to q: the straight run along the longer axis, then the diagonal one.
      for (int c = p; c != q;) {
        (*cells)[--i] = Cell{c % stride_ - 1, c / stride_ - 1};
        const int across = c % stride_ - q % stride_;
        const int down = c / stride_ - q / stride_;
        c -= (std::abs(across) >= std::abs(down) ? sign(across) : 0) +
             (std::abs(down) >= std::abs(across) ? sign(down) * stride_ : 0);
      }
    }
    (*cells)[0] = Cell{p % stride_ - 1, p / stride_ - 1};  // the start
    return count;
  }

  int stride_;
  std::vector<std::uint8_t> free_;
  Lines rows_;
  Lines columns_;
  std::vector<Node> nodes_;
  OpenList open_;
  std::uint32_t query_ = 0;  ///< even, 2 more each query
  int goal_x_ = 0;
  int goal_y_ = 0;
  int goal_ = 0;
};

}  // namespace fsweep::textbook
