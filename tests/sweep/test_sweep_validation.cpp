// Sweep validation: every problem at once, each with its JSON path, the bad value and what is
// allowed; files that cannot be read or parsed; the shipped example sweeps.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/config_error.hpp"
#include "sweep/sweep_json_reader.hpp"
#include "sweep/sweep_plan.hpp"
#include "sweep/sweep_table.hpp"

namespace fsweep {
namespace test_sweep_validation {  // not anonymous: unity builds put it beside other test files' helpers

using nlohmann::json;

json minimal() {
  return json::parse(R"({"schema_version": 1, "name": "t", "maps": ["free:w=20,h=20"],
                         "strategies": [{"name": "closest_frontier"}]})");
}

/// The ConfigError message of an invalid sweep ("" when it is valid).
std::string problems_of(const json& sweep) {
  try {
    (void)SweepPlan::from_json(sweep, "s.json");
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.where(), "s.json");
    return e.what();
  }
  return "";
}

std::string write_temp(const std::string& name, const std::string& text) {
  const auto path =
      std::filesystem::temp_directory_path() / ("fsweep_" + std::to_string(getpid()) + "_" + name);
  std::ofstream(path) << text;
  return path.string();
}

std::string from_file_error(const std::string& path) {
  try {
    (void)SweepPlan::from_file(path);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

#define EXPECT_HAS(haystack, needle) EXPECT_NE((haystack).find(needle), std::string::npos) << (haystack)

TEST(SweepValidation, ReportsEveryProblemAtOnceWithPathsAndAllowedValues) {
  json s = minimal();
  s["colour"] = "red";
  s["maps"] = json::parse(R"(["free:w=20,h=20", {"generator": "rooms", "w": 30, "h": 20, "doors": 3},
                              {"file": "/nonexistent/missing.map"}])");
  s["strategies"] = json::parse(R"([{"name": "energy_awre"},
      {"name": "energy_aware", "params": {"w1": {"range": [0, 260], "step": 10}}}])");
  const std::string m = problems_of(s);
  EXPECT_EQ(m.rfind("s.json: 5 problems in the sweep:\n", 0), 0U) << m;
  EXPECT_HAS(m, "\ns.json: /colour: unknown key 'colour'; allowed: schema_version, name,");
  EXPECT_HAS(m,
             "\ns.json: /maps/1/doors: unknown key 'doors'; allowed: w, h, res, seed, "
             "start, door");
  EXPECT_HAS(m, "\ns.json: /maps/2");
  EXPECT_HAS(m, "/nonexistent/missing.map: cannot open the file");
  EXPECT_HAS(
      m,
      "\ns.json: /strategies/0/name: unknown strategy 'energy_awre'; known: closest_frontier, energy_aware, "
      "gbl, mcdm, orientation, random_frontier, target_seeking, widest_frontier");
  EXPECT_HAS(
      m, "\ns.json: /strategies/1/params/w1/range: value 260 out of range; allowed: a number in [0, 250]");
}

TEST(SweepValidation, OneProblemPerAxisWithTheCountOfOtherBadValues) {
  json s = minimal();
  s["strategies"] =
      json::parse(R"([{"name": "energy_aware", "params": {"w1": [5, 300, 400], "w2": [-1, -2]}}])");
  const std::string m = problems_of(s);
  EXPECT_HAS(m,
             "/strategies/0/params/w1/1: value 300 out of range; allowed: a number in [0, 250] (and 1 more");
  EXPECT_HAS(m,
             "/strategies/0/params/w2: value -1 out of range; allowed: a number in [0, 250] (all 2 values");
  EXPECT_HAS(m, "2 problems");
}

TEST(SweepValidation, UnknownParameterOfAStrategyIsAProblem) {
  json s = minimal();
  s["strategies"][0]["params"] = json{{"w1", 3}};
  EXPECT_HAS(problems_of(s), "s.json: /strategies/0/params/w1: unknown key 'w1'; allowed: distance");
}

TEST(SweepValidation, ZipGroupsNeedEqualLengthsAndKnownParameters) {
  json s = minimal();
  s["strategies"] = json::parse(R"([{"name": "energy_aware", "params": {"w1": [1, 2, 3], "w3": [4, 5]},
                                     "zip": [["w1", "w3"], ["w9"]]}])");
  const std::string m = problems_of(s);
  EXPECT_HAS(m,
             "/strategies/0/zip/0: zipped parameters vary together and need equal numbers of values; got w1: "
             "3, w3: 2");
  EXPECT_HAS(m, "/strategies/0/zip/1/0: 'w9' is not a parameter of this entry; allowed: w1, w3");
}

TEST(SweepValidation, RepetitionsStateTheRealLimit) {
  // The repetition index is an int: 2^31 - 1 is the most; 1e15 (a JSON float) is refused with
  // that limit, not as "not an integer >= 1".
  json s = minimal();
  s["repetitions"] = 2147483647;
  EXPECT_EQ(problems_of(s), "");
  for (const json& bad : {json(2147483648LL), json(1e15), json(2.5)}) {
    s["repetitions"] = bad;
    EXPECT_HAS(
        problems_of(s),
        "/repetitions: value " + bad.dump() +
            " not allowed; allowed: an integer from 1 to 2147483647 (2^31 - 1, the repetition index is "
            "a 32-bit integer), written without a decimal point or exponent");
  }
}

TEST(SweepValidation, TopLevelScalars) {
  json s = minimal();
  s.erase("schema_version");
  s["name"] = "my sweep";
  s["repetitions"] = 0;
  s["seed"] = -3;
  s["output"] = json{{"objective", "speed"}, {"format", "csv"}};
  const std::string m = problems_of(s);
  EXPECT_HAS(m, "/schema_version: missing; allowed: 1");
  EXPECT_HAS(m, "/name: value \"my sweep\" not allowed; allowed: a string of letters, digits");
  EXPECT_HAS(m, "/repetitions: value 0 not allowed; allowed: an integer from 1 to 2147483647");
  EXPECT_HAS(m, "/seed: value -3 not allowed");
  EXPECT_HAS(m, "/output/format: unknown key 'format'; allowed: dir, objective");
  s["output"] = json{{"objective", "speed"}};
  EXPECT_HAS(problems_of(s),
             "/output/objective: value \"speed\" not allowed; allowed: distance_to_final_coverage_m, "
             "area_per_metre, energy");
  json v2 = minimal();
  v2["schema_version"] = 2;
  EXPECT_HAS(problems_of(v2), "/schema_version: value 2 not supported; allowed: 1");
}

TEST(SweepValidation, MissingAxesAreProblems) {
  const std::string m = problems_of(json{{"schema_version", 1}, {"name", "x"}});
  EXPECT_HAS(m, "/maps: expected a non-empty list of maps");
  EXPECT_HAS(m, "/strategies: expected a non-empty list");
}

TEST(SweepValidation, MapProblems) {
  json s = minimal();
  s["maps"] = json::parse(R"([{"file": ")" FSWEEP_TEST_DATA R"(/arena.map", "seeds": [1, 2]},
      {"generator": "rooms", "w": 30, "h": 20, "seed": 1, "seeds": [1, 2]},
      {"generator": "rooms", "w": 30, "h": 20, "seeds": [1, -2]},
      "free:w=20,h=20,res=1", {"generator": "free", "w": 20, "h": 20, "res": 1.0}, 5])");
  const std::string m = problems_of(s);
  EXPECT_HAS(m, "/maps/0/seeds: seeds apply to generated maps only");
  EXPECT_HAS(m, "/maps/1/seeds: give either 'seed' or 'seeds', not both");
  EXPECT_HAS(m, "/maps/2/seeds/1: seed -2 not allowed; allowed: integers >= 0");
  EXPECT_HAS(m, "/maps/4: the same map as /maps/3 (free:h=20,res=1.0,w=20); allowed: each map once");
  EXPECT_HAS(m, "/maps/5: expected a SPEC string or an object, got 5");
}

TEST(SweepValidation, PlannerProblems) {
  json s = minimal();
  s["planners"] = json::parse(R"(["rrt", {"type": "astar", "params": {"radius": 1}}, {"kind": "astar"}])");
  const std::string m = problems_of(s);
  EXPECT_HAS(m, "/planners/0: unknown planner 'rrt'; known: astar, dijkstra, jps, lattice, lattice_astar");
  EXPECT_HAS(m, "/planners/1/params/radius: unknown key 'radius'");
  EXPECT_HAS(m, "/planners/2/kind: unknown key 'kind'; allowed: type, params");
}

TEST(SweepValidation, RobotProblemsAtTheirPaths) {
  json s = minimal();
  s["robot"] = json::parse(R"({"sensor": {"range_m": [5, -1]}, "battery": [400, 0]})");
  const std::string m = problems_of(s);
  EXPECT_HAS(m, "/robot/sensor/range_m/1: value -1 out of range; allowed: a number > 0");
  EXPECT_HAS(m, "/robot/battery/1: value 0 out of range; allowed: a number > 0, or null");
  s["robot"] = json::parse(R"({"sensor": {"range_m": [5, -1]}, "battery": [0, 400]})");  // a bad first value
  const std::string m1 = problems_of(s);
  EXPECT_HAS(m1, "/robot/sensor/range_m/1: ");
  EXPECT_HAS(m1, "/robot/battery/0: value 0 out of range; allowed: a number > 0, or null");
  s["robot"] = json::parse(R"({"dock": [0, 0], "sensor": {"range_m": 1}, "wheels": 3})");
  const std::string m2 = problems_of(s);
  EXPECT_HAS(m2, "/robot/wheels: unknown key 'wheels'");
  s["robot"].erase("wheels");
  const std::string m3 = problems_of(s);
  EXPECT_HAS(m3,
             "/robot/dock: cell (0, 0) is outside or occupied in map free:w=20,h=20; allowed: a free cell");
  EXPECT_HAS(m3, "/robot/sensor/range_m: value 1.0 m is below one diagonal cell");
  s["robot"]["sensor"]["range_m"] = 5000;  // 5000 cells of 1 m
  EXPECT_HAS(problems_of(s),
             "/robot/sensor/range_m: value 5000.0 m is 5000.0 cells of map free:w=20,h=20; "
             "allowed: at most 2000 cells (2000.0 m)");
}

TEST(SweepValidation, ProgressStepInTwoPlacesIsAProblem) {
  json s = minimal();
  s["progress_step_m"] = 2;
  s["sim"] = json{{"progress_step_m", 3}};
  EXPECT_HAS(problems_of(s), "/progress_step_m: also given as /sim/progress_step_m; allowed: one of the two");
  s.erase("progress_step_m");
  s["sim"] = json{{"max_step", 3}};
  EXPECT_HAS(problems_of(s), "/sim/max_step: unknown key 'max_step'");
}

TEST(SweepValidation, FromFileMissingNamesTheFile) {
  const std::string m = from_file_error("/nonexistent/sweep.json");
  EXPECT_EQ(m, "/nonexistent/sweep.json: cannot read the sweep file: no such file");
}

TEST(SweepValidation, FromFileBadJsonNamesLineAndColumn) {
  const std::string path = write_temp("bad.json", "{\n  \"name\": \"x\",\n  \"maps\": [1,,]\n}\n");
  const std::string m = from_file_error(path);
  EXPECT_EQ(m.rfind(path + ":3:14: invalid JSON: syntax error", 0), 0U) << m;
  std::filesystem::remove(path);
}

TEST(SweepValidation, FromFileDeepNestingIsRefusedWithLineColumnAndPath) {
  // 100,000 levels (200 KB): printing or copying such a value recursively overflows the stack.
  const std::string head = R"({"schema_version": 1, "name": "t", "maps": )";
  const std::string path =
      write_temp("deep.json", head + std::string(100'000, '[') + std::string(100'000, ']') + "}\n");
  const std::string m = from_file_error(path);
  // Level 65 (the object is level 1, "maps" level 2) opens at column head + 63 + 1.
  std::string json_path = "/maps";
  for (int i = 0; i < kMaxSweepNesting - 1; ++i) json_path += "/0";
  EXPECT_EQ(m, path + ":1:" + std::to_string(head.size() + 64) + ": " + json_path +
                   ": arrays and objects are nested more than 64 levels deep; allowed: at most 64 levels");
  std::filesystem::remove(path);
}

TEST(SweepValidation, FromFileNumberOverflowNamesLineColumnAndPath) {
  const std::string path = write_temp("overflow.json", "{\"schema_version\": 1,\n  \"seed\": [1, -1e400]}\n");
  EXPECT_EQ(from_file_error(path), path +
                                       ":2:15: /seed/1: number -1e400 is out of range; allowed: numbers of "
                                       "magnitude below 1.8e308 (a double)");
  std::filesystem::remove(path);
}

TEST(SweepValidation, HugeValuesAreCutInMessages) {
  json s = minimal();
  s["description"] = json(std::vector<int>(100'000, 1));
  s["name"] = std::string(200'000, '!');
  s["maps"] = json::array({json{{"file", std::vector<int>(100'000, 2)}}});
  s["robot"] = json{{"dock", std::vector<int>(100'000, 3)}};
  const std::string m = problems_of(s);
  EXPECT_HAS(m, "/description: expected a string, got [1,1,1,");
  EXPECT_HAS(m, "/name: value \"!!!!");
  EXPECT_HAS(m, "/maps/0/file: 'file' must be a non-empty path string, got [2,2,2,");
  EXPECT_HAS(m, "/robot/dock: value [3,3,3,");
  EXPECT_LT(m.size(), 1000U) << m.substr(0, 3000);
}

TEST(SweepValidation, FromFileDuplicateKeysAreProblems) {
  const std::string path = write_temp("dup.json", R"({"schema_version": 1, "name": "a", "name": "b",
      "maps": [{"generator": "free", "w": 20, "w": 30, "h": 20}], "strategies": [{"name": "closest_frontier"}]})");
  const std::string m = from_file_error(path);
  EXPECT_HAS(m, path + ": /name: duplicate key 'name'");
  EXPECT_HAS(m, path + ": /maps/0/w: duplicate key 'w'");
  std::filesystem::remove(path);
}

TEST(SweepValidation, FromFileReadsAValidSweep) {
  const std::string path = write_temp("ok.json", minimal().dump(2));
  const SweepPlan plan = SweepPlan::from_file(path);
  EXPECT_EQ(plan.name(), "t");
  EXPECT_EQ(plan.source(), minimal());
  std::filesystem::remove(path);
}

TEST(SweepValidation, ShippedExamplesAreValid) {
  // Examples name their map files relative to the repository (houseexpo.json), as the README
  // runs them.
  const std::filesystem::path before = std::filesystem::current_path();
  std::filesystem::current_path(FSWEEP_SOURCE_DIR);
  int n = 0;
  for (const auto& entry : std::filesystem::directory_iterator("sweeps/examples")) {
    if (entry.path().extension() != ".json") continue;
    EXPECT_NO_THROW((void)SweepPlan::from_file(entry.path().string())) << entry.path();
    ++n;
  }
  std::filesystem::current_path(before);
  EXPECT_GE(n, 4);
}

TEST(SweepValidation, TheBaselineIsAStrategyEntrysLabel) {
  json sweep = minimal();
  sweep["strategies"].push_back(json::parse(R"({"name": "energy_aware", "label": "EA"})"));
  sweep["baseline"] = "EA";
  EXPECT_EQ(problems_of(sweep), "");
  sweep["baseline"] = "closest_frontier";  // an entry without a label is named by its strategy
  EXPECT_EQ(problems_of(sweep), "");
  sweep["baseline"] = "CF";
  EXPECT_NE(
      problems_of(sweep).find("/baseline: value \"CF\" not allowed; allowed: a strategy entry's label (the "
                              "side fsweep paired and fsweep report compare the others with): "
                              "closest_frontier, EA"),
      std::string::npos)
      << problems_of(sweep);
  sweep["baseline"] = 3;
  EXPECT_NE(problems_of(sweep).find("/baseline: value 3 not allowed"), std::string::npos);
}

TEST(SweepValidation, NoShippedSweepClipsTheFreeSpaceOptimumOrRepeatsIdenticalRuns) {
  // Every free map of the shipped sweeps holds the disc its robots can reach, the sensor band and
  // one cell (sweep_table.hpp's star_optimum()): no sweep prints the clipped-map warning; and no
  // shipped sweep has repetitions with nothing random in them (sweep_table.hpp). The paper
  // sweeps name their maps relative to the repository, so they load from there.
  const std::filesystem::path before = std::filesystem::current_path();
  std::filesystem::current_path(FSWEEP_SOURCE_DIR);
  int n = 0;
  for (const char* folder : {"sweeps", "sweeps/examples", "sweeps/paper"}) {
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
      if (entry.path().extension() != ".json") continue;
      const SweepPlan plan = SweepPlan::from_file(entry.path().string());
      EXPECT_TRUE(clipped_free_space_warnings(plan).empty()) << entry.path();
      EXPECT_TRUE(identical_repetition_warnings(plan).empty()) << entry.path();
      ++n;
    }
  }
  std::filesystem::current_path(before);
  EXPECT_GE(n, 30);
}

}  // namespace test_sweep_validation
}  // namespace fsweep
