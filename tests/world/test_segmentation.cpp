/// Room segmentation (src/world/segmentation.hpp): hand-made maps and generated buildings.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "world/ascii_world.hpp"
#include "world/map_generators.hpp"
#include "world/segmentation.hpp"

namespace fsweep {
namespace {

using test::ascii_known;

/// The segment of cell (x, y).
int segment_at(const KnownMap& known, const Segmentation& s, int x, int y) {
  return s.label[static_cast<std::size_t>(known.index(Cell{x, y}))];
}

/// Ground-truth rooms of a generated `rooms` or `office` map, from the generator's rules: a
/// door is a gap of at most `door` cells in a wall, so its cells are the free cells whose
/// horizontal or vertical free run (between occupied cells) is at most `door` long (rooms and
/// corridors are wider: min_room and corridor exceed door in these tests). Rooms are the
/// 4-connected components of the other free cells. Returns a room id per cell (-1: door,
/// occupied).
std::vector<int> true_rooms(const WorldMap& map, int door, int& count) {
  const int w = map.width();
  const int h = map.height();
  std::vector<int> run_x(static_cast<std::size_t>(w * h), 0);
  std::vector<int> run_y(static_cast<std::size_t>(w * h), 0);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w;) {
      if (!map.is_free(Cell{x, y})) {
        ++x;
        continue;
      }
      int e = x;
      while (e < w && map.is_free(Cell{e, y})) ++e;
      for (int k = x; k < e; ++k) run_x[static_cast<std::size_t>(y * w + k)] = e - x;
      x = e;
    }
  }
  for (int x = 0; x < w; ++x) {
    for (int y = 0; y < h;) {
      if (!map.is_free(Cell{x, y})) {
        ++y;
        continue;
      }
      int e = y;
      while (e < h && map.is_free(Cell{x, e})) ++e;
      for (int k = y; k < e; ++k) run_y[static_cast<std::size_t>(k * w + x)] = e - y;
      y = e;
    }
  }
  std::vector<int> room(static_cast<std::size_t>(w * h), -1);
  const auto inside = [&](Cell c) {
    const auto i = static_cast<std::size_t>(c.y * w + c.x);
    return map.is_free(c) && run_x[i] > door && run_y[i] > door;
  };
  count = 0;
  for (int i = 0; i < w * h; ++i) {
    const Cell c0{i % w, i / w};
    if (!inside(c0) || room[static_cast<std::size_t>(i)] >= 0) continue;
    std::vector<Cell> queue{c0};
    room[static_cast<std::size_t>(i)] = count;
    for (std::size_t k = 0; k < queue.size(); ++k) {
      for (int d = 0; d < 8; d += 2) {
        const Cell n{queue[k].x + kDirections[static_cast<std::size_t>(d)].x,
                     queue[k].y + kDirections[static_cast<std::size_t>(d)].y};
        if (!inside(n) || room[static_cast<std::size_t>(n.y * w + n.x)] >= 0) continue;
        room[static_cast<std::size_t>(n.y * w + n.x)] = count;
        queue.push_back(n);
      }
    }
    ++count;
  }
  return room;
}

struct Agreement {
  int rooms = 0;
  int segments = 0;
  /// Smallest share of a room's cells that lie in the room's majority segment.
  double worst_room_share = 1.0;
  /// Smallest share of a segment's cells (doors excluded) that lie in its majority room.
  double worst_segment_purity = 1.0;
};

Agreement compare(const WorldMap& map, int door) {
  Agreement a;
  const KnownMap known = fully_known(map);
  const Segmentation s = segment_free_space(known);
  const std::vector<int> room = true_rooms(map, door, a.rooms);
  a.segments = s.count;
  std::map<std::pair<int, int>, int> joint;  // (room, segment) -> cells
  std::map<int, int> room_size;
  std::map<int, int> segment_size;
  for (int i = 0; i < known.size(); ++i) {
    const int r = room[static_cast<std::size_t>(i)];
    if (r < 0) continue;
    const int g = s.label[static_cast<std::size_t>(i)];
    ++joint[{r, g}];
    ++room_size[r];
    ++segment_size[g];
  }
  std::map<int, int> room_best;
  std::map<int, int> segment_best;
  for (const auto& [key, cells] : joint) {
    room_best[key.first] = std::max(room_best[key.first], cells);
    segment_best[key.second] = std::max(segment_best[key.second], cells);
  }
  for (const auto& [r, size] : room_size) {
    a.worst_room_share = std::min(a.worst_room_share, static_cast<double>(room_best[r]) / size);
  }
  for (const auto& [g, size] : segment_size) {
    a.worst_segment_purity = std::min(a.worst_segment_purity, static_cast<double>(segment_best[g]) / size);
  }
  return a;
}

TEST(Segmentation, TwoRoomsAndADoor) {
  const KnownMap known = ascii_known({
      "##################",
      "#.......#........#",
      "#.......#........#",
      "#.......#........#",
      "#................#",
      "#................#",
      "#.......#........#",
      "#.......#........#",
      "#.......#........#",
      "##################",
  });
  const Segmentation s = segment_free_space(known);
  EXPECT_EQ(s.count, 2);
  const int left = segment_at(known, s, 1, 1);
  const int right = segment_at(known, s, 16, 8);
  EXPECT_NE(left, right);
  for (int y = 1; y <= 8; ++y) {
    for (int x = 1; x <= 7; ++x) EXPECT_EQ(segment_at(known, s, x, y), left) << x << "," << y;
    for (int x = 9; x <= 16; ++x) EXPECT_EQ(segment_at(known, s, x, y), right) << x << "," << y;
  }
  // The door cells (x = 8, y = 4, 5) go to one of the two rooms; walls have no segment.
  EXPECT_TRUE(segment_at(known, s, 8, 4) == left || segment_at(known, s, 8, 4) == right);
  EXPECT_EQ(segment_at(known, s, 0, 0), -1);
}

TEST(Segmentation, CorridorWithRooms) {
  // Three rooms above a corridor two cells wide, each with a one-cell door.
  const KnownMap known = ascii_known({
      "#####################",
      "#.....#......#......#",
      "#.....#......#......#",
      "#.....#......#......#",
      "#.....#......#......#",
      "#.....#......#......#",
      "###.######.######.###",
      "#...................#",
      "#...................#",
      "#####################",
  });
  const Segmentation s = segment_free_space(known);
  EXPECT_EQ(s.count, 4);
  const int a = segment_at(known, s, 3, 3);
  const int b = segment_at(known, s, 10, 3);
  const int c = segment_at(known, s, 17, 3);
  const int corridor = segment_at(known, s, 10, 8);
  EXPECT_EQ(std::vector<int>({a, b, c, corridor}).size(), 4U);
  for (const int x : {1, 5}) EXPECT_EQ(segment_at(known, s, x, 1), a);
  for (const int x : {7, 12}) EXPECT_EQ(segment_at(known, s, x, 5), b);
  for (const int x : {14, 19}) EXPECT_EQ(segment_at(known, s, x, 1), c);
  for (int x = 1; x <= 19; ++x) EXPECT_EQ(segment_at(known, s, x, 7), corridor) << x;
  std::vector<int> ids{a, b, c, corridor};
  std::sort(ids.begin(), ids.end());
  EXPECT_EQ(std::unique(ids.begin(), ids.end()), ids.end());
}

TEST(Segmentation, OpenSpaceIsOneSegmentAndUnknownIsNone) {
  const KnownMap known = ascii_known({
      "??????????",
      "?........?",
      "?........?",
      "?........?",
      "??????????",
  });
  const Segmentation s = segment_free_space(known);
  EXPECT_EQ(s.count, 1);
  EXPECT_EQ(segment_at(known, s, 0, 0), -1);
  EXPECT_EQ(segment_at(known, s, 4, 2), 0);
}

void expect_brute_force_clearance(const KnownMap& known);

TEST(Segmentation, ClearanceIsTheExactEuclideanDistance) {
  expect_brute_force_clearance(ascii_known({
      "#......",
      ".......",
      "......#",
  }));
  GeneratorParams p;
  p.kind = "random";
  p.width = 37;
  p.height = 23;
  p.obstacle_probability = 0.05;
  p.border = false;
  expect_brute_force_clearance(fully_known(generate_map(p)));
}

void expect_brute_force_clearance(const KnownMap& known) {
  const auto d2 = squared_clearance(known);
  // Brute force: nearest occupied cell, cells outside the grid counting as occupied.
  for (int i = 0; i < known.size(); ++i) {
    const Cell c = known.cell(i);
    long long best = std::min<long long>({c.x + 1, c.y + 1, known.width() - c.x, known.height() - c.y});
    best *= best;
    for (int j = 0; j < known.size(); ++j) {
      if (known.state(j) != CellState::Occupied) continue;
      const Cell o = known.cell(j);
      best = std::min<long long>(best, 1LL * (o.x - c.x) * (o.x - c.x) + 1LL * (o.y - c.y) * (o.y - c.y));
    }
    EXPECT_EQ(d2[static_cast<std::size_t>(i)], best) << c.x << "," << c.y;
  }
}

/// Generated buildings: each true room has >= 90% of its cells in one segment, >= 90% of each
/// segment's room cells lie in one room, and the segment count is the room count exactly.
class GeneratedSegmentation : public ::testing::TestWithParam<std::tuple<std::string, int>> {};

TEST_P(GeneratedSegmentation, FindsTheRooms) {
  GeneratorParams p;
  p.kind = std::get<0>(GetParam());
  p.seed = static_cast<std::uint64_t>(std::get<1>(GetParam()));
  p.width = 120;
  p.height = 90;
  const WorldMap map = generate_map(p);
  const Agreement a = compare(map, p.door);
  EXPECT_GE(a.rooms, 4);
  EXPECT_EQ(a.segments, a.rooms);
  EXPECT_GE(a.worst_room_share, 0.9);
  EXPECT_GE(a.worst_segment_purity, 0.9);
}

INSTANTIATE_TEST_SUITE_P(Buildings, GeneratedSegmentation,
                         ::testing::Combine(::testing::Values("rooms", "office"), ::testing::Range(1, 6)));

TEST(Segmentation, LargeOfficeRoomsAndTheCorridorsAndAPicture) {
  GeneratorParams p;
  p.kind = "office";
  p.seed = 1;
  p.width = 400;
  p.height = 400;
  const WorldMap map = generate_map(p);
  const Agreement a = compare(map, p.door);
  EXPECT_GE(a.rooms, 100);
  EXPECT_EQ(a.segments, a.rooms);
  EXPECT_GE(a.worst_room_share, 0.9);
  EXPECT_GE(a.worst_segment_purity, 0.9);
  // The corridors are the one segment that is not a room.
  const KnownMap known = fully_known(map);
  const Segmentation s = segment_free_space(known);
  EXPECT_EQ(std::count(s.room.begin(), s.room.end(), 0), 1);
  // A picture to look at: build/<dir>/segments_office.png.
  const std::string png = std::string(FSWEEP_BINARY_DIR) + "/segments_office.png";
  write_segments_png(png, known, s, 2);
  EXPECT_TRUE(std::filesystem::file_size(png) > 0);
}

}  // namespace
}  // namespace fsweep
