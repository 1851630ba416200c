// Loaders of MovingAI maps and scenarios, ASCII maps, ROS map_server maps and bitmaps.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <string>
#include <vector>

#include "core/config_error.hpp"
#include "world/map_loaders.hpp"

namespace fsweep {
namespace test_map_loaders {  // not anonymous: unity builds put it beside other test files' helpers

const std::string kData = FSWEEP_TEST_DATA;

/// Writes `content` to a fresh file in the test temp directory and returns its path.
std::string write_temp(const std::string& name, const std::string& content) {
  std::string path = testing::TempDir() + "fsweep_loaders_" + name;
  std::ofstream out(path, std::ios::binary);
  out << content;
  return path;
}

/// A binary PGM (P5) with the given grey rows.
std::string write_pgm(const std::string& name, const std::vector<std::vector<int>>& rows) {
  std::string bytes = "P5\n# test image\n" + std::to_string(rows.front().size()) + " " +
                      std::to_string(rows.size()) + "\n255\n";
  for (const auto& row : rows) {
    for (const int v : row) bytes.push_back(static_cast<char>(v));
  }
  return write_temp(name, bytes);
}

/// Expects `fn` to throw ConfigError whose message contains every one of `parts`.
void expect_config_error(const std::function<void()>& fn, std::initializer_list<std::string> parts) {
  try {
    fn();
    ADD_FAILURE() << "expected a ConfigError";
  } catch (const ConfigError& e) {
    const std::string message = e.what();
    for (const auto& part : parts) EXPECT_NE(message.find(part), std::string::npos) << message;
  }
}

int occupied_count(const WorldMap& map) { return map.occupied.size() - map.free_count(); }

// --- MovingAI ------------------------------------------------------------------------------

TEST(MovingAiMap, ArenaHasHeaderDimensionsAndCells) {
  const WorldMap map = load_movingai_map(kData + "/arena.map");
  EXPECT_EQ(map.width(), 49);
  EXPECT_EQ(map.height(), 49);
  EXPECT_DOUBLE_EQ(map.resolution_m, 1.0);
  // Row 1 of the file is "TTT............TTTT.TTT...": columns 0-2 are trees, 3-14 free.
  EXPECT_FALSE(map.is_free(Cell{0, 1}));
  EXPECT_FALSE(map.is_free(Cell{2, 1}));
  EXPECT_TRUE(map.is_free(Cell{3, 1}));
  EXPECT_TRUE(map.is_free(Cell{14, 1}));
  EXPECT_FALSE(map.is_free(Cell{15, 1}));
  EXPECT_TRUE(map.is_free(Cell{19, 1}));
  EXPECT_FALSE(map.is_free(Cell{0, 0}));
  EXPECT_FALSE(map.is_free(Cell{48, 48}));
  // 2054 '.' characters in the 49 rows (counted with a script over the file).
  EXPECT_EQ(map.free_count(), 2054);
  // The default start is the first free cell in row-major order.
  EXPECT_EQ(map.start, (Cell{3, 1}));
}

TEST(MovingAiMap, WidthIsColumnsAndHeightIsRows) {
  const WorldMap map = load_movingai_map(kData + "/den312d.map", 0.5);
  EXPECT_EQ(map.width(), 65);
  EXPECT_EQ(map.height(), 81);
  EXPECT_DOUBLE_EQ(map.resolution_m, 0.5);
  EXPECT_TRUE(map.is_free(map.start));
}

TEST(MovingAiMap, RoomMapLoads) {
  const WorldMap map = load_movingai_map(kData + "/room-64-64-8.map");
  EXPECT_EQ(map.width(), 64);
  EXPECT_EQ(map.height(), 64);
  EXPECT_GT(map.free_count(), 0);
}

TEST(MovingAiMap, BadCharacterNamesFileLineAndAllowedCharacters) {
  const std::string path = write_temp("bad_char.map", "type octile\nheight 2\nwidth 3\nmap\n...\n.x.\n");
  expect_config_error([&] { (void)load_movingai_map(path); },
                      {path + ":6", "'x'", "(1, 1)", "allowed: . G S (free), @ O T W (occupied)"});
}

TEST(MovingAiMap, ShortRowAndMissingRowsAreErrors) {
  const std::string short_row = write_temp("short_row.map", "type octile\nheight 2\nwidth 3\nmap\n...\n..\n");
  expect_config_error([&] { (void)load_movingai_map(short_row); }, {short_row + ":6", "width 3"});
  const std::string missing = write_temp("missing_rows.map", "type octile\nheight 3\nwidth 3\nmap\n...\n");
  expect_config_error([&] { (void)load_movingai_map(missing); }, {missing, "3 rows"});
}

TEST(MovingAiMap, HugeHeaderIsRefusedBeforeAllocating) {
  // 10^16 cells: allocating first ended in std::bad_alloc.
  const std::string huge = write_temp("huge.map", "type octile\nheight 100000000\nwidth 100000000\nmap\n.\n");
  expect_config_error([&] { (void)load_movingai_map(huge); },
                      {huge + ":3: width 100000000 x height 100000000", "allowed: at most 100000000 cells"});
  // 2^31 - 1 rows of one cell (2 GB).
  const std::string tallest = write_temp("tallest.map", "type octile\nheight 2147483647\nwidth 1\nmap\n.\n");
  expect_config_error([&] { (void)load_movingai_map(tallest); },
                      {tallest + ":3: width 1 x height 2147483647 is more than 100000000 cells"});
  // 10^8 rows of one cell are allowed, but not in a file of one row.
  const std::string tall = write_temp("tall.map", "type octile\nheight 100000000\nwidth 1\nmap\n.\n");
  expect_config_error([&] { (void)load_movingai_map(tall); },
                      {tall + ":2: height 100000000", "promises 100000000 rows but only 1 lines follow"});
  // 2 rows of 10^7 cells in a file of 6 bytes of rows.
  const std::string wide = write_temp("wide.map", "type octile\nwidth 10000000\nheight 2\nmap\n..\n..\n");
  expect_config_error([&] { (void)load_movingai_map(wide); },
                      {wide + ":2: width 10000000 x height 2 cells do not fit in the 6 bytes"});
}

TEST(MovingAiMap, BadHeaderAndMissingFileAreErrors) {
  const std::string path = write_temp("bad_header.map", "type hex\nheight 1\nwidth 1\nmap\n.\n");
  expect_config_error([&] { (void)load_movingai_map(path); }, {path + ":1", "allowed: octile"});
  const std::string absent = kData + "/no_such_file.map";
  expect_config_error([&] { (void)load_movingai_map(absent); }, {absent, "cannot open"});
  expect_config_error([&] { (void)load_movingai_map(kData + "/arena.map", 0.0); }, {"resolution"});
}

TEST(MovingAiMap, CrLfLineEndingsAreAccepted) {
  const std::string path = write_temp("crlf.map", "type octile\r\nheight 1\r\nwidth 2\r\nmap\r\n@.\r\n");
  const WorldMap map = load_movingai_map(path);
  EXPECT_EQ(map.width(), 2);
  EXPECT_EQ(map.start, (Cell{1, 0}));
}

// --- ASCII ---------------------------------------------------------------------------------

TEST(AsciiMap, ParsesWallsFreeCellsAndStart) {
  const WorldMap map = load_ascii_map(kData + "/two_rooms.txt", 0.25);
  EXPECT_EQ(map.width(), 8);
  EXPECT_EQ(map.height(), 6);
  EXPECT_DOUBLE_EQ(map.resolution_m, 0.25);
  EXPECT_EQ(map.start, (Cell{1, 1}));
  EXPECT_TRUE(map.is_free(Cell{4, 3}));   // the door
  EXPECT_FALSE(map.is_free(Cell{3, 3}));  // wall beside it
  EXPECT_EQ(map.free_count(), 6 + 6 + 6 + 1);
}

TEST(AsciiMap, DefaultStartIsFirstFreeCell) {
  const WorldMap map = parse_ascii_map("##\n#.\n");
  EXPECT_EQ(map.start, (Cell{1, 1}));
  EXPECT_EQ(map.source, "ascii");
}

TEST(AsciiMap, RaggedRowsUnknownCharactersAndTwoStartsAreErrors) {
  expect_config_error([] { (void)parse_ascii_map("...\n..\n", 1.0, "ragged"); }, {"ragged:2", "3"});
  expect_config_error([] { (void)parse_ascii_map("..x\n", 1.0, "letters"); },
                      {"letters:1", "'x'", "allowed: . (free), # (occupied), S (start)"});
  expect_config_error([] { (void)parse_ascii_map("S.S\n", 1.0, "starts"); }, {"starts:1", "second start"});
  expect_config_error([] { (void)parse_ascii_map("###\n", 1.0, "walls"); }, {"walls", "no free cell"});
}

// --- ROS map_server ------------------------------------------------------------------------

TEST(RosMap, TurtlebotThresholdsMakeUnknownOccupied) {
  const WorldMap map = load_ros_map(kData + "/turtlebot3_world/map.yaml");
  EXPECT_EQ(map.width(), 384);
  EXPECT_EQ(map.height(), 384);
  EXPECT_DOUBLE_EQ(map.resolution_m, 0.05);
  // The image holds 7939 pixels of 254 (free), 795 of 0 (occupied) and 138722 of 205
  // (counted with a script). p(254) = 1/255 < 0.196 -> free; p(0) = 1 > 0.65 -> occupied;
  // p(205) = 50/255 = 0.19608 lies between the thresholds -> unknown -> occupied.
  EXPECT_EQ(map.free_count(), 7939);
  EXPECT_EQ(occupied_count(map), 795 + 138722);
  EXPECT_TRUE(map.is_free(Cell{185, 132}));   // first 254 pixel in row-major order
  EXPECT_FALSE(map.is_free(Cell{184, 132}));  // first 0 pixel
  EXPECT_FALSE(map.is_free(Cell{0, 0}));      // 205: unknown
  EXPECT_TRUE(map.is_free(Cell{192, 192}));
  EXPECT_EQ(map.start, (Cell{185, 132}));
}

TEST(RosMap, NegateSwapsTheMeaningOfGreyValues) {
  // negate: p = v / 255, so only the 795 black pixels (p = 0) are free.
  const std::string yaml = write_temp(
      "negate.yaml", "image: " + kData +
                         "/turtlebot3_world/map.pgm\nresolution: 0.05\n"
                         "origin: [0, 0, 0]\nnegate: 1\noccupied_thresh: 0.65\nfree_thresh: 0.196\n");
  const WorldMap map = load_ros_map(yaml);
  EXPECT_EQ(map.free_count(), 795);
  EXPECT_TRUE(map.is_free(Cell{184, 132}));
}

TEST(RosMap, ThresholdsAreStrictAndRelativeImagePathsFollowTheYaml) {
  // p = (255 - v) / 255: 255 -> 0, 206 -> 0.1922 (free), 205 -> 0.1961 (unknown),
  // 89 -> 0.651 (occupied), 0 -> 1.
  write_pgm("strip.pgm", {{255, 206, 205, 100, 89, 0}});
  const std::string yaml = write_temp("strip.yaml",
                                      "image: fsweep_loaders_strip.pgm\nresolution: 0.5\n"
                                      "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n");
  const WorldMap map = load_ros_map(yaml);
  ASSERT_EQ(map.width(), 6);
  const std::vector<bool> expected_free{true, true, false, false, false, false};
  for (int x = 0; x < 6; ++x)
    EXPECT_EQ(map.is_free(Cell{x, 0}), expected_free[static_cast<std::size_t>(x)]) << x;
  EXPECT_DOUBLE_EQ(map.resolution_m, 0.5);
}

TEST(RosMap, MissingKeysBadValuesAndBadImagesNameTheFile) {
  const std::string no_res =
      write_temp("no_res.yaml", "image: map.pgm\noccupied_thresh: 0.65\nfree_thresh: 0.2\n");
  expect_config_error([&] { (void)load_ros_map(no_res); }, {no_res, "missing key 'resolution'"});
  const std::string bad_res = write_temp("bad_res.yaml",
                                         "image: map.pgm\nresolution: fine\n"
                                         "occupied_thresh: 0.65\nfree_thresh: 0.2\n");
  expect_config_error([&] { (void)load_ros_map(bad_res); },
                      {bad_res + ":2", "'resolution' must be a number"});
  const std::string bad_thresh = write_temp("bad_thresh.yaml",
                                            "image: map.pgm\nresolution: 0.05\n"
                                            "occupied_thresh: 0.1\nfree_thresh: 0.2\n");
  expect_config_error([&] { (void)load_ros_map(bad_thresh); }, {bad_thresh, "free_thresh < occupied_thresh"});
  const std::string raw = write_temp("raw.yaml",
                                     "image: map.pgm\nresolution: 0.05\nmode: raw\n"
                                     "occupied_thresh: 0.65\nfree_thresh: 0.2\n");
  expect_config_error([&] { (void)load_ros_map(raw); }, {raw + ":3", "allowed: trinary, scale"});
  const std::string no_image = write_temp("no_image.yaml",
                                          "image: absent.pgm\nresolution: 0.05\n"
                                          "occupied_thresh: 0.65\nfree_thresh: 0.2\n");
  expect_config_error([&] { (void)load_ros_map(no_image); }, {"absent.pgm", "cannot read the image"});
  const std::string broken = write_temp("broken.yaml", "image: [unclosed\n");
  expect_config_error([&] { (void)load_ros_map(broken); }, {broken, "invalid YAML"});
}

TEST(RosMap, InvalidYamlNamesLineAndColumn) {
  const std::string path =
      write_temp("unclosed.yaml", "image: map.pgm\nresolution: [0.05\noccupied_thresh: 0.65\n");
  expect_config_error([&] { (void)load_ros_map(path); },
                      {path + ":3:16: invalid YAML: end of sequence flow not found"});
  // A bad value is quoted cut to 80 characters, with its line and column.
  const std::string long_value =
      write_temp("long_value.yaml", std::string("image: map.pgm\nresolution: ")
                                        .append(100'000, 'x')
                                        .append("\noccupied_thresh: 0.65\nfree_thresh: 0.2\n"));
  try {
    (void)load_ros_map(long_value);
    ADD_FAILURE() << "expected a ConfigError";
  } catch (const ConfigError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message, std::string(long_value)
                           .append(":2:13: 'resolution' must be a number, got '")
                           .append(80, 'x')
                           .append("...'"));
  }
}

TEST(RosMap, TruncatedImageIsRefusedWithByteCounts) {
  const std::string pgm = write_temp("cut_ros.pgm", "P5\n3 2\n255\n\xff\xff\xff\xff");
  const std::string yaml = write_temp("cut_ros.yaml",
                                      "image: fsweep_loaders_cut_ros.pgm\nresolution: 0.5\n"
                                      "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
  expect_config_error([&] { (void)load_ros_map(yaml); },
                      {pgm + ": the pixel data is cut short", "3 x 2 pixels, 6 bytes, but only 4 bytes"});
}

// --- Bitmaps -------------------------------------------------------------------------------

TEST(Bitmap, HospitalAt40By18MetresKeepsEveryWall) {
  const std::string png = kData + "/hospital_section.png";
  // One pixel per cell first (pixel scale 1 m, square): the reference occupancy.
  const WorldMap pixels = load_bitmap(png, BitmapScale{1.0, 0.0, 0.0}, 127, 0.0);
  ASSERT_EQ(pixels.width(), 1086);
  ASSERT_EQ(pixels.height(), 443);
  for (const double res : {0.1, 0.25}) {
    const WorldMap map = load_bitmap(png, BitmapScale{0.0, 40.0, 18.0}, 127, res);
    EXPECT_EQ(map.width(), static_cast<int>(std::lround(40.0 / res)));
    EXPECT_EQ(map.height(), static_cast<int>(std::lround(18.0 / res)));
    EXPECT_DOUBLE_EQ(map.resolution_m, res);
    EXPECT_TRUE(map.is_free(map.start));
    // Max-pooling: the cell under every occupied pixel's centre is occupied, so 1-px walls never
    // vanish and rooms cannot leak into each other.
    int missed = 0;
    for (int py = 0; py < pixels.height(); ++py) {
      for (int px = 0; px < pixels.width(); ++px) {
        if (pixels.is_free(Cell{px, py})) continue;
        const Cell c{static_cast<int>((px + 0.5) * (40.0 / 1086.0) / res),
                     static_cast<int>((py + 0.5) * (18.0 / 443.0) / res)};
        if (map.is_free(c)) ++missed;
      }
    }
    EXPECT_EQ(missed, 0) << "resolution " << res;
    EXPECT_GT(map.free_count(), 0);
  }
}

TEST(Bitmap, ThinWallOffTheCellCentreStillBlocks) {
  // 6 x 6 pixels, a one-pixel wall on pixel row 3; cells of 3 x 3 pixels. The wall is not at the
  // centre of cell row 1 (pixel row 4), so centre sampling would miss it; max-pooling must not.
  std::vector<std::vector<int>> rows(6, std::vector<int>(6, 255));
  rows[3] = std::vector<int>(6, 0);
  const std::string pgm = write_pgm("thin_wall.pgm", rows);
  const WorldMap map = load_bitmap(pgm, BitmapScale{0.1, 0.0, 0.0}, 127, 0.3);
  ASSERT_EQ(map.width(), 2);
  ASSERT_EQ(map.height(), 2);
  EXPECT_TRUE(map.is_free(Cell{0, 0}));
  EXPECT_TRUE(map.is_free(Cell{1, 0}));
  EXPECT_FALSE(map.is_free(Cell{0, 1}));
  EXPECT_FALSE(map.is_free(Cell{1, 1}));
}

TEST(Bitmap, GreyAboveThresholdIsFree) {
  const std::string pgm = write_pgm("threshold.pgm", {{0, 127, 128, 255}});
  const WorldMap map = load_bitmap(pgm, BitmapScale{0.05, 0.0, 0.0}, 127, 0.0);
  EXPECT_DOUBLE_EQ(map.resolution_m, 0.05);
  EXPECT_FALSE(map.is_free(Cell{0, 0}));
  EXPECT_FALSE(map.is_free(Cell{1, 0}));
  EXPECT_TRUE(map.is_free(Cell{2, 0}));
  EXPECT_TRUE(map.is_free(Cell{3, 0}));
}

TEST(Bitmap, ReadsPgmWithStb) {
  // The turtlebot PGM as a plain bitmap: with threshold 210 only the 254 pixels are free.
  const WorldMap map =
      load_bitmap(kData + "/turtlebot3_world/map.pgm", BitmapScale{0.05, 0.0, 0.0}, 210, 0.0);
  EXPECT_EQ(map.width(), 384);
  EXPECT_EQ(map.free_count(), 7939);
}

TEST(Bitmap, BadScaleThresholdAndFileAreErrors) {
  const std::string png = kData + "/hospital_section.png";
  expect_config_error(
      [&] {
        (void)load_bitmap(png, BitmapScale{0.0, 40.0, 18.0}, 127, 0.0);
      },
      {png, "not square"});
  expect_config_error([&] { (void)load_bitmap(png, BitmapScale{}, 127, 0.1); }, {png, "metres per pixel"});
  expect_config_error(
      [&] {
        (void)load_bitmap(png, BitmapScale{0.1, 40.0, 18.0}, 127, 0.1);
      },
      {png, "not both"});
  expect_config_error(
      [&] {
        (void)load_bitmap(png, BitmapScale{0.1, 0.0, 0.0}, 300, 0.1);
      },
      {png, "allowed: 0..255"});
  const std::string text = kData + "/two_rooms.txt";
  expect_config_error(
      [&] {
        (void)load_bitmap(text, BitmapScale{0.1, 0.0, 0.0}, 127, 0.0);
      },
      {text, "cannot read the image"});
}

TEST(Bitmap, TruncatedPgmIsRefusedWithByteCounts) {
  // 3 x 2 pixels need 6 bytes; the file stops after 4 (the missing 2 used to become obstacles).
  const std::string pgm = write_temp("cut.pgm", "P5\n# cut short\n3 2\n255\n\xff\xff\xff\xff");
  expect_config_error(
      [&] {
        (void)load_bitmap(pgm, BitmapScale{1.0, 0.0, 0.0}, 127, 0.0);
      },
      {pgm + ": the pixel data is cut short: the header declares 3 x 2 pixels, 6 bytes, but "
             "only 4 bytes follow it"});
  // 16-bit samples take two bytes each.
  const std::string wide = write_temp("cut16.pgm", "P5 2 1 65535\n\xff\xff\xff");
  expect_config_error(
      [&] {
        (void)load_bitmap(wide, BitmapScale{1.0, 0.0, 0.0}, 127, 0.0);
      },
      {"4 bytes, but only 3 bytes"});
}

TEST(Bitmap, HugeDeclaredSizeIsRefusedBeforeDecoding) {
  const std::string pgm = write_temp("huge.pgm", "P5\n100000 100000\n255\n\xff");
  expect_config_error(
      [&] {
        (void)load_bitmap(pgm, BitmapScale{1.0, 0.0, 0.0}, 127, 0.0);
      },
      {pgm + ": width 100000 x height 100000 is more than 100000000 cells"});
  // A PNG whose header (IHDR) declares 20000 x 20000 grey pixels and has no pixel data.
  std::string png = "\x89PNG\r\n\x1a\n";
  png += std::string("\0\0\0\x0d", 4) + "IHDR";
  png += std::string("\0\0\x4e\x20\0\0\x4e\x20\x08\0\0\0\0", 13);
  png += std::string("\0\0\0\0", 4);  // CRC (stb_image does not check it)
  const std::string path = write_temp("huge.png", png);
  expect_config_error(
      [&] {
        (void)load_bitmap(path, BitmapScale{1.0, 0.0, 0.0}, 127, 0.0);
      },
      {path + ": width 20000 x height 20000 is more than 100000000 cells"});
}

// --- Scenarios -----------------------------------------------------------------------------

TEST(Scenario, ArenaHas160QueriesWithAllFields) {
  const std::vector<ScenarioQuery> queries = load_scenario(kData + "/arena.map.scen");
  ASSERT_EQ(queries.size(), 160U);
  // First row: "0  maps/dao/arena.map  49  49  1  11  1  12  1".
  const ScenarioQuery& q = queries.front();
  EXPECT_EQ(q.bucket, 0);
  EXPECT_EQ(q.map_name, "maps/dao/arena.map");
  EXPECT_EQ(q.map_width, 49);
  EXPECT_EQ(q.map_height, 49);
  EXPECT_EQ(q.start, (Cell{1, 11}));
  EXPECT_EQ(q.goal, (Cell{1, 12}));
  EXPECT_DOUBLE_EQ(q.optimal_length, 1.0);
  // Last row: "15  maps/dao/arena.map  49  49  1  7  47  46  62.1543".
  EXPECT_EQ(queries.back().bucket, 15);
  EXPECT_EQ(queries.back().goal, (Cell{47, 46}));
  EXPECT_DOUBLE_EQ(queries.back().optimal_length, 62.1543);
}

TEST(Scenario, MapfAndDenScenariosLoad) {
  const auto room = load_scenario(kData + "/room-64-64-8-random-1.scen");
  ASSERT_EQ(room.size(), 1000U);
  EXPECT_EQ(room.front().map_name, "room-64-64-8.map");
  EXPECT_EQ(room.front().start, (Cell{10, 58}));
  EXPECT_DOUBLE_EQ(room.front().optimal_length, 72.04163055);
  EXPECT_EQ(load_scenario(kData + "/den312d.map.scen").size(), 320U);
}

TEST(Scenario, ZeroLengthMeansUnreachableAndIsAccepted) {
  const std::string path = write_temp("gppc.scen", "version 1\n0\tm.map\t4\t4\t0\t0\t3\t3\t0\n");
  const auto queries = load_scenario(path);
  ASSERT_EQ(queries.size(), 1U);
  EXPECT_EQ(queries.front().optimal_length, 0.0);
}

TEST(Scenario, BadRowsNameTheFileAndLine) {
  const std::string no_version = write_temp("no_version.scen", "0\tm.map\t4\t4\t0\t0\t3\t3\t1\n");
  expect_config_error([&] { (void)load_scenario(no_version); }, {no_version + ":1", "version 1"});
  const std::string few = write_temp("few_fields.scen", "version 1\n0\tm.map\t4\t4\t0\t0\t3\n");
  expect_config_error([&] { (void)load_scenario(few); }, {few + ":2", "expected 9 fields"});
  const std::string bad_x = write_temp("bad_x.scen", "version 1\n0\tm.map\t4\t4\tone\t0\t3\t3\t1\n");
  expect_config_error([&] { (void)load_scenario(bad_x); }, {bad_x + ":2", "start x 'one'"});
  const std::string outside = write_temp("outside.scen", "version 1\n0\tm.map\t4\t4\t0\t0\t4\t3\t1\n");
  expect_config_error([&] { (void)load_scenario(outside); }, {outside + ":2", "outside the 4x4 map"});
}

}  // namespace test_map_loaders
}  // namespace fsweep
