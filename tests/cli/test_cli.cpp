// The `fsweep` executable end to end: outputs written, and bad input reported with one clear
// message and exit code 2.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <string>

#include "cli/fsweep_process.hpp"
#include "core/csv_reader.hpp"
#include "sim/competitive.hpp"

namespace {

using Outcome = fsweep::testing::CliOutcome;
Outcome fsweep(const std::string& args) { return fsweep::testing::run_fsweep(args); }

std::string temp_dir(const std::string& name) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("fsweep_cli_" + name + "_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  return dir.string();
}

/// The first line of a text file ("" when it cannot be read).
std::string first_line(const std::string& path) {
  std::ifstream f(path);
  std::string line;
  std::getline(f, line);
  return line;
}

TEST(Cli, SimWritesCsvProgressAndPng) {
  const std::string out = temp_dir("sim");
  const Outcome r = fsweep(
      "sim --map rooms:w=40,h=30,door=3,seed=1 --strategy energy_aware --param w1=10 "
      "--robot sensor.range_m=6 --robot battery=400 --seed 3 --out " +
      out);
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("end: "), std::string::npos);
  // The terminal rounds for reading (5 significant digits); run.csv keeps every digit.
  std::smatch m;
  ASSERT_TRUE(std::regex_search(
      r.output, m,
      std::regex(R"(distance: ([0-9,.]+) m \(([0-9,.]+) m to the final coverage\), energy: ([0-9,.]+) m)")))
      << r.output;
  for (std::size_t i = 1; i <= 3; ++i) {
    const std::string number = m[i].str();
    EXPECT_LE(std::count_if(number.begin(), number.end(), [](char c) { return c >= '0' && c <= '9'; }), 5)
        << number;
  }
  for (const char* f : {"run.csv", "progress.csv", "trajectory.png"}) {
    EXPECT_TRUE(std::filesystem::exists(out + "/" + f)) << f;
  }
  const std::string header = first_line(out + "/run.csv");
  for (const char* col : {"map", "strategy.w1", "robot.sensor.range_m", "robot.battery", "seed", "end_reason",
                          "distance_m", "coverage", "recharges"}) {
    EXPECT_NE(header.find(col), std::string::npos) << col;
  }
  std::filesystem::remove_all(out);
}

TEST(Cli, MissingMapFileIsExit2NamingTheFile) {
  const Outcome r = fsweep("sim --map /nonexistent/x.map --out " + temp_dir("missing"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("/nonexistent/x.map"), std::string::npos) << r.output;
}

TEST(Cli, UnknownStrategyListsKnownOnes) {
  const Outcome r = fsweep("sim --map free:w=10,h=10 --strategy nearest --out " + temp_dir("strategy"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("nearest"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("closest_frontier"), std::string::npos) << r.output;
}

TEST(Cli, UnknownPlannerListsKnownOnes) {
  const Outcome r = fsweep("sim --map free:w=10,h=10 --planner rrt --out " + temp_dir("planner"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("astar"), std::string::npos) << r.output;
}

TEST(Cli, UnknownParameterIsNamed) {
  const Outcome r =
      fsweep("sim --map free:w=10,h=10 --strategy energy_aware --param w9=1 --out " + temp_dir("p"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("w9"), std::string::npos) << r.output;
}

TEST(Cli, OutOfRangeValueSaysWhatIsAllowed) {
  const Outcome r =
      fsweep("sim --map free:w=10,h=10 --strategy energy_aware --param w1=300 --out " + temp_dir("r"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("[0, 250]"), std::string::npos) << r.output;
}

TEST(Cli, StartInsideObstacleNamesTheCell) {
  const Outcome r = fsweep("sim --map \"free:w=10,h=10,start=0;0\" --out " + temp_dir("start"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("(0, 0)"), std::string::npos) << r.output;
}

TEST(Cli, UnknownSensorModelIsExit2ListingTheModels) {
  const Outcome r = fsweep("sim --map free:w=10,h=10 --robot sensor.model=foo --out " + temp_dir("model"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("sensor.model"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("\"grid\""), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("\"beams\""), std::string::npos) << r.output;
  const Outcome zero = fsweep("sim --map free:w=10,h=10 --robot sensor.beams=0 --out " + temp_dir("beams"));
  EXPECT_EQ(zero.code, 2);
  EXPECT_NE(zero.output.find("sensor.beams"), std::string::npos) << zero.output;
  EXPECT_NE(zero.output.find("[1, 100000]"), std::string::npos) << zero.output;
}

TEST(Cli, SimWithABeamLidarRecordsItsKeys) {
  const std::string out = temp_dir("beam_sim");
  const Outcome r = fsweep(
      "sim --map rooms:w=40,h=30,door=3,seed=1 --robot sensor.range_m=8 --robot sensor.model=beams "
      "--robot sensor.beams=181 --robot sensor.fov_deg=180 --out " +
      out);
  ASSERT_EQ(r.code, 0) << r.output;
  const std::string header = first_line(out + "/run.csv");
  EXPECT_NE(header.find("robot.sensor.model"), std::string::npos) << header;
  EXPECT_NE(header.find("robot.sensor.beams"), std::string::npos) << header;
  std::filesystem::remove_all(out);
}

/// run.csv's one row as column -> cell.
std::map<std::string, std::string> run_row(const std::string& path) {
  fsweep::CsvReader csv(path);
  EXPECT_TRUE(csv.next()) << path;
  std::map<std::string, std::string> row;
  for (std::size_t i = 0; i < csv.header().size(); ++i) row[csv.header()[i]] = csv.fields().at(i);
  return row;
}

TEST(Cli, SimOnAFreeMapRecordsTheStarOptimumAndWarnsWhenTheMapClipsIt) {
  // r = 20 m, r_s = 2 m: d* needs a half-width of ceil(10 + 2) + 1 = 13 cells around the dock.
  const std::string robot = " --robot battery=20 --robot sensor.range_m=2 --out ";
  const std::string wide = temp_dir("sim_star_ok");
  const Outcome ok = fsweep("sim --map free:w=41,h=41" + robot + wide);
  ASSERT_EQ(ok.code, 0) << ok.output;
  EXPECT_EQ(ok.output.find("warning"), std::string::npos) << ok.output;
  EXPECT_NE(ok.output.find("free-space optimum (star pattern): "), std::string::npos) << ok.output;
  const auto row = run_row(wide + "/run.csv");
  EXPECT_EQ(row.at("optimum_check"), "ok");
  const double optimum = std::stod(row.at("optimal_distance_m"));
  EXPECT_DOUBLE_EQ(optimum, fsweep::star_pattern_optimum_m(20.0, 2.0));
  EXPECT_DOUBLE_EQ(std::stod(row.at("competitive_ratio")), std::stod(row.at("distance_m")) / optimum);

  const std::string narrow = temp_dir("sim_star_clipped");
  const Outcome clipped = fsweep("sim --map free:w=21,h=21" + robot + narrow);
  ASSERT_EQ(clipped.code, 0) << clipped.output;
  EXPECT_NE(clipped.output.find("fsweep: warning: map 'free:w=21,h=21'"), std::string::npos)
      << clipped.output;
  EXPECT_NE(clipped.output.find("need a half-width of 13 cells"), std::string::npos) << clipped.output;
  EXPECT_EQ(clipped.output.find("free-space optimum (star pattern)"), std::string::npos) << clipped.output;
  const auto cut = run_row(narrow + "/run.csv");
  EXPECT_EQ(cut.at("optimum_check").rfind("clipped: half-width ", 0), 0U) << cut.at("optimum_check");
  EXPECT_EQ(cut.at("optimal_distance_m"), "");
  EXPECT_EQ(cut.at("competitive_ratio"), "");

  // Elsewhere (another map, or no battery limit) run.csv has none of these columns.
  const std::string rooms = temp_dir("sim_star_na");
  ASSERT_EQ(fsweep("sim --map free:w=21,h=21 --robot sensor.range_m=2 --out " + rooms).code, 0);
  EXPECT_EQ(run_row(rooms + "/run.csv").count("optimum_check"), 0U);
  for (const std::string& d : {wide, narrow, rooms}) std::filesystem::remove_all(d);
}

TEST(Cli, SimPngScaleOverTheImageLimitIsExit2BeforeAnyOutput) {
  const std::string out = temp_dir("png_scale");
  const Outcome huge = fsweep("sim --map free:w=20,h=20 --png-scale 16384 --out " + out);
  EXPECT_EQ(huge.code, 2) << huge.output;
  EXPECT_NE(huge.output.find(
                "--png-scale: 16384 pixels per cell on the 20x20 map makes a 327680x327940 image "
                "(107459379200 pixels, with the title and the legend); allowed: at most 16384 pixels per "
                "side and 100000000 pixels in all"),
            std::string::npos)
      << huge.output;
  EXPECT_FALSE(std::filesystem::exists(out)) << "nothing is written";
  // Within the side limit but over the pixel limit: 20 x 600 = 12000 pixels wide, the map and its
  // title and legend bands (6.5 lines of 40 pixels at text size 4) 12260 high: 147 megapixels.
  const Outcome pixels = fsweep("sim --map free:w=20,h=20 --png-scale 600 --out " + out);
  EXPECT_EQ(pixels.code, 2) << pixels.output;
  EXPECT_NE(pixels.output.find("makes a 12000x12260 image (147120000 pixels"), std::string::npos)
      << pixels.output;
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(Cli, SimNegativePngScaleIsExit2) {
  const std::string out = temp_dir("png_negative");
  const Outcome r = fsweep("sim --map free:w=20,h=20 --png-scale -1 --out " + out);
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("--png-scale: must be >= 0 pixels per cell (0: automatic), got -1"),
            std::string::npos)
      << r.output;
  EXPECT_FALSE(std::filesystem::exists(out));
}

/// Runs `fsweep ARGS` and returns what it printed on stderr only (stdout dropped).
Outcome fsweep_stderr(const std::string& args) {
  std::string command = "{ ";
  command += FSWEEP_BINARY_DIR;
  command += "/bin/fsweep " + args + " 2>&1 >/dev/null; }";
  return fsweep::testing::run_command(command);
}

TEST(Cli, PlanEndpointOutsideTheMapOrInAnObstacleIsExit2OnStderr) {
  const std::string map = std::string(FSWEEP_TEST_DATA) + "/arena.map";  // 49x49, (0, 0) is a tree
  const std::string outside = " is outside the 49x49 map " + map + "; allowed: 0 <= x < 49, 0 <= y < 49";
  const std::array<std::array<std::string, 2>, 3> cases{{
      {"--from 0 0 --to 3 1", "--from: cell (0, 0) is occupied in the map " + map + "; allowed: a free cell"},
      {"--from 3 1 --to 49 3", "--to: cell (49, 3)" + outside},
      {"--from 3 -1 --to 3 1", "--from: cell (3, -1)" + outside},
  }};
  for (const auto& [endpoints, message] : cases) {
    const Outcome r = fsweep_stderr("plan --map " + map + " " + endpoints);
    EXPECT_EQ(r.code, 2) << r.output;
    EXPECT_NE(r.output.find("fsweep: error: " + message), std::string::npos) << r.output;
  }
  EXPECT_EQ(fsweep("plan --map " + map + " --from 0 0 --to 3 1").output.find("status:"), std::string::npos);
}

TEST(Cli, PlanScenarioCountsQueriesWithInvalidEndpointsOnStderr) {
  const std::string dir = temp_dir("plan_scen");
  std::filesystem::create_directories(dir);
  const std::string scen = dir + "/bad.scen";
  // A valid query (from arena.map.scen), a start in a tree, a goal in a tree. (A cell outside
  // the map is refused with the file's line when the .scen is read.)
  std::ofstream(scen) << "version 1\n"
                         "0\tarena.map\t49\t49\t1\t11\t1\t12\t1\n"
                         "0\tarena.map\t49\t49\t0\t0\t3\t1\t3\n"
                         "0\tarena.map\t49\t49\t3\t1\t0\t1\t3\n";
  const std::string args =
      "plan --quiet --map " + std::string(FSWEEP_TEST_DATA) + "/arena.map --scen " + scen;
  const Outcome err = fsweep_stderr(args);
  EXPECT_NE(err.output.find("fsweep: warning: " + scen +
                            ": 2 of 3 queries have a start or goal outside the 49x49 map or occupied "
                            "(first: query 1: start cell (0, 0) is occupied)"),
            std::string::npos)
      << err.output;
  const Outcome all = fsweep(args);  // the batch itself runs every query, as before
  EXPECT_NE(all.output.find("total: 3 queries, 1 match, 2 mismatches"), std::string::npos) << all.output;
  std::filesystem::remove_all(dir);
}

TEST(Cli, VersionNamesTheVersionTheCompilerAndTheLibraries) {
  for (const char* args : {"--version", "version"}) {
    const Outcome r = fsweep(args);
    EXPECT_EQ(r.code, 0) << r.output;
    EXPECT_TRUE(std::regex_search(r.output, std::regex(R"(^fsweep [0-9]+\.[0-9]+\.[0-9]+)"))) << r.output;
    for (const char* part : {"\nOMPL 1.", "\noneTBB 20", "\nnlohmann_json 3."}) {
      EXPECT_NE(r.output.find(part), std::string::npos) << args << ": " << part << "\n" << r.output;
    }
    EXPECT_TRUE(std::regex_search(r.output, std::regex("\n(gcc|clang) "))) << r.output;
  }
}

TEST(Cli, BashCompletionCompletesCommandsAndTheirOptions) {
  const Outcome r = fsweep::testing::run_command(
      "bash -c 'source <(" FSWEEP_BINARY_DIR
      "/bin/fsweep completion bash); "
      "COMP_WORDS=(fsweep pai); COMP_CWORD=1; _fsweep; echo \"${COMPREPLY[*]}\"; "
      "COMP_WORDS=(fsweep paired --base); COMP_CWORD=2; _fsweep; echo \"${COMPREPLY[*]}\"'");
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_EQ(r.output, "paired\n--baseline\n");
}

TEST(Cli, UnknownCommandIsNamedWithTheCommandsAllowed) {
  const Outcome r = fsweep("frobnicate");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("fsweep: error: unknown command 'frobnicate'; allowed: sim, optimum, plan, "
                          "plan-compare, plan-bench, run, expand, aggregate, merge, compare, paired, slurm, "
                          "plot, report, describe, export-sqlite, verify, version, completion"),
            std::string::npos)
      << r.output;
  const Outcome none = fsweep("");
  EXPECT_EQ(none.code, 2) << none.output;
  EXPECT_NE(none.output.find("fsweep: error: a command is required; allowed: sim, optimum, plan,"),
            std::string::npos)
      << none.output;
}

TEST(Cli, BadNumbersNameTheOptionAndWhatIsAllowed) {
  const std::string out = temp_dir("seed");
  const Outcome negative = fsweep("sim --map free:w=10,h=10 --seed -1 --out " + out);
  EXPECT_EQ(negative.code, 2) << negative.output;
  EXPECT_NE(negative.output.find("fsweep: error: sim: --seed: must be an integer >= 0, got '-1'"),
            std::string::npos)
      << negative.output;
  const Outcome word = fsweep("sim --map free:w=10,h=10 --seed abc --out " + out);
  EXPECT_EQ(word.code, 2) << word.output;
  EXPECT_NE(word.output.find("sim: --seed: must be an integer >= 0, got 'abc'"), std::string::npos)
      << word.output;
  const Outcome big = fsweep("sim --map free:w=10,h=10 --seed 18446744073709551616 --out " + out);
  EXPECT_EQ(big.code, 2) << big.output;
  EXPECT_NE(big.output.find("--seed: must be an integer from 0 to 18446744073709551615 (2^64 - 1), got "
                            "'18446744073709551616'"),
            std::string::npos)
      << big.output;
  const Outcome scale = fsweep("sim --map free:w=10,h=10 --png-scale two --out " + out);
  EXPECT_EQ(scale.code, 2) << scale.output;
  EXPECT_NE(scale.output.find("sim: --png-scale: must be an integer, got 'two'"), std::string::npos)
      << scale.output;
  const Outcome tolerance = fsweep("plan --map free:w=10,h=10 --from 1 1 --to 2 2 --tolerance x");
  EXPECT_EQ(tolerance.code, 2) << tolerance.output;
  EXPECT_NE(tolerance.output.find("plan: --tolerance: must be a number, got 'x'"), std::string::npos)
      << tolerance.output;
  // Before the option's own range check, which would say "Value x could not be converted".
  const Outcome significance = fsweep("compare /nonexistent /nonexistent2 --significance x");
  EXPECT_EQ(significance.code, 2) << significance.output;
  EXPECT_NE(significance.output.find("compare: --significance: must be a number, got 'x'"), std::string::npos)
      << significance.output;
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(Cli, PlanScenarioReportsZeroMismatches) {
  const std::string data = FSWEEP_TEST_DATA;
  const Outcome r = fsweep("plan --quiet --map " + data + "/arena.map --scen " + data + "/arena.map.scen");
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("160 queries, 160 match, 0 mismatches"), std::string::npos) << r.output;
}

}  // namespace
