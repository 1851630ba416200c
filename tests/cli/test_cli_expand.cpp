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

}  // namespace test_cli_expand
