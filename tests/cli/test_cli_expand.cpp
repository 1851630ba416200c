// `fsweep expand`: a dry run prints the run count and the first runs; a bad sweep exits 2
// listing every problem.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "cli/fsweep_process.hpp"

namespace test_cli_expand {  // not anonymous: unity builds put it beside other test files' helpers

using Outcome = fsweep::testing::CliOutcome;
Outcome fsweep(const std::string& args) { return fsweep::testing::run_fsweep(args); }

TEST(CliExpand, PrintsTheRunCountOfTheExhaustiveWeightSearch) {
  const Outcome r =
      fsweep("expand " FSWEEP_SOURCE_DIR "/sweeps/examples/energy_weights_exhaustive.json --limit 3");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("runs: 3,969,126,001\n"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("strategy configurations: 3,969,126,001"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("first 3 runs of 3,969,126,001:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("w1=0 w2=0 w3=0 w4=2"), std::string::npos) << r.output;  // the third run
  EXPECT_NE(r.output.find("nothing was run or written"), std::string::npos) << r.output;
}

TEST(CliExpand, WarnsThatRepetitionsWithNothingRandomAreCopiesAndRunRecordsIt) {
  const std::string dir = fsweep::testing::fresh_temp_dir("expand", "copies");
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/copies.json")
      << R"({"schema_version": 1, "name": "copies", "maps": ["rooms:w=24,h=20,seed=2"],
    "strategies": [{"name": "closest_frontier", "label": "CF"}], "repetitions": 4})";
  const std::string warning =
      "1 of 1 configurations have nothing random in them (no sensor misses, a fixed start, no seeded "
      "strategy or "
      "planner), so their 4 repetitions on a map instance will be 4 copies of one run";
  Outcome r = fsweep("expand " + dir + "/copies.json");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("fsweep: warning: " + dir + "/copies.json: " + warning), std::string::npos)
      << r.output;
  r = fsweep("run " + dir + "/copies.json --quiet --out " + dir + "/out");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find(warning), std::string::npos) << r.output;
  EXPECT_NE(fsweep::testing::read_all(dir + "/out/manifest.json").find(warning), std::string::npos);
  // After the runs, summary.csv says how many were distinct.
  const std::string summary = fsweep::testing::read_all(dir + "/out/summary.csv");
  EXPECT_NE(summary.find(",n,n_distinct,"), std::string::npos) << summary;
  EXPECT_NE(summary.find(",4,1,"), std::string::npos) << summary;
}

TEST(CliExpand, BadSweepExits2ListingEveryProblem) {
  const auto path = (std::filesystem::temp_directory_path() /
                     ("fsweep_cli_bad_sweep_" + std::to_string(getpid()) + ".json"))
                        .string();
  std::ofstream(path) << R"({"schema_version": 1, "name": "bad", "maps": ["free:w=20,h=20"], "extra": 1,
    "strategies": [{"name": "energy_aware", "params": {"w4": {"range": [0, 300], "step": 100}}}]})";
  const Outcome r = fsweep("expand " + path);
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("2 problems"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(path + ": /extra: unknown key 'extra'"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(path + ": /strategies/0/params/w4/range: value 300 out of range"),
            std::string::npos)
      << r.output;
  std::filesystem::remove(path);
}

TEST(CliExpand, WarnsAboutAFreeMapThatClipsTheFreeSpaceOptimum) {
  // r = 60 m, r_s = 5 m on 1 m cells: the optimum needs 30 + 5 + 1 = 36 free cells beyond the
  // dock each way. free:w=73 (frame, dock 36;36) has 35, free:w=75 has 36.
  const auto path =
      (std::filesystem::temp_directory_path() / ("fsweep_cli_clipped_" + std::to_string(getpid()) + ".json"))
          .string();
  std::ofstream(path)
      << R"({"schema_version": 1, "name": "clipped", "maps": ["free:w=73,h=73", "free:w=75,h=75"],
    "strategies": [{"name": "closest_frontier"}], "robot": {"sensor": {"range_m": 5}, "battery": 60}})";
  const Outcome r = fsweep("expand " + path + " --limit 0");
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("fsweep: warning: " + path +
                          ": map 'free:w=73,h=73' (73x73 cells of 1 m, dock 36;36): "
                          "clips the free-space optimum"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("need a half-width of 36 cells (r/2 + r_s + 1 cell), the map has 35"),
            std::string::npos)
      << r.output;
  EXPECT_EQ(r.output.find("free:w=75,h=75' ("), std::string::npos) << r.output;  // it fits: no warning
  std::filesystem::remove(path);
}

TEST(CliExpand, NegativeCountsAreExit2NotWrappedTo2To64) {
  // CLI11 2.1 reads "-1" into an unsigned option as 2^64 - 1: every unsigned option refuses it.
  const std::string sweep = FSWEEP_SOURCE_DIR "/sweeps/default.json";
  for (const char* option : {"--limit", "--from"}) {
    const Outcome r = fsweep("expand " + sweep + " " + option + " -1");
    EXPECT_EQ(r.code, 2) << r.output;
    EXPECT_NE(r.output.find("fsweep: error: expand: " + std::string(option) +
                            ": must be an integer >= 0, got '-1'"),
              std::string::npos)
        << r.output;
    EXPECT_EQ(r.output.find("18446744073709551615"), std::string::npos) << r.output;
  }
  const Outcome rows = fsweep("report /nonexistent --rows -1");
  EXPECT_EQ(rows.code, 2) << rows.output;
  EXPECT_NE(rows.output.find("report: --rows: must be an integer >= 0, got '-1'"), std::string::npos)
      << rows.output;
  const Outcome runs = fsweep("compare /nonexistent /nonexistent2 --min-runs -1");
  EXPECT_EQ(runs.code, 2) << runs.output;
  EXPECT_NE(runs.output.find("compare: --min-runs: must be an integer >= 0, got '-1'"), std::string::npos)
      << runs.output;
  const Outcome top = fsweep("plot /nonexistent --top -1");
  EXPECT_EQ(top.code, 2) << top.output;
  EXPECT_NE(top.output.find("plot: --top: must be > 0, got '-1'"), std::string::npos) << top.output;
}

TEST(CliExpand, CountsWithLeadingZerosAreDecimalNotOctal) {
  const Outcome r = fsweep("expand " FSWEEP_SOURCE_DIR "/sweeps/default.json --from 010 --limit 1");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("runs from index 10, 1 run of 90:"), std::string::npos) << r.output;
}

TEST(CliExpand, ShowsItsOverridesAndWarnsAboutAMapReadFromTheWorkingDirectory) {
  // <dir>/sub/s.json names maps/two_rooms.txt as sweeps did when paths followed the working
  // directory: found under <dir>, read from there with a warning that says what to write.
  const std::string dir = fsweep::testing::fresh_temp_dir("expand", "fallback");
  std::filesystem::create_directories(dir + "/sub");
  std::filesystem::create_directories(dir + "/maps");
  std::filesystem::copy_file(FSWEEP_TEST_DATA "/two_rooms.txt", dir + "/maps/two_rooms.txt");
  std::ofstream(dir + "/sub/s.json") << R"({"schema_version": 1, "name": "fallback",
    "maps": [{"file": "maps/two_rooms.txt"}], "strategies": [{"name": "closest_frontier"}],
    "robot": {"sensor": {"range_m": 3}}})";
  const std::string warning =
      "fsweep: warning: sub/s.json: /maps/0/file: 'maps/two_rooms.txt' is not beside the "
      "sweep file (no " +
      dir +
      "/sub/maps/two_rooms.txt); read from the working directory "
      "instead (" +
      dir + "/maps/two_rooms.txt)";
  Outcome r =
      fsweep::testing::run_fsweep("expand sub/s.json repetitions=2 'robot.sensor.miss_probability=0.1'", dir);
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("overrides: repetitions=2 robot.sensor.miss_probability=0.1\n"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("runs: 2\n"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(warning), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("write '../maps/two_rooms.txt'"), std::string::npos) << r.output;
  r = fsweep::testing::run_fsweep("run sub/s.json --quiet --out out", dir);
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(fsweep::testing::read_all(dir + "/out/manifest.json").find("is not beside the sweep file"),
            std::string::npos);
  // runs.csv names the map as the sweep does.
  EXPECT_NE(fsweep::testing::read_all(dir + "/out/runs.csv").find(",maps/two_rooms.txt,"), std::string::npos);
  // From another folder, neither holds it: both absolute paths named.
  r = fsweep("expand " + dir + "/sub/s.json");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("/maps/0/file: no such file 'maps/two_rooms.txt': tried " + dir +
                          "/sub/maps/two_rooms.txt (beside the sweep file) and "),
            std::string::npos)
      << r.output;
}

}  // namespace test_cli_expand
