// `fsweep report DIR` end to end: the page of a sweep run by `fsweep run` (what it holds, text
// from the sweep file escaped, DIR/plots left alone), and bad input (exit 2 naming the file).
// tests/browser/check_pages.py opens the pages in a browser.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "cli/fsweep_process.hpp"

namespace {

namespace fs = std::filesystem;
using fsweep::testing::read_all;
using fsweep::testing::run_fsweep;

/// Runs a sweep of 1 map x 2 strategies x 2 repetitions whose description and labels hold markup
/// into `dir`/out; returns the directory.
std::string make_result(const std::string& dir) {
  fs::create_directories(dir);
  std::ofstream(dir + "/sweep.json") << R"({"schema_version": 1, "name": "cli_report",
    "description": "a <script>alert(1)</script> sweep",
    "maps": [{"spec": "rooms:w=24,h=20,door=2,seed=2", "label": "map<1>"}],
    "strategies": [{"name": "closest_frontier", "label": "cf \"quoted\" & <b>bold</b>"},
                   {"name": "energy_aware", "label": "ea's"}],
    "robot": {"sensor": {"range_m": 4}}, "repetitions": 2, "seed": 3})";
  const auto r = run_fsweep("run " + dir + "/sweep.json --quiet --out " + dir + "/out");
  EXPECT_EQ(r.code, 0) << r.output;
  return dir + "/out";
}

std::size_t occurrences(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(CliReport, WritesOneSelfContainedPageOfTheResultDirectory) {
  const std::string dir = fsweep::testing::fresh_temp_dir("report", "page");
  const std::string out = make_result(dir);
  // A rerun with nothing to do is a second session of the directory.
  ASSERT_EQ(run_fsweep("run " + dir + "/sweep.json --quiet --out " + out).code, 0);
  const auto r = run_fsweep("report " + out);
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("wrote " + out + "/report.html (2 plots, 2 of 2 trajectories)"), std::string::npos)
      << r.output;
  const std::string page = read_all(out + "/report.html");
  // What ran, from the manifest.
  const auto manifest = nlohmann::json::parse(read_all(out + "/manifest.json"));
  EXPECT_NE(page.find(manifest["sweep_hash"].get<std::string>()), std::string::npos);
  EXPECT_NE(page.find(dir + "/sweep.json"), std::string::npos);
  EXPECT_NE(page.find("4 runs: complete 4"), std::string::npos);
  // Both sessions; the speed is that of the one that ran the sweep, not the rerun's 0.
  EXPECT_NE(page.find("total 4, done 4, ran 4 over 2 sessions (the last found 4 done), failed 0"),
            std::string::npos);
  EXPECT_NE(page.find("<p>Sessions (one per <code>fsweep run</code> on the directory, oldest first):</p>"),
            std::string::npos);
  EXPECT_NE(page.find("<th>runs per second</th><td>"), std::string::npos);
  EXPECT_EQ(page.find("<th>runs per second</th><td>0 "), std::string::npos);
  // The sections, the figures of fsweep plot and both trajectories, every picture embedded.
  for (const char* id :
       {"id='what-ran'", "id='ranking'", "id='paired'", "id='best'", "id='summary'", "id='plot-progress'",
        "id='plot-metrics'", "id='trajectory-1'", "id='trajectory-2'", "id='reproduce'"}) {
    EXPECT_NE(page.find(id), std::string::npos) << id;
  }
  // The ranking names rows by their labels and marks configurations whose two repetitions (nothing
  // random in them) are one run twice; the paired comparison is against the first entry.
  EXPECT_EQ(occurrences(page, "<tr class='copies'>"), 2U);
  EXPECT_NE(page.find("<td class='num'>2 (1 distinct) ⚠</td>"), std::string::npos);
  EXPECT_NE(page.find("Each strategy against <b>cf &quot;quoted&quot; &amp; &lt;b&gt;bold&lt;/b&gt;</b>"),
            std::string::npos);
  EXPECT_NE(page.find("<td>ea&#39;s</td>"), std::string::npos);
  EXPECT_EQ(occurrences(page, "<img "), 4U);
  EXPECT_EQ(occurrences(page, "src='data:image/png;base64,iVBORw0KGgo"), 4U);  // the PNG signature
  EXPECT_NE(page.find("best configuration (rank 1 of 2 in best.csv): its first run"), std::string::npos);
  EXPECT_NE(page.find("worst configuration (rank 2 of 2 in best.csv): its first run"), std::string::npos);
  EXPECT_NE(
      page.find(
          "recorded outcome cells (end reason and every metric but timings and search counters) are equal"),
      std::string::npos);
  // The commands that reproduce it.
  EXPECT_NE(page.find("fsweep run " + dir + "/sweep.json --threads "), std::string::npos);
  EXPECT_NE(page.find("fsweep compare " + out + "-rerun " + out), std::string::npos);
  EXPECT_NE(page.find("fsweep report " + out), std::string::npos);
  // Text from the sweep file is text: no script, no markup of its own.
  EXPECT_EQ(page.find("<script"), std::string::npos);
  EXPECT_EQ(page.find("<b>bold"), std::string::npos);
  EXPECT_EQ(page.find("map<1>"), std::string::npos);
  EXPECT_NE(page.find("a &lt;script&gt;alert(1)&lt;/script&gt; sweep"), std::string::npos);
  EXPECT_NE(page.find("cf &quot;quoted&quot; &amp; &lt;b&gt;bold&lt;/b&gt;"), std::string::npos);
  EXPECT_NE(page.find("ea&#39;s"), std::string::npos);
  // `fsweep plot`'s directory is its own: the report drew elsewhere.
  EXPECT_FALSE(fs::exists(out + "/plots"));
  fs::remove_all(dir);
}

TEST(CliReport, OptionsChooseTheFileAndLeaveOutTrajectories) {
  const std::string dir = fsweep::testing::fresh_temp_dir("report", "options");
  const std::string out = make_result(dir);
  const auto r = run_fsweep("report " + out + " --no-trajectories --rows 1 --out " + dir + "/page.html");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_FALSE(fs::exists(out + "/report.html"));
  const std::string page = read_all(dir + "/page.html");
  EXPECT_EQ(page.find("id='trajectory-"), std::string::npos);
  EXPECT_NE(page.find("Trajectories were left out (fsweep report --no-trajectories)."), std::string::npos);
  EXPECT_NE(page.find("The first 1 of 2 rows; every row is in <code>" + out + "/best.csv</code>"),
            std::string::npos);
  fs::remove_all(dir);
}

TEST(CliReport, ARunTheManifestsSweepDoesNotHaveIsNamedNotDrawn) {
  const std::string dir = fsweep::testing::fresh_temp_dir("report", "changed");
  const std::string out = make_result(dir);
  // Another sweep seed: the recorded runs' keys are no longer the sweep's.
  auto manifest = nlohmann::json::parse(read_all(out + "/manifest.json"));
  manifest["sweep"]["seed"] = 4;
  std::ofstream(out + "/manifest.json", std::ios::trunc) << manifest.dump(2);
  const auto r = run_fsweep("report " + out);
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("0 of 2 trajectories"), std::string::npos) << r.output;
  const std::string page = read_all(out + "/report.html");
  EXPECT_NE(page.find("not re-simulated: run "), std::string::npos);
  EXPECT_NE(page.find("the sweep in manifest.json is not the one that ran"), std::string::npos);
  fs::remove_all(dir);
}

TEST(CliReport, NotAResultDirectoryIsExit2NamingTheFile) {
  const std::string dir = fsweep::testing::fresh_temp_dir("report", "bad");
  auto r = run_fsweep("report " + dir);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find(dir + ": not a directory"), std::string::npos) << r.output;

  fs::create_directories(dir + "/shard-notes");  // not a shard folder: no merge hint
  r = run_fsweep("report " + dir);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("not a sweep result directory"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("fsweep merge"), std::string::npos) << r.output;

  fs::create_directories(dir + "/shard-0-of-2");
  r = run_fsweep("report " + dir);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find(dir + "/manifest.json: not found: not a sweep result directory"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("fsweep merge " + dir), std::string::npos) << r.output;

  std::ofstream(dir + "/manifest.json") << "{\"status\": \"complete\"}";
  r = run_fsweep("report " + dir);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find(dir + "/manifest.json: not a sweep manifest"), std::string::npos) << r.output;

  std::ofstream(dir + "/manifest.json", std::ios::trunc) << R"({"sweep": {"name": "x"}})";
  r = run_fsweep("report " + dir);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find(dir + "/runs.csv: not found"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir + "/report.html"));
  fs::remove_all(dir);
}

}  // namespace
