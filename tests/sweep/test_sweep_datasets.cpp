// Dataset map entries (a folder of HouseExpo plans as one map class: id lists, seeded samples,
// plans that do not load) and random starts drawn from the run seed.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "core/config_error.hpp"
#include "report/runs_schema.hpp"
#include "sweep/manifest.hpp"
#include "sweep/sweep_plan.hpp"
#include "sweep/sweep_table.hpp"
#include "world/world_map.hpp"

namespace fsweep {
namespace test_sweep_datasets {  // not anonymous: unity builds put it beside other test files' helpers

using nlohmann::json;
namespace fs = std::filesystem;

const std::string kPlans = std::string(FSWEEP_TEST_DATA) + "/houseexpo";

json sweep_with(const json& map) {
  json s = json::parse(R"({"schema_version": 1, "name": "t", "strategies": [{"name": "closest_frontier"}],
                           "robot": {"sensor": {"range_m": 3}}})");
  s["maps"] = json::array({map});
  return s;
}

std::string problems_of(const json& sweep) {
  try {
    (void)SweepPlan::from_json(sweep, "s.json");
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

#define EXPECT_HAS(haystack, needle) EXPECT_NE((haystack).find(needle), std::string::npos) << (haystack)

/// A fresh folder of small plans (a triangle, one per id) under the temp dir.
std::string plan_folder(const std::string& name, const std::vector<std::string>& ids) {
  const fs::path dir =
      fs::temp_directory_path() / ("fsweep_datasets_" + std::to_string(getpid()) + "_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  for (std::size_t k = 0; k < ids.size(); ++k) {
    // Plans of different sizes, so each is its own map.
    std::ofstream(dir / (ids[k] + ".json")) << R"({"verts": [[0, 0], [)" << 2 + static_cast<int>(k)
                                            << R"(, 0], [0, 2]], "id": ")" << ids[k] << "\"}";
  }
  return dir.string();
}

std::vector<std::string> files_of(const SweepPlan& plan) {
  std::vector<std::string> out;
  for (const SweepMap& m : plan.maps())
    out.push_back(fs::path(m.spec.at("file").get<std::string>()).stem().string());
  return out;
}

TEST(SweepDatasets, AFolderIsOneMapClassOfEveryPlanInNameOrder) {
  const SweepPlan plan = SweepPlan::from_json(sweep_with({{"dataset", kPlans}, {"res", 0.2}}), "s.json");
  ASSERT_EQ(plan.maps().size(), 2U);
  EXPECT_EQ(files_of(plan), (std::vector<std::string>{"house_expo_room_0000", "house_expo_room_1451"}));
  EXPECT_EQ(plan.maps()[0].map_class, "dataset " + kPlans);
  EXPECT_EQ(plan.maps()[1].map_class, plan.maps()[0].map_class);
  EXPECT_EQ(plan.maps()[0].map->width(), 53);  // the plan at 0.2 m (tests/world/test_houseexpo.cpp)
  // Each plan's key is the one of the same plan given as a file map.
  const SweepPlan single = SweepPlan::from_json(
      sweep_with({{"file", kPlans + "/house_expo_room_1451.json"}, {"res", 0.2}}), "s.json");
  EXPECT_EQ(plan.run_key(1), single.run_key(0));
}

TEST(SweepDatasets, AnIdListNamesThePlansAndASampleIsSeeded) {
  const std::string dir = plan_folder("sample", {"a", "b", "c", "d", "e"});
  const std::string ids = dir + "/ids.txt";
  std::ofstream(ids) << "c\n a \n\ne\nb\nd\n";
  const json all{{"dataset", dir}, {"ids", ids}, {"label", "five"}};
  const SweepPlan listed = SweepPlan::from_json(sweep_with(all), "s.json");
  EXPECT_EQ(files_of(listed), (std::vector<std::string>{"c", "a", "e", "b", "d"}));
  EXPECT_EQ(listed.maps()[0].map_class, "five");

  json sampled = all;
  sampled["sample"] = 3;
  sampled["sample_seed"] = 7;
  const std::vector<std::string> first = files_of(SweepPlan::from_json(sweep_with(sampled), "s.json"));
  EXPECT_EQ(first, files_of(SweepPlan::from_json(sweep_with(sampled), "s.json")));
  ASSERT_EQ(first.size(), 3U);
  // A subset, kept in list order.
  const std::vector<std::string> order{"c", "a", "e", "b", "d"};
  std::vector<std::size_t> positions;
  for (const std::string& f : first) {
    positions.push_back(static_cast<std::size_t>(std::find(order.begin(), order.end(), f) - order.begin()));
  }
  EXPECT_TRUE(std::is_sorted(positions.begin(), positions.end()));
  EXPECT_LT(positions.back(), order.size());
  // Other seeds draw other subsets.
  std::set<std::vector<std::string>> subsets;
  for (int seed = 0; seed < 10; ++seed) {
    sampled["sample_seed"] = seed;
    subsets.insert(files_of(SweepPlan::from_json(sweep_with(sampled), "s.json")));
  }
  EXPECT_GE(subsets.size(), 4U);
  fs::remove_all(dir);
}

TEST(SweepDatasets, PlansThatDoNotLoadRefuseTheSweepOrAreSkippedVisibly) {
  const std::string dir = plan_folder("bad", {"good", "other"});
  std::ofstream(dir + "/broken.json") << R"({"verts": [[0, 0], [1, "x"], [0, 1]]})";
  const std::string ids = dir + "/ids.txt";
  std::ofstream(ids) << "good\nbroken\nmissing\nother\n";
  json item{{"dataset", dir}, {"ids", ids}};
  const std::string m = problems_of(sweep_with(item));
  EXPECT_HAS(m, "/maps/0: plan " + dir + "/broken.json does not load");
  EXPECT_HAS(m, "/verts/1");
  EXPECT_HAS(m, "/maps/0: plan " + dir + "/missing.json does not load");
  EXPECT_HAS(m, "cannot open");
  EXPECT_HAS(m, "\"on_bad_map\": \"skip\"");

  item["on_bad_map"] = "skip";
  const SweepPlan plan = SweepPlan::from_json(sweep_with(item), "s.json");
  EXPECT_EQ(files_of(plan), (std::vector<std::string>{"good", "other"}));
  ASSERT_EQ(plan.skipped_maps().size(), 2U);
  EXPECT_EQ(plan.skipped_maps()[0].file, dir + "/broken.json");
  EXPECT_HAS(plan.skipped_maps()[0].reason, "/verts/1");
  EXPECT_EQ(plan.skipped_maps()[1].file, dir + "/missing.json");
  const std::vector<std::string> warnings = sweep_warnings(plan);
  ASSERT_EQ(warnings.size(), 2U);
  EXPECT_HAS(warnings[0], "skipped plan " + dir + "/broken.json");
  const json manifest = manifest_json(plan, ManifestInfo{});
  ASSERT_EQ(manifest.at("skipped_maps").size(), 2U);
  EXPECT_EQ(manifest.at("skipped_maps")[1].at("file"), dir + "/missing.json");
  EXPECT_EQ(manifest.at("warnings"), json(warnings));
  fs::remove_all(dir);
}

TEST(SweepDatasets, BadDatasetItemsAreProblemsWithTheirPaths) {
  const std::string dir = plan_folder("items", {"a", "b"});
  EXPECT_HAS(problems_of(sweep_with({{"dataset", dir + "/nowhere"}})),
             "/maps/0/dataset: '" + dir + "/nowhere' is not a folder");
  EXPECT_HAS(problems_of(sweep_with({{"dataset", dir}, {"sample", 3}})),
             "/maps/0/sample: 3 not allowed; allowed: an integer from 1 to 2");
  EXPECT_HAS(problems_of(sweep_with({{"dataset", dir}, {"sample", 0}})), "/maps/0/sample: 0 not allowed");
  EXPECT_HAS(problems_of(sweep_with({{"dataset", dir}, {"seeds", {1, 2}}})),
             "/maps/0/seeds: unknown key for a dataset");
  EXPECT_HAS(problems_of(sweep_with({{"dataset", dir}, {"on_bad_map", "ignore"}})),
             "/maps/0/on_bad_map: \"ignore\" not allowed; allowed: \"refuse\"");
  EXPECT_HAS(problems_of(sweep_with({{"dataset", dir}, {"ids", dir + "/none.txt"}})),
             "/maps/0/ids: cannot read");
  const std::string empty = plan_folder("empty", {});
  EXPECT_HAS(problems_of(sweep_with({{"dataset", empty}})), "/maps/0: the dataset has no plans");
  std::ofstream(dir + "/twice.txt") << "a\na\n";
  EXPECT_HAS(problems_of(sweep_with({{"dataset", dir}, {"ids", dir + "/twice.txt"}})), "is listed twice");
  fs::remove_all(dir);
  fs::remove_all(empty);
}

TEST(SweepDatasets, RandomStartsAreDrawnFromTheRunSeedAndRecorded) {
  json s = sweep_with({{"file", kPlans + "/house_expo_room_1451.json"}, {"res", 0.2}, {"start", "random"}});
  s["repetitions"] = 6;
  const SweepPlan plan = SweepPlan::from_json(s, "s.json");
  const Grid<std::uint8_t> region = largest_free_region(*plan.maps()[0].map);
  std::set<std::string> starts;
  std::set<std::string> keys;
  for (std::uint64_t i = 0; i < plan.run_count(); ++i) {
    const RunSpec spec = plan.run_spec(i);
    EXPECT_EQ(region.at(spec.map->start), 1) << i;
    EXPECT_EQ(spec.map->start, draw_region_cell(region, spec.seed)) << i;
    EXPECT_EQ(plan.run_spec(i).map->start, spec.map->start);  // a pure function of the run
    const Columns columns = config_columns(spec);
    const auto start = std::find_if(columns.begin(), columns.end(),
                                    [](const auto& c) { return c.first == kMapStartColumn; });
    ASSERT_NE(start, columns.end());
    EXPECT_EQ(start->second, std::to_string(spec.map->start.x) + ";" + std::to_string(spec.map->start.y));
    starts.insert(start->second);
    keys.insert(plan.run_key(i));
  }
  EXPECT_GE(starts.size(), 5U);
  EXPECT_EQ(keys.size(), plan.run_count());
  EXPECT_EQ(plan.maps()[0].spec.at("start"), "random");
  // With corner cutting the region of the other motion rule is drawn from.
  s["robot"]["allow_corner_cutting"] = true;
  const SweepPlan cutting = SweepPlan::from_json(s, "s.json");
  const Grid<std::uint8_t> region_cc = largest_free_region(*cutting.maps()[0].map, true);
  EXPECT_EQ(cutting.run_spec(0).map->start, draw_region_cell(region_cc, cutting.run_spec(0).seed));
}

TEST(SweepDatasets, RandomStartsAreRefusedOnFreeMaps) {
  EXPECT_HAS(problems_of(sweep_with("free:w=20,h=20,start=random")),
             "\"random\" is not allowed on a free map");
  EXPECT_EQ(problems_of(sweep_with("rooms:w=30,h=20,start=random")), "");
}

TEST(SweepDatasets, AFolderAndItsIdListAreFoundBesideTheSweepFileAndKeptAsWritten) {
  // <root>/plans/{a,b}.json and ids.txt, and <root>/sweeps/s.json naming them "../plans".
  const std::string root = plan_folder("beside", {});
  const std::string plans = plan_folder("beside_plans", {"a", "b"});
  fs::rename(plans, root + "/plans");
  std::ofstream(root + "/plans/ids.txt") << "b\na\n";
  fs::create_directories(root + "/sweeps");
  json listed = sweep_with({{"dataset", "../plans"}, {"ids", "../plans/ids.txt"}, {"label", "two"}});
  std::ofstream(root + "/sweeps/s.json") << listed.dump();
  json every = sweep_with({{"dataset", "../plans"}});
  std::ofstream(root + "/sweeps/every.json") << every.dump();
  const fs::path before = fs::current_path();
  fs::current_path(fs::temp_directory_path());
  const SweepPlan plan = SweepPlan::from_file(root + "/sweeps/s.json");
  const SweepPlan all = SweepPlan::from_file(root + "/sweeps/every.json");
  fs::current_path(before);
  EXPECT_TRUE(plan.path_warnings().empty());
  ASSERT_EQ(plan.maps().size(), 2U);
  EXPECT_EQ(plan.maps()[0].spec.at("file"), "../plans/b.json");  // run keys hash the path as written
  EXPECT_EQ(plan.maps()[0].map->source, "../plans/b.json");
  EXPECT_EQ(files_of(all), (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(all.maps()[0].map_class, "dataset ../plans");
  EXPECT_EQ(all.run_key(0), plan.run_key(1));
  fs::remove_all(root);
}

}  // namespace test_sweep_datasets
}  // namespace fsweep
