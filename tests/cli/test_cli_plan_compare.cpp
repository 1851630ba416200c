// `fsweep plan-compare` end to end: the table, the three output files, and bad input reported
// with one clear message and exit code 2.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "cli/fsweep_process.hpp"

namespace test_cli_plan_compare {  // not anonymous: unity builds put it beside other test files' helpers

using Outcome = fsweep::testing::CliOutcome;
Outcome fsweep(const std::string& args) { return fsweep::testing::run_fsweep(args); }

std::string temp_dir(const std::string& name) { return fsweep::testing::fresh_temp_dir("pc", name); }
using fsweep::testing::count_lines;

/// The first `n` comma-separated fields of a CSV line.
std::string first_fields(const std::string& line, int n) {
  std::size_t end = 0;
  for (int i = 0; i < n && end != std::string::npos; ++i) end = line.find(',', end == 0 ? 0 : end + 1);
  return line.substr(0, end);
}

TEST(CliPlanCompare, WritesTableAndFiles) {
  const std::string out = temp_dir("ok");
  const Outcome r = fsweep(
      "plan-compare --map random:w=24,h=20,p=0.2,seed=3 --planners dijkstra,shortest_fewest_turns,lattice "
      "--pairs 50 --seed 2 --energy mei2006 --out " +
      out);
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("dijkstra -> lattice"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("smaller cell index"), std::string::npos) << r.output;  // tie-breaking documented
  EXPECT_EQ(count_lines(out + "/pairs.csv"), 51);
  EXPECT_EQ(count_lines(out + "/summary.csv"), 4);  // header + 3 planner pairs
  std::ifstream pairs(out + "/pairs.csv");
  std::string header;
  std::getline(pairs, header);
  for (const char* col :
       {"source_x", "start_heading", "dijkstra.energy", "lattice.turns", "shortest_fewest_turns.time_s"}) {
    EXPECT_NE(header.find(col), std::string::npos) << col;
  }
  std::ifstream manifest_file(out + "/manifest.json");
  const nlohmann::json manifest = nlohmann::json::parse(manifest_file);
  EXPECT_EQ(manifest.at("seed"), 2);
  EXPECT_EQ(manifest.at("pairs"), 50);
  EXPECT_EQ(manifest.at("start_heading"), "random");
  EXPECT_EQ(manifest.at("energy").at("per_stop"), 0.5);
  EXPECT_EQ(manifest.at("planners").size(), 3U);

  // The same seed gives the same pairs (and the same lengths and energies).
  const std::string out2 = temp_dir("ok2");
  ASSERT_EQ(fsweep("plan-compare --map random:w=24,h=20,p=0.2,seed=3 --planners "
                   "dijkstra,shortest_fewest_turns,lattice "
                   "--pairs 50 --seed 2 --out " +
                   out2)
                .code,
            0);
  std::ifstream a(out + "/summary.csv");
  std::ifstream b(out2 + "/summary.csv");
  std::string la;
  std::string lb;
  std::getline(a, la);
  std::getline(b, lb);
  EXPECT_EQ(la, lb);
  std::getline(a, la);
  std::getline(b, lb);
  // baseline, candidate, pairs_used, 12 statistics, 2 totals, 3 shares: everything but timings.
  EXPECT_EQ(first_fields(la, 20), first_fields(lb, 20));
  std::filesystem::remove_all(out);
  std::filesystem::remove_all(out2);
}

TEST(CliPlanCompare, FixedHeadingIsRecorded) {
  const std::string out = temp_dir("heading");
  const Outcome r = fsweep(
      "plan-compare --map free:w=12,h=10 --planners dijkstra,lattice_astar --pairs 20 "
      "--start-heading 2 --out " +
      out);
  ASSERT_EQ(r.code, 0) << r.output;
  std::ifstream manifest_file(out + "/manifest.json");
  EXPECT_EQ(nlohmann::json::parse(manifest_file).at("start_heading"), 2);
  std::filesystem::remove_all(out);
}

TEST(CliPlanCompare, BadInputIsExit2WithAClearMessage) {
  Outcome r = fsweep("plan-compare --map free:w=12,h=10 --planners dijkstra,rrt --pairs 5");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("rrt"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("lattice"), std::string::npos) << r.output;

  r = fsweep("plan-compare --map free:w=12,h=10 --planners dijkstra --pairs 5");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("at least 2 planners"), std::string::npos) << r.output;

  r = fsweep("plan-compare --map /nonexistent/x.map --planners dijkstra,lattice --pairs 5");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("/nonexistent/x.map"), std::string::npos) << r.output;

  r = fsweep("plan-compare --map free:w=4,h=4 --planners dijkstra,lattice --pairs 5000");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("distinct reachable pairs"), std::string::npos) << r.output;

  r = fsweep("plan-compare --map free:w=12,h=10 --planners dijkstra,lattice --start-heading 9");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("--start-heading"), std::string::npos) << r.output;

  r = fsweep("plan-compare --map free:w=12,h=10 --planners dijkstra,lattice --energy mei2007");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("mei2007"), std::string::npos) << r.output;
}

}  // namespace test_cli_plan_compare
