// Sweep expansion: counts, run order (mixed radix, last axis fastest), zip groups, map seeds,
// robot variants, lazy decoding of huge sweeps, run keys.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "core/config_error.hpp"
#include "core/random.hpp"
#include "sweep/manifest.hpp"
#include "sweep/sweep_plan.hpp"
#include "sweep/sweep_table.hpp"
#include "sweep/sweep_test_files.hpp"

namespace fsweep {
namespace {

/// The strategy params of run `index` as the sweep file gives them (null: none given).
nlohmann::json given_params(const SweepPlan& plan, std::uint64_t index) {
  const RunCoordinates c = plan.coordinates(index);
  return plan.strategies()[c.strategy_entry].params_at(c.strategy_combo);
}

using nlohmann::json;

json minimal() {
  return json::parse(R"({"schema_version": 1, "name": "t", "maps": ["free:w=20,h=20"],
                         "strategies": [{"name": "closest_frontier"}]})");
}

/// 2 maps x (3 x 2 + 1) strategy configurations x 2 planners x 2 robots x 3 repetitions.
json cartesian() {
  return json::parse(R"({
    "schema_version": 1, "name": "cartesian", "seed": 9,
    "maps": ["free:w=20,h=20", "rooms:w=30,h=20,seed=1"],
    "strategies": [
      {"name": "energy_aware", "params": {"w1": [0, 10, 20], "w4": {"range": [0, 1], "step": 1}}},
      {"name": "closest_frontier"}
    ],
    "planners": ["astar", {"type": "dijkstra"}],
    "robot": {"battery": [100, 200]},
    "repetitions": 3
  })");
}

TEST(SweepPlan, MinimalSweepHasOneRunWithDefaults) {
  const SweepPlan plan = SweepPlan::from_json(minimal(), "s.json");
  EXPECT_EQ(plan.run_count(), 1U);
  EXPECT_EQ(plan.output_dir(), "results/t");
  EXPECT_EQ(plan.objective(), "distance_to_final_coverage_m");
  const RunSpec spec = plan.run_spec(0);
  EXPECT_EQ(spec.strategy.name, "closest_frontier");
  EXPECT_TRUE(given_params(plan, 0).is_null());
  EXPECT_EQ(spec.strategy.params, (json{{"distance", "path"}}));  // resolved: the defaults
  EXPECT_EQ(spec.planner.name, "astar");
  EXPECT_EQ(spec.seed, derive_seed(0, "repetition/0"));
  EXPECT_TRUE(plan.maps()[0].free_space);
  EXPECT_EQ(plan.robots()[0].label, "-");
}

TEST(SweepPlan, CartesianProductCount) {
  const SweepPlan plan = SweepPlan::from_json(cartesian(), "s.json");
  EXPECT_EQ(plan.configuration_count(), 2U * 7U * 2U * 2U);
  EXPECT_EQ(plan.run_count(), 2U * 7U * 2U * 2U * 3U);
  const auto axes = plan.axes();
  ASSERT_EQ(axes.size(), 5U);
  EXPECT_EQ(axes[0], (std::pair<std::string, std::uint64_t>{"maps", 2}));
  EXPECT_EQ(axes[1], (std::pair<std::string, std::uint64_t>{"strategy configurations", 7}));
  EXPECT_EQ(axes[2], (std::pair<std::string, std::uint64_t>{"planners", 2}));
  EXPECT_EQ(axes[3], (std::pair<std::string, std::uint64_t>{"robots", 2}));
  EXPECT_EQ(axes[4], (std::pair<std::string, std::uint64_t>{"repetitions", 3}));
}

TEST(SweepPlan, MixedRadixOrderRepetitionsFastestMapsSlowest) {
  const SweepPlan plan = SweepPlan::from_json(cartesian(), "s.json");
  EXPECT_EQ(plan.coordinates(1).repetition, 1);
  EXPECT_EQ(plan.coordinates(3).robot, 1U);  // after 3 repetitions
  EXPECT_EQ(plan.coordinates(3).repetition, 0);
  EXPECT_EQ(plan.coordinates(6).planner, 1U);          // after 2 robots x 3 repetitions
  EXPECT_EQ(plan.coordinates(12).strategy_combo, 1U);  // after 2 planners
  EXPECT_EQ(plan.coordinates(72).strategy_entry, 1U);  // after the 6 energy_aware combinations
  EXPECT_EQ(plan.coordinates(84).map, 1U);             // after 7 strategy configurations
  // Inside an entry the last parameter varies fastest: w4 (0, 1) before w1 (0, 10, 20).
  EXPECT_EQ(given_params(plan, 12), (json{{"w1", 0}, {"w4", 1}}));
  EXPECT_EQ(given_params(plan, 24), (json{{"w1", 10}, {"w4", 0}}));
  EXPECT_TRUE(given_params(plan, 72).is_null());
  EXPECT_THROW((void)plan.coordinates(plan.run_count()), std::out_of_range);
}

TEST(SweepPlan, RunSpecOfAnIndexEqualsAHandDecode) {
  const SweepPlan plan = SweepPlan::from_json(cartesian(), "s.json");
  // map 1, strategy configuration 4 (energy_aware combo 4: w1 = 20, w4 = 0), planner 1,
  // robot 0, repetition 2: (((1 * 7 + 4) * 2 + 1) * 2 + 0) * 3 + 2 = 140.
  const RunCoordinates c = plan.coordinates(140);
  EXPECT_EQ(c.map, 1U);
  EXPECT_EQ(c.strategy_entry, 0U);
  EXPECT_EQ(c.strategy_combo, 4U);
  EXPECT_EQ(c.planner, 1U);
  EXPECT_EQ(c.robot, 0U);
  EXPECT_EQ(c.repetition, 2);
  const RunSpec spec = plan.run_spec(140);
  EXPECT_EQ(spec.map.get(), plan.maps()[1].map.get());  // shared, not copied
  EXPECT_EQ(spec.strategy.name, "energy_aware");
  EXPECT_EQ(given_params(plan, 140), (json{{"w1", 20}, {"w4", 0}}));
  EXPECT_EQ(spec.strategy.params["w1"], 20.0);  // resolved: every parameter
  EXPECT_EQ(spec.strategy.params["w2"], 0.0);
  EXPECT_EQ(spec.planner.name, "dijkstra");
  EXPECT_EQ(spec.robot.battery_capacity, 100.0);
  EXPECT_EQ(spec.seed, derive_seed(9, "repetition/2"));
}

TEST(SweepPlan, RunSeedDependsOnlyOnTheRepetition) {
  const SweepPlan plan = SweepPlan::from_json(cartesian(), "s.json");
  for (std::uint64_t i = 0; i < plan.run_count(); ++i) {
    EXPECT_EQ(plan.run_spec(i).seed, derive_seed(9, "repetition/" + std::to_string(i % 3))) << i;
  }
  EXPECT_NE(plan.run_spec(0).seed, plan.run_spec(1).seed);
}

TEST(SweepPlan, ZipGroupVariesTogether) {
  json s = minimal();
  s["strategies"] = json::parse(R"([{"name": "energy_aware",
      "params": {"w1": [1, 2, 3], "w3": [4, 5, 6], "w4": [0, 1]}, "zip": [["w3", "w1"]]}])");
  const SweepPlan plan = SweepPlan::from_json(s, "s.json");
  const StrategyEntry& e = plan.strategies()[0];
  EXPECT_EQ(e.count(), 6U);  // 3 zipped pairs x 2, not 3 x 3 x 2
  ASSERT_EQ(e.groups.size(), 2U);
  EXPECT_EQ(e.groups[0].names, (std::vector<std::string>{"w3", "w1"}));  // zip order inside the group
  EXPECT_EQ(e.params_at(0), (json{{"w1", 1}, {"w3", 4}, {"w4", 0}}));
  EXPECT_EQ(e.params_at(1), (json{{"w1", 1}, {"w3", 4}, {"w4", 1}}));
  EXPECT_EQ(e.params_at(2), (json{{"w1", 2}, {"w3", 5}, {"w4", 0}}));
  EXPECT_EQ(e.params_at(5), (json{{"w1", 3}, {"w3", 6}, {"w4", 1}}));
}

TEST(SweepPlan, ExhaustiveWeightSearchIsCountedAndDecodedLazily) {
  json s = minimal();
  s["strategies"] = json::parse(R"([{"name": "energy_aware", "params": {
      "w1": {"range": [0, 250], "step": 1}, "w2": {"range": [0, 250], "step": 1},
      "w3": {"range": [0, 250], "step": 1}, "w4": {"range": [0, 250], "step": 1}}}])");
  s["repetitions"] = 2;
  const SweepPlan plan = SweepPlan::from_json(s, "s.json");
  const std::uint64_t weights = 251ULL * 251ULL * 251ULL * 251ULL;  // 3,969,126,001
  EXPECT_EQ(plan.configuration_count(), weights);
  EXPECT_EQ(plan.run_count(), 2 * weights);
  for (const auto& g : plan.strategies()[0].groups) EXPECT_EQ(g.combos.size(), 251U);  // 4 x 251 values held

  const RunCoordinates last = plan.coordinates(plan.run_count() - 1);
  EXPECT_EQ(last.strategy_combo, weights - 1);
  EXPECT_EQ(last.repetition, 1);
  EXPECT_EQ(given_params(plan, plan.run_count() - 1),
            (json{{"w1", 250}, {"w2", 250}, {"w3", 250}, {"w4", 250}}));
  const std::uint64_t combo = ((1ULL * 251 + 2) * 251 + 3) * 251 + 4;
  EXPECT_EQ(given_params(plan, combo * 2 + 1), (json{{"w1", 1}, {"w2", 2}, {"w3", 3}, {"w4", 4}}));
}

TEST(SweepPlan, MapSeedsExpandIntoOneMapPerSeed) {
  json s = minimal();
  s["maps"] = json::parse(R"([
      {"generator": "rooms", "w": 30, "h": 20, "label": "r", "seeds": {"range": [1, 3], "step": 1}},
      {"spec": "rooms:w=30,h=20", "seeds": [7, 8]}])");
  const SweepPlan plan = SweepPlan::from_json(s, "s.json");
  ASSERT_EQ(plan.maps().size(), 5U);
  EXPECT_EQ(plan.maps()[0].label, "r seed=1");
  EXPECT_EQ(plan.maps()[2].spec, (json{{"generator", "rooms"}, {"w", 30}, {"h", 20}, {"seed", 3}}));
  EXPECT_EQ(plan.maps()[3].label, "rooms:w=30,h=20,seed=7");
  EXPECT_EQ(plan.maps()[4].spec, (json{{"generator", "rooms"}, {"w", 30}, {"h", 20}, {"seed", 8}}));
  EXPECT_FALSE(plan.maps()[0].free_space);
  EXPECT_NE(plan.maps()[0].map->occupied.data(), plan.maps()[1].map->occupied.data());
  EXPECT_EQ(plan.run_count(), 5U);
}

TEST(SweepPlan, RobotLeavesSweepAsACartesianProductInPathOrder) {
  json s = minimal();
  s["robot"] = json::parse(R"({"sensor": {"range_m": {"range": [4, 8], "step": 2}}, "battery": [400, 800],
                               "dock": [1, 1], "energy": "mei2006"})");
  const SweepPlan plan = SweepPlan::from_json(s, "s.json");
  ASSERT_EQ(plan.robots().size(), 6U);
  // /battery sorts before /sensor/range_m, so battery varies slowest.
  EXPECT_EQ(plan.robots()[0].label, "battery=400 sensor.range_m=4");
  EXPECT_EQ(plan.robots()[1].label, "battery=400 sensor.range_m=6");
  EXPECT_EQ(plan.robots()[5].label, "battery=800 sensor.range_m=8");
  EXPECT_EQ(plan.robots()[4].params.sensor.range_m, 6.0);
  EXPECT_EQ(plan.robots()[4].params.battery_capacity, 800.0);
  for (const auto& r : plan.robots()) {
    EXPECT_EQ(r.params.dock, (Cell{1, 1}));  // [x, y] is one value, not a sweep
    EXPECT_EQ(r.params.energy.preset, "mei2006");
  }
}

TEST(SweepPlan, RobotArrayFieldsSweepAsListsOfArrays) {
  json s = minimal();
  s["robot"] = json::parse(R"({"dock": [[1, 1], [2, 3]], "energy": ["distance", {"preset": "mei2006"}]})");
  const SweepPlan plan = SweepPlan::from_json(s, "s.json");
  ASSERT_EQ(plan.robots().size(), 4U);
  EXPECT_EQ(plan.robots()[2].params.dock, (Cell{2, 3}));
  EXPECT_EQ(plan.robots()[1].params.energy.preset, "mei2006");
  EXPECT_EQ(plan.robots()[1].label, R"(dock=[1,1] energy={"preset":"mei2006"})");
}

TEST(SweepPlan, ProgressStepMayBeGivenAtTheTopLevel) {
  json s = minimal();
  s["progress_step_m"] = 2.5;
  EXPECT_EQ(SweepPlan::from_json(s, "s.json").sim().progress_step_m, 2.5);
}

// Guards against accidental changes of run keys, which would make every existing output
// unresumable: the key of the minimal sweep's only run, computed once with this build
// (FNV-1a 64 of the canonical JSON documented in sweep_plan.hpp).
TEST(SweepPlan, RunKeyGolden) {
  const SweepPlan plan = SweepPlan::from_json(minimal(), "s.json");
  EXPECT_EQ(plan.run_key(0), "7d398fd7110be79c");
  EXPECT_EQ(plan.run_key(0).size(), 16U);
}

TEST(SweepPlan, RunKeyChangesWithEverySingleField) {
  const json base = json::parse(R"({"schema_version": 1, "name": "k", "maps": ["free:w=20,h=20"],
      "strategies": [{"name": "energy_aware", "params": {"w1": 10}}], "robot": {"battery": 400}})");
  auto key = [](const json& s, std::uint64_t index = 0) {
    return SweepPlan::from_json(s, "s.json").run_key(index);
  };
  std::vector<json> variants;
  auto vary = [&](const std::string& pointer, const json& value) {
    json s = base;
    s[json::json_pointer(pointer)] = value;
    variants.push_back(s);
  };
  vary("/maps/0", "free:w=21,h=20");
  vary("/strategies/0/params/w1", 11);
  vary("/strategies/0", json{{"name", "closest_frontier"}});
  vary("/planners", json{"dijkstra"});
  vary("/robot/battery", 401);
  vary("/robot/sensor", json{{"range_m", 11}});
  vary("/robot/sensor", json{{"model", "beams"}});
  vary("/robot/sensor", json{{"beams", 90}});
  vary("/robot/dock", json{2, 2});
  vary("/sim", json{{"stuck_decisions", 50}});
  vary("/seed", 1);
  std::set<std::string> keys{key(base)};
  for (const auto& v : variants) EXPECT_TRUE(keys.insert(key(v)).second) << v.dump();
  json reps = base;
  reps["repetitions"] = 2;
  EXPECT_EQ(key(reps, 0), key(base));
  EXPECT_TRUE(keys.insert(key(reps, 1)).second);
}

TEST(SweepPlan, RunKeyIsTheSameForTheSameConfigurationInAnySweep) {
  const json base = json::parse(R"({"schema_version": 1, "name": "k", "maps": ["free:w=20,h=20"],
      "strategies": [{"name": "energy_aware", "params": {"w1": 10}}]})");
  const SweepPlan plan = SweepPlan::from_json(base, "s.json");
  const std::string key = plan.run_key(0);
  const Cell start = plan.maps()[0].map->start;

  json other = base;
  other["name"] = "other";
  other["description"] = "another sweep";
  other["maps"] =
      json::parse(R"(["rooms:w=30,h=20,seed=1", {"generator": "free", "w": 20, "h": 20, "label": "f"}])");
  other["strategies"] =
      json::parse(R"([{"name": "energy_aware", "label": "ea", "params": {"w1": [5, 10.0]}}])");
  // The default dock and the default sensor model, written out.
  other["robot"] = json{{"dock", {start.x, start.y}}, {"sensor", {{"model", "grid"}, {"beams", 360}}}};
  const SweepPlan o = SweepPlan::from_json(other, "o.json");
  ASSERT_EQ(o.run_count(), 4U);
  EXPECT_EQ(o.run_key(3), key);  // map 1, w1 = 10.0: defaults resolved, labels ignored
  EXPECT_NE(o.run_key(2), key);
}

TEST(SweepPlan, AnOverriddenSweepIsTheSweepItBecomesInHashAndKeys) {
  const std::string dir = testing::fresh_dir("plan", "overridden");
  testing::write_file(dir + "/s.json", cartesian().dump());
  json written = cartesian();
  written["robot"]["battery"] = 800;
  written["seed"] = 3;
  const SweepPlan overridden = SweepPlan::from_file(dir + "/s.json", {"robot.battery=800", "seed=3"});
  const SweepPlan plain = SweepPlan::from_json(written, dir + "/w.json");
  EXPECT_EQ(overridden.source(), written);
  EXPECT_EQ(sweep_hash(overridden.source()), sweep_hash(written));  // so a resume with the same ones matches
  ASSERT_EQ(overridden.run_count(), plain.run_count());
  for (std::uint64_t i = 0; i < plain.run_count(); i += 7) EXPECT_EQ(overridden.run_key(i), plain.run_key(i));
}

/// A checkout-like folder: <root>/sweeps/s.json naming `file` for its map, and the ASCII map
/// <root>/maps/two_rooms.txt.
std::string checkout_with_sweep(const std::string& root, const std::string& file) {
  std::filesystem::create_directories(root + "/sweeps");
  std::filesystem::create_directories(root + "/maps");
  std::filesystem::copy_file(FSWEEP_TEST_DATA "/two_rooms.txt", root + "/maps/two_rooms.txt");
  testing::write_file(root + "/sweeps/s.json", R"({"schema_version": 1, "name": "t",
      "maps": [{"file": ")" + file + R"(", "label": "rooms"}, ")" +
                                                   file + R"(:res=0.5"],
      "strategies": [{"name": "closest_frontier"}], "robot": {"sensor": {"range_m": 3}}})");
  return root + "/sweeps/s.json";
}

TEST(SweepPlan, RelativePathsAreFoundBesideTheSweepFileAndKeptAsWritten) {
  const std::string dir = testing::fresh_dir("plan", "relative");
  const std::filesystem::path before = std::filesystem::current_path();
  std::filesystem::current_path(std::filesystem::temp_directory_path());
  const SweepPlan here = SweepPlan::from_file(checkout_with_sweep(dir + "/a", "../maps/two_rooms.txt"));
  const SweepPlan there = SweepPlan::from_file(checkout_with_sweep(dir + "/b/c", "../maps/two_rooms.txt"));
  std::filesystem::current_path(before);
  EXPECT_TRUE(here.path_warnings().empty());
  for (const SweepMap& m : here.maps()) {
    EXPECT_EQ(m.spec["file"], "../maps/two_rooms.txt");  // what run keys hash
    EXPECT_EQ(m.map->source, "../maps/two_rooms.txt");   // runs.csv's map column, the manifest
  }
  EXPECT_EQ(here.maps()[1].label, "../maps/two_rooms.txt:res=0.5");
  // Two checkouts in different places: the same keys.
  for (std::uint64_t i = 0; i < here.run_count(); ++i) EXPECT_EQ(here.run_key(i), there.run_key(i));
}

TEST(SweepPlan, APathOnlyUnderTheWorkingDirectoryIsReadFromThereWithAWarning) {
  const std::string dir = testing::fresh_dir("plan", "fallback");
  const std::string sweep = checkout_with_sweep(dir, "maps/two_rooms.txt");  // as sweeps used to be written
  const std::filesystem::path before = std::filesystem::current_path();
  std::filesystem::current_path(dir);
  const SweepPlan plan = SweepPlan::from_file(sweep);
  const SweepPlan written_beside = SweepPlan::from_json(plan.source(), "s.json");  // in the working directory
  std::filesystem::current_path(before);
  ASSERT_EQ(plan.path_warnings().size(), 2U);
  EXPECT_EQ(plan.path_warnings()[0],
            "/maps/0/file: 'maps/two_rooms.txt' is not beside the sweep file (no " + dir +
                "/sweeps/maps/two_rooms.txt); read from the working directory instead (" + dir +
                "/maps/two_rooms.txt), which is tried when a relative path is not beside the "
                "sweep file; write '../maps/two_rooms.txt'");
  EXPECT_EQ(plan.path_warnings()[1].rfind("/maps/1: 'maps/two_rooms.txt' is not beside the sweep file", 0),
            0U);
  EXPECT_EQ(sweep_warnings(plan).front(), plan.path_warnings().front());  // printed and in the manifest
  EXPECT_TRUE(written_beside.path_warnings().empty());
  EXPECT_EQ(plan.run_key(0), written_beside.run_key(0));
}

TEST(SweepPlan, ARelativePathInNeitherFolderNamesTheAbsolutePathsTried) {
  const std::string dir = testing::fresh_dir("plan", "neither");
  const std::string sweep = checkout_with_sweep(dir, "nowhere/x.txt");
  std::string m;
  try {
    (void)SweepPlan::from_file(sweep);
  } catch (const ConfigError& e) {
    m = e.what();
  }
  const std::string cwd = std::filesystem::current_path().string();
  EXPECT_NE(m.find(sweep + ": /maps/0/file: no such file 'nowhere/x.txt': tried " + dir +
                   "/sweeps/nowhere/x.txt (beside the sweep file) and " + cwd +
                   "/nowhere/x.txt (in the working directory)"),
            std::string::npos)
      << m;
  EXPECT_NE(m.find(sweep + ": /maps/1: no such file 'nowhere/x.txt'"), std::string::npos) << m;
}

}  // namespace
}  // namespace fsweep
