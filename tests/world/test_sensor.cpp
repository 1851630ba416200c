#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "core/config_error.hpp"
#include "world/ascii_world.hpp"
#include "world/map_spec.hpp"
#include "world/scan_fixture.hpp"
#include "world/sensor.hpp"

namespace fsweep {
namespace test_sensor {  // not anonymous: unity builds put it beside other test files' helpers

using test::ascii_world;
using test::known;
using test::open_world;
using test::random_world;
using test::scan_fresh;

SensorParams range(double range_m) {
  SensorParams p;
  p.range_m = range_m;
  return p;
}

TEST(Sensor, RangeBoundaryIsInclusive) {
  const WorldMap map = open_world(13, 13);
  const Cell at{6, 6};
  const auto r = scan_fresh(map, range(5.0), at);
  // (3, 4) offset: distance exactly 5.
  EXPECT_TRUE(known(r, Cell{9, 10}));
  EXPECT_TRUE(known(r, Cell{11, 6}));
  EXPECT_TRUE(known(r, Cell{6, 1}));
  // Just beyond: 6 and sqrt(32) = 5.66.
  EXPECT_FALSE(known(r, Cell{12, 6}));
  EXPECT_FALSE(known(r, Cell{10, 10}));
  Sensor sensor(range(5.0), 1.0);
  EXPECT_TRUE(sensor.visible(map, at, Cell{9, 10}));
  EXPECT_FALSE(sensor.visible(map, at, Cell{12, 6}));
}

TEST(Sensor, OpenSpaceRevealsTheLatticeDisc) {
  // Lattice points with dx^2 + dy^2 <= 9, counted by hand: 7 + 2*5 + 2*5 + 2*1 = 29.
  const WorldMap map = open_world(11, 11);
  EXPECT_EQ(scan_fresh(map, range(3.0), Cell{5, 5}).revealed.size(), 29U);
}

TEST(Sensor, RangeInMetresIsDividedByResolution) {
  // 1.5 m at 0.5 m per cell and 0.9 m at 0.3 m per cell are both 3 cells (29 cells, above);
  // 0.9 / 0.3 is not exactly 3 in floating point.
  EXPECT_EQ(
      scan_fresh(ascii_world(std::vector<std::string>(11, std::string(11, '.')), 0.5), range(1.5), Cell{5, 5})
          .revealed.size(),
      29U);
  EXPECT_EQ(
      scan_fresh(ascii_world(std::vector<std::string>(11, std::string(11, '.')), 0.3), range(0.9), Cell{5, 5})
          .revealed.size(),
      29U);
  EXPECT_DOUBLE_EQ(Sensor(range(1.5), 0.5).range_cells(), 3.0);
}

TEST(Sensor, WallBlocksSight) {
  const WorldMap map = ascii_world({
      "........",
      "S..#....",
      "........",
  });
  const auto r = scan_fresh(map, range(10.0), map.start);
  for (int x = 4; x < 8; ++x) EXPECT_FALSE(known(r, Cell{x, 1})) << "x=" << x;
  // The ray to (4, 0) leaves row 1 before the wall: (1,1) (2,1) (2,0) (3,0).
  EXPECT_TRUE(known(r, Cell{4, 0}));
  EXPECT_EQ(r.known.state(Cell{3, 1}), CellState::Occupied);
}

TEST(Sensor, OccupiedCellIsObserved) {
  const WorldMap map = ascii_world({"S.##."});
  const auto r = scan_fresh(map, range(10.0), map.start);
  EXPECT_EQ(r.known.state(Cell{2, 0}), CellState::Occupied);
  EXPECT_EQ(r.known.state(Cell{3, 0}), CellState::Unknown);  // behind the first wall cell
  EXPECT_EQ(r.known.state(Cell{1, 0}), CellState::Free);
  EXPECT_NE(std::find(r.revealed.begin(), r.revealed.end(), 2), r.revealed.end());
  EXPECT_EQ(r.known.occupied_count(), 1);
  EXPECT_EQ(r.known.free_count(), 2);
}

TEST(Sensor, DiagonalGapBetweenTwoWallsIsOpaque) {
  const WorldMap map = ascii_world({
      "S#..",
      "#...",
      "....",
      "....",
  });
  const auto r = scan_fresh(map, range(10.0), map.start);
  // Only the robot's cell and the two walls beside it.
  EXPECT_EQ(r.known.known_count(), 3);
  EXPECT_FALSE(known(r, Cell{1, 1}));
  EXPECT_FALSE(known(r, Cell{3, 3}));
  Sensor sensor(range(10.0), 1.0);
  EXPECT_FALSE(sensor.visible(map, Cell{0, 0}, Cell{1, 1}));
  EXPECT_FALSE(sensor.visible(map, Cell{1, 1}, Cell{0, 0}));
}

TEST(Sensor, DiagonalGapWithOneFreeSideIsSeeThrough) {
  for (const auto& rows : {std::vector<std::string>{"S#..", "....", "....", "...."},
                           std::vector<std::string>{"S...", "#...", "....", "...."}}) {
    const WorldMap map = ascii_world(rows);
    const auto r = scan_fresh(map, range(10.0), map.start);
    EXPECT_TRUE(known(r, Cell{1, 1})) << rows[0];
    EXPECT_TRUE(known(r, Cell{2, 2})) << rows[0];
    EXPECT_TRUE(known(r, Cell{3, 3})) << rows[0];
  }
}

TEST(Sensor, CornerRuleAppliesToShallowRays) {
  // The segment from (0,0) to (3,1) passes exactly through the corner shared by (2,0) and
  // (1,1) (at x = 1.5, y = 0.5 with centres on integers).
  Sensor sensor(range(10.0), 1.0);
  EXPECT_FALSE(sensor.visible(ascii_world({"S.#.", ".#.."}), Cell{0, 0}, Cell{3, 1}));
  EXPECT_TRUE(sensor.visible(ascii_world({"S.#.", "...."}), Cell{0, 0}, Cell{3, 1}));
  EXPECT_TRUE(sensor.visible(ascii_world({"S...", ".#.."}), Cell{0, 0}, Cell{3, 1}));
}

TEST(Sensor, FieldOfViewLimitsCells) {
  const WorldMap map = open_world(9, 9);
  const Cell at{4, 4};
  SensorParams p = range(4.0);
  p.fov_deg = 180.0;
  // Lattice disc of radius 4 has 49 points: 9 on dx = 0, 20 on each side. The boundary
  // (dx = 0) is inside the field of view.
  const auto east = scan_fresh(map, p, at, heading_angle(0));
  EXPECT_EQ(east.revealed.size(), 29U);
  for (const int i : east.revealed) EXPECT_GE(map.occupied.cell(i).x, at.x);
  EXPECT_TRUE(known(east, Cell{4, 0}));
  EXPECT_TRUE(known(east, Cell{4, 8}));
  // Heading west wraps around +-pi.
  const auto west = scan_fresh(map, p, at, heading_angle(4));
  EXPECT_EQ(west.revealed.size(), 29U);
  for (const int i : west.revealed) EXPECT_LE(map.occupied.cell(i).x, at.x);
  // Heading south (y grows downward).
  const auto south = scan_fresh(map, p, at, heading_angle(2));
  for (const int i : south.revealed) EXPECT_GE(map.occupied.cell(i).y, at.y);
  // 90 degrees facing east: |dy| <= dx, diagonals included.
  p.fov_deg = 90.0;
  const auto narrow = scan_fresh(map, p, at, 0.0);
  for (const int i : narrow.revealed) {
    const Cell c = map.occupied.cell(i);
    EXPECT_LE(std::abs(c.y - at.y), c.x - at.x);
  }
  EXPECT_TRUE(known(narrow, Cell{6, 6}));
  EXPECT_TRUE(known(narrow, Cell{6, 2}));
  EXPECT_FALSE(known(narrow, Cell{5, 7}));
}

TEST(Sensor, RobotCellIsAlwaysSeen) {
  const WorldMap map = open_world(5, 5);
  SensorParams p = range(0.5);  // less than one cell
  p.fov_deg = 10.0;
  p.miss_probability = 0.99;
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    const auto r = scan_fresh(map, p, Cell{2, 2}, heading_angle(4), seed);
    ASSERT_EQ(r.revealed, std::vector<int>{12});
  }
}

TEST(Sensor, MissProbabilityIsSeededAndDeterministic) {
  const WorldMap map = open_world(41, 41);
  SensorParams p = range(15.0);
  p.miss_probability = 0.3;
  const Cell at{20, 20};
  const auto a = scan_fresh(map, p, at, 0.0, 7);
  const auto b = scan_fresh(map, p, at, 0.0, 7);
  const auto c = scan_fresh(map, p, at, 0.0, 8);
  EXPECT_EQ(a.revealed, b.revealed);
  EXPECT_EQ(a.known, b.known);
  EXPECT_NE(a.revealed, c.revealed);
  // 709 cells in range (from the noiseless scan); about 30 % missed (binomial sd ~ 12 cells).
  const auto clean = scan_fresh(map, range(15.0), at);
  const double missed =
      1.0 - static_cast<double>(a.revealed.size()) / static_cast<double>(clean.revealed.size());
  EXPECT_GT(missed, 0.2);
  EXPECT_LT(missed, 0.4);
  // A miss lasts one scan: scanning again reveals more.
  Sensor sensor(p, 1.0);
  KnownMap known = a.known;
  Rng rng = make_rng(9, "sensor");
  EXPECT_FALSE(sensor.scan(map, known, at, 0.0, rng).empty());
}

TEST(Sensor, NoiselessScanDoesNotDrawRandomNumbers) {
  const WorldMap map = open_world(11, 11);
  Sensor sensor(range(4.0), 1.0);
  KnownMap known(11, 11, 1.0);
  Rng rng = make_rng(3, "sensor");
  const Rng before = rng;
  (void)sensor.scan(map, known, Cell{5, 5}, 0.0, rng);
  EXPECT_EQ(rng, before);
}

TEST(Sensor, ReturnsOnlyNewlyRevealedCells) {
  const WorldMap map = random_world(30, 30, 0.2, 5);
  Sensor sensor(range(6.0), 1.0);
  KnownMap known(30, 30, 1.0);
  Rng rng = make_rng(1, "sensor");
  const Cell at = map.start;
  const auto first = sensor.scan(map, known, at, 0.0, rng);
  EXPECT_EQ(static_cast<int>(first.size()), known.known_count());
  EXPECT_TRUE(sensor.scan(map, known, at, 0.0, rng).empty());

  Cell next = at;
  for (int x = at.x + 5; x > at.x; --x) {
    if (map.is_free(Cell{x, at.y}) && known.is_free(Cell{x, at.y})) {
      next = Cell{x, at.y};
      break;
    }
  }
  const KnownMap before = known;
  const auto second = sensor.scan(map, known, next, 0.0, rng);
  std::vector<int> changed;
  for (int i = 0; i < known.size(); ++i) {
    if (before.state(i) != known.state(i)) {
      EXPECT_EQ(before.state(i), CellState::Unknown);
      EXPECT_EQ(known.state(i), map.is_free(i) ? CellState::Free : CellState::Occupied);
      changed.push_back(i);
    }
  }
  std::vector<int> got(second.begin(), second.end());
  std::sort(got.begin(), got.end());
  EXPECT_EQ(got, changed);
  EXPECT_EQ(known.known_count() - before.known_count(), static_cast<int>(second.size()));
}

TEST(Sensor, ScanMatchesVisible) {
  const WorldMap map = random_world(31, 31, 0.3, 11);
  Sensor sensor(range(7.5), 1.0);
  for (const Cell at : {map.start, Cell{0, 0}, Cell{30, 3}, Cell{4, 29}}) {
    const auto r = scan_fresh(map, range(7.5), at);
    std::set<int> got(r.revealed.begin(), r.revealed.end());
    ASSERT_EQ(got.size(), r.revealed.size());
    for (int i = 0; i < map.occupied.size(); ++i) {
      const bool expected = i == map.occupied.index(at) || sensor.visible(map, at, map.occupied.cell(i));
      EXPECT_EQ(got.count(i) == 1, expected) << "cell " << i;
    }
  }
}

TEST(Sensor, VisibilityBetweenFreeCellsIsSymmetric) {
  // Free targets use the centre ray only, which is the same segment both ways. (Occupied
  // targets may also be seen through a face ray, which has no reverse counterpart.)
  const WorldMap map = random_world(20, 20, 0.35, 3);
  Sensor sensor(range(8.0), 1.0);
  for (int a = 0; a < map.occupied.size(); ++a) {
    if (!map.is_free(a)) continue;
    for (int b = a + 1; b < map.occupied.size(); ++b) {
      if (!map.is_free(b)) continue;
      const Cell ca = map.occupied.cell(a);
      const Cell cb = map.occupied.cell(b);
      ASSERT_EQ(sensor.visible(map, ca, cb), sensor.visible(map, cb, ca)) << a << " " << b;
    }
  }
}

TEST(Sensor, CentreRayOnTheKnownMapIsTheSensorsRuleForFreeTargets) {
  // centre_ray_clear() on a fully known map decides in range exactly as visible() on the true
  // map does for free targets (both take the centre ray; corners need both side cells
  // occupied). Unknown cells are transparent: on an all-unknown map every ray is clear.
  const WorldMap map = random_world(24, 24, 0.3, 7);
  KnownMap known(24, 24, 1.0);
  for (int i = 0; i < map.occupied.size(); ++i) (void)known.reveal(i, !map.is_free(i));
  const KnownMap unknown(24, 24, 1.0);
  Sensor sensor(range(9.0), 1.0);
  int compared = 0;
  int blocked = 0;
  for (int a = 0; a < map.occupied.size(); ++a) {
    if (!map.is_free(a)) continue;
    const Cell at = map.occupied.cell(a);
    for (int b = 0; b < map.occupied.size(); ++b) {
      const Cell t = map.occupied.cell(b);
      if (!map.is_free(b) || (t.x - at.x) * (t.x - at.x) + (t.y - at.y) * (t.y - at.y) > 81) continue;
      const bool clear = centre_ray_clear(known, at, t);
      ASSERT_EQ(clear, sensor.visible(map, at, t)) << at.x << ";" << at.y << " -> " << t.x << ";" << t.y;
      ASSERT_TRUE(centre_ray_clear(unknown, at, t));
      ++compared;
      blocked += clear ? 0 : 1;
    }
  }
  EXPECT_GT(compared, 10000);
  EXPECT_GT(blocked, 1000);  // walls do block: the comparison is not trivially all-clear
}

// ---------------------------------------------------------------------------------------------
// Occupied targets: face rays (see the rule list in sensor.hpp).

TEST(Sensor, StraightWallIsSeenAtGrazingAngles) {
  // Robot 2 cells below a straight wall, range 5: wall cells (x, 0) with (x - 4)^2 + 4 <= 25,
  // i.e. x = 0..8, are in range. The centre ray to (x, 0) with |x - 4| >= 3 enters the side of
  // the neighbouring wall cell first (it reaches row 0 at |dx| * 3/4 > |dx| - 1/2 cells), so
  // under a centre-only rule only x = 2..6 were seen. The face ray to the bottom face's
  // midpoint (2dx, -3 in doubled coordinates) crosses only rows 2 and 1, which are free.
  const WorldMap map = ascii_world({
      "##########",
      "..........",
      "....S.....",
  });
  const auto r = scan_fresh(map, range(5.0), map.start);
  Sensor sensor(range(5.0), 1.0);
  for (int x = 0; x <= 8; ++x) {
    EXPECT_EQ(r.known.state(Cell{x, 0}), CellState::Occupied) << "x=" << x;
    EXPECT_TRUE(sensor.visible(map, map.start, Cell{x, 0})) << "x=" << x;
  }
  EXPECT_FALSE(known(r, Cell{9, 0}));  // out of range: 25 + 4 > 25
  EXPECT_FALSE(sensor.visible(map, map.start, Cell{9, 0}));
  EXPECT_EQ(r.known.occupied_count(), 9);
}

TEST(Sensor, ClosedBoxHidesOnlyItsCorners) {
  // Robot at (1,1), range 5 (every cell is in range). Rays are worked in doubled coordinates
  // relative to the robot's centre (cell (x, y) relative spans (2x-1, 2x+1) x (2y-1, 2y+1)).
  //
  // (3,0), offset (2,-1): the centre ray to (4,-2) enters (2,1) and then, at t = 1/2 (height
  // -1 before x = 3), the wall (2,0): blocked; the vertical-face ray to (3,-2) likewise enters
  // (2,1) then (2,0). The horizontal-face ray to (4,-1) only crosses x = 1 and x = 3 before
  // its end, entering (2,1) and (3,1), both free: (3,0) is seen (the grazing case).
  //
  // (4,0), offset (3,-1): the centre ray to (6,-2) enters (2,1), passes the corner at (3,-1)
  // (beside (3,1) free and (2,0) wall: see-through) and enters (3,0), a wall: blocked. The
  // vertical-face ray to (5,-2) (the west face) enters (2,1) at t = 1/5, then crosses height -1
  // at t = 1/2 before x = 3 at t = 3/5, entering the wall (2,0): blocked. The horizontal-face
  // ray to (6,-1) (the south face) ends on height -1, so it stays in row 1 and enters (2,1),
  // (3,1) and then (4,1), the wall in front of that face: blocked. So (4,0) stays hidden
  // (and (4,2) by symmetry).
  //
  // (0,0), offset (-1,-1): the centre ray passes the corner at (-1,-1) between the walls (0,1)
  // and (1,0): opaque. Its east-face ray to (-1,-2) enters (1,0) and its south-face ray to
  // (-2,-1) enters (0,1), both walls: the near corners (0,0) and (0,2) stay hidden too, as
  // with a centre-only rule (a diagonal gap between two walls is opaque).
  const WorldMap map = ascii_world({
      "#####",
      "#S..#",
      "#####",
  });
  const auto r = scan_fresh(map, range(5.0), map.start);
  Sensor sensor(range(5.0), 1.0);
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 5; ++x) {
      const bool corner = (x == 0 || x == 4) && y != 1;
      EXPECT_EQ(known(r, Cell{x, y}), !corner) << x << "," << y;
      EXPECT_EQ(sensor.visible(map, map.start, Cell{x, y}), !corner) << x << "," << y;
    }
  }
  EXPECT_EQ(r.known.known_count(), 11);
}

TEST(Sensor, WallCellBehindAWallCellStaysHidden) {
  // A wall two cells thick: every back-row cell has a wall cell in front of each face that
  // looks toward the robot ((x, 1) below it; (x -+ 1, 0) beside it), and its centre ray
  // enters row 1. (6,0) ends the back row: its east face borders free space, but that face
  // looks away from the robot, so it does not count.
  const WorldMap map = ascii_world({
      "#######...",
      "##########",
      "..........",
      "....S.....",
  });
  const auto r = scan_fresh(map, range(5.0), map.start);
  Sensor sensor(range(5.0), 1.0);
  for (int x = 0; x <= 8; ++x) EXPECT_EQ(r.known.state(Cell{x, 1}), CellState::Occupied) << "x=" << x;
  for (int x = 0; x < 10; ++x) {
    EXPECT_FALSE(known(r, Cell{x, 0})) << "x=" << x;
    EXPECT_FALSE(sensor.visible(map, map.start, Cell{x, 0})) << "x=" << x;
  }
  // In a single row: the second wall cell's only face toward the robot is covered.
  const WorldMap row = ascii_world({"S..##."});
  EXPECT_TRUE(sensor.visible(row, row.start, Cell{3, 0}));
  EXPECT_FALSE(sensor.visible(row, row.start, Cell{4, 0}));
}

TEST(Sensor, FreeCellsKeepTheCentreRule) {
  // Target (4,1) from (0,0): the centre ray to (8,2) (doubled) enters (1,0), (2,0) and, at
  // t = 1/2, the wall (2,1): blocked. The ray to the north face's midpoint (8,1) would stay in
  // row 0 and be clear, so the cell is seen when it is a wall, but not when it is free.
  const WorldMap free_target = ascii_world({
      "S.....",
      "..#...",
  });
  const WorldMap wall_target = ascii_world({
      "S.....",
      "..#.#.",
  });
  Sensor sensor(range(10.0), 1.0);
  EXPECT_FALSE(sensor.visible(free_target, Cell{0, 0}, Cell{4, 1}));
  EXPECT_FALSE(known(scan_fresh(free_target, range(10.0), Cell{0, 0}), Cell{4, 1}));
  EXPECT_TRUE(sensor.visible(wall_target, Cell{0, 0}, Cell{4, 1}));
  EXPECT_EQ(scan_fresh(wall_target, range(10.0), Cell{0, 0}).known.state(Cell{4, 1}), CellState::Occupied);
  // The west face's ray to (7,2) enters (2,1) as well.
  const WorldMap west_only = ascii_world({
      "S...#.",
      "..#.#.",
  });
  EXPECT_FALSE(sensor.visible(west_only, Cell{0, 0}, Cell{4, 1}));
}

// A reference for the ray rule by brute force: a ray from the robot's centre (origin) to
// (ex, ey) in doubled coordinates enters cell (x, y) (relative) when the open segment meets
// the cell's open interior; it passes a corner (X, Y) (both odd) when that point lies on it
// strictly between its ends. Times are compared as exact fractions.
struct Fraction {
  long long num;
  long long den;  // > 0
  friend bool operator<(Fraction a, Fraction b) { return a.num * b.den < b.num * a.den; }
};

/// Open interval of t where t * e lies in (lo, hi); empty interval when e == 0 and 0 is not
/// inside.
std::pair<Fraction, Fraction> times_inside(long long e, long long lo, long long hi) {
  if (e == 0) {
    return lo < 0 && 0 < hi ? std::pair{Fraction{0, 1}, Fraction{1, 1}}
                            : std::pair{Fraction{1, 1}, Fraction{0, 1}};
  }
  if (e > 0) return {Fraction{lo, e}, Fraction{hi, e}};
  return {Fraction{-hi, -e}, Fraction{-lo, -e}};
}

bool reference_ray_clear(const WorldMap& map, Cell at, int ex, int ey, Cell skip) {
  const auto occupied = [&](int x, int y) { return !map.is_free(Cell{at.x + x, at.y + y}); };
  const int x0 = std::min(0, ex / 2) - 1;
  const int x1 = std::max(0, ex / 2) + 1;
  const int y0 = std::min(0, ey / 2) - 1;
  const int y1 = std::max(0, ey / 2) + 1;
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      if ((x == 0 && y == 0) || (x == skip.x && y == skip.y)) continue;
      const auto [ax, bx] = times_inside(ex, 2 * x - 1, 2 * x + 1);
      const auto [ay, by] = times_inside(ey, 2 * y - 1, 2 * y + 1);
      const Fraction lo = std::max({ax, ay, Fraction{0, 1}});
      const Fraction hi = std::min({bx, by, Fraction{1, 1}});
      if (lo < hi && occupied(x, y)) return false;
    }
  }
  for (int cy = 2 * y0 - 1; cy <= 2 * y1 + 1; cy += 2) {
    for (int cx = 2 * x0 - 1; cx <= 2 * x1 + 1; cx += 2) {
      if (ex == 0 || static_cast<long long>(cx) * ey != static_cast<long long>(cy) * ex) continue;
      const Fraction t{ex > 0 ? cx : -cx, ex > 0 ? ex : -ex};
      if (!(Fraction{0, 1} < t && t < Fraction{1, 1})) continue;
      const int sx = ex > 0 ? 1 : -1;
      const int sy = ey > 0 ? 1 : -1;
      // Beside the corner: ahead in x but not in y, and ahead in y but not in x.
      if (occupied((cx + sx) / 2, (cy - sy) / 2) && occupied((cx - sx) / 2, (cy + sy) / 2)) return false;
    }
  }
  return true;
}

bool reference_visible(const WorldMap& map, double range_cells, Cell at, Cell target) {
  const int dx = target.x - at.x;
  const int dy = target.y - at.y;
  if (dx * dx + dy * dy > range_cells * range_cells + 1e-9) return false;
  if (reference_ray_clear(map, at, 2 * dx, 2 * dy, Cell{dx, dy})) return true;
  if (map.is_free(target)) return false;
  const Cell none{1 << 20, 1 << 20};
  return (dx != 0 && reference_ray_clear(map, at, 2 * dx - (dx > 0 ? 1 : -1), 2 * dy, none)) ||
         (dy != 0 && reference_ray_clear(map, at, 2 * dx, 2 * dy - (dy > 0 ? 1 : -1), none));
}

TEST(Sensor, MatchesBruteForceReference) {
  for (const double p : {0.15, 0.3, 0.5}) {
    const WorldMap map = random_world(27, 27, p, static_cast<std::uint64_t>(p * 100));
    Sensor sensor(range(9.0), 1.0);
    int occupied_seen = 0;
    for (const Cell at : {map.start, Cell{0, 0}, Cell{26, 4}, Cell{3, 26}, Cell{7, 9}}) {
      const auto r = scan_fresh(map, range(9.0), at);
      for (int i = 0; i < map.occupied.size(); ++i) {
        const Cell c = map.occupied.cell(i);
        const bool expected = c == at || reference_visible(map, 9.0, at, c);
        ASSERT_EQ(sensor.visible(map, at, c) || c == at, expected)
            << "p " << p << " at " << at.x << "," << at.y << " cell " << c.x << "," << c.y;
        ASSERT_EQ(known(r, c), expected) << "p " << p << " cell " << c.x << "," << c.y;
        if (expected && !map.is_free(c)) ++occupied_seen;
      }
    }
    EXPECT_GT(occupied_seen, 20);
  }
}

TEST(Sensor, CopiesScanIndependently) {
  // Copies share the precomputed tables but not the result buffer.
  const WorldMap map = random_world(30, 30, 0.2, 5);
  const Sensor original(range(6.0), 1.0);
  Sensor a = original;
  Sensor b = a;
  KnownMap known_a(30, 30, 1.0);
  KnownMap known_b(30, 30, 1.0);
  Rng rng = make_rng(1, "sensor");
  const auto from_a = a.scan(map, known_a, map.start, 0.0, rng);
  const std::vector<int> saved(from_a.begin(), from_a.end());
  const auto from_b = b.scan(map, known_b, Cell{2, 3}, 0.0, rng);
  EXPECT_EQ(std::vector<int>(from_a.begin(), from_a.end()), saved);  // still a's result
  EXPECT_NE(std::vector<int>(from_b.begin(), from_b.end()), saved);
  const auto fresh = scan_fresh(map, range(6.0), Cell{2, 3});
  EXPECT_EQ(std::vector<int>(from_b.begin(), from_b.end()), fresh.revealed);
  EXPECT_EQ(known_a, scan_fresh(map, range(6.0), map.start).known);
  Sensor unset;
  EXPECT_TRUE(unset.scan(map, known_a, map.start, 0.0, rng).empty());
}

TEST(SensorParams, JsonRoundTrips) {
  SensorParams p;
  p.range_m = 4.5;
  p.fov_deg = 180.0;
  p.miss_probability = 0.25;
  const nlohmann::json j = p;
  const SensorParams q = sensor_params_from_json(j, "/sensor");
  EXPECT_EQ(q.range_m, 4.5);
  EXPECT_EQ(q.fov_deg, 180.0);
  EXPECT_EQ(q.miss_probability, 0.25);
}

TEST(SensorParams, MissingKeysKeepDefaults) {
  const SensorParams q = sensor_params_from_json(nlohmann::json::object({{"range_m", 3}}), "/sensor");
  EXPECT_EQ(q.range_m, 3.0);
  EXPECT_EQ(q.fov_deg, SensorParams{}.fov_deg);
  EXPECT_EQ(q.miss_probability, SensorParams{}.miss_probability);
}

TEST(SensorParams, UnknownKeyIsConfigError) {
  try {
    (void)sensor_params_from_json(nlohmann::json{{"rnage_m", 3}}, "/sensor");
    FAIL() << "no exception";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.where(), "/sensor/rnage_m");
    EXPECT_NE(std::string(e.what()).find("range_m"), std::string::npos);
  }
}

/// The message of the ConfigError thrown for `j`, or "" when none is thrown.
std::string error_of(const nlohmann::json& j) { return test::sensor_params_error(j, "/runs/0/sensor"); }

TEST(SensorParams, InvalidValuesNamePathValueAndRange) {
  const std::string range_error = error_of({{"range_m", -1.5}});
  EXPECT_NE(range_error.find("/runs/0/sensor/range_m"), std::string::npos) << range_error;
  EXPECT_NE(range_error.find("-1.5"), std::string::npos) << range_error;
  EXPECT_NE(range_error.find("> 0"), std::string::npos) << range_error;
  EXPECT_NE(error_of({{"range_m", 0}}), "");

  const std::string fov_error = error_of({{"fov_deg", 400}});
  EXPECT_NE(fov_error.find("/runs/0/sensor/fov_deg"), std::string::npos) << fov_error;
  EXPECT_NE(fov_error.find("400"), std::string::npos) << fov_error;
  EXPECT_NE(fov_error.find("(0, 360]"), std::string::npos) << fov_error;
  EXPECT_NE(error_of({{"fov_deg", 0}}), "");
  EXPECT_EQ(error_of({{"fov_deg", 360}}), "");

  const std::string miss_error = error_of({{"miss_probability", 1.0}});
  EXPECT_NE(miss_error.find("/runs/0/sensor/miss_probability"), std::string::npos) << miss_error;
  EXPECT_NE(miss_error.find("[0, 1)"), std::string::npos) << miss_error;
  EXPECT_NE(error_of({{"miss_probability", -0.1}}), "");
  EXPECT_EQ(error_of({{"miss_probability", 0.0}}), "");

  EXPECT_NE(error_of({{"range_m", "ten"}}).find("/runs/0/sensor/range_m"), std::string::npos);
  EXPECT_NE(error_of(nlohmann::json::array()), "");
}

// --- Sensor::gain: simulated scans on the known map (Holz 2010 sections IV-B, IV-C) ---

/// The known map as a world for Sensor::visible(): known occupied cells are walls, unknown and
/// free cells are free (gain() treats unknown cells as transparent, non-wall targets).
WorldMap walls_of(const KnownMap& known) {
  WorldMap w = open_world(known.width(), known.height());
  w.resolution_m = known.resolution_m();
  for (int i = 0; i < known.size(); ++i) w.occupied[i] = known.state(i) == CellState::Occupied ? 1 : 0;
  return w;
}

// Range 2 cells: 13 targets, the 3 x 3 block and (+-2, 0), (0, +-2). Robot R = (3, 3).
//   row 2: (3,2) occupied, just north of R
//   row 3: (2,3) and (4,3) free, R free
//   everything else unknown
const std::vector<std::string> kGainMap = {
    "???????",  //
    "???????",  //
    "???#???",  //
    "??...??",  //
    "???????",  //
    "???????",  //
    "???????",  //
};

TEST(SensorGain, HandCountedOmnidirectional) {
  const KnownMap k = test::ascii_known(kGainMap);
  const Sensor sensor(range(2.0), 1.0);
  // Known: R, (2,3), (4,3), and the wall (3,2) (adjacent: nothing in between) = 4.
  // Unknown: (3,4); the four diagonals (each corner has at least one non-occupied cell beside
  // it); (1,3) through free (2,3); (5,3) through free (4,3); (3,5) through unknown (3,4),
  // which is transparent = 8. Not seen: (3,1), behind the wall (an unknown target needs its
  // centre ray). 4 + 8 + 1 = 13 targets.
  EXPECT_EQ(sensor.gain(k, Cell{3, 3}, 0.0), (ScanCounts{8, 4}));
}

TEST(SensorGain, FieldOfViewFollowsTheHeading) {
  const KnownMap k = test::ascii_known(kGainMap);
  SensorParams p = range(2.0);
  p.fov_deg = 180.0;
  const Sensor sensor(p, 1.0);
  // Facing east: dx >= 0 (the +-90 degree boundary is inclusive). Known: R, (4,3), the wall
  // (3,2) at -90 degrees = 3. Unknown: (3,4) at +90, (4,2), (4,4), (5,3), (3,5) = 5.
  EXPECT_EQ(sensor.gain(k, Cell{3, 3}, 0.0), (ScanCounts{5, 3}));
  // Facing north (-pi/2, up the screen): dy <= 0. Known: R, (2,3), (4,3) on the boundary, the
  // wall (3,2) = 4. Unknown: (2,2), (4,2), (1,3), (5,3) = 4; (3,1) is behind the wall.
  EXPECT_EQ(sensor.gain(k, Cell{3, 3}, -M_PI / 2.0), (ScanCounts{4, 4}));
}

TEST(SensorGain, WallFaceSeenAtAGrazingAngle) {
  // A straight wall in row 0 seen from (0, 1): the centre ray to (3, 0) enters (1, 0) and
  // (2, 0), walls, but its face ray towards the robot's side stays in row 1 (free) until the
  // face, so the wall cell counts as seen, as in scan(). Unknown row 2 is transparent.
  const KnownMap k = test::ascii_known({
      "####",  //
      "....",  //
      "????",  //
  });
  const Sensor sensor(range(10.0), 1.0);
  const WorldMap w = walls_of(k);
  EXPECT_TRUE(sensor.visible(w, Cell{0, 1}, Cell{3, 0}));
  // Everything is in range and nothing hides anything: 8 known + 4 unknown.
  EXPECT_EQ(sensor.gain(k, Cell{0, 1}, 0.0), (ScanCounts{4, 8}));
}

TEST(SensorGain, EqualsVisibleCellsByStateOnRandomKnownMaps) {
  // Independent check against Sensor::visible(), which walks rays without the tables.
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    Rng rng = make_rng(seed, "gain-test");
    KnownMap k(21, 17, 1.0);
    for (int i = 0; i < k.size(); ++i) {
      const double r = uniform01(rng);
      if (r < 0.6) k.reveal(i, r < 0.25);  // 25% occupied, 35% free, the rest unknown
    }
    const Cell at{10, 8};
    const WorldMap w = walls_of(k);
    const Sensor sensor(range(6.5), 1.0);
    ScanCounts expected;
    for (int i = 0; i < k.size(); ++i) {
      if (!sensor.visible(w, at, k.cell(i))) continue;
      ++(k.state(i) == CellState::Unknown ? expected.unknown : expected.known);
    }
    EXPECT_EQ(sensor.gain(k, at, 0.0), expected) << "seed " << seed;
  }
}

TEST(SensorGain, EqualsAScanOfTheKnownWallsWithFieldOfView) {
  // A scan on a world whose walls are the known occupied cells, from an empty known map,
  // reveals exactly the cells gain() counts; splitting them by their state on the known map
  // gives the two counts. Checks the field of view against scan()'s.
  Rng rng = make_rng(7, "gain-test");
  KnownMap k(25, 25, 0.5);
  for (int i = 0; i < k.size(); ++i) {
    const double r = uniform01(rng);
    if (r < 0.5) k.reveal(i, r < 0.2);  // 20% occupied, 30% free, the rest unknown
  }
  const Cell at{12, 12};
  const WorldMap w = walls_of(k);
  for (const double fov : {360.0, 180.0, 90.0}) {
    for (const double heading : {0.0, 1.0, -2.5}) {
      SensorParams p = range(5.0);
      p.fov_deg = fov;
      const auto r = scan_fresh(w, p, at, heading);
      ScanCounts expected;
      for (const int i : r.revealed) ++(k.state(i) == CellState::Unknown ? expected.unknown : expected.known);
      EXPECT_EQ(Sensor(p, 0.5).gain(k, at, heading), expected) << "fov " << fov << " heading " << heading;
    }
  }
}

TEST(SensorGain, OffTheMapOrDefaultSensorCountsNothing) {
  const KnownMap k = test::ascii_known(kGainMap);
  EXPECT_EQ(Sensor(range(2.0), 1.0).gain(k, Cell{-1, 3}, 0.0), (ScanCounts{0, 0}));
  EXPECT_EQ(Sensor().gain(k, Cell{3, 3}, 0.0), (ScanCounts{0, 0}));
  // At the map's corner only the on-map part of the disc counts: range 1, from (0, 0) of a
  // fully unknown map: (0,0), (1,0), (0,1) = 3 unknown.
  EXPECT_EQ(Sensor(range(1.0), 1.0).gain(KnownMap(4, 4, 1.0), Cell{0, 0}, 0.0), (ScanCounts{3, 0}));
}

// --- The sweep of scan() and gain() against the rule, target by target ---

/// Offsets of the (2r+1)^2 square in offset-table order: squared distance, then dy, then dx.
std::vector<Cell> offsets_in_table_order(int r) {
  std::vector<Cell> out;
  for (int dy = -r; dy <= r; ++dy) {
    for (int dx = -r; dx <= r; ++dx) out.push_back(Cell{dx, dy});
  }
  std::stable_sort(out.begin(), out.end(),
                   [](Cell a, Cell b) { return a.x * a.x + a.y * a.y < b.x * b.x + b.y * b.y; });
  return out;
}

/// The field-of-view test as documented in sensor.hpp, with the sensor's slack (1e-9 rad) and
/// the same double computations: the direction to the target's centre by std::atan2.
bool in_field_of_view(const SensorParams& p, Cell offset, double heading_rad) {
  if (p.fov_deg >= 360.0 || offset == Cell{0, 0}) return true;
  double d = std::fmod(std::atan2(static_cast<double>(offset.y), static_cast<double>(offset.x)) - heading_rad,
                       2.0 * M_PI);
  if (d < 0.0) d += 2.0 * M_PI;
  if (d > M_PI) d = 2.0 * M_PI - d;
  return d <= p.fov_deg * (M_PI / 360.0) + 1e-9;
}

/// scan() spelled out: every unknown target on the map in offset-table order, the field of
/// view, then Sensor::visible() (range and rays, walked directly); one noise draw per visible
/// unknown target but the robot's cell.
std::vector<int> reference_scan(const Sensor& sensor, const WorldMap& truth, KnownMap& known, Cell at,
                                double heading_rad, Rng& rng) {
  std::vector<int> out;
  const SensorParams& p = sensor.params();
  for (const Cell o : offsets_in_table_order(static_cast<int>(sensor.range_cells()) + 1)) {
    const Cell c{at.x + o.x, at.y + o.y};
    if (!truth.occupied.in_bounds(c) || known.state(c) != CellState::Unknown) continue;
    const bool own = o == Cell{0, 0};
    if (!in_field_of_view(p, o, heading_rad)) continue;
    if (!own && !sensor.visible(truth, at, c)) continue;
    if (p.miss_probability > 0.0 && !own && uniform01(rng) < p.miss_probability) continue;
    const int i = truth.occupied.index(c);
    known.reveal(i, !truth.is_free(i));
    out.push_back(i);
  }
  return out;
}

/// gain() spelled out: the same targets, known occupied cells as the only walls.
ScanCounts reference_gain(const Sensor& sensor, const KnownMap& known, Cell at, double heading_rad) {
  ScanCounts counts;
  const WorldMap walls = walls_of(known);
  for (const Cell o : offsets_in_table_order(static_cast<int>(sensor.range_cells()) + 1)) {
    const Cell c{at.x + o.x, at.y + o.y};
    if (!known.in_bounds(c) || !in_field_of_view(sensor.params(), o, heading_rad)) continue;
    if (o != Cell{0, 0} && !sensor.visible(walls, at, c)) continue;
    ++(known.state(c) == CellState::Unknown ? counts.unknown : counts.known);
  }
  return counts;
}

/// A seeded map with obstacle cells of density p and the shapes that stress the ray rules:
/// straight runs, long walls at grazing slopes (1/2 .. 1/9) and diagonal lines (whose steps
/// are diagonal gaps), some of them doubled into opaque diagonal pairs.
WorldMap stress_world(int width, int height, double p, std::uint64_t seed) {
  WorldMap map = open_world(width, height);
  Rng rng = make_rng(seed, "stress-map");
  const auto below = [&](int n) {
    return static_cast<int>(uniform_below(rng, static_cast<std::uint64_t>(n)));
  };
  const auto put = [&](int x, int y) {
    if (map.occupied.in_bounds(Cell{x, y})) map.occupied.at(Cell{x, y}) = 1;
  };
  for (int i = 0; i < map.occupied.size(); ++i) map.occupied[i] = uniform01(rng) < p ? 1 : 0;
  for (int k = below(6); k > 0; --k) {  // runs along a row or a column
    const int x = below(width);
    const int y = below(height);
    const bool along_x = below(2) == 0;
    for (int j = 0, n = 2 + below(12); j < n; ++j) put(along_x ? x + j : x, along_x ? y : y + j);
  }
  for (int k = below(4); k > 0; --k) {  // grazing walls: slope 1/m, either way up
    const int m = 2 + below(8);
    const int x = below(width);
    const int y = below(height);
    const int sx = below(2) == 0 ? 1 : -1;
    const int sy = below(2) == 0 ? 1 : -1;
    const bool steep = below(2) == 0;
    for (int j = 0; j < 3 * m; ++j) {
      const int a = sx * j;
      const int b = sy * (j / m);
      put(steep ? x + b : x + a, steep ? y + a : y + b);
    }
  }
  for (int k = below(4); k > 0; --k) {  // diagonal lines, sometimes doubled
    const int x = below(width);
    const int y = below(height);
    const int sx = below(2) == 0 ? 1 : -1;
    const bool doubled = below(2) == 0;
    for (int j = 0, n = 3 + below(10); j < n; ++j) {
      put(x + sx * j, y + j);
      if (doubled) put(x + sx * j + 1, y + j);
    }
  }
  return map;
}

TEST(SensorSweep, EqualsTheRuleTargetByTarget) {
  // Seeded random cases: map size and density, robot anywhere (edges and corners included),
  // range (whole and fractional numbers of cells, and metres that round, e.g. 3.0 m / 0.3 m),
  // field of view and heading, noise, and a partly known map (scan skips known targets; gain()
  // sees only the known walls). Every scan must reveal the same cells in the same order with
  // the same noise draws, and gain() must count the same cells.
  const std::vector<double> ranges_cells = {0.5, 1.0, 1.5, 2.0,  2.2,  3.0,  4.0,  5.0,  5.5,
                                            7.0, 8.0, 9.9, 10.0, 12.5, 15.0, 18.0, 20.0, 25.0};
  const std::vector<double> fovs = {360.0, 359.0, 270.0, 180.0, 120.0, 90.0, 45.0, 10.0};
  Rng rng = make_rng(2024, "sensor-sweep-test");
  const auto below = [&](int n) {
    return static_cast<int>(uniform_below(rng, static_cast<std::uint64_t>(n)));
  };
  int scans = 0;
  int revealed = 0;
  int occupied_revealed = 0;
  for (int trial = 0; trial < 1500; ++trial) {
    const bool tiny = below(5) == 0;  // maps narrower than the range, down to one cell
    const int width = tiny ? 1 + below(8) : 20 + below(40);
    const int height = tiny ? 1 + below(8) : 20 + below(40);
    const double u = uniform01(rng);
    const double density = 0.05 + 0.55 * u * u;  // 0.05 .. 0.6, mostly sparse
    WorldMap truth = stress_world(width, height, density, static_cast<std::uint64_t>(trial));
    // Resolution and range: exact metres (1 m cells), or a range that is a whole number of
    // cells only up to rounding (e.g. 3.0 m at 0.3 m).
    const double range_cells =
        ranges_cells[static_cast<std::size_t>(below(static_cast<int>(ranges_cells.size())))];
    const bool rounding = below(2) == 0;
    truth.resolution_m = rounding ? 0.3 : 1.0;
    SensorParams p;
    p.range_m = rounding ? range_cells * 0.3 : range_cells;
    p.fov_deg = below(2) == 0 ? 360.0 : fovs[static_cast<std::size_t>(below(static_cast<int>(fovs.size())))];
    p.miss_probability = below(3) == 0 ? 0.3 : 0.0;
    // Robot: anywhere, often on an edge or in a corner.
    Cell at{below(width), below(height)};
    if (below(3) == 0) at.x = below(2) == 0 ? 0 : width - 1;
    if (below(3) == 0) at.y = below(2) == 0 ? 0 : height - 1;
    // Headings: the eight headings of the robot and arbitrary ones.
    const double heading = below(2) == 0 ? heading_angle(below(8)) : (2.0 * uniform01(rng) - 1.0) * M_PI;
    // Known map: empty, or some cells already known (free or occupied as in the truth).
    KnownMap known(width, height, truth.resolution_m);
    const double known_share = below(3) != 0 ? 0.0 : 0.6 * uniform01(rng);
    for (int i = 0; i < known.size(); ++i) {
      if (uniform01(rng) < known_share) known.reveal(i, !truth.is_free(i));
    }
    Sensor sensor(p, truth.resolution_m);
    const std::uint64_t seed = static_cast<std::uint64_t>(trial);
    const std::string where = "trial " + std::to_string(trial) + ": " + std::to_string(width) + "x" +
                              std::to_string(height) + " at " + std::to_string(at.x) + "," +
                              std::to_string(at.y) + " range_m " + std::to_string(p.range_m) + " fov " +
                              std::to_string(p.fov_deg) + " heading " + std::to_string(heading);
    // gain() on the partly known map, before the scans change it.
    ASSERT_EQ(sensor.gain(known, at, heading), reference_gain(sensor, known, at, heading)) << where;
    // Two scans in a row from the same known map: the second one sees what the first one left.
    KnownMap expected_known = known;
    Rng scan_rng = make_rng(seed, "sensor");
    Rng expected_rng = scan_rng;
    for (int again = 0; again < 2; ++again) {
      const auto got = sensor.scan(truth, known, at, heading, scan_rng);
      const std::vector<int> expected =
          reference_scan(sensor, truth, expected_known, at, heading, expected_rng);
      ASSERT_EQ(std::vector<int>(got.begin(), got.end()), expected) << where << " scan " << again;
      ASSERT_EQ(known, expected_known) << where;
      ASSERT_EQ(scan_rng, expected_rng) << where;  // the same number of noise draws
      ++scans;
      revealed += static_cast<int>(expected.size());
      for (const int i : expected) occupied_revealed += truth.is_free(i) ? 0 : 1;
    }
    // gain() on the map the scans left (fewer unknown cells, more known walls).
    ASSERT_EQ(sensor.gain(known, at, heading), reference_gain(sensor, known, at, heading)) << where;
  }
  // The cases are not trivial: many cells and walls seen.
  EXPECT_EQ(scans, 3000);
  EXPECT_GT(revealed, 20000);
  EXPECT_GT(occupied_revealed, 4000);
}

TEST(SensorSweep, LongRangeInClutterEqualsTheRule) {
  // A few scans at 40 cells on 90 x 90 maps (robot inside and on the edge): long grazing rays.
  for (const double p : {0.02, 0.08}) {
    const WorldMap truth = stress_world(90, 90, p, static_cast<std::uint64_t>(p * 1000));
    const Sensor sensor(range(40.0), 1.0);
    for (const Cell at : {Cell{45, 45}, Cell{0, 30}, Cell{89, 89}, Cell{20, 70}}) {
      KnownMap known(90, 90, 1.0);
      KnownMap expected_known = known;
      Rng rng = make_rng(1, "sensor");
      Sensor s = sensor;
      const auto got = s.scan(truth, known, at, 0.0, rng);
      const std::vector<int> expected = reference_scan(sensor, truth, expected_known, at, 0.0, rng);
      ASSERT_EQ(std::vector<int>(got.begin(), got.end()), expected)
          << "p " << p << " at " << at.x << "," << at.y;
      ASSERT_EQ(sensor.gain(known, at, 0.0), reference_gain(sensor, known, at, 0.0));
    }
  }
}

TEST(SensorSweep, OneUnknownCellInAKnownDiscIsFound) {
  // Every cell in range known but one: the scan reveals exactly that one (open space, so it is
  // visible), wherever it lies in the disc (the rim included: (3, 4) is exactly 5 cells away)
  // and wherever the robot stands. With none unknown, nothing is revealed and no noise drawn.
  const WorldMap map = open_world(15, 13);
  SensorParams p = range(5.0);
  p.miss_probability = 0.5;
  Sensor sensor(p, 1.0);
  for (const Cell at : {Cell{7, 6}, Cell{0, 0}, Cell{14, 3}, Cell{2, 12}}) {
    KnownMap all(15, 13, 1.0);
    std::vector<int> in_range;
    for (int i = 0; i < all.size(); ++i) {
      const Cell c = all.cell(i);
      if ((c.x - at.x) * (c.x - at.x) + (c.y - at.y) * (c.y - at.y) <= 25) {
        all.reveal(i, false);
        in_range.push_back(i);
      }
    }
    Rng rng = make_rng(5, "sensor");
    const Rng before = rng;
    EXPECT_TRUE(sensor.scan(map, all, at, 0.0, rng).empty());
    EXPECT_EQ(rng, before);
    for (const int i : in_range) {
      if (i == map.occupied.index(at)) continue;
      KnownMap known(15, 13, 1.0);
      for (const int j : in_range) {
        if (j != i) known.reveal(j, false);
      }
      KnownMap expected_known = known;
      Rng expected_rng = rng;
      const auto got = sensor.scan(map, known, at, 0.0, rng);
      const std::vector<int> expected = reference_scan(sensor, map, expected_known, at, 0.0, expected_rng);
      ASSERT_EQ(std::vector<int>(got.begin(), got.end()), expected) << at.x << "," << at.y << " cell " << i;
      ASSERT_EQ(rng, expected_rng);
      ASSERT_NE(rng, before);  // one draw for the unknown cell
    }
  }
}

TEST(SensorSweep, OpenDiscEqualsTheRule) {
  // scan() skips the sweep when no cell in range is occupied (up to Sensor::kOpenDiscMaxCells).
  // Seeded cases where that is common: nearly open maps (a few obstacles, often at or just
  // inside the range's rim), ranges up to and past that limit, robot near edges, field of view,
  // noise, partly known maps. Each scan must reveal what the rule says, in order, with the same
  // draws.
  const std::vector<double> ranges_cells = {0.5, 1.0, 1.5, 2.0, 3.0, 4.5, 5.0, 8.0, 8.9, 9.0};
  const std::vector<double> fovs = {360.0, 270.0, 180.0, 90.0, 45.0};
  Rng rng = make_rng(2025, "sensor-open-disc-test");
  const auto below = [&](int n) {
    return static_cast<int>(uniform_below(rng, static_cast<std::uint64_t>(n)));
  };
  int open_scans = 0;
  int blocked_scans = 0;
  for (int trial = 0; trial < 800; ++trial) {
    const int width = 1 + below(24);
    const int height = 1 + below(24);
    WorldMap truth = open_world(width, height);
    const double range_cells =
        ranges_cells[static_cast<std::size_t>(below(static_cast<int>(ranges_cells.size())))];
    SensorParams p = range(range_cells);
    p.fov_deg = below(2) == 0 ? 360.0 : fovs[static_cast<std::size_t>(below(static_cast<int>(fovs.size())))];
    p.miss_probability = below(3) == 0 ? 0.3 : 0.0;
    Cell at{below(width), below(height)};
    if (below(3) == 0) at.x = below(2) == 0 ? 0 : width - 1;
    // Obstacles: none, or a few anywhere, or one on the rim of the range (blocks the fast path
    // although it hides nothing but itself).
    const int kind = below(3);
    if (kind == 1) {
      for (int k = below(4); k >= 0; --k) truth.occupied[below(truth.occupied.size())] = 1;
    } else if (kind == 2) {
      const auto r = static_cast<int>(std::floor(range_cells));
      const Cell rim{at.x + (below(2) == 0 ? r : -r), at.y};
      if (truth.occupied.in_bounds(rim)) truth.occupied.at(rim) = 1;
    }
    truth.occupied.at(at) = 0;
    bool open = true;
    for (int i = 0; i < truth.occupied.size(); ++i) {
      const Cell c = truth.occupied.cell(i);
      const double d2 = (c.x - at.x) * (c.x - at.x) + (c.y - at.y) * (c.y - at.y);
      if (truth.occupied[i] != 0 && d2 <= range_cells * range_cells) open = false;
    }
    ++(open && range_cells < Sensor::kOpenDiscMaxCells + 1 ? open_scans : blocked_scans);
    const double heading = below(2) == 0 ? heading_angle(below(8)) : (2.0 * uniform01(rng) - 1.0) * M_PI;
    KnownMap known(width, height, 1.0);
    if (below(2) == 0) {
      for (int i = 0; i < known.size(); ++i) {
        if (uniform01(rng) < 0.3) known.reveal(i, !truth.is_free(i));
      }
    }
    Sensor sensor(p, 1.0);
    KnownMap expected_known = known;
    Rng scan_rng = make_rng(static_cast<std::uint64_t>(trial), "sensor");
    Rng expected_rng = scan_rng;
    const auto got = sensor.scan(truth, known, at, heading, scan_rng);
    const std::vector<int> expected =
        reference_scan(sensor, truth, expected_known, at, heading, expected_rng);
    const std::string where = "trial " + std::to_string(trial) + ": " + std::to_string(width) + "x" +
                              std::to_string(height) + " at " + std::to_string(at.x) + "," +
                              std::to_string(at.y) + " range " + std::to_string(range_cells) + " fov " +
                              std::to_string(p.fov_deg) + " heading " + std::to_string(heading);
    ASSERT_EQ(std::vector<int>(got.begin(), got.end()), expected) << where;
    ASSERT_EQ(known, expected_known) << where;
    ASSERT_EQ(scan_rng, expected_rng) << where;
  }
  // Both paths are exercised.
  EXPECT_GT(open_scans, 300);
  EXPECT_GT(blocked_scans, 150);
}

TEST(SensorSweep, RangeAtTheSupportedMaximum) {
  // 2000 cells is the documented maximum (sensor.hpp); more is refused.
  EXPECT_THROW(Sensor(range(2001.0), 1.0), std::invalid_argument);
  // A long range on a small map: the cells of the map, nothing else.
  const WorldMap map = open_world(30, 20);
  EXPECT_EQ(scan_fresh(map, range(500.0), Cell{3, 17}).revealed.size(), 600U);
}

// --- The sight table: what each cell sees, swept once and kept (Sensor::sight_table) ---

TEST(SightTable, ScansWithTheTableEqualTheRule) {
  // Seeded cases as in EqualsTheRuleTargetByTarget. Each map gets one table. A first scan fills
  // the robot's row, a second reads it, and a scan from that row on another partly known map
  // (a row holds what the cell sees, not what is known) reveals what the rule says, with the
  // same noise draws.
  const std::vector<double> ranges_cells = {1.0, 1.5, 2.0, 3.0, 5.0, 5.5, 7.0, 9.9, 12.5, 20.0};
  const std::vector<double> fovs = {360.0, 270.0, 120.0, 45.0};
  Rng rng = make_rng(2026, "sight-table-test");
  const auto below = [&](int n) {
    return static_cast<int>(uniform_below(rng, static_cast<std::uint64_t>(n)));
  };
  int read_rows = 0;
  int revealed = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const bool tiny = below(5) == 0;
    const int width = tiny ? 1 + below(8) : 20 + below(30);
    const int height = tiny ? 1 + below(8) : 20 + below(30);
    const double u = uniform01(rng);
    WorldMap truth =
        stress_world(width, height, 0.05 + 0.55 * u * u, static_cast<std::uint64_t>(trial) + 7000);
    const bool rounding = below(2) == 0;
    truth.resolution_m = rounding ? 0.3 : 1.0;
    const double range_cells =
        ranges_cells[static_cast<std::size_t>(below(static_cast<int>(ranges_cells.size())))];
    SensorParams p;
    p.range_m = rounding ? range_cells * 0.3 : range_cells;
    p.fov_deg = below(2) == 0 ? 360.0 : fovs[static_cast<std::size_t>(below(static_cast<int>(fovs.size())))];
    p.miss_probability = below(3) == 0 ? 0.3 : 0.0;
    Sensor sensor(p, truth.resolution_m);
    const std::unique_ptr<SightTable> table = sensor.sight_table(truth);
    ASSERT_NE(table, nullptr);
    const Cell at{below(width), below(height)};
    const int at_index = truth.occupied.index(at);
    const auto partly_known = [&] {
      KnownMap known(width, height, truth.resolution_m);
      const double share = below(2) == 0 ? 0.0 : 0.7 * uniform01(rng);
      for (int i = 0; i < known.size(); ++i) {
        if (uniform01(rng) < share) known.reveal(i, !truth.is_free(i));
      }
      return known;
    };
    const std::string where = "trial " + std::to_string(trial) + " at " + std::to_string(at.x) + "," +
                              std::to_string(at.y) + " range " + std::to_string(range_cells) + " fov " +
                              std::to_string(p.fov_deg);
    for (int map = 0; map < 2; ++map) {
      const double heading = (2.0 * uniform01(rng) - 1.0) * M_PI;
      KnownMap known = partly_known();
      KnownMap expected_known = known;
      Rng scan_rng = make_rng(static_cast<std::uint64_t>(trial * 2 + map), "sensor");
      Rng expected_rng = scan_rng;
      for (int again = 0; again < 2; ++again) {
        const bool held = table->filled(at_index);
        read_rows += held ? 1 : 0;
        const auto got = sensor.scan(truth, known, at, heading, scan_rng, nullptr, table.get());
        const std::vector<int> expected =
            reference_scan(sensor, truth, expected_known, at, heading, expected_rng);
        ASSERT_EQ(std::vector<int>(got.begin(), got.end()), expected)
            << where << " map " << map << " scan " << again;
        ASSERT_EQ(known, expected_known) << where;
        ASSERT_EQ(scan_rng, expected_rng) << where;
        if (!expected.empty()) {
          ASSERT_TRUE(table->filled(at_index)) << where;
        }
        revealed += static_cast<int>(expected.size());
      }
    }
  }
  EXPECT_GT(read_rows, 600);  // most scans after the first read the row
  EXPECT_GT(revealed, 20000);
}

TEST(SightTable, ThreadsFillingOneTableRevealWhatTheRuleSays) {
  // Two threads scan every cell of one street grid with one table, each on its own known map,
  // so both fill rows and read rows the other filled (or sweep for themselves while it fills).
  const WorldMap truth = load_map_spec("manhattan:w=60,h=60,seed=2");
  const Sensor sensor(range(6.0), truth.resolution_m);
  const std::unique_ptr<SightTable> table = sensor.sight_table(truth);
  ASSERT_NE(table, nullptr);
  std::vector<int> order;
  for (int i = 0; i < truth.occupied.size(); ++i) {
    if (truth.is_free(i)) order.push_back(i);
  }
  std::vector<std::vector<int>> got(2);
  const auto run = [&](int thread) {
    Sensor own = sensor;
    KnownMap known(truth.width(), truth.height(), truth.resolution_m);
    Rng rng = make_rng(1, "sensor");
    for (std::size_t k = 0; k < order.size(); ++k) {
      const int i = order[thread == 0 ? k : order.size() - 1 - k];
      for (const int c : own.scan(truth, known, truth.occupied.cell(i), 0.0, rng, nullptr, table.get()))
        got[static_cast<std::size_t>(thread)].push_back(c);
    }
  };
  std::thread other(run, 1);
  run(0);
  other.join();
  for (int thread = 0; thread < 2; ++thread) {
    KnownMap known(truth.width(), truth.height(), truth.resolution_m);
    Rng rng = make_rng(1, "sensor");
    std::vector<int> expected;
    for (std::size_t k = 0; k < order.size(); ++k) {
      const int i = order[thread == 0 ? k : order.size() - 1 - k];
      for (const int c : reference_scan(sensor, truth, known, truth.occupied.cell(i), 0.0, rng))
        expected.push_back(c);
    }
    EXPECT_EQ(got[static_cast<std::size_t>(thread)], expected) << "thread " << thread;
  }
}

TEST(SightTable, OnlyForTheMapAndRangeItWasMadeFor) {
  const WorldMap truth = open_world(20, 10);
  Sensor sensor(range(3.0), 1.0);
  const std::unique_ptr<SightTable> table = sensor.sight_table(truth);
  ASSERT_NE(table, nullptr);
  EXPECT_EQ(table->bytes(), 200U * (1 * 8 + 1));  // 29 offsets in range: one word per cell
  Rng rng = make_rng(1, "sensor");
  KnownMap wide(21, 10, 1.0);
  EXPECT_THROW((void)sensor.scan(open_world(21, 10), wide, Cell{1, 1}, 0.0, rng, nullptr, table.get()),
               std::invalid_argument);
  KnownMap known(20, 10, 1.0);
  const WorldMap same_size = open_world(20, 10);  // another map object of the same size
  EXPECT_THROW((void)sensor.scan(same_size, known, Cell{1, 1}, 0.0, rng, nullptr, table.get()),
               std::invalid_argument);
  Sensor longer(range(4.0), 1.0);
  EXPECT_THROW((void)longer.scan(truth, known, Cell{1, 1}, 0.0, rng, nullptr, table.get()),
               std::invalid_argument);
  // A sensor of the same range made apart shares the table.
  Sensor same(range(3.0), 1.0);
  EXPECT_EQ(same.scan(truth, known, Cell{1, 1}, 0.0, rng, nullptr, table.get()).size(), 18U);
  EXPECT_TRUE(table->filled(truth.occupied.index(Cell{1, 1})));
  // A scan with nothing unknown in range (explored space) leaves its cell's row empty.
  KnownMap explored(20, 10, 1.0);
  for (int i = 0; i < explored.size(); ++i) explored.reveal(i, false);
  EXPECT_TRUE(same.scan(truth, explored, Cell{2, 2}, 0.0, rng, nullptr, table.get()).empty());
  EXPECT_FALSE(table->filled(truth.occupied.index(Cell{2, 2})));
}

TEST(SightTable, NoneForBeamsOrBeyondTheSizeLimit) {
  SensorParams beams = range(5.0);
  beams.model = SensorModel::Beams;
  EXPECT_EQ(Sensor(beams, 1.0).sight_table(open_world(10, 10)), nullptr);
  EXPECT_EQ(Sensor().sight_table(open_world(10, 10)), nullptr);
  // 100 cells of range: 31,417 offsets, 491 words (3,929 bytes) a cell; 68,000 cells pass the
  // 256 MiB limit, 69,000 do not (nothing is allocated for them).
  const Sensor wide(range(100.0), 1.0);
  EXPECT_NE(wide.sight_table(open_world(340, 200)), nullptr);
  EXPECT_EQ(wide.sight_table(open_world(345, 200)), nullptr);
}

}  // namespace test_sensor
}  // namespace fsweep
