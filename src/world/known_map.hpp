#pragma once
/// @file known_map.hpp
/// The robot's map: unknown / free / occupied per cell, built only from sensor updates.

#include <atomic>
#include <cstdint>
#include <vector>

#include "world/grid.hpp"

namespace fsweep {
inline namespace world {

/// Knowledge state of one cell.
enum class CellState : std::uint8_t { Unknown = 0, Free = 1, Occupied = 2 };

/// What the robot knows. Cells outside the grid count as occupied.
///
/// Beside the cells it keeps their freedom as bits, by rows and by columns (bit x of row y and
/// bit y of column x set when cell (x, y) is known free; 64 cells a word, the bits past the
/// grid's edge clear), for planners that scan a row or column a word at a time (`jps`). They
/// follow every reveal() and forget(). Each line has a clear guard word before and after it, and
/// a clear guard line lies beyond each edge, so that such a scan reads its line's neighbours
/// without bounds checks.
///
/// For planners that cache what they derive from the map (`jps+`'s jump table), instance_id()
/// and revision() together name the map's content: a cache made when both read the same is
/// still valid.
class KnownMap {
 public:
  KnownMap() = default;
  KnownMap(int width, int height, double resolution_m)
      : cells_(width, height, CellState::Unknown),
        resolution_m_(resolution_m),
        row_words_((width + 63) / 64),
        column_words_((height + 63) / 64),
        free_rows_(static_cast<std::size_t>(row_words_ + 2) * static_cast<std::size_t>(height + 2), 0),
        free_columns_(static_cast<std::size_t>(column_words_ + 2) * static_cast<std::size_t>(width + 2), 0) {}

  [[nodiscard]] int width() const { return cells_.width(); }
  [[nodiscard]] int height() const { return cells_.height(); }
  [[nodiscard]] int size() const { return cells_.size(); }
  [[nodiscard]] double resolution_m() const { return resolution_m_; }
  [[nodiscard]] bool in_bounds(Cell c) const { return cells_.in_bounds(c); }
  [[nodiscard]] int index(Cell c) const { return cells_.index(c); }
  [[nodiscard]] Cell cell(int index) const { return cells_.cell(index); }

  [[nodiscard]] CellState state(int index) const { return cells_[index]; }
  [[nodiscard]] CellState state(Cell c) const {
    return cells_.in_bounds(c) ? cells_.at(c) : CellState::Occupied;
  }
  [[nodiscard]] bool is_free(Cell c) const { return state(c) == CellState::Free; }
  [[nodiscard]] bool is_free(int index) const { return cells_[index] == CellState::Free; }
  [[nodiscard]] bool is_unknown(int index) const { return cells_[index] == CellState::Unknown; }

  /// Records an observation of a so far unknown cell. Returns true when the cell was unknown.
  bool reveal(int index, bool occupied) { return reveal(index, cells_.cell(index), occupied); }
  /// The same for a caller that has the cell `c` of `index` at hand (the sensor's scans).
  bool reveal(int index, Cell c, bool occupied) {
    if (cells_[index] != CellState::Unknown) return false;
    cells_[index] = occupied ? CellState::Occupied : CellState::Free;
    ++(occupied ? occupied_count_ : free_count_);
    ++revision_;
    if (!occupied) set_free_bits(c, true);
    return true;
  }

  /// Makes a known cell unknown again. For callers that reuse one map for many independent
  /// scans (the visibility tables of the offline optimum, optimum/coverage_instance.hpp).
  /// Returns true when the cell was known.
  bool forget(int index) {
    const CellState s = cells_[index];
    if (s == CellState::Unknown) return false;
    --(s == CellState::Occupied ? occupied_count_ : free_count_);
    cells_[index] = CellState::Unknown;
    ++revision_;
    if (s == CellState::Free) set_free_bits(cells_.cell(index), false);
    return true;
  }

  [[nodiscard]] int free_count() const { return free_count_; }
  [[nodiscard]] int occupied_count() const { return occupied_count_; }
  [[nodiscard]] int known_count() const { return free_count_ + occupied_count_; }
  [[nodiscard]] const Grid<CellState>& cells() const { return cells_; }

  /// Changes so far: grows by one with every reveal() or forget() that changes a cell (a copy
  /// starts from its source's count).
  [[nodiscard]] std::uint64_t revision() const { return revision_; }
  /// A number of this object alone in the process (>= 1): every construction, copy and
  /// assignment draws a new one, so a map made at the address of a destroyed one, or a copy
  /// that then changes apart from its source, never passes for it.
  [[nodiscard]] std::uint64_t instance_id() const { return instance_id_.value(); }

  /// Words per row of free_row() and per column of free_column().
  [[nodiscard]] int row_words() const { return row_words_; }
  [[nodiscard]] int column_words() const { return column_words_; }
  /// Row y's free cells as bits (bit x % 64 of word x / 64), row_words() words; -1 <= y <=
  /// height (the rows beyond the edges are clear), and words -1 and row_words() are readable
  /// (clear).
  [[nodiscard]] const std::uint64_t* free_row(int y) const { return line_bits(free_rows_, row_words_, y); }
  /// Column x's free cells as bits (bit y % 64 of word y / 64), column_words() words; -1 <= x <=
  /// width, with the same guards.
  [[nodiscard]] const std::uint64_t* free_column(int x) const {
    return line_bits(free_columns_, column_words_, x);
  }

  friend bool operator==(const KnownMap& a, const KnownMap& b) {
    // The bits follow the cells; the revision and instance id name an object's history, not
    // its content.
    return a.cells_ == b.cells_ && a.resolution_m_ == b.resolution_m_ && a.free_count_ == b.free_count_ &&
           a.occupied_count_ == b.occupied_count_;
  }

 private:
  /// instance_id()'s number: drawn from one process-wide counter by every construction, copy
  /// and assignment, moves included (they use the copy members, which are noexcept, so that a
  /// KnownMap still moves without throwing).
  class InstanceId {
   public:
    InstanceId() noexcept : value_(draw()) {}
    InstanceId(const InstanceId& /*other*/) noexcept : value_(draw()) {}
    InstanceId& operator=(const InstanceId& /*other*/) noexcept {
      value_ = draw();
      return *this;
    }
    ~InstanceId() = default;
    [[nodiscard]] std::uint64_t value() const { return value_; }

   private:
    static std::uint64_t draw() noexcept {
      static std::atomic<std::uint64_t> next{0};
      return next.fetch_add(1, std::memory_order_relaxed) + 1;
    }
    std::uint64_t value_;
  };

  /// The first data word of line `l` (-1 <= l <= lines) in `bits`, whose lines are `words` + 2
  /// long (a guard word each side) from the guard line -1 on.
  [[nodiscard]] static const std::uint64_t* line_bits(const std::vector<std::uint64_t>& bits, int words,
                                                      int l) {
    return bits.data() + static_cast<std::size_t>(l + 1) * static_cast<std::size_t>(words + 2) + 1;
  }

  void set_free_bits(Cell c, bool free) {
    const auto flip = [free](std::uint64_t& word, int bit) {
      const std::uint64_t mask = std::uint64_t{1} << static_cast<unsigned>(bit);
      word = free ? (word | mask) : (word & ~mask);
    };
    flip(free_rows_[static_cast<std::size_t>(c.y + 1) * static_cast<std::size_t>(row_words_ + 2) + 1 +
                    static_cast<std::size_t>(c.x / 64)],
         c.x % 64);
    flip(free_columns_[static_cast<std::size_t>(c.x + 1) * static_cast<std::size_t>(column_words_ + 2) + 1 +
                       static_cast<std::size_t>(c.y / 64)],
         c.y % 64);
  }

  Grid<CellState> cells_;
  double resolution_m_ = 1.0;
  int free_count_ = 0;
  int occupied_count_ = 0;
  int row_words_ = 0;
  int column_words_ = 0;
  std::vector<std::uint64_t> free_rows_;
  std::vector<std::uint64_t> free_columns_;
  std::uint64_t revision_ = 0;
  InstanceId instance_id_;
};

/// A KnownMap that knows every cell of the ground truth (for planning on known maps).
struct WorldMap;
[[nodiscard]] KnownMap fully_known(const WorldMap& map);

}  // namespace world
}  // namespace fsweep
