// Ground-truth queries: free counts, reachability (corner cutting), nearest free cell, the cell
// nearest a region's centroid, and the fully known map.
#include <gtest/gtest.h>

#include "core/random.hpp"
#include "world/known_map.hpp"
#include "world/map_loaders.hpp"
#include "world/world_map.hpp"

namespace fsweep {
namespace {

int count(const Grid<std::uint8_t>& g) {
  int n = 0;
  for (const auto v : g.data()) n += v;
  return n;
}

TEST(WorldMap, ContentHashCoversCellsSizeResolutionAndStartButNotTheSource) {
  const WorldMap base = parse_ascii_map("#..\n.#.\n");
  WorldMap same = parse_ascii_map("#..\n.#.\n");
  same.source = "another file";
  EXPECT_EQ(content_hash(base), content_hash(same));
  // The layout: FNV-1a 64 of "W H RES X Y" then one byte per cell, 1 = occupied.
  ASSERT_EQ(base.start, (Cell{1, 0}));
  std::string text = "3 2 1 1 0";
  text += std::string("\x01\x00\x00\x00\x01\x00", 6);
  EXPECT_EQ(content_hash(base), fnv1a(text));
  WorldMap cell = base;
  cell.occupied.at(Cell{2, 1}) = 1;
  WorldMap resolution = base;
  resolution.resolution_m = 0.05;
  WorldMap start = base;
  start.start = Cell{2, 1};
  WorldMap shape = parse_ascii_map("#.\n..\n#.\n");  // the same bytes, 2x3
  for (const WorldMap* m : {&cell, &resolution, &start, &shape})
    EXPECT_NE(content_hash(*m), content_hash(base));
}

TEST(KnownMap, FreeBitsByRowAndColumnFollowTheCells) {
  // 70 x 130: rows of two words, columns of three; reveals and forgets in a seeded order.
  KnownMap known(70, 130, 1.0);
  EXPECT_EQ(known.row_words(), 2);
  EXPECT_EQ(known.column_words(), 3);
  std::uint64_t state = 7;
  for (int round = 0; round < 4; ++round) {
    for (int i = 0; i < known.size(); ++i) {
      state = state * 6364136223846793005ULL + 1442695040888963407ULL;
      const auto draw = static_cast<unsigned>(state >> 60U);
      if (draw < 6) (void)known.reveal(i, draw < 2);
      if (draw == 15) (void)known.forget(i);
    }
    for (int y = 0; y < known.height(); ++y) {
      for (int x = 0; x < known.width(); ++x) {
        const bool free = known.is_free(Cell{x, y});
        const auto bit = [](const std::uint64_t* words, int i) {
          return ((words[i / 64] >> (i % 64)) & 1U) != 0;
        };
        ASSERT_EQ(bit(known.free_row(y), x), free) << x << "," << y << " round " << round;
        ASSERT_EQ(bit(known.free_column(x), y), free) << x << "," << y << " round " << round;
      }
      // The bits past the edge stay clear, and so do the guard words on either side.
      EXPECT_EQ(known.free_row(y)[1] >> 6U, 0U);
      EXPECT_EQ(known.free_row(y)[-1], 0U);
      EXPECT_EQ(known.free_row(y)[known.row_words()], 0U);
    }
    for (int x = 0; x < known.width(); ++x) {
      EXPECT_EQ(known.free_column(x)[-1], 0U);
      EXPECT_EQ(known.free_column(x)[known.column_words()], 0U);
    }
    // The guard lines beyond the edges, words -1 to row_words() (column_words()), stay clear.
    for (const int y : {-1, known.height()}) {
      for (int w = -1; w <= known.row_words(); ++w) EXPECT_EQ(known.free_row(y)[w], 0U) << y << " " << w;
    }
    for (const int x : {-1, known.width()}) {
      for (int w = -1; w <= known.column_words(); ++w)
        EXPECT_EQ(known.free_column(x)[w], 0U) << x << " " << w;
    }
  }
  const KnownMap copy = known;
  EXPECT_TRUE(copy == known);
}

TEST(KnownMap, ForgetMakesACellUnknownAgainAndKeepsTheCounts) {
  KnownMap known(3, 2, 1.0);
  EXPECT_TRUE(known.reveal(0, false));
  EXPECT_TRUE(known.reveal(4, true));
  EXPECT_EQ(known.free_count(), 1);
  EXPECT_EQ(known.occupied_count(), 1);
  EXPECT_TRUE(known.forget(4));
  EXPECT_TRUE(known.is_unknown(4));
  EXPECT_EQ(known.occupied_count(), 0);
  EXPECT_FALSE(known.forget(4));  // already unknown
  EXPECT_TRUE(known.forget(0));
  EXPECT_EQ(known.known_count(), 0);
  EXPECT_EQ(known, KnownMap(3, 2, 1.0));  // as new
  EXPECT_TRUE(known.reveal(0, true));     // and revealed again, differently
  EXPECT_EQ(known.occupied_count(), 1);
}

TEST(WorldMap, FreeCountCountsFreeCells) { EXPECT_EQ(parse_ascii_map("#..\n.#.\n").free_count(), 4); }

TEST(ReachableFree, DiagonalGapIsClosedWithoutCornerCutting) {
  // The two free cells touch only diagonally between two walls.
  const WorldMap map = parse_ascii_map("S#\n#.\n");
  EXPECT_EQ(count(reachable_free(map, Cell{0, 0})), 1);
  EXPECT_EQ(count(reachable_free(map, Cell{0, 0}, true)), 2);
}

TEST(ReachableFree, DiagonalNeedsBothOrthogonalNeighbours) {
  // One orthogonal neighbour free is not enough for the diagonal step, but the free cells are
  // still joined through that neighbour.
  const WorldMap map = parse_ascii_map("S.#\n#..\n###\n");
  const Grid<std::uint8_t> reached = reachable_free(map, Cell{0, 0});
  EXPECT_EQ(count(reached), 4);
  EXPECT_EQ(reached.at(Cell{2, 1}), 1);
}

TEST(ReachableFree, WallsSeparateRoomsAndAnOccupiedStartReachesNothing) {
  const WorldMap map = parse_ascii_map("..#..\n..#..\n");
  EXPECT_EQ(count(reachable_free(map, Cell{0, 0})), 4);
  EXPECT_EQ(count(reachable_free(map, Cell{2, 0})), 0);
  EXPECT_EQ(count(reachable_free(map, Cell{-1, 0})), 0);
}

TEST(NearestFreeCell, EuclideanWithTiesByIndex) {
  const WorldMap map = parse_ascii_map(".#.\n###\n.#.\n");
  // All four corners are sqrt(2) from the centre: the lowest index wins.
  EXPECT_EQ(nearest_free_cell(map, Cell{1, 1}), (Cell{0, 0}));
  EXPECT_EQ(nearest_free_cell(map, Cell{2, 1}), (Cell{2, 0}));
  EXPECT_EQ(nearest_free_cell(parse_ascii_map("#.\n"), Cell{0, 0}), (Cell{1, 0}));
  WorldMap full = parse_ascii_map("#.\n");
  full.occupied.fill(1);
  EXPECT_EQ(nearest_free_cell(full, Cell{0, 0}), (Cell{-1, -1}));
}

TEST(RegionCentreCell, NearestTheCentroidWithTiesByRowThenColumn) {
  // A ring around an occupied cell: the centroid (1, 1) is a wall; (1, 0), (0, 1), (2, 1) and
  // (1, 2) are 1 from it, and (1, 0) comes first in row-major order.
  EXPECT_EQ(region_centre_cell(largest_free_region(parse_ascii_map("...\n.#.\n...\n"))), (Cell{1, 0}));
  // Two cells side by side: the centroid (0.5, 0) is halfway, the left one (lower index) wins.
  EXPECT_EQ(region_centre_cell(largest_free_region(parse_ascii_map("..\n"))), (Cell{0, 0}));
  // An L: 4 cells in rows 0-1 (x 0..1), 8 in rows 2-3 (x 0..3); sums x 14, y 22 over 12 cells,
  // centroid (1.17, 1.83): (1, 2) is 0.24 from it, (1, 1) 0.85.
  EXPECT_EQ(region_centre_cell(largest_free_region(parse_ascii_map("..##\n..##\n....\n....\n"))),
            (Cell{1, 2}));
  // Only the largest region counts: the right room (8 cells, centroid (4.5, 0.5)), not the left.
  EXPECT_EQ(region_centre_cell(largest_free_region(parse_ascii_map("..#....\n..#....\n"))), (Cell{4, 0}));
  EXPECT_EQ(region_centre_cell(Grid<std::uint8_t>(3, 2, 0)), (Cell{-1, -1}));
}

TEST(FullyKnown, KnowsEveryCellOfTheGroundTruth) {
  const WorldMap map = parse_ascii_map("S.#\n##.\n", 0.5);
  const KnownMap known = fully_known(map);
  EXPECT_EQ(known.width(), 3);
  EXPECT_DOUBLE_EQ(known.resolution_m(), 0.5);
  EXPECT_EQ(known.free_count(), 3);
  EXPECT_EQ(known.occupied_count(), 3);
  EXPECT_EQ(known.state(Cell{2, 0}), CellState::Occupied);
  EXPECT_EQ(known.state(Cell{1, 0}), CellState::Free);
}

}  // namespace
}  // namespace fsweep
