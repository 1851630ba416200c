#include <gtest/gtest.h>

#include <cstdint>
#include <limits>

#include "core/random.hpp"
#include "search/cell_indexer.hpp"

namespace fsweep {
namespace test_cell_indexer {

/// The cell by hardware division, the definition CellIndexer must match.
Cell divided(int index, int width) { return Cell{index % width, index / width}; }

TEST(CellIndexer, MatchesDivisionOnEveryIndexOfSmallGrids) {
  for (int width = 1; width <= 70; ++width) {
    const CellIndexer cells(width);
    for (int index = 0; index < width * 80; ++index)
      ASSERT_EQ(cells.cell(index), divided(index, width)) << width;
  }
}

TEST(CellIndexer, MatchesDivisionUpToTheLargestIndex) {
  constexpr int kMaxIndex = std::numeric_limits<int>::max();
  Rng rng = make_rng(7, "cell_indexer");
  for (int k = 0; k < 2000; ++k) {
    // Widths of every size class, powers of two and their neighbours included.
    const int bits = 1 + static_cast<int>(uniform_below(rng, 30));
    const int base = 1 << bits;
    const int width = base + static_cast<int>(uniform_below(rng, 3)) - 1;
    const CellIndexer cells(width);
    for (const int index : {0, width - 1, width, kMaxIndex, kMaxIndex - 1, kMaxIndex - kMaxIndex % width,
                            kMaxIndex - kMaxIndex % width - 1,
                            static_cast<int>(uniform_below(rng, static_cast<std::uint64_t>(kMaxIndex)))}) {
      ASSERT_EQ(cells.cell(index), divided(index, width)) << "width " << width << " index " << index;
    }
  }
}

}  // namespace test_cell_indexer
}  // namespace fsweep
