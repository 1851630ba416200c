// `fsweep optimum` end to end: exact on a tiny map (lower == upper), bounds, optimum.csv's columns
// and route.png on a rooms map, and the refusals (exit 2 naming the option, nothing written).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "cli/fsweep_process.hpp"
#include "core/csv_reader.hpp"

namespace test_cli_optimum {

using fsweep::CsvReader;
using fsweep::parse_number;
using fsweep::testing::CliOutcome;
using fsweep::testing::fresh_temp_dir;
using fsweep::testing::run_fsweep;

/// The one row of `dir`/optimum.csv as column -> cell (empty when the file has no row).
std::map<std::string, std::string> optimum_row(const std::string& dir) {
  CsvReader in(dir + "/optimum.csv");
  std::map<std::string, std::string> row;
  if (!in.next()) return row;
  for (std::size_t c = 0; c < in.header().size(); ++c) row[in.header()[c]] = in.fields()[c];
  EXPECT_FALSE(in.next()) << "one row only";
  return row;
}

/// A number cell of `row` (NaN when missing or not a number).
double number(const std::map<std::string, std::string>& row, const std::string& column) {
  const auto it = row.find(column);
  if (it == row.end()) return std::numeric_limits<double>::quiet_NaN();
  return parse_number(it->second).value_or(std::numeric_limits<double>::quiet_NaN());
}

TEST(CliOptimum, TinyMapIsSolvedExactly) {
  const std::string out = fresh_temp_dir("optimum", "tiny");
  const CliOutcome r = run_fsweep("optimum --map free:w=8,h=6 --robot sensor.range_m=2 --out " + out);
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("exact: yes"), std::string::npos) << r.output;
  const auto row = optimum_row(out);
  EXPECT_EQ(row.at("exact"), "1");
  EXPECT_GT(number(row, "lower_m"), 0.0);
  EXPECT_EQ(row.at("lower_m"), row.at("upper_m"));
  EXPECT_EQ(number(row, "gap"), 0.0);
  EXPECT_EQ(row.at("out_of_reach"), "0");
  EXPECT_GT(number(row, "exact_expansions"), 0.0);
  EXPECT_TRUE(std::filesystem::exists(out + "/route.png"));

  // Budgets that stop the exact search early leave an interval, still in order.
  for (const char* budget : {"--max-expansions 10", "--time-limit 0"}) {
    const CliOutcome b = run_fsweep("optimum --map free:w=8,h=6 --robot sensor.range_m=2 " +
                                    std::string(budget) + " --out " + out);
    ASSERT_EQ(b.code, 0) << budget << "\n" << b.output;
    const auto early = optimum_row(out);
    EXPECT_EQ(early.at("exact"), "0") << budget;
    EXPECT_LE(number(early, "lower_m"), number(row, "lower_m")) << budget;
    EXPECT_GE(number(early, "upper_m"), number(row, "upper_m")) << budget;
    EXPECT_EQ(early.at("stopped_by_time"), std::string(budget) == "--time-limit 0" ? "1" : "0") << budget;
  }
}

TEST(CliOptimum, RoomsMapBoundsWriteEveryColumnAndTheRoute) {
  const std::string out = fresh_temp_dir("optimum", "rooms");
  const std::string map = "rooms:w=20,h=16,door=2,seed=3";
  const CliOutcome r = run_fsweep("optimum --map " + map + " --robot sensor.range_m=4 --out " + out);
  ASSERT_EQ(r.code, 0) << r.output;
  for (const char* text : {"lower bound: ", "upper bound: ", " m (covering route)", "gap: ", "exact: ",
                           "observable cells", "witnesses: ", "viewpoints: ", "exact search: ", "time: "}) {
    EXPECT_NE(r.output.find(text), std::string::npos) << text << "\n" << r.output;
  }
  const auto row = optimum_row(out);
  for (const char* column : {"map", "map_hash", "robot", "lower_m", "upper_m", "gap", "exact", "trips",
                             "time_s", "nodes", "targets", "out_of_reach", "witnesses", "viewpoints",
                             "lower_method", "upper_method", "exact_expansions", "stopped_by_time"}) {
    EXPECT_EQ(row.count(column), 1U) << column;
  }
  EXPECT_EQ(row.at("map"), map);
  EXPECT_EQ(row.at("map_hash").size(), 16U);
  EXPECT_NE(row.at("robot").find("\"range_m\":4"), std::string::npos) << row.at("robot");
  const double lower = number(row, "lower_m");
  const double upper = number(row, "upper_m");
  EXPECT_GT(lower, 0.0);
  EXPECT_LE(lower, upper);
  EXPECT_NEAR(number(row, "gap"), (upper - lower) / lower, 1e-12);
  EXPECT_EQ(row.at("trips"), "1");
  EXPECT_EQ(row.at("stopped_by_time"), "0");
  EXPECT_TRUE(std::filesystem::exists(out + "/route.png"));

  // The same directory again is the command's own output; a sim directory is not.
  EXPECT_EQ(run_fsweep("optimum --map " + map + " --robot sensor.range_m=4 --out " + out).code, 0);
  const CliOutcome sim = run_fsweep("sim --map " + map + " --out " + out);
  EXPECT_EQ(sim.code, 2) << sim.output;
  EXPECT_NE(sim.output.find("holds the output of fsweep optimum (optimum.csv, route.png)"), std::string::npos)
      << sim.output;
}

TEST(CliOptimum, BadInputsAreExit2NamingTheOptionBeforeAnyFile) {
  const std::string out = fresh_temp_dir("optimum", "bad");
  const std::vector<std::pair<std::string, std::string>> cases{
      {"--map free:w=8,h=6 --robot sensor.fov_deg=0", "--robot: sensor.fov_deg: "},
      {"--map free:w=8,h=6 --robot sensor.model=beams", "--robot: sensor.model: "},
      {"--map free:w=8,h=6 --time-limit -1", "optimum: --time-limit: must be >= 0, got '-1'"},
      {"--map free:w=8,h=6 --max-expansions -1", "optimum: --max-expansions: must be >= 0"},
      {"--map /nonexistent/x.map", "--map: map spec '/nonexistent/x.map'"},
  };
  for (const auto& [args, message] : cases) {
    const CliOutcome r = run_fsweep("optimum " + args + " --out " + out);
    EXPECT_EQ(r.code, 2) << args << "\n" << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << args << "\n" << r.output;
    EXPECT_FALSE(std::filesystem::exists(out)) << args;
  }
  const std::string sim_dir = fresh_temp_dir("optimum", "sim");
  ASSERT_EQ(run_fsweep("sim --map free:w=8,h=6 --out " + sim_dir).code, 0);
  const CliOutcome r = run_fsweep("optimum --map free:w=8,h=6 --out " + sim_dir);
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("holds the output of fsweep sim"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(sim_dir + "/optimum.csv"));
  // A competitive sweep's cache of optima alone (a sweep stopped before its first run) is a sweep's.
  const std::string sweep_dir = fresh_temp_dir("optimum", "sweep");
  std::filesystem::create_directories(sweep_dir);
  std::ofstream(sweep_dir + "/optima.csv") << "solver,map_hash,robot\n";
  const CliOutcome s = run_fsweep("optimum --map free:w=8,h=6 --out " + sweep_dir);
  EXPECT_EQ(s.code, 2) << s.output;
  EXPECT_NE(s.output.find("the offline optima of a sweep (optima.csv)"), std::string::npos) << s.output;
}

}  // namespace test_cli_optimum
