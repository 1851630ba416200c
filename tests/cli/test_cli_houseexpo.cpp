// HouseExpo end to end: the README's dataset sweep (sweeps/examples/houseexpo.json) pools its
// plans into one map class with starts drawn per run, and `fsweep sim` repeats a run's start.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "cli/fsweep_process.hpp"
#include "core/csv_reader.hpp"

namespace {

using fsweep::testing::run_fsweep;

/// Every record of a CSV file as column -> value.
std::vector<std::map<std::string, std::string>> read_rows(const std::string& path) {
  fsweep::CsvReader csv(path);
  std::vector<std::map<std::string, std::string>> rows;
  while (csv.next()) {
    std::map<std::string, std::string> row;
    for (std::size_t i = 0; i < csv.header().size(); ++i) row[csv.header()[i]] = csv.fields()[i];
    rows.push_back(row);
  }
  return rows;
}

TEST(CliHouseExpo, TheExampleDatasetSweepPoolsItsPlansAndDrawsStarts) {
  const std::string out = fsweep::testing::fresh_temp_dir("houseexpo", "example");
  const auto r = run_fsweep("run sweeps/examples/houseexpo.json --quiet --out " + out, FSWEEP_SOURCE_DIR);
  ASSERT_EQ(r.code, 0) << r.output;
  const auto runs = read_rows(out + "/runs.csv");
  ASSERT_EQ(runs.size(), 20U);  // 2 plans x 2 strategies x 5 repetitions
  std::set<std::string> plans;
  std::set<std::string> starts;
  for (const auto& run : runs) {
    EXPECT_EQ(run.at("map_class"), "houseexpo");
    EXPECT_EQ(run.at("end_reason"), "complete") << run.at("map") << " " << run.at("map.start");
    plans.insert(run.at("map"));
    starts.insert(run.at("map") + " " + run.at("map.start"));
  }
  EXPECT_EQ(plans.size(), 2U);
  EXPECT_GE(starts.size(), 8U);  // 5 drawn starts per plan, nearly always distinct
  // One configuration per strategy: the plans (of different sizes) and starts are its repetitions.
  const auto summary = read_rows(out + "/summary.csv");
  ASSERT_EQ(summary.size(), 2U);
  for (const auto& row : summary) EXPECT_EQ(row.at("n"), "10") << row.at("strategy_label");
  std::filesystem::remove_all(out);
}

TEST(CliHouseExpo, SimDrawsTheStartASweepRunWithTheSameSeedDraws) {
  const std::string out = fsweep::testing::fresh_temp_dir("houseexpo", "sim");
  const auto sweep = run_fsweep("run sweeps/examples/houseexpo.json --quiet --out " + out, FSWEEP_SOURCE_DIR);
  ASSERT_EQ(sweep.code, 0) << sweep.output;
  const auto run = read_rows(out + "/runs.csv").at(3);  // plan 0000, closest_frontier, repetition 3
  const std::string sim_out = out + "/sim";
  const auto sim = run_fsweep(
      "sim --map tests/data/houseexpo/house_expo_room_0000.json:res=0.1,start=random "
      "--strategy closest_frontier --robot sensor.range_m=4 --seed " +
          run.at("seed") + " --out " + sim_out,
      FSWEEP_SOURCE_DIR);
  ASSERT_EQ(sim.code, 0) << sim.output;
  const auto sim_run = read_rows(sim_out + "/run.csv").at(0);
  EXPECT_EQ(sim_run.at("map.start"), run.at("map.start"));
  EXPECT_EQ(sim_run.at("distance_m"), run.at("distance_m"));
  std::filesystem::remove_all(out);
}

TEST(CliHouseExpo, RandomStartsOutsideRunsAreRefusedWithExit2) {
  const auto r =
      run_fsweep("plan --map tests/data/houseexpo/house_expo_room_0000.json:start=random --from 5 5 --to 9 9",
                 FSWEEP_SOURCE_DIR);
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("start \"random\" is drawn per run"), std::string::npos) << r.output;
}

}  // namespace
