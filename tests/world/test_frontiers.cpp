#include <gtest/gtest.h>

#include <cmath>
#include <deque>
#include <string>
#include <vector>

#include "engine/world/frontiers.hpp"
#include "engine/world/sensor.hpp"
#include "world/ascii_world.hpp"

namespace fsweep {
namespace {

using test::ascii_known;
using test::ascii_world;

std::vector<int> from_scratch(const KnownMap& known) {
  std::vector<int> out;
  for (int i = 0; i < known.size(); ++i) {
    if (is_frontier_cell(known, i)) out.push_back(i);
  }
  return out;
}

TEST(Frontiers, FrontierIsKnownFreeCellWithUnknownNeighbour) {
  const KnownMap known = ascii_known({
      "....",
      "..??",
      "#.#?",
  });
  // (1,0): unknown diagonal (2,1) with free sides; (2,0), (3,0), (1,1): orthogonal unknowns;
  // (1,2): diagonal (2,1) beside (2,2) '#' and (1,1) '.'. Occupied and unknown cells never are.
  EXPECT_EQ(from_scratch(known), (std::vector<int>{1, 2, 3, 5, 9}));
  EXPECT_EQ(FrontierMap(known).cells(), (std::vector<int>{1, 2, 3, 5, 9}));
  EXPECT_EQ(FrontierMap(known).count(), 5);
}

TEST(Frontiers, SealedDiagonalIsNotFrontier) {
  const KnownMap sealed = ascii_known({
      ".#?",
      "..#",
      "...",
  });
  EXPECT_FALSE(is_frontier_cell(sealed, 4));  // (1,1): its only unknown neighbour is sealed off
  EXPECT_EQ(FrontierMap(sealed).count(), 0);
  const KnownMap open = ascii_known({
      "..?",
      "..#",
      "...",
  });
  EXPECT_TRUE(is_frontier_cell(open, 4));
  EXPECT_TRUE(is_frontier_cell(open, 1));
}

TEST(Frontiers, MapEdgeIsNotUnknown) { EXPECT_EQ(FrontierMap(ascii_known({"...", "..."})).count(), 0); }

TEST(Frontiers, UpdateTracksRevealedCells) {
  KnownMap known = ascii_known({
      "???????",
      "???????",
      "???????",
  });
  FrontierMap frontiers(known);
  EXPECT_EQ(frontiers.count(), 0);
  known.reveal(known.index(Cell{3, 1}), false);
  const int first[] = {known.index(Cell{3, 1})};
  frontiers.update(known, first);
  EXPECT_EQ(frontiers.cells(), std::vector<int>{10});
  // Reveal the whole 3x3 block around (3,1): only its free border cells stay frontiers.
  std::vector<int> block;
  for (int y = 0; y < 3; ++y) {
    for (int x = 2; x < 5; ++x) {
      if (known.reveal(known.index(Cell{x, y}), x == 4 && y == 0)) block.push_back(known.index(Cell{x, y}));
    }
  }
  frontiers.update(known, block);
  EXPECT_EQ(frontiers.cells(), from_scratch(known));
  EXPECT_FALSE(frontiers.is_frontier(10));
  EXPECT_FALSE(frontiers.is_frontier(4));  // occupied
}

TEST(Frontiers, ClustersAreEightConnectedComponents) {
  const KnownMap known = ascii_known({
      "#......#..",
      "????##????",
  });
  const auto clusters = FrontierMap(known).clusters(known, 0.0);
  ASSERT_EQ(clusters.size(), 2U);
  EXPECT_EQ(clusters[0].cells, (std::vector<int>{1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(clusters[1].cells, (std::vector<int>{8, 9}));
  EXPECT_EQ(clusters[0].representative, 3);  // centroid x = 3.5: tie 3 / 4, lowest index
  EXPECT_EQ(clusters[1].representative, 8);
  EXPECT_DOUBLE_EQ(clusters[0].centroid_x, 3.5);
  EXPECT_DOUBLE_EQ(clusters[0].centroid_y, 0.0);
  EXPECT_DOUBLE_EQ(clusters[0].length_m, 6.0);
}

TEST(Frontiers, DiagonalNeighboursShareACluster) {
  const KnownMap known = ascii_known({
      ".?####",
      "#.?###",
      "##.?##",
      "######",
  });
  const auto clusters = FrontierMap(known).clusters(known, 0.0);
  ASSERT_EQ(clusters.size(), 1U);
  EXPECT_EQ(clusters[0].cells, (std::vector<int>{0, 7, 14}));
  EXPECT_EQ(clusters[0].representative, 7);
}

const std::vector<std::string> kRow = {
    "..........",
    "??????????",
};

TEST(Frontiers, ClustersSplitByLength) {
  const KnownMap known = ascii_known(kRow);
  const FrontierMap frontiers(known);
  const auto pieces = frontiers.clusters(known, 3.0);
  ASSERT_EQ(pieces.size(), 4U);
  EXPECT_EQ(pieces[0].cells, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(pieces[1].cells, (std::vector<int>{3, 4, 5}));
  EXPECT_EQ(pieces[2].cells, (std::vector<int>{6, 7, 8}));
  EXPECT_EQ(pieces[3].cells, (std::vector<int>{9}));
  EXPECT_EQ(pieces[0].representative, 1);
  EXPECT_EQ(pieces[1].representative, 4);
  EXPECT_EQ(pieces[3].representative, 9);
  EXPECT_DOUBLE_EQ(pieces[1].length_m, 3.0);
  EXPECT_DOUBLE_EQ(pieces[3].length_m, 1.0);
  // A length that is not a whole number of cells rounds down: 3.9 m -> 3 cells.
  EXPECT_EQ(frontiers.clusters(known, 3.9).size(), 4U);
  // Shorter than a cell: one cell per piece.
  EXPECT_EQ(frontiers.clusters(known, 0.2).size(), 10U);
  // No splitting at <= 0; 10 cells, centroid 4.5, tie 4 / 5.
  const auto whole = frontiers.clusters(known, -1.0);
  ASSERT_EQ(whole.size(), 1U);
  EXPECT_EQ(whole[0].representative, 4);
}

TEST(Frontiers, SplitLengthIsInMetres) {
  // 0.9 m at 0.3 m per cell is 3 cells (0.9 / 0.3 is just below 3 in floating point).
  const KnownMap known = ascii_known(kRow, 0.3);
  const auto pieces = FrontierMap(known).clusters(known, 0.9);
  ASSERT_EQ(pieces.size(), 4U);
  EXPECT_EQ(pieces[0].cells.size(), 3U);
  EXPECT_NEAR(pieces[0].length_m, 0.9, 1e-12);
}

TEST(Frontiers, ClusterPiecesFollowBreadthFirstOrder) {
  // Frontier cells (0,0) (1,0) (2,0) (0,1) (0,2) = 0 1 2 3 6. The walk from 0 visits
  // neighbours in heading order (E, SE, S, ...): 0, 1, 3, 2, 6; pieces of two cells.
  const KnownMap known = ascii_known({
      "...",
      ".??",
      ".??",
  });
  const auto pieces = FrontierMap(known).clusters(known, 2.0);
  ASSERT_EQ(pieces.size(), 3U);
  EXPECT_EQ(pieces[0].cells, (std::vector<int>{0, 1}));
  EXPECT_EQ(pieces[1].cells, (std::vector<int>{2, 3}));
  EXPECT_EQ(pieces[2].cells, (std::vector<int>{6}));
}

TEST(Frontiers, RepresentativeIsNearestToCentroidTiesLowestIndex) {
  // Same L of five cells: centroid (0.6, 0.6); (1,0) and (0,1) are both at squared distance
  // 0.52, nearer than (0,0) at 0.72; the lower index (1,0) = 1 wins.
  const KnownMap known = ascii_known({
      "...",
      ".??",
      ".??",
  });
  const auto clusters = FrontierMap(known).clusters(known, 0.0);
  ASSERT_EQ(clusters.size(), 1U);
  EXPECT_EQ(clusters[0].representative, 1);
  EXPECT_DOUBLE_EQ(clusters[0].centroid_x, 0.6);
  EXPECT_DOUBLE_EQ(clusters[0].centroid_y, 0.6);
}

TEST(Frontiers, ExcludedCellsAreLeftOut) {
  const KnownMap known = ascii_known(kRow);
  std::vector<std::uint8_t> excluded(static_cast<std::size_t>(known.size()), 0);
  excluded[4] = 1;
  excluded[5] = 1;
  const auto clusters = FrontierMap(known).clusters(known, 0.0, excluded);
  ASSERT_EQ(clusters.size(), 2U);
  EXPECT_EQ(clusters[0].cells, (std::vector<int>{0, 1, 2, 3}));
  EXPECT_EQ(clusters[1].cells, (std::vector<int>{6, 7, 8, 9}));
  std::fill(excluded.begin(), excluded.end(), 1);
  EXPECT_TRUE(FrontierMap(known).clusters(known, 0.0, excluded).empty());
}

TEST(Frontiers, PiecesAreOrderedByLowestMember) {
  // Component A = column 0 (cells 0 4 8 12, pieces {0,4} and {8,12}); component B = (2,0) = 2.
  // A's second piece comes after B although A is walked first.
  const KnownMap known = ascii_known({
      ".?.?",
      ".?#?",
      ".?##",
      ".?##",
  });
  const auto pieces = FrontierMap(known).clusters(known, 2.0);
  ASSERT_EQ(pieces.size(), 3U);
  EXPECT_EQ(pieces[0].cells, (std::vector<int>{0, 4}));
  EXPECT_EQ(pieces[1].cells, std::vector<int>{2});
  EXPECT_EQ(pieces[2].cells, (std::vector<int>{8, 12}));
}

// ---------------------------------------------------------------------------------------------
// Whole explorations: after every scan the incremental set equals a from-scratch one.

WorldMap random_world(int width, int height, double p, std::uint64_t seed) {
  WorldMap map = ascii_world(std::vector<std::string>(static_cast<std::size_t>(height),
                                                      std::string(static_cast<std::size_t>(width), '.')));
  Rng rng = make_rng(seed, "test-map");
  for (int i = 0; i < map.occupied.size(); ++i) map.occupied[i] = uniform01(rng) < p ? 1 : 0;
  map.start = Cell{width / 2, height / 2};
  map.occupied.at(map.start) = 0;
  return map;
}

/// Whether a move from `a` to its neighbour `b` passes (b free, a diagonal not sealed by two
/// cells for which `blocked` holds).
template <typename Blocked>
bool passable(Cell a, Cell b, Blocked&& blocked) {
  if (blocked(b)) return false;
  return a.x == b.x || a.y == b.y || !(blocked(Cell{b.x, a.y}) && blocked(Cell{a.x, b.y}));
}

/// Nearest frontier cell by breadth-first search over known free cells (-1 if none reachable).
int nearest_frontier(const KnownMap& known, const FrontierMap& frontiers, Cell from) {
  std::vector<std::uint8_t> seen(static_cast<std::size_t>(known.size()), 0);
  std::deque<Cell> queue{from};
  seen[static_cast<std::size_t>(known.index(from))] = 1;
  const auto blocked = [&](Cell c) { return !known.is_free(c); };
  while (!queue.empty()) {
    const Cell c = queue.front();
    queue.pop_front();
    if (frontiers.is_frontier(known.index(c))) return known.index(c);
    for (const Cell d : kDirections) {
      const Cell n{c.x + d.x, c.y + d.y};
      if (!known.in_bounds(n) || seen[static_cast<std::size_t>(known.index(n))] != 0) continue;
      if (!passable(c, n, blocked)) continue;
      seen[static_cast<std::size_t>(known.index(n))] = 1;
      queue.push_back(n);
    }
  }
  return -1;
}

/// Explores `map` to the end, checking FrontierMap::update against a rebuild after every scan.
void explore_and_check(const WorldMap& map, const SensorParams& params, std::uint64_t seed) {
  Sensor sensor(params, map.resolution_m);
  KnownMap known(map.width(), map.height(), map.resolution_m);
  FrontierMap frontiers(known);
  Rng rng = make_rng(seed, "sensor");
  Cell at = map.start;
  double heading = 0.0;
  int steps = 0;
  for (; steps < 20000; ++steps) {
    const auto revealed = sensor.scan(map, known, at, heading, rng);
    frontiers.update(known, revealed);
    const FrontierMap scratch(known);
    ASSERT_EQ(frontiers.count(), scratch.count()) << "step " << steps;
    ASSERT_EQ(frontiers.cells(), scratch.cells()) << "step " << steps;
    ASSERT_EQ(frontiers.cells(), from_scratch(known)) << "step " << steps;
    if (frontiers.count() == 0) break;
    int target = nearest_frontier(known, frontiers, at);
    if (target < 0) target = frontiers.cells().front();  // teleport
    const Cell next = known.cell(target);
    if (next == at) {
      heading += M_PI / 2.0;  // the unknown neighbour is out of view (or was missed): turn
    } else {
      heading = std::atan2(static_cast<double>(next.y - at.y), static_cast<double>(next.x - at.x));
      at = next;
    }
  }
  ASSERT_LT(steps, 20000) << "exploration did not finish";
  // Finished: every free cell reachable from the start through unsealed moves is known, and
  // everything known matches the ground truth.
  const auto blocked = [&](Cell c) { return !map.is_free(c); };
  std::vector<std::uint8_t> seen(static_cast<std::size_t>(known.size()), 0);
  std::deque<Cell> queue{map.start};
  seen[static_cast<std::size_t>(known.index(map.start))] = 1;
  while (!queue.empty()) {
    const Cell c = queue.front();
    queue.pop_front();
    ASSERT_TRUE(known.is_free(c)) << c.x << "," << c.y;
    for (const Cell d : kDirections) {
      const Cell n{c.x + d.x, c.y + d.y};
      if (!known.in_bounds(n) || seen[static_cast<std::size_t>(known.index(n))] != 0) continue;
      if (!passable(c, n, blocked)) continue;
      seen[static_cast<std::size_t>(known.index(n))] = 1;
      queue.push_back(n);
    }
  }
  for (int i = 0; i < known.size(); ++i) {
    if (!known.is_unknown(i)) {
      ASSERT_EQ(known.is_free(i), map.is_free(i)) << "cell " << i;
    }
  }
}

std::vector<WorldMap> exploration_maps() {
  std::vector<WorldMap> maps;
  maps.push_back(random_world(40, 30, 0.25, 1));
  maps.push_back(random_world(35, 35, 0.4, 2));
  maps.push_back(ascii_world({
      "##########################",
      "#S.......#.......#.......#",
      "#........#.......#.......#",
      "#........#...............#",
      "#........#.......#.......#",
      "####.#####.......####.####",
      "#..............#.#.......#",
      "#.........#.#..#.#.......#",
      "#..........#...#.........#",
      "#.........#.#..#.#.......#",
      "##########################",
  }));
  maps.push_back(ascii_world({
      "S.....#.......",
      "......#.......",
      "......#.......",
      ".......#......",
      "........#.....",
      "#.#.#.#.#.#.#.",
      ".#.#.#.#.#.#.#",
      "..............",
  }));
  return maps;
}

TEST(Frontiers, IncrementalMatchesFromScratch) {
  std::vector<SensorParams> sensors(4);
  sensors[0].range_m = 4.0;
  sensors[1].range_m = 6.0;
  sensors[1].fov_deg = 180.0;
  sensors[2].range_m = 5.0;
  sensors[2].miss_probability = 0.3;
  sensors[3].range_m = 1.5;  // >= sqrt(2) cells: a frontier's diagonal unknown is in range
  sensors[3].fov_deg = 90.0;
  sensors[3].miss_probability = 0.1;
  std::uint64_t seed = 0;
  for (const WorldMap& map : exploration_maps()) {
    for (const SensorParams& params : sensors) {
      SCOPED_TRACE("map " + std::to_string(map.width()) + "x" + std::to_string(map.height()) + " range " +
                   std::to_string(params.range_m) + " fov " + std::to_string(params.fov_deg) + " miss " +
                   std::to_string(params.miss_probability));
      explore_and_check(map, params, ++seed);
    }
  }
}

}  // namespace
}  // namespace fsweep
