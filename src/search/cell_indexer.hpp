#pragma once
/// @file cell_indexer.hpp
/// The cell of a row-major grid index (`index = y * width + x`) without a hardware division,
/// for the hot loops that turn state ids back into cells (the A* heuristic runs once per opened
/// state; a 32-bit division costs tens of cycles, a multiply and shift a few).

#include <bit>
#include <cstdint>

#include "world/grid.hpp"

namespace fsweep {
inline namespace search {

/// floor(index / width) as (index * magic) >> shift: Granlund and Montgomery, "Division by
/// invariant integers using multiplication" (PLDI 1994), section 4, with N = 32 and
/// l = ceil(log2 width); exact for every index in [0, 2^31) and width in [1, 2^31).
class CellIndexer {
 public:
  explicit CellIndexer(int width) : width_(width) {
    const auto w = static_cast<std::uint64_t>(width);
    const int l = static_cast<int>(std::bit_width(w - 1));  // ceil(log2 width); 0 for width 1
    shift_ = 32 + l;
    magic_ = ((std::uint64_t{1} << shift_) + w - 1) / w;  // ceil(2^shift / width) <= 2^33
  }
  /// The cell of `index` (>= 0).
  [[nodiscard]] Cell cell(int index) const {
    const auto y = static_cast<int>((static_cast<std::uint64_t>(index) * magic_) >> shift_);
    return Cell{index - y * width_, y};
  }
  [[nodiscard]] int width() const { return width_; }

 private:
  int width_;
  int shift_ = 32;
  std::uint64_t magic_ = 0;
};

}  // namespace search
}  // namespace fsweep
