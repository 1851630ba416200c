// HouseExpo floor plans (load_houseexpo) and OpenCV's polygon fill (fill_polygon): hand-computed
// cell counts, OpenCV's own output on small polygons and on the two shipped plans, errors.
#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "core/config_error.hpp"
#include "core/random.hpp"
#include "world/map_loaders.hpp"
#include "world/map_spec.hpp"
#include "world/polygon_fill.hpp"
#include "world/world_map.hpp"

namespace fsweep {
namespace test_houseexpo {  // not anonymous: unity builds put it beside other test files' helpers

const std::string kPlans = std::string(FSWEEP_TEST_DATA) + "/houseexpo/";

std::string write_plan(const std::string& name, const std::string& content) {
  const std::string path = testing::TempDir() + "fsweep_houseexpo_" + name;
  std::ofstream(path, std::ios::binary) << content;
  return path;
}

/// Rows of a grid: `x` for cells equal to `value`, `.` otherwise.
std::vector<std::string> rows_of(const Grid<std::uint8_t>& grid, std::uint8_t value) {
  std::vector<std::string> rows;
  for (int y = 0; y < grid.height(); ++y) {
    std::string row;
    for (int x = 0; x < grid.width(); ++x) row += grid.at(Cell{x, y}) == value ? 'x' : '.';
    rows.push_back(row);
  }
  return rows;
}

/// FNV-1a 64 of the free mask (1 free, 0 wall, row-major), as computed from OpenCV's image.
std::uint64_t free_mask_hash(const WorldMap& map) {
  std::string bytes(static_cast<std::size_t>(map.occupied.size()), '\0');
  for (int i = 0; i < map.occupied.size(); ++i) bytes[static_cast<std::size_t>(i)] = map.is_free(i) ? 1 : 0;
  return fnv1a(bytes);
}

void expect_config_error(const std::function<void()>& fn, std::initializer_list<std::string_view> parts) {
  try {
    fn();
  } catch (const ConfigError& e) {
    const std::string message = e.what();
    for (const auto part : parts) EXPECT_NE(message.find(part), std::string::npos) << message;
    return;
  }
  ADD_FAILURE() << "expected a ConfigError";
}

TEST(PolygonFill, MatchesOpenCvOnSmallPolygons) {
  // Expected rows are cv2.drawContours(img, [verts], 0, 255, -1) of OpenCV 4.6 (Debian's
  // python3-opencv) on a grid just holding the vertices. Each case once broke a candidate rule:
  // rounding both crossings to nearest (first), floor on the left (second, third), and the
  // outline's error term (third); the bow tie checks even-odd pairing.
  struct Case {
    std::vector<Cell> vertices;
    std::vector<std::string> rows;
  };
  const std::vector<Case> cases{
      {{{2, 0}, {0, 0}, {5, 4}}, {"xxx...", ".xxx..", "..xx..", "....x.", ".....x"}},
      {{{5, 3}, {2, 5}, {6, 1}}, {".......", "......x", ".....x.", "....xx.", "...xx..", "..x...."}},
      {{{5, 0}, {0, 0}, {10, 8}},
       {"xxxxxx.....", ".xxxxxx....", "..xxxxx....", "....xxxx...", ".....xxx...", "......xxx..",
        ".......xxx.", ".........x.", "..........x"}},
      {{{0, 0}, {6, 6}, {6, 0}, {0, 6}},
       {"x.....x", "xx...xx", "xxx.xxx", "xxxxxxx", "xxx.xxx", "xx...xx", "x.....x"}},
  };
  for (const Case& c : cases) {
    Grid<std::uint8_t> grid(static_cast<int>(c.rows.front().size()), static_cast<int>(c.rows.size()), 0);
    fill_polygon(grid, c.vertices, 1);
    EXPECT_EQ(rows_of(grid, 1), c.rows);
  }
}

TEST(PolygonFill, ClipsToTheGrid) {
  Grid<std::uint8_t> grid(3, 3, 0);
  fill_polygon(grid, {{-2, -2}, {5, -2}, {5, 5}, {-2, 5}}, 1);
  EXPECT_EQ(rows_of(grid, 1), (std::vector<std::string>{"xxx", "xxx", "xxx"}));
}

TEST(HouseExpo, HandComputedLShape) {
  // (0,0) (2,0) (2,1) (1,1) (1,2) (0,2) m at 0.5 m: cells (0,0) (4,0) (4,2) (2,2) (2,4) (0,4).
  // Rows 0..2 hold x = 0..4 (15 cells), rows 3..4 x = 0..2 (6): 21 free cells, in a 5x5 box plus
  // a one-cell wall border: 7x7.
  const std::string path =
      write_plan("l_shape.json", R"({"verts": [[0, 0], [2, 0], [2, 1], [1, 1], [1, 2], [0, 2]], "id": "l"})");
  const WorldMap map = load_houseexpo(path, 0.5);
  EXPECT_EQ(map.width(), 7);
  EXPECT_EQ(map.height(), 7);
  EXPECT_EQ(map.free_count(), 21);
  EXPECT_DOUBLE_EQ(map.resolution_m, 0.5);
  EXPECT_EQ(rows_of(map.occupied, 0), (std::vector<std::string>{".......", ".xxxxx.", ".xxxxx.", ".xxxxx.",
                                                                ".xxx...", ".xxx...", "......."}));
  // One region of 21 cells; sums x 3 * 15 + 2 * 6 = 57, y 5 * 6 + 3 * 9 = 57: centroid
  // (2.71, 2.71), nearest cell (3, 3).
  EXPECT_EQ(map.start, (Cell{3, 3}));
}

TEST(HouseExpo, HandComputedTriangleAndOffset) {
  // (1,1) (5,1) (1,5) m at 1 m, shifted so the smallest x and y are 0: lattice points with
  // x + y <= 4: 5 + 4 + 3 + 2 + 1 = 15 cells, 5x5 box, 7x7 with the border.
  const std::string path = write_plan("triangle.json", R"({"verts": [[1, 1], [5, 1], [1, 5]]})");
  const WorldMap map = load_houseexpo(path, 1.0);
  EXPECT_EQ(map.width(), 7);
  EXPECT_EQ(map.free_count(), 15);
  EXPECT_TRUE(map.is_free(Cell{5, 1}));
  EXPECT_TRUE(map.is_free(Cell{1, 5}));
  EXPECT_FALSE(map.is_free(Cell{5, 2}));
}

TEST(HouseExpo, VerticesAreTruncatedAsPseudoSlamDoes) {
  // 1.16 * 25 is 28.999999999999996 in doubles, so numpy's astype(int) gives 28: columns 0..28
  // (29), rows 0..25 (26), 754 free cells in a 31x28 grid. Rounding would give 30 columns.
  const std::string path =
      write_plan("truncate.json", R"({"verts": [[0, 0], [1.16, 0], [1.16, 1], [0, 1]]})");
  const WorldMap map = load_houseexpo(path);  // HouseExpo's 0.04 m
  EXPECT_EQ(map.width(), 31);
  EXPECT_EQ(map.height(), 28);
  EXPECT_EQ(map.free_count(), 29 * 26);
}

TEST(HouseExpo, ShippedPlansEqualOpenCvsDrawing) {
  // Width, height, free cells and the hash of the free mask of PseudoSLAM's drawing
  // (cv2.drawContours of the truncated vertices, OpenCV 4.6) with a one-pixel border, at 25, 20,
  // 10, 5 and 4 cells per metre.
  struct Expected {
    const char* plan;
    double res;
    int width;
    int height;
    int free;
    std::uint64_t hash;
  };
  const std::vector<Expected> expected{
      {"house_expo_room_0000.json", 0.04, 255, 205, 36625, 0x3ffa2cd7d261105cULL},
      {"house_expo_room_0000.json", 0.05, 204, 164, 23527, 0xd21d571ca906810aULL},
      {"house_expo_room_0000.json", 0.1, 103, 83, 5978, 0x92a7a29f6119e227ULL},
      {"house_expo_room_0000.json", 0.2, 53, 43, 1571, 0x1aa3406239e65bceULL},
      {"house_expo_room_0000.json", 0.25, 43, 35, 1013, 0x53279f26ff4733c0ULL},
      {"house_expo_room_1451.json", 0.04, 285, 272, 74458, 0x0c561543c78b8c7fULL},
      {"house_expo_room_1451.json", 0.05, 228, 218, 47615, 0xdecc1127a1136b06ULL},
      {"house_expo_room_1451.json", 0.1, 115, 110, 12025, 0x28579dc2da3d6a5cULL},
      {"house_expo_room_1451.json", 0.2, 59, 57, 3134, 0x38e94156bda712dbULL},
      {"house_expo_room_1451.json", 0.25, 48, 46, 2024, 0x12cb7890d4aaedfdULL},
  };
  for (const Expected& e : expected) {
    const WorldMap map = load_houseexpo(kPlans + e.plan, e.res);
    EXPECT_EQ(map.width(), e.width) << e.plan << " at " << e.res;
    EXPECT_EQ(map.height(), e.height) << e.plan << " at " << e.res;
    EXPECT_EQ(map.free_count(), e.free) << e.plan << " at " << e.res;
    EXPECT_EQ(free_mask_hash(map), e.hash) << e.plan << " at " << e.res;
  }
}

TEST(HouseExpo, IsAMapSpecWithTheDatasetsResolutionByDefault) {
  const WorldMap by_default = load_map_spec(kPlans + "house_expo_room_0000.json");
  EXPECT_DOUBLE_EQ(by_default.resolution_m, kHouseExpoResolution);
  EXPECT_EQ(by_default.width(), 255);
  const WorldMap coarse = load_map_spec(kPlans + "house_expo_room_0000.json:res=0.1,start=50;40");
  EXPECT_EQ(coarse.width(), 103);
  EXPECT_EQ(coarse.start, (Cell{50, 40}));
  expect_config_error([] { (void)load_map_spec(kPlans + "house_expo_room_0000.json:threshold=3"); },
                      {"unknown key 'threshold'", "allowed: res, start"});
}

TEST(HouseExpo, ShippedPlansStartNearestTheCentreOfTheirLargestRegion) {
  struct Expected {
    const char* plan;
    double res;
    Cell start;  // as computed by region_centre_cell(); the loop below checks it against every cell
  };
  const std::vector<Expected> expected{
      {"house_expo_room_0000.json", 0.04, Cell{134, 78}},
      {"house_expo_room_0000.json", 0.1, Cell{54, 32}},
      {"house_expo_room_1451.json", 0.04, Cell{142, 136}},
      {"house_expo_room_1451.json", 0.1, Cell{57, 54}},
  };
  for (const Expected& e : expected) {
    SCOPED_TRACE(std::string(e.plan) + " at " + std::to_string(e.res));
    const WorldMap map = load_houseexpo(kPlans + e.plan, e.res);
    EXPECT_EQ(map.start, e.start);
    ASSERT_TRUE(map.is_free(map.start));
    // In the largest region of the default motion rule (no corner cutting), and no cell of it
    // nearer its centroid; of equally near cells (within rounding) none comes earlier.
    const Grid<std::uint8_t> region = largest_free_region(map, false);
    ASSERT_EQ(region.at(map.start), 1);
    double n = 0.0;
    double sum_x = 0.0;
    double sum_y = 0.0;
    for (int i = 0; i < region.size(); ++i) {
      if (region[i] == 0) continue;
      n += 1.0;
      sum_x += region.cell(i).x;
      sum_y += region.cell(i).y;
    }
    const auto d2 = [&](Cell c) {
      const double dx = c.x - sum_x / n;
      const double dy = c.y - sum_y / n;
      return dx * dx + dy * dy;
    };
    const int start_index = region.index(map.start);
    for (int i = 0; i < region.size(); ++i) {
      if (region[i] == 0) continue;
      EXPECT_GE(d2(region.cell(i)), d2(map.start) - (i < start_index ? -1e-12 : 1e-12)) << i;
    }
    // Stable: the same map loads with the same start; an explicit start still wins.
    EXPECT_EQ(load_houseexpo(kPlans + e.plan, e.res).start, map.start);
    const std::string spec = kPlans + e.plan + ":res=" + std::to_string(e.res) +
                             ",start=" + std::to_string(map.start.x + 1) + ";" + std::to_string(map.start.y);
    if (map.is_free(Cell{map.start.x + 1, map.start.y})) {
      EXPECT_EQ(load_map_spec(spec).start, (Cell{map.start.x + 1, map.start.y}));
    }
    EXPECT_EQ(load_map_spec(kPlans + e.plan + ":res=" + std::to_string(e.res)).start, map.start);
  }
}

TEST(HouseExpo, RandomStartsAreForRunsOnly) {
  const std::string spec = kPlans + "house_expo_room_0000.json:res=0.1,start=random";
  expect_config_error([&] { (void)load_map_spec(spec); },
                      {"start \"random\" is drawn per run", "fsweep sim"});
  const RunMap run_map = load_run_map_spec(spec);
  EXPECT_TRUE(run_map.random_start);
  EXPECT_EQ(run_map.map.width(), 103);
  EXPECT_FALSE(load_run_map_spec(kPlans + "house_expo_room_0000.json:res=0.1").random_start);
}

TEST(HouseExpo, BadJsonAndNumberOverflowNameLineAndColumn) {
  const std::string not_json = write_plan("not_json_at.json", "{\"verts\":\n  [[0, 0],,");
  expect_config_error([&] { (void)load_houseexpo(not_json); },
                      {not_json + ":2:11: not a valid JSON file: syntax error"});
  // nlohmann's own message named neither the file nor the place.
  const std::string overflow = write_plan("overflow.json", "{\"verts\": [[0, 0],\n  [1e400, 0], [0, 1]]}");
  expect_config_error([&] { (void)load_houseexpo(overflow); },
                      {overflow + ":2:4: number 1e400 is out of range; allowed: numbers of magnitude below "
                                  "1.8e308 (a double)"});
}

TEST(HouseExpo, BadPlansNameTheFileAndTheJsonPath) {
  expect_config_error([] { (void)load_houseexpo(write_plan("not_json.json", "{\"verts\": [")); },
                      {"not_json.json", "not a valid JSON file"});
  expect_config_error([] { (void)load_houseexpo(write_plan("no_verts.json", R"({"id": "x"})")); },
                      {"no_verts.json", "'verts'"});
  expect_config_error([] { (void)load_houseexpo(write_plan("two.json", R"({"verts": [[0, 0], [1, 1]]})")); },
                      {"two.json: /verts", "at least 3 vertices"});
  expect_config_error(
      [] { (void)load_houseexpo(write_plan("bad_vertex.json", R"({"verts": [[0, 0], [1, 0], [1, "a"]]})")); },
      {"bad_vertex.json: /verts/2", "two numbers"});
  expect_config_error(
      [] { (void)load_houseexpo(write_plan("far.json", R"({"verts": [[0, 0], [1e300, 0], [0, 1]]})")); },
      {"far.json: /verts/1", "out of range"});
  expect_config_error(
      [] {
        (void)load_houseexpo(write_plan("huge.json", R"({"verts": [[0, 0], [1000, 0], [1000, 1000]]})"));
      },
      {"huge.json", "over the limit of 10^8 cells", "coarser res"});
  expect_config_error([] { (void)load_houseexpo(write_plan("deep.json", std::string(100000, '[')), 0.04); },
                      {"deep.json", "nested deeper than 16"});
  expect_config_error([] { (void)load_houseexpo(kPlans + "missing.json"); }, {"missing.json", "cannot open"});
  expect_config_error([] { (void)load_houseexpo(kPlans + "house_expo_room_0000.json", -1.0); },
                      {"resolution -1"});
}

TEST(LargestFreeRegion, TakesTheLargestAndTheEarliestOfEqualOnes) {
  WorldMap map;
  // Region A (3 cells, top left), region B (4 cells, right), region C (3 cells, bottom left).
  // Without corner cutting, the diagonal pair at the bottom right is two regions of 1 cell.
  map.occupied = Grid<std::uint8_t>(6, 5, 1);
  for (const Cell c : {Cell{0, 0}, Cell{1, 0}, Cell{2, 0}, Cell{4, 0}, Cell{5, 0}, Cell{4, 1}, Cell{5, 1},
                       Cell{0, 3}, Cell{1, 3}, Cell{2, 3}, Cell{4, 3}, Cell{5, 4}}) {
    map.occupied.at(c) = 0;
  }
  const Grid<std::uint8_t> largest = largest_free_region(map);
  EXPECT_EQ(rows_of(largest, 1),
            (std::vector<std::string>{"....xx", "....xx", "......", "......", "......"}));
  map.occupied.at(Cell{5, 1}) = 1;  // B shrinks to 3: A, the earliest of three equal regions
  EXPECT_EQ(rows_of(largest_free_region(map), 1),
            (std::vector<std::string>{"xxx...", "......", "......", "......", "......"}));
}

TEST(LargestFreeRegion, FollowsTheMotionRule) {
  WorldMap map;
  map.occupied = Grid<std::uint8_t>(3, 2, 1);
  map.occupied.at(Cell{0, 0}) = 0;
  map.occupied.at(Cell{1, 1}) = 0;
  map.occupied.at(Cell{2, 1}) = 0;
  EXPECT_EQ(rows_of(largest_free_region(map, false), 1), (std::vector<std::string>{"...", ".xx"}));
  EXPECT_EQ(rows_of(largest_free_region(map, true), 1), (std::vector<std::string>{"x..", ".xx"}));
}

TEST(DrawRegionCell, IsAPureFunctionOfTheSeedAndCoversTheRegion) {
  Grid<std::uint8_t> region(4, 3, 0);
  for (const Cell c : {Cell{1, 0}, Cell{3, 1}, Cell{0, 2}, Cell{2, 2}}) region.at(c) = 1;
  std::vector<int> hits(4, 0);
  for (std::uint64_t seed = 0; seed < 400; ++seed) {
    const Cell c = draw_region_cell(region, seed);
    ASSERT_EQ(region.at(c), 1) << seed;
    EXPECT_EQ(draw_region_cell(region, seed), c);
    const int k = c == Cell{1, 0} ? 0 : c == Cell{3, 1} ? 1 : c == Cell{0, 2} ? 2 : 3;
    ++hits[static_cast<std::size_t>(k)];
  }
  for (const int h : hits) EXPECT_GT(h, 60);  // 100 expected each; 60 is far in the tail
  EXPECT_EQ(draw_region_cell(Grid<std::uint8_t>(2, 2, 0), 1), (Cell{-1, -1}));
}

}  // namespace test_houseexpo
}  // namespace fsweep
