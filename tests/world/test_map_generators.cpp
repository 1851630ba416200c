// Seeded map generators: determinism, free start, connectivity and each kind's shape.
#include <gtest/gtest.h>

#include <functional>
#include <initializer_list>
#include <string>

#include "core/config_error.hpp"
#include "world/map_generators.hpp"

namespace fsweep {
namespace {

GeneratorParams params_of(const std::string& kind, int width, int height, std::uint64_t seed) {
  GeneratorParams p;
  p.kind = kind;
  p.width = width;
  p.height = height;
  p.seed = seed;
  return p;
}

int reachable_count(const WorldMap& map) {
  const Grid<std::uint8_t> reached = reachable_free(map, map.start);
  int n = 0;
  for (const auto v : reached.data()) n += v;
  return n;
}

void expect_config_error(const std::function<void()>& fn, std::initializer_list<std::string> parts) {
  try {
    fn();
    ADD_FAILURE() << "expected a ConfigError";
  } catch (const ConfigError& e) {
    const std::string message = e.what();
    for (const auto& part : parts) EXPECT_NE(message.find(part), std::string::npos) << message;
  }
}

// --- Properties every kind shares ----------------------------------------------------------

class EveryKind : public testing::TestWithParam<std::string> {};

TEST_P(EveryKind, SameSeedGivesTheSameMap) {
  const GeneratorParams p = params_of(GetParam(), 90, 70, 11);
  const WorldMap a = generate_map(p);
  const WorldMap b = generate_map(p);
  EXPECT_EQ(a.occupied, b.occupied);
  EXPECT_EQ(a.start, b.start);
}

TEST_P(EveryKind, DifferentSeedsGiveDifferentMaps) {
  if (GetParam() == "free") GTEST_SKIP() << "free space has no randomness";
  EXPECT_NE(generate_map(params_of(GetParam(), 90, 70, 1)).occupied,
            generate_map(params_of(GetParam(), 90, 70, 2)).occupied);
}

TEST_P(EveryKind, StartIsFreeAndSizeAndResolutionAreKept) {
  for (const std::uint64_t seed : {0U, 1U, 2U, 3U, 4U}) {
    GeneratorParams p =
        params_of(GetParam(), 80 + static_cast<int>(seed) * 7, 60 + static_cast<int>(seed) * 5, seed);
    p.resolution_m = 0.25;
    const WorldMap map = generate_map(p);
    EXPECT_EQ(map.width(), p.width);
    EXPECT_EQ(map.height(), p.height);
    EXPECT_DOUBLE_EQ(map.resolution_m, 0.25);
    EXPECT_TRUE(map.is_free(map.start)) << "seed " << seed;
  }
}

TEST_P(EveryKind, AllFreeCellsAreReachableFromTheStart) {
  // Guaranteed for every kind but random: no free cell is cut off (8-connected moves without
  // corner cutting, so doors and lanes are passable for the MovingAI motion model).
  if (GetParam() == "random") GTEST_SKIP() << "random maps guarantee no connectivity";
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    const WorldMap map = generate_map(
        params_of(GetParam(), 70 + static_cast<int>(seed) * 3, 60 + static_cast<int>(seed) * 4, seed));
    EXPECT_EQ(reachable_count(map), map.free_count()) << "seed " << seed;
  }
}

TEST_P(EveryKind, ExplicitStartIsUsedAndAnOccupiedStartIsAnError) {
  const WorldMap map = generate_map(params_of(GetParam(), 90, 70, 5));
  // Any free cell other than the default may be requested.
  Cell other{-1, -1};
  for (int i = map.occupied.size() - 1; i >= 0 && other.x < 0; --i) {
    if (map.is_free(i)) other = map.occupied.cell(i);
  }
  GeneratorParams p = params_of(GetParam(), 90, 70, 5);
  p.start_x = other.x;
  p.start_y = other.y;
  EXPECT_EQ(generate_map(p).start, other);
  if (GetParam() == "manhattan") return;  // (0, 0) may be a street
  p.start_x = 0;
  p.start_y = 0;
  expect_config_error([&] { (void)generate_map(p); }, {"start cell (0, 0) is occupied"});
  p.start_x = 90;
  expect_config_error([&] { (void)generate_map(p); }, {"start cell (90, 0) is outside the 90x70 map"});
}

INSTANTIATE_TEST_SUITE_P(MapGenerators, EveryKind,
                         testing::Values("free", "random", "rooms", "office", "manhattan", "oldtown"),
                         [](const testing::TestParamInfo<std::string>& info) { return info.param; });

// --- Kind by kind --------------------------------------------------------------------------

TEST(FreeGenerator, BorderIsAWallFrameAndStartIsTheCentre) {
  GeneratorParams p = params_of("free", 20, 10, 0);
  p.wall = 2;
  const WorldMap framed = generate_map(p);
  EXPECT_EQ(framed.free_count(), 16 * 6);
  EXPECT_FALSE(framed.is_free(Cell{1, 5}));
  EXPECT_TRUE(framed.is_free(Cell{2, 5}));
  EXPECT_EQ(framed.start, (Cell{10, 5}));
  p.border = false;
  EXPECT_EQ(generate_map(p).free_count(), 200);
}

TEST(RandomGenerator, ObstacleFractionIsNearP) {
  for (const double prob : {0.1, 0.3}) {
    GeneratorParams p = params_of("random", 200, 200, 3);
    p.border = false;
    p.obstacle_probability = prob;
    const WorldMap map = generate_map(p);
    const double fraction = 1.0 - static_cast<double>(map.free_count()) / map.occupied.size();
    // 40000 Bernoulli draws: the standard deviation is below 0.0025, so 0.01 is four of them.
    EXPECT_NEAR(fraction, prob, 0.01);
  }
}

TEST(RandomGenerator, StartLiesInTheLargestFreeComponent) {
  GeneratorParams p = params_of("random", 100, 100, 8);
  p.obstacle_probability = 0.2;
  const WorldMap map = generate_map(p);
  // At p = 0.2 almost all free space percolates; the start must be in that giant component.
  EXPECT_GT(reachable_count(map), map.free_count() * 9 / 10);
}

TEST(RoomsGenerator, InteriorWallsWithDoorsJoinEveryRoom) {
  GeneratorParams p = params_of("rooms", 80, 60, 4);
  p.min_room = 10;
  p.door = 2;
  const WorldMap map = generate_map(p);
  // Interior walls exist (more than the frame is occupied) and yet every free cell is
  // reachable: every room is entered through a door.
  const int frame = 2 * 80 + 2 * 58;
  EXPECT_GT(map.occupied.size() - map.free_count(), frame + 100);
  EXPECT_EQ(reachable_count(map), map.free_count());
}

TEST(RoomsGenerator, RoomsAreNotSplitBelowMinRoom) {
  // 20 < 2 * min_room + wall: one room only, the interior of the frame.
  GeneratorParams p = params_of("rooms", 20, 20, 4);
  p.min_room = 10;
  EXPECT_EQ(generate_map(p).free_count(), 18 * 18);
  // Every maximal free run along a row or column that is bounded by walls at both ends is
  // either a door (at most `door` long) or at least min_room long.
  p = params_of("rooms", 100, 80, 9);
  p.min_room = 8;
  p.door = 2;
  const WorldMap map = generate_map(p);
  for (int y = 1; y < 79; ++y) {
    int run = 0;
    for (int x = 1; x < 100; ++x) {
      if (map.is_free(Cell{x, y})) {
        ++run;
        continue;
      }
      if (run > 0) {
        EXPECT_TRUE(run <= p.door || run >= p.min_room) << "row " << y << " ends at " << x;
      }
      run = 0;
    }
  }
}

TEST(OfficeGenerator, HasFullWidthCorridorsAndConnectedRooms) {
  GeneratorParams p = params_of("office", 90, 80, 6);
  p.min_room = 8;
  p.corridor = 3;
  const WorldMap map = generate_map(p);
  int corridor_rows = 0;
  for (int y = 1; y < 79; ++y) {
    bool open = true;
    for (int x = 1; x < 89 && open; ++x) open = map.is_free(Cell{x, y});
    if (open) ++corridor_rows;
  }
  // (80 - 1) / (2 * 8 + 3 * 1 + 3) = 3 corridors of 3 rows each.
  EXPECT_EQ(corridor_rows, 9);
  EXPECT_EQ(reachable_count(map), map.free_count());
}

TEST(ManhattanGenerator, StreetsCrossAtTheCentreAndBlocksAreSquare) {
  GeneratorParams p = params_of("manhattan", 100, 80, 2);
  p.block = 12;
  p.street = 4;
  const WorldMap map = generate_map(p);
  for (int x = 0; x < 100; ++x) EXPECT_TRUE(map.is_free(Cell{x, 40})) << x;
  for (int y = 0; y < 80; ++y) EXPECT_TRUE(map.is_free(Cell{50, y})) << y;
  // The street at the centre spans columns [48, 52); the next block starts at 52 and the next
  // street at 52 + 12 = 64, every 16 columns.
  for (int y = 0; y < 80; ++y) {
    EXPECT_TRUE(map.is_free(Cell{64, y}));
    EXPECT_TRUE(map.is_free(Cell{67, y}));
  }
  EXPECT_LT(map.free_count(), map.occupied.size());
}

TEST(ManhattanGenerator, ParkAndAlleySharesDecideTheBlocks) {
  // 240 x 240 cells, blocks 16, streets 4: the block of columns and rows [122, 138) lies wholly
  // inside (the centre street spans [118, 122)).
  GeneratorParams p = params_of("manhattan", 240, 240, 3);
  p.block = 16;
  p.street = 4;
  const WorldMap defaults = generate_map(p);
  p.park_share = 0.1;
  p.alley_share = 0.35;
  EXPECT_EQ(generate_map(p).occupied, defaults.occupied);  // the documented defaults
  // No parks, no alleys: every block a solid building; the free cells are the streets alone.
  p.park_share = 0.0;
  p.alley_share = 0.0;
  const WorldMap plain = generate_map(p);
  for (int y = 122; y < 138; ++y) {
    for (int x = 122; x < 138; ++x) EXPECT_FALSE(plain.is_free(Cell{x, y})) << x << ";" << y;
  }
  int street_cells = 0;
  for (int i = 0; i < plain.occupied.size(); ++i) {
    const Cell c = plain.occupied.cell(i);
    const auto on_street = [](int v) { return ((v - 118) % 20 + 20) % 20 < 4; };
    street_cells += on_street(c.x) || on_street(c.y) ? 1 : 0;
  }
  EXPECT_EQ(plain.free_count(), street_cells);
  // Every block a park: all free. Every block cut by an alley: each block has free cells inside.
  p.park_share = 1.0;
  EXPECT_EQ(generate_map(p).free_count(), 240 * 240);
  p.park_share = 0.0;
  p.alley_share = 1.0;
  const WorldMap alleys = generate_map(p);
  int free_inside = 0;
  for (int y = 122; y < 138; ++y) {
    for (int x = 122; x < 138; ++x) free_inside += alleys.is_free(Cell{x, y}) ? 1 : 0;
  }
  EXPECT_EQ(free_inside, 2 * 16);  // an alley street / 2 = 2 cells wide across the block
  EXPECT_EQ(reachable_count(alleys), alleys.free_count());
  // Shares outside [0, 1] or above 1 together are refused.
  p.alley_share = 0.95;
  p.park_share = 0.1;
  expect_config_error([&] { (void)generate_map(p); }, {"parks + alleys = 1.05", "at most 1"});
  p.park_share = -0.1;
  expect_config_error([&] { (void)generate_map(p); }, {"parks = -0.1 is out of range; allowed: 0..1"});
}

TEST(OldtownGenerator, HasOpenSquaresAndNarrowLanes) {
  GeneratorParams p = params_of("oldtown", 120, 100, 7);
  p.lane = 2;
  p.squares = 3;
  const WorldMap map = generate_map(p);
  // Some free 6 x 6 (3 * lane) block exists: a square.
  bool found_square = false;
  for (int y = 0; y + 6 <= 100 && !found_square; ++y) {
    for (int x = 0; x + 6 <= 120 && !found_square; ++x) {
      bool open = true;
      for (int k = 0; k < 36 && open; ++k) open = map.is_free(Cell{x + k % 6, y + k / 6});
      found_square = open;
    }
  }
  EXPECT_TRUE(found_square);
  // Lanes leave most of the town built up.
  EXPECT_LT(map.free_count(), map.occupied.size() / 2);
  EXPECT_EQ(reachable_count(map), map.free_count());
  // The frame is occupied.
  for (int x = 0; x < 120; ++x) EXPECT_FALSE(map.is_free(Cell{x, 0}));
}

// --- Bad parameters ------------------------------------------------------------------------

TEST(MapGenerators, OutOfRangeParametersNameTheKeyAndTheAllowedRange) {
  GeneratorParams p = params_of("rooms", 60, 60, 0);
  p.door = 20;
  expect_config_error([&] { (void)generate_map(p); }, {"generator 'rooms'", "door = 20", "allowed: 1..12"});
  p = params_of("office", 20, 60, 0);
  expect_config_error([&] { (void)generate_map(p); }, {"w = 20", "allowed: 32..65536"});
  p = params_of("random", 60, 60, 0);
  p.obstacle_probability = 1.5;
  expect_config_error([&] { (void)generate_map(p); }, {"p = 1.5", "allowed: 0..1"});
  p = params_of("free", 0, 60, 0);
  expect_config_error([&] { (void)generate_map(p); }, {"w = 0"});
  p = params_of("forest", 60, 60, 0);
  expect_config_error([&] { (void)generate_map(p); },
                      {"unknown generator kind 'forest'", "free, random, rooms, office, manhattan, oldtown"});
  p = params_of("random", 10, 10, 0);
  p.obstacle_probability = 1.0;
  expect_config_error([&] { (void)generate_map(p); }, {"no free cell"});
}

}  // namespace
}  // namespace fsweep
