// `fsweep merge DIR` end to end: shards written by `fsweep run --shard i/N`, merged (exit 0),
// incomplete (exit 1, nothing written) and mismatched (exit 2), also with the results of another
// sweep in DIR.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "cli/fsweep_process.hpp"

namespace {

namespace fs = std::filesystem;
using fsweep::testing::run_fsweep;

/// A sweep of 1 map x 2 strategies x 2 repetitions = 4 runs, written to `dir`/sweep.json.
std::string write_sweep(const std::string& dir) {
  fs::create_directories(dir);
  const std::string path = dir + "/sweep.json";
  std::ofstream(path) << R"({"schema_version": 1, "name": "cli_merge",
    "maps": ["rooms:w=24,h=20,door=2,seed=2"],
    "strategies": [{"name": "closest_frontier"}, {"name": "energy_aware"}],
    "repetitions": 2, "seed": 3})";
  return path;
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(CliMerge, MergesShardsAndReportsMissingShards) {
  const std::string dir = fsweep::testing::fresh_temp_dir("merge", "ok");
  const std::string sweep = write_sweep(dir);
  const std::string out = dir + "/out";
  auto r = run_fsweep("run " + sweep + " --quiet --out " + out + " --shard 0/2");
  ASSERT_EQ(r.code, 0) << r.output;
  r = run_fsweep("merge " + out);
  EXPECT_EQ(r.code, 1) << r.output;
  EXPECT_NE(r.output.find("missing shard directory " + out + "/shard-1-of-2"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("missing run_index 1 (run_key "), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out + "/runs.csv"));
  r = run_fsweep("run " + sweep + " --quiet --out " + out + " --shard 1/2");
  ASSERT_EQ(r.code, 0) << r.output;
  r = run_fsweep("merge " + out);
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_EQ(fsweep::testing::count_lines(out + "/runs.csv"), 5);  // header + 4 runs
  EXPECT_TRUE(fs::exists(out + "/best.csv"));
  fs::remove_all(dir);
}

TEST(CliMerge, MismatchedShardCountsAreExit2) {
  const std::string dir = fsweep::testing::fresh_temp_dir("merge", "mixed");
  const std::string sweep = write_sweep(dir);
  const std::string out = dir + "/out";
  ASSERT_EQ(run_fsweep("run " + sweep + " --quiet --out " + out + " --shard 0/2").code, 0);
  ASSERT_EQ(run_fsweep("run " + sweep + " --quiet --out " + out + " --shard 1/3").code, 0);
  const auto r = run_fsweep("merge " + out);
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("shard-1-of-3"), std::string::npos) << r.output;
  EXPECT_EQ(run_fsweep("merge " + dir + "/nowhere").code, 2);
  fs::remove_all(dir);
}

TEST(CliMerge, ShardsOfAnotherSweepThanTheDirectoryHoldsAreExit2) {
  const std::string dir = fsweep::testing::fresh_temp_dir("merge", "other_sweep");
  const std::string first = fsweep::testing::write_named_sweep(dir, "first", 1);
  const std::string second = fsweep::testing::write_named_sweep(dir, "second", 2);
  const std::string out = dir + "/results";
  ASSERT_EQ(run_fsweep("run " + first + " --quiet --out " + out).code, 0);
  ASSERT_EQ(run_fsweep("run " + second + " --quiet --out " + out + " --shard 0/2").code, 0);
  ASSERT_EQ(run_fsweep("run " + second + " --quiet --out " + out + " --shard 1/2").code, 0);
  const std::string runs = fsweep::testing::read_all(out + "/runs.csv");
  const std::string manifest = fsweep::testing::read_all(out + "/manifest.json");

  const auto r = run_fsweep("merge " + out);
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_TRUE(has(r.output, out + ": holds the results of sweep 'first' (sweep_hash ")) << r.output;
  EXPECT_TRUE(has(r.output, "its shards are of sweep 'second' (sweep_hash ")) << r.output;
  EXPECT_TRUE(has(r.output, "nothing written")) << r.output;
  EXPECT_EQ(fsweep::testing::read_all(out + "/runs.csv"), runs);
  EXPECT_EQ(fsweep::testing::read_all(out + "/manifest.json"), manifest);

  // The shards of the directory's own sweep merge (again) as before.
  const std::string own = dir + "/own";
  ASSERT_EQ(run_fsweep("run " + second + " --quiet --out " + own + " --shard 0/2").code, 0);
  ASSERT_EQ(run_fsweep("run " + second + " --quiet --out " + own + " --shard 1/2").code, 0);
  EXPECT_EQ(run_fsweep("merge " + own).code, 0);
  EXPECT_EQ(run_fsweep("merge " + own).code, 0);
  fs::remove_all(dir);
}

}  // namespace
