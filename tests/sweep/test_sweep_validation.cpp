// Sweep validation: every problem at once, each with its JSON path, the bad value and what is
// allowed; files that cannot be read or parsed; the shipped example sweeps.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/config_error.hpp"
#include "strategies/registry.hpp"
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

TEST(SweepValidation, CompetitiveIsABooleanAtTheTopOrPerMapItemAndTheItemWins) {
  json s = minimal();
  s["competitive"] = "yes";
  s["maps"] = json::parse(R"(["free:w=20,h=20", {"spec": "rooms:w=30,h=24,door=2,seed=1", "competitive": 1},
                              {"dataset": "nowhere", "competitive": null}])");
  const std::string p = problems_of(s);
  EXPECT_HAS(p, "s.json: /competitive: value \"yes\" not allowed; allowed: true");
  EXPECT_HAS(p, "s.json: /maps/1/competitive: value 1 not allowed; allowed: true");
  EXPECT_HAS(p, "s.json: /maps/2/competitive: value null not allowed");
  // Resolved: the top-level value, unless the item gives its own; not part of run keys.
  s = minimal();
  s["competitive"] = true;
  s["maps"] =
      json::parse(R"(["free:w=20,h=20", {"spec": "rooms:w=30,h=24,door=2,seed=1", "competitive": false},
                              {"generator": "rooms", "w": 30, "h": 24, "seeds": [2, 3]}])");
  const SweepPlan plan = SweepPlan::from_json(s, "s.json");
  ASSERT_EQ(plan.maps().size(), 4U);
  EXPECT_TRUE(plan.maps()[0].competitive);
  EXPECT_FALSE(plan.maps()[1].competitive);
  EXPECT_TRUE(plan.maps()[2].competitive);
  EXPECT_TRUE(plan.maps()[3].competitive);
  EXPECT_TRUE(plan.competitive());
  json plain = s;
  plain.erase("competitive");
  plain["maps"][1].erase("competitive");
  const SweepPlan without = SweepPlan::from_json(plain, "s.json");
  EXPECT_FALSE(without.competitive());
  for (std::uint64_t i = 0; i < plan.run_count(); ++i) EXPECT_EQ(plan.run_key(i), without.run_key(i));
  // The columns: only with a competitive map, last, after the free-space ones.
  const std::vector<std::string> with = SweepTable(plan).columns();
  const std::vector<std::string> none = SweepTable(without).columns();
  EXPECT_EQ(std::vector<std::string>(with.begin(), with.begin() + static_cast<std::ptrdiff_t>(none.size())),
            none);
  EXPECT_EQ(std::vector<std::string>(with.begin() + static_cast<std::ptrdiff_t>(none.size()), with.end()),
            std::vector<std::string>(kCompetitiveColumns.begin(), kCompetitiveColumns.end()));
}

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

TEST(SweepValidation, ZippedParametersMayRepeatValuesButNotTuples) {
  // (1, 2) and (1, 3) are different runs; a repeated (1, 2) would be the same run twice; a
  // parameter outside the zip may not repeat a value.
  json s = minimal();
  s["strategies"] = json::parse(R"([{"name": "energy_aware", "params": {"w1": [1, 1, 2], "w3": [2, 3, 2]},
                                     "zip": [["w1", "w3"]]}])");
  EXPECT_EQ(problems_of(s), "");
  EXPECT_EQ(SweepPlan::from_json(s, "s.json").strategies()[0].count(), 3U);
  s["strategies"][0]["params"]["w3"] = json{2, 3, 2, 3};
  s["strategies"][0]["params"]["w1"] = json{1, 1, 2, 1};
  EXPECT_HAS(
      problems_of(s),
      "/strategies/0/zip/0: tuple 3 (w1 = 1, w3 = 3) repeats tuple 1; allowed: distinct tuples (repeated "
      "ones would be the same runs)");
  s["strategies"][0]["params"]["w4"] = json{5, 5};
  EXPECT_HAS(problems_of(s), "/strategies/0/params/w4/1: value 5 repeats an earlier element");
  // Heuristics zipped with a weight: the same list of heuristics twice, with different weights.
  json h = minimal();
  h["strategies"] = json::parse(R"([{"name": "energy_aware", "params": {"w1": [1, 2]},
                                     "heuristics": [["rr"], ["rr"]], "zip": [["heuristics", "w1"]]}])");
  EXPECT_EQ(problems_of(h), "");
}

TEST(SweepValidation, WholeVectorsAreOneZippedGroupOfTuples) {
  json s = minimal();
  // The shorthand: a linear-scored strategy's weights in its order; times another parameter.
  s["strategies"] = json::parse(R"([{"name": "energy_aware",
      "vectors": [[10, 0, 9, 20], [220, 21, 104, 100], [10, 0, 9, 21]], "params": {"unit": ["m", "cell"]}}])");
  const SweepPlan plan = SweepPlan::from_json(s, "s.json");
  const StrategyEntry& e = plan.strategies()[0];
  EXPECT_EQ(e.count(), 6U);
  EXPECT_EQ(e.params_at(0), (json{{"unit", "m"}, {"w1", 10}, {"w2", 0}, {"w3", 9}, {"w4", 20}}));
  EXPECT_EQ(e.params_at(4), (json{{"unit", "cell"}, {"w1", 220}, {"w2", 21}, {"w3", 104}, {"w4", 100}}))
      << e.params_at(4).dump();
  // Named parameters, and a CSV file beside the sweep file (integers stay integers).
  s["strategies"] = json::parse(
      R"([{"name": "energy_aware", "vectors": {"params": ["w3", "w1"], "values": [[9, 1], [0, 2]]}}])");
  EXPECT_EQ(SweepPlan::from_json(s, "s.json").strategies()[0].params_at(1), (json{{"w1", 2}, {"w3", 0}}));
  const std::string csv = write_temp("vectors.csv", "w1,w2,w3,w4\n10,0,9,20\n220,21,104,100.5\n");
  s["strategies"] = json{
      {{"name", "energy_aware"}, {"vectors", {{"file", std::filesystem::path(csv).filename().string()}}}}};
  const SweepPlan from_csv =
      SweepPlan::from_json(s, (std::filesystem::path(csv).parent_path() / "s.json").string());
  ASSERT_EQ(from_csv.strategies()[0].count(), 2U);
  EXPECT_EQ(from_csv.strategies()[0].params_at(0).dump(), R"({"w1":10,"w2":0,"w3":9,"w4":20})");
  EXPECT_EQ(from_csv.strategies()[0].params_at(1).at("w4"), 100.5);
  std::filesystem::remove(csv);
}

TEST(SweepValidation, WholeVectorsThatDoNotFitAreProblems) {
  json s = minimal();
  const auto problem = [&](const char* entry) {
    s["strategies"] = json::array({json::parse(entry)});
    return problems_of(s);
  };
  EXPECT_HAS(
      problem(R"({"name": "energy_aware", "vectors": [[1, 2, 3, 4], [1, 2, 3]]})"),
      "/strategies/0/vectors/1: value [1,2,3] not allowed; allowed: one value for each of w1, w2, w3, w4");
  EXPECT_HAS(problem(R"({"name": "energy_aware", "vectors": [[1, 2, 3, 4], [5, 6, 7, 8], [1, 2, 3, 4]]})"),
             "/strategies/0/vectors: tuple 2 (w1 = 1, w2 = 2, w3 = 3, w4 = 4) repeats tuple 0");
  EXPECT_HAS(problem(R"({"name": "energy_aware", "vectors": [[1, 2, 3, 4]], "params": {"w2": [0, 1]}})"),
             "/strategies/0/vectors: parameter 'w2' is also in params; allowed: each parameter in one place");
  EXPECT_HAS(problem(R"({"name": "random_frontier", "vectors": [[1]]})"),
             "/strategies/0/vectors: a list of vectors names no parameters and this strategy has no weights");
  EXPECT_HAS(
      problem(R"({"name": "energy_aware", "vectors": [[1, 2, 3, 4]], "search": {"mode": "all"}})"),
      "/strategies/0/vectors: a search covers the whole box of its weights; allowed: vectors or search");
  EXPECT_HAS(problem(R"({"name": "energy_aware", "vectors": [[-1, 2, 3, 4]]})"), "/strategies/0/vectors");
  EXPECT_HAS(problem(R"({"name": "energy_aware", "vectors": {"file": "no_such_vectors.csv"}})"),
             "/strategies/0/vectors/file");
  EXPECT_HAS(
      problem(R"({"name": "energy_aware", "vectors": {"params": ["w1"]}})"),
      "/strategies/0/vectors: value {\"params\":[\"w1\"]} not allowed; allowed: a list of weight vectors");
  const std::string csv = write_temp("bad_vectors.csv", "w1,w2\n1,x\n");
  s["strategies"] = json{{{"name", "energy_aware"}, {"vectors", {{"file", csv}}}}};
  EXPECT_HAS(problems_of(s), csv + ":2: column w2: 'x' is not a number");
  std::filesystem::remove(csv);
}

TEST(SweepValidation, TheSameConfigurationFromTwoEntriesIsCaughtWhenRead) {
  json s = minimal();
  const auto problems_with = [&](const char* strategies) {
    s["strategies"] = json::parse(strategies);
    return problems_of(s);
  };
  // Two labels, one configuration: w1 = 2 (1.0 and 1 are one value too).
  EXPECT_HAS(
      problems_with(R"([{"name": "energy_aware", "label": "a", "params": {"w1": [1, 2]}},
                               {"name": "energy_aware", "label": "b", "params": {"w1": [2.0, 3]}}])"),
      "/strategies/1: the same configuration as /strategies/0 (energy_aware: w1 = 2); a label is not part "
      "of a run's identity, so both entries would run it; allowed: each configuration in one entry");
  // Defaults filled in: closest frontier with nothing set twice; energy_aware's declared default
  // of w2 written out in one entry.
  EXPECT_HAS(problems_with(R"([{"name": "closest_frontier"}, {"name": "closest_frontier", "label": "CF2"}])"),
             "/strategies/1: the same configuration as /strategies/0 (closest_frontier)");
  const json w2 = strategy_registry().params("energy_aware").at(1).default_value;
  s["strategies"] = json::array({json{{"name", "energy_aware"}, {"params", {{"w1", 4}}}},
                                 json{{"name", "energy_aware"}, {"params", {{"w1", 4}, {"w2", w2}}}}});
  EXPECT_HAS(problems_of(s), "/strategies/1: the same configuration as /strategies/0");
  // Disjoint values, another strategy, another unit: no overlap.
  EXPECT_EQ(problems_with(R"([{"name": "energy_aware", "params": {"w1": [1, 2]}},
                              {"name": "energy_aware", "params": {"w1": [3, 4]}},
                              {"name": "energy_aware", "params": {"w1": [1, 2], "unit": "cell"}},
                              {"name": "closest_frontier"}])"),
            "");
  // Zipped tuples compare as tuples: (1, 3) is not among (1, 2), (2, 3); (2, 3) is.
  const char* zipped =
      R"({"name": "energy_aware", "params": {"w1": [1, 2], "w3": [2, 3]}, "zip": [["w1", "w3"]]})";
  EXPECT_EQ(problems_with(
                (std::string("[") + zipped + R"(, {"name": "energy_aware", "params": {"w1": 1, "w3": 3}}])")
                    .c_str()),
            "");
  EXPECT_HAS(
      problems_with(
          (std::string("[") + zipped +
           R"(, {"name": "energy_aware", "vectors": {"params": ["w3", "w1"], "values": [[9, 9], [3, 2]]}}])")
              .c_str()),
      "/strategies/1: the same configuration as /strategies/0 (energy_aware: w1 = 2, w3 = 3)");
  // Billions of configurations each, lazily: the value sets intersect.
  EXPECT_HAS(problems_with(R"([{"name": "energy_aware", "params": {"w1": {"range": [0, 250], "step": 1},
                                  "w2": {"range": [0, 250], "step": 1}, "w3": {"range": [0, 250], "step": 1},
                                  "w4": {"range": [0, 250], "step": 1}}},
                               {"name": "energy_aware", "label": "paper", "params": {"w1": 220, "w2": 21, "w3": 104, "w4": 100}}])"),
             "/strategies/1: the same configuration as /strategies/0 (energy_aware: w1 = 220, w2 = 21, w3 = "
             "104, w4 = 100)");
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
             "area_per_metre, energy, distance_to_coverage_target_m");
  // The distance to a coverage target needs the target.
  s["output"] = json{{"objective", "distance_to_coverage_target_m"}};
  EXPECT_HAS(
      problems_of(s),
      "/output/objective: distance_to_coverage_target_m needs a coverage target, /sim/stop_at_coverage "
      "in (0, 1]");
  s["sim"] = json{{"stop_at_coverage", 1.2}};
  EXPECT_HAS(problems_of(s), "sim/stop_at_coverage");
  s["sim"] = json{{"stop_at_coverage", 0.9}};
  const std::string fine = problems_of(s);
  EXPECT_EQ(fine.find("stop_at_coverage"), std::string::npos) << fine;
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
  EXPECT_HAS(m,
             "/planners/0: unknown planner 'rrt'; known: astar, dijkstra, jps, jps+, lattice, lattice_astar");
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

TEST(SweepValidation, AMisspeltKeyWhereTheRobotTakesAnObjectIsAnUnknownKeyNotARange) {
  // {"range": ...} is a sweep range only where a value is swept; in the sensor and an energy model
  // an object is that object, so a misspelt key gets the reader's message with the keys allowed
  // (as `fsweep sim --robot sensor.range=5`).
  json s = minimal();
  s["robot"] = json::parse(R"({"sensor": {"range": 5}})");
  std::string m = problems_of(s);
  EXPECT_HAS(
      m,
      "/robot/sensor/range: unknown key 'range'; allowed: range_m, fov_deg, miss_probability, model, beams");
  EXPECT_EQ(m.find("a range needs"), std::string::npos) << m;
  s["robot"] = json::parse(R"({"sensor": {"range": [4, 8], "step": 2}})");
  m = problems_of(s);
  EXPECT_HAS(m, "/robot/sensor/range: unknown key 'range'; allowed: range_m, fov_deg");
  EXPECT_HAS(m, "/robot/sensor/step: unknown key 'step'; allowed: range_m, fov_deg");
  s["robot"] = json::parse(R"({"energy": {"preset": "distance", "range": 5}})");
  m = problems_of(s);
  EXPECT_HAS(m, "/robot/energy/range: unknown key 'range'");
  EXPECT_EQ(m.find("a range needs"), std::string::npos) << m;
  s["robot"] = json::parse(R"({"batery": [100, 200]})");  // an unknown key is no axis
  EXPECT_HAS(problems_of(s), "/robot/batery: unknown key 'batery'; allowed: sensor, energy, battery, dock");
  // Ranges where values are swept still are.
  s["robot"] = json::parse(R"({"sensor": {"range_m": {"range": [4, 8], "step": 2}},
                               "energy": {"preset": "distance", "per_metre": {"range": [1, 2], "step": 1}}})");
  EXPECT_EQ(SweepPlan::from_json(s, "s.json").robots().size(), 6U);
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

TEST(SweepValidation, ShippedExamplesAreValidFromAnyWorkingDirectory) {
  // Examples name their map files relative to their own folder (houseexpo.json), so they load
  // from anywhere, without reading from the working directory.
  const std::filesystem::path before = std::filesystem::current_path();
  std::filesystem::current_path(std::filesystem::temp_directory_path());
  int n = 0;
  for (const auto& entry : std::filesystem::directory_iterator(FSWEEP_SOURCE_DIR "/sweeps/examples")) {
    if (entry.path().extension() != ".json") continue;
    try {
      EXPECT_TRUE(SweepPlan::from_file(entry.path().string()).path_warnings().empty()) << entry.path();
    } catch (const ConfigError& e) {
      ADD_FAILURE() << e.what();
    }
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

TEST(SweepValidation, NoShippedSweepClipsTheFreeSpaceOptimumRepeatsIdenticalRunsOrNeedsTheCheckout) {
  // Every free map of the shipped sweeps holds the disc its robots can reach, the sensor band and
  // one cell (sweep_table.hpp's star_optimum()): no sweep prints the clipped-map warning; and no
  // shipped sweep has repetitions with nothing random in them (sweep_table.hpp). They name their
  // map files relative to their own folder, so they load from any working directory without
  // reading from it (no path warning).
  const std::filesystem::path before = std::filesystem::current_path();
  std::filesystem::current_path(std::filesystem::temp_directory_path());
  int n = 0;
  for (const char* folder : {"sweeps", "sweeps/examples", "sweeps/paper", "tests/slurm"}) {
    for (const auto& entry :
         std::filesystem::directory_iterator(std::string(FSWEEP_SOURCE_DIR "/") + folder)) {
      if (entry.path().extension() != ".json") continue;
      const SweepPlan plan = SweepPlan::from_file(entry.path().string());
      EXPECT_TRUE(clipped_free_space_warnings(plan).empty()) << entry.path();
      EXPECT_TRUE(identical_repetition_warnings(plan).empty()) << entry.path();
      EXPECT_TRUE(plan.path_warnings().empty()) << entry.path();
      ++n;
    }
  }
  std::filesystem::current_path(before);
  EXPECT_GE(n, 30);
}

/// The ConfigError message of SweepPlan::from_file(path, overrides) ("" when it loads).
std::string override_error(const std::string& path, const std::vector<std::string>& overrides) {
  try {
    (void)SweepPlan::from_file(path, overrides);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

/// A sweep file of two strategies, for the override tests.
std::string two_strategies(const std::string& name) {
  return write_temp(name, R"({"schema_version": 1, "name": "t", "maps": ["free:w=20,h=20"],
      "strategies": [{"name": "closest_frontier"}, {"name": "energy_aware", "params": {"w1": 10}}],
      "robot": {"battery": 300, "sensor": {"range_m": 4}}})");
}

TEST(SweepValidation, OverridesSetValuesOfTheParsedSweepBeforeValidation) {
  const std::string path = two_strategies("overrides.json");
  const std::vector<std::string> overrides{"robot.battery=800",
                                           "repetitions=5",
                                           "strategies[1].params.w1=[1,2,3]",
                                           "name=my_run",
                                           "maps[0]=rooms:w=30,h=20,seed=1",
                                           "robot.sensor.miss_probability=0.05",
                                           "output.dir=\"out/x\""};
  const SweepPlan plan = SweepPlan::from_file(path, overrides);
  EXPECT_EQ(plan.overrides(), overrides);  // as given
  EXPECT_EQ(plan.source()["robot"]["battery"], 800);
  EXPECT_EQ(plan.source()["strategies"][1]["params"]["w1"], json::parse("[1, 2, 3]"));
  EXPECT_EQ(plan.name(), "my_run");  // a bare string
  EXPECT_EQ(plan.maps()[0].label, "rooms:w=30,h=20,seed=1");
  EXPECT_EQ(plan.source()["robot"]["sensor"], json::parse(R"({"range_m": 4, "miss_probability": 0.05})"));
  EXPECT_EQ(plan.output_dir(), "out/x");  // a key added, with the object on the way
  EXPECT_EQ(plan.run_count(), (1U + 3U) * 5U);
  // A later override may change part of an earlier one's value.
  const SweepPlan later = SweepPlan::from_file(path, {R"(robot={"battery": 1})", "robot.battery=2"});
  EXPECT_EQ(later.source()["robot"], json::parse(R"({"battery": 2})"));
  std::filesystem::remove(path);
}

TEST(SweepValidation, AProblemAtOrUnderAnOverridesPathNamesTheOverride) {
  const std::string path = two_strategies("override_problems.json");
  const std::string m = override_error(path, {"robot.battery=-1", "repetitions=2", "strategies[1].params=5"});
  EXPECT_HAS(m, path + ": 2 problems in the sweep with its command-line overrides:\n");
  EXPECT_HAS(
      m, "\n" + path +
             ": override 'robot.battery=-1': /robot/battery: value -1 out of range; allowed: a number > 0");
  EXPECT_HAS(m,
             "\n" + path + ": override 'strategies[1].params=5': /strategies/1/params: expected an object");
  EXPECT_HAS(override_error(path, {"robot.wheels=3"}),
             path + ": override 'robot.wheels=3': /robot/wheels: unknown key 'wheels'");
  // The file's own problems stay the file's.
  const std::string bad_seed = write_temp("override_bad_seed.json", R"({"schema_version": 1, "name": "t",
      "maps": ["free:w=20,h=20"], "strategies": [{"name": "closest_frontier"}], "seed": -1})");
  EXPECT_EQ(override_error(bad_seed, {"repetitions=2"}),
            bad_seed + ": 1 problem in the sweep with its command-line overrides:\n" + bad_seed +
                ": /seed: value -1 not allowed; allowed: an integer in [0, 2^64)");
  std::filesystem::remove(bad_seed);
  const std::string misspelt = override_error(path, {"robot.sensor.range=5"});
  EXPECT_HAS(misspelt,
             "override 'robot.sensor.range=5': /robot/sensor/range: unknown key 'range'; allowed: range_m");
  std::filesystem::remove(path);
}

TEST(SweepValidation, OverridesThatCannotBeAppliedAreRefusedNamingWhatIsInTheWay) {
  const std::string path = two_strategies("override_refused.json");
  const auto refused = [&](const std::string& text) { return override_error(path, {text}); };
  EXPECT_EQ(refused("=5"), path + ": 1 override of the sweep cannot be applied:\n" + path +
                               ": override '=5': the path before '=' is empty; allowed: PATH=VALUE, e.g. "
                               "robot.battery=800");
  EXPECT_HAS(refused("repetitions"), "override 'repetitions': expected PATH=VALUE");
  EXPECT_HAS(refused("a..b=1"), "override 'a..b=1': empty key at character 3 of the path");
  EXPECT_HAS(refused("a.=1"), "override 'a.=1': empty key at the end of the path");
  EXPECT_HAS(refused("[0]=1"), "override '[0]=1': the path starts with '['");
  EXPECT_HAS(refused("na me=1"), "override 'na me=1': ' ' at character 3 of the path is not allowed");
  EXPECT_HAS(
      refused("maps[99].w=3"),
      "override 'maps[99].w=3': maps has 1 entry (maps[0]), so there is no maps[99]; allowed: an entry "
      "that is there");
  EXPECT_HAS(refused("strategies[2]=x"),
             "strategies has 2 entries (strategies[0] to strategies[1]), so there is "
             "no strategies[2]");
  EXPECT_HAS(refused("maps[-1]=1"),
             "override 'maps[-1]=1': '[' at character 5 of the path must be followed by a "
             "list position and ']' (maps[0], maps[1], ...), got '-1'");
  EXPECT_HAS(refused("x[=1"),
             "override 'x[=1': '[' at character 2 of the path must be followed by a list "
             "position and ']' (x[0], x[1], ...), got nothing");
  EXPECT_HAS(refused("name.x=1"),
             "override 'name.x=1': name is the string \"t\", not an object, so it has no key 'x'");
  EXPECT_HAS(refused("robot[0]=1"),
             "robot is an object, not a list, so there is no robot[0]; allowed: robot.KEY");
  EXPECT_HAS(
      refused("planners[0]=astar"),
      "override 'planners[0]=astar': planners is not in the sweep, so there is no planners[0]; allowed: the "
      "whole list, planners=[...]");
  EXPECT_HAS(refused("strategies[0].params.w1=[1,"),
             "override 'strategies[0].params.w1=[1,': value:1:4: invalid JSON");
  EXPECT_HAS(refused("repetitions=1e400"), "number 1e400 is out of range");
  EXPECT_HAS(refused("name=\xff"), "override 'name=\xff': the value is not UTF-8 text");
  EXPECT_HAS(refused("robot=" + std::string(64, '[') + std::string(64, ']')),
             "makes the sweep nested more than 64 levels deep");
  // 10 MB: refused unread, the message cut.
  const std::string huge = "name=" + std::string(10'000'000, 'x');
  const std::string m = refused(huge);
  EXPECT_HAS(m, "...' (10000005 characters): it is 10000005 characters long; allowed: at most 65536");
  EXPECT_LT(m.size(), 600U);
  // The same path twice: refused (as a key twice in a JSON object), every bad override listed.
  const std::string twice = override_error(path, {"repetitions=2", "repetitions=3", "maps[5]=x"});
  EXPECT_HAS(twice, "2 overrides of the sweep cannot be applied:");
  EXPECT_HAS(
      twice,
      "override 'repetitions=3': sets the same path as override 'repetitions=2'; allowed: each path once");
  // Duplicate keys in a value are problems, as in the file.
  EXPECT_HAS(override_error(path, {R"(robot={"battery": 1, "battery": 2})"}),
             "override 'robot={\"battery\": 1, \"battery\": 2}': /robot/battery: duplicate key 'battery'");
  std::filesystem::remove(path);
}

}  // namespace test_sweep_validation
}  // namespace fsweep
