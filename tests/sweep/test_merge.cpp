// fsweep merge: shards of a sweep joined into the unsharded sweep's runs.csv; missing, duplicate
// and mismatched shards reported.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "core/config_error.hpp"
#include "sweep/csv_journal.hpp"
#include "sweep/merge.hpp"
#include "sweep/sweep_plan.hpp"
#include "sweep/sweep_runner.hpp"
#include "sweep/sweep_test_files.hpp"
#include "sweep/sweep_test_run.hpp"

namespace fsweep {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::string temp_dir(const std::string& name) { return testing::fresh_dir("merge", name); }

using testing::read_file;
using testing::write_file;

/// 1 map x 3 strategy configurations x 2 repetitions = 6 short runs.
json tiny_sweep() {
  return json::parse(R"({
    "schema_version": 1,
    "name": "merge_test",
    "maps": ["rooms:w=24,h=20,door=2,seed=2"],
    "strategies": [{"name": "closest_frontier"}, {"name": "energy_aware", "params": {"w1": [0, 10]}}],
    "repetitions": 2,
    "seed": 5
  })");
}

void run(const json& sweep, const std::string& dir, std::uint64_t shard, std::uint64_t count) {
  (void)testing::run_test_shard(sweep, dir, shard, count);
}

/// Lines of a CSV text (runs.csv has no quoted newlines) with the `*_time_s` columns removed:
/// they measure the machine, the only cells allowed to differ.
std::vector<std::string> without_timing(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  std::string line;
  std::vector<bool> keep;
  while (std::getline(in, line)) {
    const auto f = split_csv_line(line);
    if (keep.empty()) {
      for (const auto& h : f) keep.push_back(!h.ends_with("_time_s"));
    }
    EXPECT_EQ(f.size(), keep.size()) << line;
    std::string kept;
    for (std::size_t i = 0; i < f.size() && i < keep.size(); ++i) {
      if (keep[i]) kept += f[i] + ",";
    }
    out.push_back(kept);
  }
  return out;
}

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += x + "\n";
  return s;
}

class MergeTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    whole_ = new std::string(temp_dir("whole"));
    run(tiny_sweep(), *whole_, 0, 1);
  }
  static void TearDownTestSuite() {
    fs::remove_all(*whole_);
    delete whole_;
  }
  static std::string* whole_;
};
std::string* MergeTest::whole_ = nullptr;

TEST_F(MergeTest, ShardsMergeIntoTheUnshardedOutputs) {
  const auto expected = without_timing(read_file(*whole_ + "/runs.csv"));
  ASSERT_EQ(expected.size(), 7U);  // header + 6 runs
  for (const std::uint64_t n : {2U, 3U}) {
    const std::string dir = temp_dir("n" + std::to_string(n));
    for (std::uint64_t i = 0; i < n; ++i) run(tiny_sweep(), dir, i, n);
    const MergeReport r = merge_shards(dir);
    EXPECT_TRUE(r.written) << joined(r.problems);
    EXPECT_TRUE(r.problems.empty()) << joined(r.problems);
    EXPECT_EQ(r.total, 6U);
    EXPECT_EQ(r.shard_count, n);
    EXPECT_EQ(joined(without_timing(read_file(dir + "/runs.csv"))), joined(expected)) << "n = " << n;
    EXPECT_EQ(read_file(dir + "/progress.csv"), read_file(*whole_ + "/progress.csv")) << "n = " << n;
    for (const char* f : {"summary.csv", "progress_summary.csv", "best.csv", "manifest.json"}) {
      EXPECT_TRUE(fs::exists(dir + "/" + f)) << f;
    }
    const json m = json::parse(read_file(dir + "/manifest.json"));
    EXPECT_EQ(m["runs"]["total"], 6U);
    EXPECT_EQ(m["shard"]["count"], 1U);
    EXPECT_EQ(m["status"], "complete");
    EXPECT_EQ(m["shard"]["merged_from"], n);
    // Throughput over the longest shard's wall time.
    EXPECT_DOUBLE_EQ(m["runs_per_s"].get<double>(), 6.0 / m["wall_s"].get<double>());
    // Every shard's session, by start time.
    ASSERT_EQ(m["sessions"].size(), n);
    std::vector<bool> seen(n, false);
    for (const json& session : m["sessions"]) {
      EXPECT_EQ(session["shard"]["count"], n);
      seen.at(session["shard"]["index"].get<std::size_t>()) = true;
      EXPECT_LE(m["start_utc"].get<std::string>(), session["start_utc"].get<std::string>());
    }
    EXPECT_EQ(std::count(seen.begin(), seen.end(), true), static_cast<std::ptrdiff_t>(n));
    EXPECT_EQ(m["start_utc"], m["sessions"][0]["start_utc"]);
    fs::remove_all(dir);
  }
}

TEST_F(MergeTest, DeletedRowIsReportedMissingByIndexAndKey) {
  const std::string dir = temp_dir("missing");
  for (std::uint64_t i = 0; i < 2; ++i) run(tiny_sweep(), dir, i, 2);
  // shard 1 holds runs 1, 3, 5: drop the row of run 3.
  const std::string path = dir + "/shard-1-of-2/runs.csv";
  std::istringstream in(read_file(path));
  std::string line;
  std::string kept;
  std::string key;
  while (std::getline(in, line)) {
    if (line.starts_with("3,")) {
      key = split_csv_line(line).at(1);
      continue;
    }
    kept += line + "\n";
  }
  ASSERT_FALSE(key.empty());
  write_file(path, kept);
  const MergeReport r = merge_shards(dir);
  EXPECT_FALSE(r.written);
  ASSERT_EQ(r.problems.size(), 1U) << joined(r.problems);
  EXPECT_EQ(r.problems[0], "missing run_index 3 (run_key " + key + ")");
  EXPECT_FALSE(fs::exists(dir + "/runs.csv"));
  EXPECT_FALSE(fs::exists(dir + "/summary.csv"));
  fs::remove_all(dir);
}

TEST_F(MergeTest, DuplicatedRowIsReported) {
  const std::string dir = temp_dir("dup");
  for (std::uint64_t i = 0; i < 2; ++i) run(tiny_sweep(), dir, i, 2);
  // Copy run 0's row (shard 0) into shard 1.
  std::istringstream in(read_file(dir + "/shard-0-of-2/runs.csv"));
  std::string line;
  std::string row0;
  while (std::getline(in, line)) {
    if (line.starts_with("0,")) row0 = line;
  }
  ASSERT_FALSE(row0.empty());
  write_file(dir + "/shard-1-of-2/runs.csv", read_file(dir + "/shard-1-of-2/runs.csv") + row0 + "\n");
  const MergeReport r = merge_shards(dir);
  EXPECT_FALSE(r.written);
  ASSERT_EQ(r.problems.size(), 1U) << joined(r.problems);
  EXPECT_TRUE(r.problems[0].starts_with("duplicate run_index 0 ")) << r.problems[0];
  EXPECT_NE(r.problems[0].find("shard-1-of-2"), std::string::npos) << r.problems[0];
  EXPECT_FALSE(fs::exists(dir + "/runs.csv"));
  fs::remove_all(dir);
}

TEST_F(MergeTest, MissingShardDirectoryIsReported) {
  const std::string dir = temp_dir("noshard");
  run(tiny_sweep(), dir, 0, 3);
  run(tiny_sweep(), dir, 2, 3);
  const MergeReport r = merge_shards(dir);
  EXPECT_FALSE(r.written);
  ASSERT_EQ(r.problems.size(), 3U) << joined(r.problems);  // the directory and runs 1 and 4
  EXPECT_EQ(r.problems[0], "missing shard directory " + dir + "/shard-1-of-3");
  EXPECT_TRUE(r.problems[1].starts_with("missing run_index 1 (run_key ")) << r.problems[1];
  EXPECT_TRUE(r.problems[2].starts_with("missing run_index 4 (run_key ")) << r.problems[2];
  fs::remove_all(dir);
}

TEST_F(MergeTest, MismatchedShardCountsAndSweepsAreErrors) {
  const std::string dir = temp_dir("mixed");
  run(tiny_sweep(), dir, 0, 2);
  run(tiny_sweep(), dir, 1, 3);
  try {
    (void)merge_shards(dir);
    ADD_FAILURE() << "no ConfigError";
  } catch (const ConfigError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("shard-0-of-2"), std::string::npos) << what;
    EXPECT_NE(what.find("shard-1-of-3"), std::string::npos) << what;
  }
  fs::remove_all(dir);
  const std::string other = temp_dir("othersweep");
  json changed = tiny_sweep();
  changed["seed"] = 6;
  run(tiny_sweep(), other, 0, 2);
  run(changed, other, 1, 2);
  EXPECT_THROW((void)merge_shards(other), ConfigError);
  fs::remove_all(other);
  EXPECT_THROW((void)merge_shards(temp_dir("empty")), ConfigError);
  fs::remove_all(fs::temp_directory_path() / ("fsweep_merge_empty_" + std::to_string(::getpid())));
}

TEST_F(MergeTest, ShardsRunBeforeAndAfterADescriptionAloneChangedMerge) {
  const std::string dir = temp_dir("described");
  json described = tiny_sweep();
  described["description"] = "shard 1 ran after this sentence was added";
  run(tiny_sweep(), dir, 0, 2);
  run(described, dir, 1, 2);
  const MergeReport r = merge_shards(dir);
  EXPECT_TRUE(r.written) << joined(r.problems);
  EXPECT_EQ(joined(without_timing(read_file(dir + "/runs.csv"))),
            joined(without_timing(read_file(*whole_ + "/runs.csv"))));
  // The merged manifest is the first shard's: its sweep, without the description.
  const json m = json::parse(read_file(dir + "/manifest.json"));
  EXPECT_EQ(m["sweep"], tiny_sweep());
  fs::remove_all(dir);
  // Shards of a new description merged over an unsharded run of the old one: the same sweep.
  const std::string over = temp_dir("described_over");
  run(tiny_sweep(), over, 0, 1);
  for (std::uint64_t i = 0; i < 2; ++i) run(described, over, i, 2);
  const MergeReport again = merge_shards(over);
  EXPECT_TRUE(again.written) << joined(again.problems);
  EXPECT_EQ(json::parse(read_file(over + "/manifest.json"))["sweep"], described);
  fs::remove_all(over);
}

TEST_F(MergeTest, ShardsRunOnDifferentMapContentsAreRefused) {
  const std::string dir = temp_dir("edited_map");
  const std::string map_path = dir + "/m.txt";  // beside the shards: merge looks at shard-* only
  write_file(map_path, "########\n#......#\n#......#\n#......#\n########\n");
  json sweep = tiny_sweep();
  sweep["maps"] = json::array({json{{"file", map_path}, {"start", "1;1"}}});
  run(sweep, dir, 0, 2);
  write_file(map_path, "########\n#......#\n#..#...#\n#......#\n########\n");  // one cell more wall
  run(sweep, dir, 1, 2);
  try {
    (void)merge_shards(dir);
    ADD_FAILURE() << "shards of two map contents were merged";
  } catch (const ConfigError& e) {
    const std::string what = e.what();
    for (const std::string& part :
         {std::string("different map contents"), map_path + ":start=1;1': content hash",
          std::string("shard-0-of-2"), std::string("shard-1-of-2")}) {
      EXPECT_NE(what.find(part), std::string::npos) << part << "\nnot in: " << what;
    }
  }
  EXPECT_FALSE(fs::exists(dir + "/runs.csv"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace fsweep
