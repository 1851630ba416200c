// The offline optimum's table of report.html (report_tables.hpp: optimum_html), from a runs.csv
// written here: one row per map instance and robot, the gap, the star optimum on free maps, the
// runs with a ratio and the notes of the others; maps that are not competitive left out.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "report/report_tables.hpp"

namespace fsweep {
namespace {

std::string write_runs(const std::string& name, const std::string& text) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("fsweep_report_tables_" + name + "_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "runs.csv").string();
  std::ofstream(path) << text;
  return path;
}

/// The rows of the table's HTML (the header's included).
int rows(const std::string& html) {
  int n = 0;
  for (std::size_t at = html.find("<tr"); at != std::string::npos; at = html.find("<tr", at + 1)) ++n;
  return n;
}

TEST(OptimumTable, ARowPerMapAndRobotWithTheGapTheStarAndWhyRunsHaveNoRatio) {
  const std::string path =
      write_runs("star",
                 "map,robot.battery,optimal_distance_m,optimum_lower_m,optimum_upper_m,optimum_exact,"
                 "competitive_ratio_min,competitive_ratio_max,competitive_note\n"
                 "\"free:w=31,h=31\",100,1500.25,1000,1200,0,1.5,1.8,\n"
                 "\"free:w=31,h=31\",100,1500.25,1000,1200,0,,,end range_limited\n"
                 "\"free:w=31,h=31\",200,,1000,2000,0,1.1,2.2,\n"
                 "\"rooms:w=30,h=24\",100,,,,,,,map not competitive\n");
  const std::string html = optimum_html(path);
  EXPECT_EQ(rows(html), 3);  // the header and the two robots of the free map
  EXPECT_EQ(html.find("rooms:"), std::string::npos);
  EXPECT_NE(html.find("<th>robot.battery</th>"), std::string::npos) << html;  // the column that differs
  EXPECT_NE(html.find("star optimum (m)"), std::string::npos);
  EXPECT_NE(html.find("1,500"), std::string::npos);  // the star, rounded for reading
  EXPECT_NE(html.find("20%"), std::string::npos);    // (1200 - 1000) / 1000
  EXPECT_NE(html.find("100%"), std::string::npos);   // (2000 - 1000) / 1000
  EXPECT_NE(html.find("1 of 2"), std::string::npos);
  EXPECT_NE(html.find("end range_limited (1)"), std::string::npos);
}

TEST(OptimumTable, NothingWithoutTheOptimumColumnsOrWithoutAStarColumn) {
  EXPECT_EQ(optimum_html(write_runs("plain", "map,distance_m\n\"free:w=9,h=9\",12\n")), "");
  const std::string html = optimum_html(
      write_runs("nostar",
                 "map,optimum_lower_m,optimum_upper_m,optimum_exact,competitive_ratio_min,competitive_note\n"
                 "\"rooms:w=30,h=24\",73.3,111.2,0,1.7,\n"));
  EXPECT_EQ(rows(html), 2);
  EXPECT_EQ(html.find("star optimum"), std::string::npos);
  EXPECT_NE(html.find("51.7%"), std::string::npos) << html;
  EXPECT_NE(html.find("1 of 1"), std::string::npos);
}

}  // namespace
}  // namespace fsweep
