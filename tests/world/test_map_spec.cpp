// Map SPEC strings and their JSON form: parsing, dispatch to loaders/generators, errors.
#include <gtest/gtest.h>

#include <functional>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <string>

#include "core/config_error.hpp"
#include "world/map_generators.hpp"
#include "world/map_loaders.hpp"
#include "world/map_spec.hpp"

namespace fsweep {
namespace test_map_spec {  // not anonymous: unity builds put it beside other test files' helpers

using nlohmann::json;
const std::string kData = FSWEEP_TEST_DATA;

/// Expects `fn` to throw ConfigError whose message contains every one of `parts`; returns it.
ConfigError expect_config_error(const std::function<void()>& fn, std::initializer_list<std::string> parts) {
  try {
    fn();
  } catch (const ConfigError& e) {
    const std::string message = e.what();
    for (const auto& part : parts) EXPECT_NE(message.find(part), std::string::npos) << message;
    return e;
  }
  ADD_FAILURE() << "expected a ConfigError";
  return ConfigError("", "");
}

TEST(MapSpec, GeneratorSpecEqualsGeneratorParams) {
  GeneratorParams p;
  p.kind = "rooms";
  p.width = 60;
  p.height = 40;
  p.door = 2;
  p.min_room = 8;
  p.seed = 4;
  p.resolution_m = 0.5;
  const WorldMap expected = generate_map(p);
  const WorldMap map = load_map_spec("rooms:w=60,h=40,door=2,min_room=8,seed=4,res=0.5");
  EXPECT_EQ(map.occupied, expected.occupied);
  EXPECT_EQ(map.start, expected.start);
  EXPECT_DOUBLE_EQ(map.resolution_m, 0.5);
}

TEST(MapSpec, KindAloneUsesDefaults) {
  const WorldMap map = load_map_spec("free");
  EXPECT_EQ(map.width(), 100);
  EXPECT_EQ(map.height(), 100);
  EXPECT_EQ(map.start, (Cell{50, 50}));
}

TEST(MapSpec, JsonFormEqualsStringForm) {
  const json j = {{"generator", "oldtown"}, {"w", 80}, {"h", 60}, {"lane", 2}, {"squares", 2}, {"seed", 9}};
  const WorldMap from_string = load_map_spec("oldtown:w=80,h=60,lane=2,squares=2,seed=9");
  const WorldMap from_json = load_map_json(j, "/maps/0");
  EXPECT_EQ(from_json.occupied, from_string.occupied);
  EXPECT_EQ(from_json.start, from_string.start);
  // Another free cell as start: [x, y] or "x;y" in JSON, x;y in the string.
  Cell s{-1, -1};
  for (int i = from_string.occupied.size() - 1; i >= 0 && s.x < 0; --i) {
    if (from_string.is_free(i)) s = from_string.occupied.cell(i);
  }
  json with_start = j;
  with_start["start"] = {s.x, s.y};
  EXPECT_EQ(load_map_json(with_start, "/maps/0").start, s);
  with_start["start"] = std::to_string(s.x) + ";" + std::to_string(s.y);
  EXPECT_EQ(load_map_json(with_start, "/maps/0").start, s);
  const std::string spec =
      "oldtown:w=80,h=60,lane=2,squares=2,seed=9,start=" + std::to_string(s.x) + ";" + std::to_string(s.y);
  EXPECT_EQ(load_map_spec(spec).start, s);
}

TEST(MapSpec, BorderAndProbabilityKeys) {
  const WorldMap open = load_map_spec("free:w=10,h=8,border=false");
  EXPECT_EQ(open.free_count(), 80);
  EXPECT_EQ(load_map_spec("free:w=10,h=8,border=0").free_count(), 80);
  EXPECT_EQ(load_map_spec("random:w=30,h=30,p=0,border=true,wall=2").free_count(), 26 * 26);
}

TEST(MapSpec, MovingAiFileWithResolutionAndStart) {
  const WorldMap map = load_map_spec(kData + "/arena.map:res=0.5,start=19;1");
  EXPECT_EQ(map.width(), 49);
  EXPECT_DOUBLE_EQ(map.resolution_m, 0.5);
  EXPECT_EQ(map.start, (Cell{19, 1}));
  EXPECT_EQ(load_map_spec(kData + "/arena.map").start, (Cell{3, 1}));
  const WorldMap from_json = load_map_json({{"file", kData + "/arena.map"}, {"res", 2}}, "/maps/1");
  EXPECT_DOUBLE_EQ(from_json.resolution_m, 2.0);
}

TEST(MapSpec, RosAsciiAndBitmapFiles) {
  const WorldMap ros = load_map_spec(kData + "/turtlebot3_world/map.yaml");
  EXPECT_EQ(ros.width(), 384);
  EXPECT_DOUBLE_EQ(ros.resolution_m, 0.05);
  const WorldMap ascii = load_map_spec(kData + "/two_rooms.txt:res=0.2");
  EXPECT_EQ(ascii.start, (Cell{1, 1}));
  EXPECT_DOUBLE_EQ(ascii.resolution_m, 0.2);
  const WorldMap stage = load_map_spec(kData + "/hospital_section.png:size=40x18,res=0.1");
  EXPECT_EQ(stage.width(), 400);
  EXPECT_EQ(stage.height(), 180);
  const WorldMap stage_json =
      load_map_json({{"file", kData + "/hospital_section.png"}, {"size", {40, 18}}, {"res", 0.1}}, "/maps/2");
  EXPECT_EQ(stage_json.occupied, stage.occupied);
  // Without a scale one pixel is one cell of res metres.
  const WorldMap raw = load_map_spec(kData + "/hospital_section.png:res=0.04,threshold=100");
  EXPECT_EQ(raw.width(), 1086);
  EXPECT_DOUBLE_EQ(raw.resolution_m, 0.04);
  const WorldMap by_mpp = load_map_spec(kData + "/hospital_section.png:mpp=0.05,res=0.1");
  EXPECT_EQ(by_mpp.width(), 543);   // 1086 * 0.05 / 0.1
  EXPECT_EQ(by_mpp.height(), 222);  // ceil(443 * 0.05 / 0.1): the last cell is half outside
}

TEST(MapSpec, StartInsideAnObstacleNamesTheCell) {
  expect_config_error([] { (void)load_map_spec(kData + "/arena.map:start=0;0"); },
                      {"arena.map", "start cell (0, 0) is occupied"});
  expect_config_error([] { (void)load_map_spec(kData + "/arena.map:start=60;2"); },
                      {"start cell (60, 2) is outside the 49x49 map"});
  expect_config_error([] { (void)load_map_spec("rooms:w=40,h=40,start=0;0"); },
                      {"map spec 'rooms:w=40,h=40,start=0;0'", "start cell (0, 0) is occupied"});
  const ConfigError e = expect_config_error(
      [] {
        (void)load_map_json({{"file", kData + "/arena.map"}, {"start", {0, 0}}}, "/maps/3");
      },
      {"start cell (0, 0) is occupied"});
  EXPECT_EQ(e.where(), "/maps/3/start");
}

TEST(MapSpec, UnknownKeysListTheAllowedOnes) {
  expect_config_error(
      [] { (void)load_map_spec("rooms:w=40,colour=red"); },
      {"unknown key 'colour'", "generator 'rooms'", "allowed: w, h, res, seed, start, door, min_room, wall"});
  expect_config_error(
      [] { (void)load_map_spec("manhattan:door=3"); },
      {"unknown key 'door'", "allowed: w, h, res, seed, start, block, street, parks, alleys"});
  expect_config_error([] { (void)load_map_spec(kData + "/turtlebot3_world/map.yaml:res=0.1"); },
                      {"unknown key 'res'", "allowed: start"});
  const ConfigError e = expect_config_error(
      [] {
        (void)load_map_json({{"generator", "free"}, {"lanes", 2}}, "/maps/4");
      },
      {"unknown key 'lanes'"});
  EXPECT_EQ(e.where(), "/maps/4/lanes");
}

TEST(MapSpec, UnknownKindsAndExtensionsListTheAllowedOnes) {
  expect_config_error(
      [] { (void)load_map_spec("forest:w=10"); },
      {"unknown map kind 'forest'", "free, random, rooms, office, manhattan, oldtown", ".map"});
  expect_config_error([] { (void)load_map_spec("maps/plan.bmp"); },
                      {"unknown extension", ".map, .txt, .json, .yaml, .yml, .png, .pgm"});
  expect_config_error(
      [] {
        (void)load_map_json({{"generator", "free"}, {"file", "x.map"}}, "/maps/5");
      },
      {"exactly one of 'generator'"});
  expect_config_error([] { (void)load_map_json(json::array(), "/maps/6"); }, {"/maps/6", "JSON object"});
}

TEST(MapSpec, BadValuesAreErrorsNotRounded) {
  expect_config_error([] { (void)load_map_spec("rooms:w=12.5"); },
                      {"w: value 12.5 not allowed; allowed: an integer in [1, 65536]"});
  expect_config_error([] { (void)load_map_spec("rooms:w"); }, {"option 'w' is not key=value"});
  expect_config_error([] { (void)load_map_spec("rooms:w=40,w=50"); }, {"key 'w' is repeated"});
  expect_config_error([] { (void)load_map_spec("free:res=-1"); },
                      {"res: value -1 out of range", "allowed: a number > 0"});
  expect_config_error([] { (void)load_map_spec("free:seed=-3"); }, {"'seed' must be a non-negative integer"});
  expect_config_error([] { (void)load_map_spec("free:border=maybe"); },
                      {"'border' must be true, false, 1 or 0"});
  expect_config_error([] { (void)load_map_spec("free:start=3"); },
                      {"start must be two non-negative integer cell coordinates"});
  expect_config_error([] { (void)load_map_spec("rooms:w=40,h=40,door=30"); },
                      {"map spec 'rooms:w=40,h=40,door=30'", "door = 30 is out of range"});
  expect_config_error([] { (void)load_map_spec(kData + "/hospital_section.png:mpp=0.1,size=40x18"); },
                      {"either 'mpp' or 'size'"});
  expect_config_error([] { (void)load_map_spec(kData + "/hospital_section.png:size=40by18,res=0.1"); },
                      {"'size' must be [a, b] or \"axb\""});
  const ConfigError e = expect_config_error(
      [] {
        (void)load_map_json({{"generator", "rooms"}, {"w", "big"}}, "/maps/7");
      },
      {"value \"big\" not allowed; allowed: an integer in [1, 65536]"});
  EXPECT_EQ(e.where(), "/maps/7/w");
}

TEST(MapSpec, LoaderErrorsKeepTheFileAndLine) {
  expect_config_error([] { (void)load_map_spec(kData + "/missing.map"); }, {"missing.map", "cannot open"});
}

}  // namespace test_map_spec
}  // namespace fsweep
