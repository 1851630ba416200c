// The beam lidar model of Sensor (sensor.hpp, "Beam model"): beam directions, the traversal
// with its corner and range rules, scan order, noise, gain() and visible() against scan(), and
// the parameters.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "world/ascii_world.hpp"
#include "world/beam_lidar.hpp"
#include "world/scan_fixture.hpp"
#include "world/sensor.hpp"

namespace fsweep {
namespace test_beam_lidar {  // not anonymous: unity builds put it beside other test files' helpers

using test::ascii_world;
using test::known;
using test::open_world;
using test::random_world;
using test::scan_fresh;

SensorParams beams(int n, double fov_deg, double range_m) {
  SensorParams p;
  p.model = SensorModel::Beams;
  p.beams = n;
  p.fov_deg = fov_deg;
  p.range_m = range_m;
  return p;
}

/// One noiseless beam along the heading (a single beam points along it for any fov < 360).
SensorParams one_beam(double range_m) { return beams(1, 10.0, range_m); }

/// Indices of cells, for comparing with scan() results.
std::vector<int> indices(const WorldMap& map, const std::vector<Cell>& cells) {
  std::vector<int> out;
  for (const Cell c : cells) out.push_back(map.occupied.index(c));
  return out;
}

// --- Beam directions ---

TEST(BeamLidar, LimitedFieldOfViewPutsFirstAndLastBeamAtItsEdges) {
  const BeamLidar lidar(5, 270.0, 100.0);
  ASSERT_EQ(lidar.beams(), 5);
  const double half = 135.0 * M_PI / 180.0;
  EXPECT_DOUBLE_EQ(lidar.offset_rad(0), -half);
  EXPECT_DOUBLE_EQ(lidar.offset_rad(1), -half / 2);
  EXPECT_EQ(lidar.offset_rad(2), 0.0);  // the middle beam of an odd count lies on the heading
  EXPECT_DOUBLE_EQ(lidar.offset_rad(4), half);
  EXPECT_EQ(BeamLidar(1, 90.0, 100.0).offset_rad(0), 0.0);
}

TEST(BeamLidar, FullCircleSpreadsEvenlyWithoutRepeatingTheFirstBeam) {
  const BeamLidar lidar(4, 360.0, 100.0);
  // theta_i = 2 pi (i - 2) / 4: -pi, -pi/2, 0, pi/2.
  EXPECT_DOUBLE_EQ(lidar.offset_rad(0), -M_PI);
  EXPECT_DOUBLE_EQ(lidar.offset_rad(1), -M_PI / 2);
  EXPECT_EQ(lidar.offset_rad(2), 0.0);
  EXPECT_DOUBLE_EQ(lidar.offset_rad(3), M_PI / 2);
  const BeamLidar odd(3, 360.0, 100.0);  // -120, 0, 120 degrees
  EXPECT_DOUBLE_EQ(odd.offset_rad(0), -2.0 * M_PI / 3);
  EXPECT_EQ(odd.offset_rad(1), 0.0);
  EXPECT_DOUBLE_EQ(odd.offset_rad(2), 2.0 * M_PI / 3);
}

TEST(BeamLidar, FourAxisBeamsSeeACross) {
  // 4 beams over 360 degrees: east, south, west, north; range 5 in open space: the robot's cell
  // and 5 cells along each axis, and nothing between the beams (e.g. the diagonal neighbour).
  const WorldMap map = open_world(21, 21);
  const Cell at{10, 10};
  const auto r = scan_fresh(map, beams(4, 360.0, 5.0), at);
  EXPECT_EQ(r.revealed.size(), 21U);
  for (int k = 1; k <= 5; ++k) {
    EXPECT_TRUE(known(r, Cell{10 + k, 10}));
    EXPECT_TRUE(known(r, Cell{10 - k, 10}));
    EXPECT_TRUE(known(r, Cell{10, 10 + k}));
    EXPECT_TRUE(known(r, Cell{10, 10 - k}));
  }
  EXPECT_FALSE(known(r, Cell{11, 11}));
  EXPECT_FALSE(known(r, Cell{16, 10}));
  // Scan order: beam 0 (west, -pi) first, along the beam outward, then north, east, south.
  EXPECT_EQ(std::vector<int>(r.revealed.begin(), r.revealed.begin() + 3),
            indices(map, {at, Cell{9, 10}, Cell{8, 10}}));
  EXPECT_EQ(r.revealed[6], map.occupied.index(Cell{10, 9}));
}

// --- Traversal, obstacles, corners, range ---

TEST(BeamLidar, SingleBeamAlongXStopsAtTheWallAndRevealsIt) {
  const WorldMap map = ascii_world({
      "......",
      "S...#.",
      "......",
  });
  const auto r = scan_fresh(map, one_beam(10.0), map.start);
  EXPECT_EQ(r.revealed, indices(map, {Cell{0, 1}, Cell{1, 1}, Cell{2, 1}, Cell{3, 1}, Cell{4, 1}}));
  EXPECT_EQ(r.known.state(Cell{4, 1}), CellState::Occupied);
  EXPECT_EQ(r.known.state(Cell{5, 1}), CellState::Unknown);  // behind the wall
  EXPECT_EQ(r.known.state(Cell{1, 0}), CellState::Unknown);  // beside the beam
}

TEST(BeamLidar, BeamEndsAtTheMapEdge) {
  const WorldMap map = ascii_world({"S..."});
  EXPECT_EQ(scan_fresh(map, one_beam(10.0), map.start).revealed.size(), 4U);
  // Facing west, the robot on the left edge sees only its own cell.
  EXPECT_EQ(scan_fresh(map, one_beam(10.0), map.start, M_PI).revealed, indices(map, {map.start}));
}

TEST(BeamLidar, CornerBetweenTwoOccupiedCellsBlocksAndRevealsBoth) {
  // A 45 degree beam from (0, 0) passes the corner (1/2, 1/2) between the walls (1, 0) and
  // (0, 1): blocked there, both walls seen (the one across the vertical side first), (1, 1) not.
  const WorldMap map = ascii_world({
      "S#..",
      "#...",
      "....",
      "....",
  });
  const auto r = scan_fresh(map, one_beam(10.0), map.start, heading_angle(1));
  EXPECT_EQ(r.revealed, indices(map, {Cell{0, 0}, Cell{1, 0}, Cell{0, 1}}));
  EXPECT_EQ(r.known.state(Cell{1, 1}), CellState::Unknown);
}

TEST(BeamLidar, CornerWithOneFreeSideLetsTheBeamThrough) {
  // The wall (1, 0) is touched at the corner only: not seen; the beam runs on along the
  // diagonal to the map's corner.
  const WorldMap map = ascii_world({
      "S#..",
      "....",
      "....",
      "....",
  });
  const auto r = scan_fresh(map, one_beam(10.0), map.start, heading_angle(1));
  EXPECT_EQ(r.revealed, indices(map, {Cell{0, 0}, Cell{1, 1}, Cell{2, 2}, Cell{3, 3}}));
  EXPECT_EQ(r.known.state(Cell{1, 0}), CellState::Unknown);
}

TEST(BeamLidar, RangeBoundaryIsInclusiveCentreToCentre) {
  const WorldMap row = open_world(12, 1);
  // Range 5 along +x: cells 0..5 (the centre of cell 5 is exactly 5 away).
  EXPECT_EQ(scan_fresh(row, one_beam(5.0), Cell{0, 0}).revealed.size(), 6U);
  // 0.9 m at 0.3 m per cell is 3 cells although 0.9 / 0.3 is not exactly 3 in floating point.
  WorldMap fine = row;
  fine.resolution_m = 0.3;
  EXPECT_EQ(scan_fresh(fine, one_beam(0.9), Cell{0, 0}).revealed.size(), 4U);
  // Along the diagonal with range 5: (3, 3) is 4.24 away, (4, 4) 5.66: entered at
  // t = 3.5 sqrt(2) = 4.95 <= 5 but out of range, so not seen (the grid model's disc).
  const WorldMap square = open_world(8, 8);
  const auto r = scan_fresh(square, one_beam(5.0), Cell{0, 0}, heading_angle(1));
  EXPECT_EQ(r.revealed, indices(square, {Cell{0, 0}, Cell{1, 1}, Cell{2, 2}, Cell{3, 3}}));
}

TEST(BeamLidar, BeamsMissCellsBetweenRaysAtLongRange) {
  // 360 beams, one per degree, range 100 in open space. A cell at distance d subtends at least
  // 1/d radians, more than the 1 degree spacing while d < 57.3: every cell within 50 is seen;
  // near the range the beams are 1.7 cells apart and cells between them are not.
  const WorldMap map = open_world(201, 201);
  const Cell at{100, 100};
  const auto r = scan_fresh(map, beams(360, 360.0, 100.0), at);
  int missed_near = 0;
  int missed_far = 0;
  for (int y = 0; y < 201; ++y) {
    for (int x = 0; x < 201; ++x) {
      const double d = std::hypot(x - at.x, y - at.y);
      if (d <= 50.0 && !known(r, Cell{x, y})) ++missed_near;
      if (d >= 90.0 && d <= 100.0 && !known(r, Cell{x, y})) ++missed_far;
      if (d > 100.0) {
        EXPECT_FALSE(known(r, Cell{x, y}));
      }
    }
  }
  EXPECT_EQ(missed_near, 0);
  EXPECT_GT(missed_far, 100);
  EXPECT_LT(r.revealed.size(), scan_fresh(map, SensorParams{.range_m = 100.0}, at).revealed.size());
}

TEST(BeamLidar, FullCircleSeesBehindTheRobotAndTwoSeventyDoesNot) {
  // Facing east (heading 0), 270 degrees leave the 90 degrees behind unseen: the extreme beams at
  // +-135 degrees pass the corners of the cell west of the robot without entering it.
  const WorldMap map = open_world(31, 31);
  const Cell at{15, 15};
  const auto full = scan_fresh(map, beams(1440, 360.0, 10.0), at);
  const auto fan = scan_fresh(map, beams(1080, 270.0, 10.0), at);
  for (int k = 1; k <= 10; ++k) {
    EXPECT_TRUE(known(full, Cell{15 - k, 15})) << k;
    EXPECT_FALSE(known(fan, Cell{15 - k, 15})) << k;
    EXPECT_TRUE(known(fan, Cell{15 + k, 15})) << k;
  }
  EXPECT_TRUE(known(fan, Cell{14, 14}));  // on the -135 degree beam
  EXPECT_LT(fan.revealed.size(), full.revealed.size());
  // Facing west the fan sees that side instead.
  EXPECT_TRUE(known(scan_fresh(map, beams(1080, 270.0, 10.0), at, M_PI), Cell{10, 15}));
}

TEST(BeamLidar, ScanRevealsEachCellOnceInBeamOrder) {
  const Cell at{20, 20};
  const WorldMap map = random_world(41, 41, 0.2, 5);
  const auto r = scan_fresh(map, beams(720, 360.0, 15.0), at);
  EXPECT_EQ(std::set<int>(r.revealed.begin(), r.revealed.end()).size(), r.revealed.size());
  EXPECT_EQ(r.revealed.front(), map.occupied.index(at));
  EXPECT_EQ(static_cast<int>(r.revealed.size()), r.known.known_count());
  // A second scan from the same place reveals nothing.
  Sensor sensor(beams(720, 360.0, 15.0), 1.0);
  KnownMap k = r.known;
  Rng rng = make_rng(1, "sensor");
  EXPECT_TRUE(sensor.scan(map, k, at, 0.0, rng).empty());
}

// --- The grid model is unchanged ---

TEST(BeamLidar, GridModelIgnoresTheBeamKeys) {
  const Cell at{20, 20};
  const WorldMap map = random_world(41, 41, 0.25, 3);
  SensorParams grid;
  grid.range_m = 12.0;
  grid.fov_deg = 200.0;
  SensorParams grid_with_beams = grid;
  grid_with_beams.beams = 7;
  for (const double heading : {0.0, 1.0, heading_angle(5)}) {
    const auto a = scan_fresh(map, grid, at, heading);
    const auto b = scan_fresh(map, grid_with_beams, at, heading);
    EXPECT_EQ(a.revealed, b.revealed);
    EXPECT_EQ(a.known, b.known);
  }
  // The grid model sees cells between the beams' directions: more than 8 beams do.
  EXPECT_GT(scan_fresh(map, grid, at).revealed.size(),
            scan_fresh(map, beams(8, 200.0, 12.0), at).revealed.size());
}

// --- Noise ---

TEST(BeamLidar, NoiseDrawsOncePerUnknownCellInScanOrder) {
  // With miss probability p the revealed cells are those of the noiseless scan (the robot's
  // cell always) whose draw, one per cell in the noiseless scan's order, is >= p; cells that
  // several beams cross are not drawn again, so the stream advances exactly once per cell.
  const Cell at{25, 25};
  const WorldMap map = random_world(51, 51, 0.15, 8);
  SensorParams noisy = beams(1000, 360.0, 20.0);
  noisy.miss_probability = 0.4;
  const auto clean = scan_fresh(map, beams(1000, 360.0, 20.0), at);
  Sensor sensor(noisy, 1.0);
  KnownMap k(map.width(), map.height(), 1.0);
  Rng rng = make_rng(7, "sensor");
  const auto span = sensor.scan(map, k, at, 0.0, rng);
  const std::vector<int> got(span.begin(), span.end());

  Rng expected_rng = make_rng(7, "sensor");
  std::vector<int> expected{clean.revealed.front()};
  for (std::size_t i = 1; i < clean.revealed.size(); ++i) {
    if (uniform01(expected_rng) >= 0.4) expected.push_back(clean.revealed[i]);
  }
  EXPECT_EQ(got, expected);
  EXPECT_EQ(rng(), expected_rng());  // the same number of draws
  EXPECT_LT(got.size(), clean.revealed.size());

  // Deterministic: the same seed gives the same cells, another seed others.
  EXPECT_EQ(scan_fresh(map, noisy, at, 0.0, 3).revealed, scan_fresh(map, noisy, at, 0.0, 3).revealed);
  EXPECT_NE(scan_fresh(map, noisy, at, 0.0, 3).revealed, scan_fresh(map, noisy, at, 0.0, 4).revealed);
}

// --- gain() and visible() agree with scan() ---

TEST(BeamLidar, GainAgreesWithScanWhenTheWallsAreKnown) {
  // Known map: every wall of the truth known, some free cells known. The beams then stop where
  // they stop on the truth: gain's unknown cells are the cells a scan reveals, and all the
  // cells it counts are those a scan into an empty map reveals.
  for (const std::uint64_t seed : {1U, 2U, 3U}) {
    const Cell at{30, 30};
    const WorldMap map = random_world(61, 61, 0.2, seed);
    KnownMap k(map.width(), map.height(), 1.0);
    Rng pick = make_rng(seed, "known");
    for (int i = 0; i < map.occupied.size(); ++i) {
      if (map.occupied[i] != 0 || uniform01(pick) < 0.3) k.reveal(i, map.occupied[i] != 0);
    }
    for (const SensorParams& p : {beams(181, 180.0, 8.0), beams(1080, 270.0, 25.0), beams(7, 360.0, 40.0)}) {
      for (const double heading : {0.0, 2.0, heading_angle(3)}) {
        const Sensor sensor(p, 1.0);
        const ScanCounts counts = sensor.gain(k, at, heading);
        KnownMap after = k;
        Sensor scanner(p, 1.0);
        Rng rng = make_rng(1, "sensor");
        EXPECT_EQ(counts.unknown, static_cast<int>(scanner.scan(map, after, at, heading, rng).size()));
        EXPECT_EQ(counts.known + counts.unknown,
                  static_cast<int>(scan_fresh(map, p, at, heading).revealed.size()));
        EXPECT_EQ(sensor.gain(k, at, heading), counts);  // the scratch is left clean
      }
    }
  }
}

TEST(BeamLidar, GainTreatsUnknownCellsAsTransparent) {
  // Known: the robot's cell; a known wall 3 cells east. A beam east counts the 2 unknown cells
  // before the wall and the wall (known), and stops.
  KnownMap k = test::ascii_known({".??#??"});
  const Sensor sensor(one_beam(10.0), 1.0);
  EXPECT_EQ(sensor.gain(k, Cell{0, 0}, 0.0), (ScanCounts{2, 2}));
  EXPECT_EQ(sensor.gain(k, Cell{-1, 0}, 0.0), (ScanCounts{}));  // off the map
}

TEST(BeamLidar, VisibleAgreesWithScan) {
  for (const std::uint64_t seed : {11U, 12U}) {
    const Cell at{15, 15};
    const WorldMap map = random_world(31, 31, 0.2, seed);
    for (const SensorParams& p : {beams(1, 10.0, 12.0), beams(4, 360.0, 12.0), beams(181, 180.0, 12.0),
                                  beams(1080, 270.0, 12.0), beams(90, 360.0, 14.5)}) {
      const Sensor sensor(p, 1.0);
      for (const double heading : {0.0, 0.3, heading_angle(1), heading_angle(4), heading_angle(6)}) {
        const auto r = scan_fresh(map, p, at, heading);
        for (int y = 0; y < 31; ++y) {
          for (int x = 0; x < 31; ++x) {
            EXPECT_EQ(sensor.visible(map, at, Cell{x, y}, heading), known(r, Cell{x, y}))
                << p.beams << " beams, heading " << heading << ", cell " << x << "," << y;
          }
        }
      }
    }
  }
}

// --- Parameters ---

/// The message of the ConfigError thrown for `j`, or "" when none is thrown.
std::string error_of(const nlohmann::json& j) { return test::sensor_params_error(j, "/robot/sensor"); }

TEST(BeamLidarParams, ModelAndBeamsAreRead) {
  const SensorParams p =
      sensor_params_from_json({{"model", "beams"}, {"beams", 1080}, {"fov_deg", 270}}, "s");
  EXPECT_EQ(p.model, SensorModel::Beams);
  EXPECT_EQ(p.beams, 1080);
  EXPECT_EQ(sensor_params_from_json(nlohmann::json::object(), "s").model, SensorModel::Grid);
}

TEST(BeamLidarParams, BadModelOrBeamCountNamesTheKeyAndWhatIsAllowed) {
  const std::string model = error_of({{"model", "foo"}});
  EXPECT_NE(model.find("/robot/sensor/model"), std::string::npos) << model;
  EXPECT_NE(model.find("foo"), std::string::npos) << model;
  EXPECT_NE(model.find("\"grid\""), std::string::npos) << model;
  EXPECT_NE(model.find("\"beams\""), std::string::npos) << model;
  const std::string zero = error_of({{"beams", 0}});
  EXPECT_NE(zero.find("/robot/sensor/beams"), std::string::npos) << zero;
  EXPECT_NE(zero.find("[1, 100000]"), std::string::npos) << zero;
  EXPECT_NE(error_of({{"beams", 100001}}), "");
  EXPECT_NE(error_of({{"beams", 2.5}}), "");
  EXPECT_EQ(error_of({{"beams", 100000}}), "");
  EXPECT_THROW(Sensor(beams(0, 360.0, 5.0), 1.0), std::invalid_argument);
}

TEST(BeamLidarParams, DefaultsAreLeftOutOfTheRecordedJson) {
  // Run keys hash this JSON: a grid sensor's must stay what it was before the beam keys.
  EXPECT_EQ(nlohmann::json(SensorParams{}),
            (nlohmann::json{{"range_m", 10.0}, {"fov_deg", 360.0}, {"miss_probability", 0.0}}));
  const nlohmann::json j = beams(181, 180.0, 8.0);
  EXPECT_EQ(j.at("model").get<std::string>(), "beams");
  EXPECT_EQ(j.at("beams").get<int>(), 181);
  EXPECT_EQ(sensor_params_from_json(j, "s"), beams(181, 180.0, 8.0));
  SensorParams grid;
  grid.beams = 90;
  EXPECT_EQ(nlohmann::json(grid).at("beams").get<int>(), 90);  // a non-default value is recorded
  EXPECT_FALSE(nlohmann::json(grid).contains("model"));
}

}  // namespace test_beam_lidar
}  // namespace fsweep
