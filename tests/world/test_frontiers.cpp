#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <deque>
#include <stdexcept>
#include <string>
#include <vector>

#include "world/ascii_world.hpp"
#include "world/frontiers.hpp"
#include "world/sensor.hpp"

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

TEST(Frontiers, FrontierTestMatchesTheDefinitionOnRandomMaps) {
  // The definition in frontiers.hpp, spelled out, against is_frontier_cell() at every cell of
  // seeded random maps (edges, corners and interior cells; sealed diagonals are common with
  // many occupied cells).
  Rng rng = make_rng(7, "frontier-definition");
  int frontier_cells = 0;
  int sealed_only = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const int width = 1 + static_cast<int>(uniform_below(rng, 12));
    const int height = 1 + static_cast<int>(uniform_below(rng, 12));
    const KnownMap known = test::random_partly_known(width, height, 0.4, 0.35, rng);
    for (int i = 0; i < known.size(); ++i) {
      const Cell c = known.cell(i);
      bool want = false;
      bool sealed = false;
      if (known.is_free(c)) {
        for (const Cell d : kDirections) {
          const Cell n{c.x + d.x, c.y + d.y};
          if (!known.in_bounds(n) || known.state(n) != CellState::Unknown) continue;
          const bool diagonal = d.x != 0 && d.y != 0;
          if (diagonal && known.state(Cell{n.x, c.y}) == CellState::Occupied &&
              known.state(Cell{c.x, n.y}) == CellState::Occupied) {
            sealed = true;
          } else {
            want = true;
          }
        }
      }
      ASSERT_EQ(is_frontier_cell(known, i), want) << "trial " << trial << " cell " << c.x << "," << c.y;
      frontier_cells += want ? 1 : 0;
      sealed_only += sealed && !want ? 1 : 0;
    }
  }
  EXPECT_GT(frontier_cells, 1000);
  EXPECT_GT(sealed_only, 20);
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

TEST(Frontiers, UpdateHandlesCellsLeavingAndReturning) {
  // update() trusts only the 3x3 neighbourhoods of `revealed`; feeding it two different maps
  // makes cell (1,1) = 4 leave the set and come back while the list still holds it.
  const KnownMap with = ascii_known({
      "...",
      "...",
      "..?",
  });
  const KnownMap without = ascii_known({
      "...",
      "...",
      "..#",
  });
  FrontierMap frontiers(with);
  EXPECT_EQ(frontiers.cells(), (std::vector<int>{4, 5, 7}));
  const int changed[] = {8};
  frontiers.update(without, changed);
  EXPECT_EQ(frontiers.count(), 0);
  frontiers.update(with, changed);  // no query in between
  EXPECT_EQ(frontiers.count(), 3);
  EXPECT_EQ(frontiers.cells(), (std::vector<int>{4, 5, 7}));
  frontiers.update(without, changed);
  EXPECT_TRUE(frontiers.cells().empty());
  EXPECT_TRUE(frontiers.clusters(without, 0.0, false).empty());
  frontiers.update(with, changed);
  const auto clusters = frontiers.clusters(with, 0.0, false);
  ASSERT_EQ(clusters.size(), 1U);
  EXPECT_EQ(clusters[0].cells, (std::vector<int>{4, 5, 7}));
}

TEST(Frontiers, ClustersAreConnectedComponents) {
  const KnownMap known = ascii_known({
      "#......#..",
      "????##????",
  });
  const auto clusters = FrontierMap(known).clusters(known, 0.0, false);
  ASSERT_EQ(clusters.size(), 2U);
  EXPECT_EQ(clusters[0].cells, (std::vector<int>{1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(clusters[1].cells, (std::vector<int>{8, 9}));
  EXPECT_EQ(clusters[0].representative, 3);  // centroid x = 3.5: tie 3 / 4, lowest index
  EXPECT_EQ(clusters[1].representative, 8);
  EXPECT_DOUBLE_EQ(clusters[0].centroid_x, 3.5);
  EXPECT_DOUBLE_EQ(clusters[0].centroid_y, 0.0);
  EXPECT_DOUBLE_EQ(clusters[0].length_m, 6.0);
}

TEST(Frontiers, DiagonalNeighboursConnectLikeTheRobotMoves) {
  // Frontier cells 0, 7, 14 on a diagonal; the cells beside each diagonal step are a wall and
  // an unknown cell, so the robot cannot make those steps without corner cutting.
  const KnownMap known = ascii_known({
      ".?####",
      "#.?###",
      "##.?##",
      "######",
  });
  const FrontierMap frontiers(known);
  const auto apart = frontiers.clusters(known, 0.0, false);
  ASSERT_EQ(apart.size(), 3U);
  EXPECT_EQ(apart[0].cells, std::vector<int>{0});
  EXPECT_EQ(apart[1].cells, std::vector<int>{7});
  EXPECT_EQ(apart[2].cells, std::vector<int>{14});
  const auto together = frontiers.clusters(known, 0.0, true);
  ASSERT_EQ(together.size(), 1U);
  EXPECT_EQ(together[0].cells, (std::vector<int>{0, 7, 14}));
  EXPECT_EQ(together[0].representative, 7);
}

TEST(Frontiers, DiagonalThroughKnownFreeCellsConnects) {
  // Frontier cells {1, 4, 5} around the unknown (0,0) and {10, 11, 14} around (3,3). (1,1) = 5
  // and (2,2) = 10 are diagonal neighbours; (2,1) and (1,2) beside them are free and not
  // frontiers (no unknown neighbour). One cluster; with (2,1) a wall, two unless corners may
  // be cut.
  const KnownMap open = ascii_known({
      "?...",
      "....",
      "....",
      "...?",
  });
  const auto one = FrontierMap(open).clusters(open, 0.0, false);
  ASSERT_EQ(one.size(), 1U);
  EXPECT_EQ(one[0].cells, (std::vector<int>{1, 4, 5, 10, 11, 14}));
  const KnownMap wall = ascii_known({
      "?...",
      "..#.",
      "....",
      "...?",
  });
  const FrontierMap frontiers(wall);
  const auto two = frontiers.clusters(wall, 0.0, false);
  ASSERT_EQ(two.size(), 2U);
  EXPECT_EQ(two[0].cells, (std::vector<int>{1, 4, 5}));
  EXPECT_EQ(two[1].cells, (std::vector<int>{10, 11, 14}));
  EXPECT_EQ(frontiers.clusters(wall, 0.0, true).size(), 1U);
}

const std::vector<std::string> kRow = {
    "..........",
    "??????????",
};

TEST(Frontiers, ClustersSplitByLength) {
  const KnownMap known = ascii_known(kRow);
  const FrontierMap frontiers(known);
  const auto pieces = frontiers.clusters(known, 3.0, false);
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
  EXPECT_EQ(frontiers.clusters(known, 3.9, false).size(), 4U);
  // Shorter than a cell: one cell per piece.
  EXPECT_EQ(frontiers.clusters(known, 0.2, false).size(), 10U);
  // No splitting at <= 0; 10 cells, centroid 4.5, tie 4 / 5.
  const auto whole = frontiers.clusters(known, -1.0, false);
  ASSERT_EQ(whole.size(), 1U);
  EXPECT_EQ(whole[0].representative, 4);
}

TEST(Frontiers, SplitLengthIsInMetres) {
  // 0.9 m at 0.3 m per cell is 3 cells (0.9 / 0.3 is just below 3 in floating point).
  const KnownMap known = ascii_known(kRow, 0.3);
  const auto pieces = FrontierMap(known).clusters(known, 0.9, false);
  ASSERT_EQ(pieces.size(), 4U);
  EXPECT_EQ(pieces[0].cells.size(), 3U);
  EXPECT_NEAR(pieces[0].length_m, 0.9, 1e-12);
}

TEST(Frontiers, ClusterPiecesAreConnectedBreadthFirstWalks) {
  // Frontier cells (0,0) (1,0) (2,0) (0,1) (0,2) = 0 1 2 3 6; pieces of two cells. The walk
  // from 0 visits neighbours in heading order (E, SE, S, ...) and closes {0, 1}. The next walk
  // starts from the lowest cell left, 2, whose only frontier neighbour (1,0) is placed: {2}.
  // Then {3, 6}. (Cutting the first walk's order 0 1 3 2 6 into twos would give {2, 3}, two
  // cells that do not touch.)
  const KnownMap known = ascii_known({
      "...",
      ".??",
      ".??",
  });
  const auto pieces = FrontierMap(known).clusters(known, 2.0, false);
  ASSERT_EQ(pieces.size(), 3U);
  EXPECT_EQ(pieces[0].cells, (std::vector<int>{0, 1}));
  EXPECT_EQ(pieces[1].cells, std::vector<int>{2});
  EXPECT_EQ(pieces[2].cells, (std::vector<int>{3, 6}));
}

TEST(Frontiers, LongPiecesFollowTheWalk) {
  // A ring of 14 frontier cells around an unknown block, linked orthogonally only (each
  // diagonal between ring cells has an unknown cell beside it). Pieces of 4 cells:
  // - from 0: E 1, S 5; from 1: E 2 -> {0, 1, 2, 5};
  // - from 3 (lowest left): E 4 (SE 9 is not linked); from 4: S 9; from 9: S 14;
  // - from 10: S 15 (SE 16 is not linked); from 15: E 16; from 16: E 17;
  // - from 18: E 19.
  const KnownMap known = ascii_known({
      ".....",
      ".???.",
      ".???.",
      ".....",
  });
  const FrontierMap frontiers(known);
  ASSERT_EQ(frontiers.count(), 14);
  const auto pieces = frontiers.clusters(known, 4.0, false);
  ASSERT_EQ(pieces.size(), 4U);
  EXPECT_EQ(pieces[0].cells, (std::vector<int>{0, 1, 2, 5}));
  EXPECT_EQ(pieces[1].cells, (std::vector<int>{3, 4, 9, 14}));
  EXPECT_EQ(pieces[2].cells, (std::vector<int>{10, 15, 16, 17}));
  EXPECT_EQ(pieces[3].cells, (std::vector<int>{18, 19}));
}

TEST(Frontiers, RepresentativeIsNearestToCentroidTiesLowestIndex) {
  // Same L of five cells: centroid (0.6, 0.6); (1,0) and (0,1) are both at squared distance
  // 0.52, nearer than (0,0) at 0.72; the lower index (1,0) = 1 wins.
  const KnownMap known = ascii_known({
      "...",
      ".??",
      ".??",
  });
  const auto clusters = FrontierMap(known).clusters(known, 0.0, false);
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
  const auto clusters = FrontierMap(known).clusters(known, 0.0, false, excluded);
  ASSERT_EQ(clusters.size(), 2U);
  EXPECT_EQ(clusters[0].cells, (std::vector<int>{0, 1, 2, 3}));
  EXPECT_EQ(clusters[1].cells, (std::vector<int>{6, 7, 8, 9}));
  std::fill(excluded.begin(), excluded.end(), 1);
  EXPECT_TRUE(FrontierMap(known).clusters(known, 0.0, false, excluded).empty());
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
  const auto pieces = FrontierMap(known).clusters(known, 2.0, false);
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

/// Sensors the explorations below run with: full circle, half circle, noisy, and a narrow
/// short one.
std::vector<SensorParams> exploration_sensors() {
  std::vector<SensorParams> sensors(4);
  sensors[0].range_m = 4.0;
  sensors[1].range_m = 6.0;
  sensors[1].fov_deg = 180.0;
  sensors[2].range_m = 5.0;
  sensors[2].miss_probability = 0.3;
  sensors[3].range_m = 1.5;  // >= sqrt(2) cells: a frontier's diagonal unknown is in range
  sensors[3].fov_deg = 90.0;
  sensors[3].miss_probability = 0.1;
  return sensors;
}

/// Clusters by the rule in frontiers.hpp, written plainly over the whole map.
std::vector<FrontierCluster> reference_clusters(const KnownMap& known, double max_length_m, bool cut,
                                                const std::vector<std::uint8_t>& excluded) {
  const int n = known.size();
  const auto candidate = [&](Cell c) {
    return known.in_bounds(c) && is_frontier_cell(known, known.index(c)) &&
           (excluded.empty() || excluded[static_cast<std::size_t>(known.index(c))] == 0);
  };
  const auto linked = [&](Cell a, Cell b) {
    if (!candidate(b)) return false;
    return a.x == b.x || a.y == b.y || cut ||
           (known.is_free(Cell{b.x, a.y}) && known.is_free(Cell{a.x, b.y}));
  };
  int total = 0;
  for (int i = 0; i < n; ++i) total += is_frontier_cell(known, i) ? 1 : 0;
  std::size_t cap = static_cast<std::size_t>(std::max(total, 1));
  if (max_length_m > 0.0) {
    cap = std::max<std::size_t>(
        static_cast<std::size_t>(std::floor(max_length_m / known.resolution_m() * (1.0 + 1e-9))), 1);
  }
  // Breadth-first walk from `start` over cells with `allowed`, at most `limit` cells.
  const auto walk = [&](int start, const std::vector<std::uint8_t>& allowed, std::size_t limit) {
    std::vector<int> out{start};
    std::vector<std::uint8_t> in(static_cast<std::size_t>(n), 0);
    in[static_cast<std::size_t>(start)] = 1;
    for (std::size_t head = 0; head < out.size() && out.size() < limit; ++head) {
      const Cell c = known.cell(out[head]);
      for (const Cell d : kDirections) {
        const Cell m{c.x + d.x, c.y + d.y};
        if (out.size() == limit || !linked(c, m)) continue;
        const auto mi = static_cast<std::size_t>(known.index(m));
        if (allowed[mi] == 0 || in[mi] != 0) continue;
        in[mi] = 1;
        out.push_back(known.index(m));
      }
    }
    return out;
  };
  std::vector<FrontierCluster> result;
  std::vector<std::uint8_t> unplaced(static_cast<std::size_t>(n), 0);
  for (int i = 0; i < n; ++i) unplaced[static_cast<std::size_t>(i)] = candidate(known.cell(i)) ? 1 : 0;
  std::vector<std::uint8_t> reached(static_cast<std::size_t>(n), 0);
  for (int i = 0; i < n; ++i) {
    if (unplaced[static_cast<std::size_t>(i)] == 0 || reached[static_cast<std::size_t>(i)] != 0) continue;
    std::vector<int> component = walk(i, unplaced, static_cast<std::size_t>(n));
    for (const int c : component) reached[static_cast<std::size_t>(c)] = 1;
    std::sort(component.begin(), component.end());
    std::vector<std::uint8_t> left(static_cast<std::size_t>(n), 0);
    for (const int c : component) left[static_cast<std::size_t>(c)] = 1;
    for (const int start : component) {
      if (left[static_cast<std::size_t>(start)] == 0) continue;
      FrontierCluster cl;
      cl.cells = walk(start, left, cap);
      for (const int c : cl.cells) left[static_cast<std::size_t>(c)] = 0;
      std::sort(cl.cells.begin(), cl.cells.end());
      const auto m = static_cast<long long>(cl.cells.size());
      long long sx = 0;
      long long sy = 0;
      for (const int c : cl.cells) {
        sx += known.cell(c).x;
        sy += known.cell(c).y;
      }
      cl.centroid_x = static_cast<double>(sx) / static_cast<double>(m);
      cl.centroid_y = static_cast<double>(sy) / static_cast<double>(m);
      cl.length_m = static_cast<double>(m) * known.resolution_m();
      long long best = -1;
      for (const int c : cl.cells) {
        const long long ex = m * known.cell(c).x - sx;
        const long long ey = m * known.cell(c).y - sy;
        if (best < 0 || ex * ex + ey * ey < best) {
          best = ex * ex + ey * ey;
          cl.representative = c;
        }
      }
      result.push_back(std::move(cl));
    }
  }
  std::sort(result.begin(), result.end(), [](const FrontierCluster& a, const FrontierCluster& b) {
    return a.cells.front() < b.cells.front();
  });
  return result;
}

/// Checks clusters() against the reference for several settings, and that every piece is
/// connected by robot moves among its own cells.
void check_clusters(const KnownMap& known, const FrontierMap& frontiers, std::uint64_t seed) {
  std::vector<std::uint8_t> some(static_cast<std::size_t>(known.size()), 0);
  Rng rng = make_rng(seed, "excluded");
  for (auto& e : some) e = uniform01(rng) < 0.1 ? 1 : 0;
  for (const bool cut : {false, true}) {
    for (const double length : {0.0, 3.0, 7.5}) {
      for (const std::vector<std::uint8_t>* excluded :
           {static_cast<std::vector<std::uint8_t>*>(nullptr), &some}) {
        const std::vector<std::uint8_t> none;
        const std::vector<std::uint8_t>& ex = excluded == nullptr ? none : *excluded;
        const auto got = frontiers.clusters(known, length, cut, ex);
        const auto want = reference_clusters(known, length, cut, ex);
        ASSERT_EQ(got.size(), want.size()) << "cut " << cut << " length " << length;
        for (std::size_t k = 0; k < got.size(); ++k) {
          ASSERT_EQ(got[k].cells, want[k].cells) << "cluster " << k;
          ASSERT_EQ(got[k].representative, want[k].representative);
          ASSERT_DOUBLE_EQ(got[k].centroid_x, want[k].centroid_x);
          ASSERT_DOUBLE_EQ(got[k].centroid_y, want[k].centroid_y);
          ASSERT_DOUBLE_EQ(got[k].length_m, want[k].length_m);
          // Connected by moves between its own cells (a diagonal move needs both cells beside
          // it known free unless corners may be cut).
          const std::vector<int>& cells = got[k].cells;
          std::vector<int> seen{cells.front()};
          for (std::size_t head = 0; head < seen.size(); ++head) {
            const Cell a = known.cell(seen[head]);
            for (const int other : cells) {
              const Cell b = known.cell(other);
              if (std::find(seen.begin(), seen.end(), other) != seen.end()) continue;
              if (std::abs(a.x - b.x) > 1 || std::abs(a.y - b.y) > 1) continue;
              if (!cut && !passable(a, b, [&](Cell c) { return !known.is_free(c); })) continue;
              seen.push_back(other);
            }
          }
          ASSERT_EQ(seen.size(), cells.size()) << "piece " << k << " is not connected";
        }
      }
    }
  }
}

TEST(Frontiers, ClustersMatchReferenceDuringExplorations) {
  SensorParams params;
  params.range_m = 4.0;
  params.miss_probability = 0.2;
  std::uint64_t seed = 100;
  for (const WorldMap& map : exploration_maps()) {
    SCOPED_TRACE("map " + std::to_string(map.width()) + "x" + std::to_string(map.height()));
    Sensor sensor(params, map.resolution_m);
    KnownMap known(map.width(), map.height(), map.resolution_m);
    FrontierMap frontiers(known);
    Rng rng = make_rng(++seed, "sensor");
    Cell at = map.start;
    for (int step = 0; step < 400; ++step) {
      frontiers.update(known, sensor.scan(map, known, at, 0.0, rng));
      if (step % 3 == 0) check_clusters(known, frontiers, seed + static_cast<std::uint64_t>(step));
      if (HasFatalFailure() || frontiers.count() == 0) break;
      const int target = nearest_frontier(known, frontiers, at);
      at = known.cell(target < 0 ? frontiers.cells().front() : target);
    }
  }
}

TEST(Frontiers, TrackedClustersMatchFromScratch) {
  // FrontierClusters rebuilds only the clusters holding a changed cell: after any number of
  // scans and exclusion changes (both ways) it must equal the reference, for every setting.
  std::uint64_t seed = 300;
  int checks = 0;
  // Besides the exploration maps, open space: long frontiers cut into short pieces, which shift
  // one after another as the frontier grows.
  std::vector<WorldMap> maps = exploration_maps();
  maps.push_back(random_world(40, 40, 0.02, 3));
  for (const SensorParams& params : exploration_sensors()) {
    for (const WorldMap& map : maps) {
      SCOPED_TRACE("map " + std::to_string(map.width()) + "x" + std::to_string(map.height()) + " range " +
                   std::to_string(params.range_m));
      Sensor sensor(params, map.resolution_m);
      KnownMap known(map.width(), map.height(), map.resolution_m);
      FrontierMap frontiers(known);
      struct Tracked {
        bool cut;
        double length;
        FrontierClusters clusters;
      };
      std::vector<Tracked> tracked;
      for (const bool cut : {false, true}) {
        for (const double length : {0.0, 2.0, 3.0, 7.5})
          tracked.push_back({cut, length, FrontierClusters(known, length, cut)});
      }
      std::vector<std::uint8_t> excluded(static_cast<std::size_t>(known.size()), 0);
      Rng rng = make_rng(++seed, "sensor");
      Rng choices = make_rng(seed, "test-choices");
      Cell at = map.start;
      for (int step = 0; step < 400; ++step) {
        const auto revealed = sensor.scan(map, known, at, 0.5 * step, rng);
        frontiers.update(known, revealed);
        for (auto& t : tracked) t.clusters.revealed(revealed);
        // Exclude some frontier cells, and let some excluded cells back in.
        for (int k = 0; k < 3 && frontiers.count() > 0; ++k) {
          const auto cells = frontiers.cells();
          const int c =
              cells[static_cast<std::size_t>(uniform01(choices) * static_cast<double>(cells.size()))];
          if (uniform01(choices) < 0.3) {
            excluded[static_cast<std::size_t>(c)] ^= 1;
            for (auto& t : tracked) t.clusters.exclusion_changed(c);
          }
        }
        if (uniform01(choices) < 0.5 || frontiers.count() == 0) {  // some calls see several scans
          ++checks;
          for (auto& t : tracked) {
            const auto& got = t.clusters.clusters(known, frontiers, excluded);
            const auto want = reference_clusters(known, t.length, t.cut, excluded);
            ASSERT_EQ(got.size(), want.size())
                << "step " << step << " cut " << t.cut << " length " << t.length;
            for (std::size_t k = 0; k < got.size(); ++k) {
              ASSERT_EQ(got[k].cells, want[k].cells) << "step " << step << " cluster " << k;
              ASSERT_EQ(got[k].representative, want[k].representative);
              ASSERT_EQ(got[k].centroid_x, want[k].centroid_x);
              ASSERT_EQ(got[k].centroid_y, want[k].centroid_y);
              ASSERT_EQ(got[k].length_m, want[k].length_m);
            }
          }
        }
        if (frontiers.count() == 0) break;
        const int target = nearest_frontier(known, frontiers, at);
        at = known.cell(target < 0 ? frontiers.cells().front() : target);
      }
    }
  }
  EXPECT_GT(checks, 300);
}

TEST(Frontiers, TrackedClustersSeeADiagonalOpenedByARevealedCell) {
  // Frontier cells c (1, 1), s (1, 2) and n (2, 2) stay frontier cells while r (2, 1), beside
  // the diagonal c-n, is revealed free without becoming a frontier cell itself (its neighbours
  // are all known): no cell changes whether it may join a cluster, only r's known state, which
  // opens the diagonal c-n (without corner cutting). The pieces near r must be walked again
  // all the same.
  const KnownMap before = ascii_known({
      "?###",
      "?.?#",
      "?..#",
      "????",
  });
  const int r = before.index(Cell{2, 1});
  int changed = 0;
  for (const bool cut : {false, true}) {
    for (const double length : {0.0, 1.0, 2.0, 3.0, 4.0, 5.0}) {
      KnownMap known = before;
      FrontierMap frontiers(known);
      FrontierClusters tracked(known, length, cut);
      const std::vector<FrontierCluster> first = tracked.clusters(known, frontiers, {});
      known.reveal(r, false);
      const std::vector<int> revealed{r};
      frontiers.update(known, revealed);
      tracked.revealed(revealed);
      ASSERT_FALSE(frontiers.is_frontier(r));
      ASSERT_EQ(frontiers.cells(), (std::vector<int>{known.index(Cell{1, 1}), known.index(Cell{1, 2}),
                                                     known.index(Cell{2, 2})}));
      const auto& got = tracked.clusters(known, frontiers, {});
      const auto want = reference_clusters(known, length, cut, {});
      ASSERT_EQ(got.size(), want.size()) << "cut " << cut << " length " << length;
      for (std::size_t k = 0; k < got.size(); ++k) {
        ASSERT_EQ(got[k].cells, want[k].cells) << "cut " << cut << " length " << length << " cluster " << k;
        ASSERT_EQ(got[k].representative, want[k].representative);
      }
      bool same = first.size() == want.size();
      for (std::size_t k = 0; same && k < want.size(); ++k) same = first[k].cells == want[k].cells;
      changed += same ? 0 : 1;
    }
  }
  EXPECT_GT(changed, 0);  // some pieces do change
}

TEST(Frontiers, TrackedClustersRefuseAMapOfAnotherSize) {
  const KnownMap known = ascii_known({"..?", "..."});
  const KnownMap other = ascii_known({"..?", "...", "..."});
  FrontierClusters clusters(known, 0.0, false);
  EXPECT_THROW((void)clusters.clusters(other, FrontierMap(other), {}), std::invalid_argument);
  const std::vector<std::uint8_t> wrong(3, 0);
  EXPECT_THROW((void)clusters.clusters(known, FrontierMap(known), wrong), std::invalid_argument);
  EXPECT_EQ(clusters.clusters(known, FrontierMap(known), {}).size(), 1U);
}

TEST(Frontiers, ManyUpdatesWithoutQueriesStayConsistent) {
  // cells() and clusters() sort and prune the frontier list; between them update() alone must
  // keep it bounded and correct (here: a whole exploration without a query until the end).
  const WorldMap map = exploration_maps().front();
  Sensor sensor(SensorParams{3.0, 360.0, 0.0}, map.resolution_m);
  KnownMap known(map.width(), map.height(), map.resolution_m);
  FrontierMap frontiers(known);
  Rng rng = make_rng(5, "sensor");
  for (int y = 1; y < map.height(); y += 3) {
    for (int x = 1; x < map.width(); x += 3) {
      if (map.is_free(Cell{x, y})) frontiers.update(known, sensor.scan(map, known, Cell{x, y}, 0.0, rng));
    }
  }
  EXPECT_EQ(frontiers.cells(), from_scratch(known));
  EXPECT_EQ(frontiers.count(), static_cast<int>(from_scratch(known).size()));
  const FrontierMap copy = frontiers;
  EXPECT_EQ(copy.cells(), frontiers.cells());
}

TEST(Frontiers, IncrementalMatchesFromScratchWithABeamLidar) {
  // A beam lidar reveals cells in beam order and leaves cells between beams unknown.
  SensorParams params;
  params.model = SensorModel::Beams;
  params.beams = 60;
  params.fov_deg = 270.0;
  params.range_m = 6.0;
  params.miss_probability = 0.2;
  std::uint64_t seed = 100;
  for (const WorldMap& map : exploration_maps()) explore_and_check(map, params, ++seed);
}

TEST(Frontiers, IncrementalMatchesFromScratch) {
  const std::vector<SensorParams> sensors = exploration_sensors();
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
