#pragma once
/// @file known_map.hpp
/// The robot's map: unknown / free / occupied per cell, built only from sensor updates.

#include <cstdint>

#include "world/grid.hpp"

namespace fsweep {
inline namespace world {

/// Knowledge state of one cell.
enum class CellState : std::uint8_t { Unknown = 0, Free = 1, Occupied = 2 };

/// What the robot knows. Cells outside the grid count as occupied.
class KnownMap {
 public:
  KnownMap() = default;
  KnownMap(int width, int height, double resolution_m)
      : cells_(width, height, CellState::Unknown), resolution_m_(resolution_m) {}

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
  bool reveal(int index, bool occupied) {
    if (cells_[index] != CellState::Unknown) return false;
    cells_[index] = occupied ? CellState::Occupied : CellState::Free;
    ++(occupied ? occupied_count_ : free_count_);
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
    return true;
  }

  [[nodiscard]] int free_count() const { return free_count_; }
  [[nodiscard]] int occupied_count() const { return occupied_count_; }
  [[nodiscard]] int known_count() const { return free_count_ + occupied_count_; }
  [[nodiscard]] const Grid<CellState>& cells() const { return cells_; }

  friend bool operator==(const KnownMap&, const KnownMap&) = default;

 private:
  Grid<CellState> cells_;
  double resolution_m_ = 1.0;
  int free_count_ = 0;
  int occupied_count_ = 0;
};

/// A KnownMap that knows every cell of the ground truth (for planning on known maps).
struct WorldMap;
[[nodiscard]] KnownMap fully_known(const WorldMap& map);

}  // namespace world
}  // namespace fsweep
