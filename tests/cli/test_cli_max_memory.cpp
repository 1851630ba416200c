// `fsweep run --max-memory` and `fsweep merge --max-memory`: sizes they refuse (exit 2, naming
// the option); a weight search the guard stops, with the process's real memory, exits 1 with its
// journal whole, and the same command without the tight limit resumes it to the files of an
// uninterrupted search.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "cli/fsweep_process.hpp"
#include "sweep/sweep_test_files.hpp"

namespace test_cli_max_memory {  // not anonymous: unity builds put it beside other test files' helpers

using fsweep::testing::CliOutcome;
using fsweep::testing::read_all;
using fsweep::testing::run_fsweep;
using nlohmann::json;

/// The free-space search of docs/weight-search.md, "A small search to try" (847 behaviours, about
/// 2 s on 2 threads), written into `dir`; returns its path.
std::string write_small_search(const std::string& dir) {
  std::filesystem::create_directories(dir);
  const std::string path = dir + "/small_search.json";
  std::ofstream(path) << R"({"schema_version": 1, "name": "small_search",
    "maps": [{"generator": "free", "w": 71, "h": 71, "res": 10, "label": "free 710 m"}],
    "strategies": [{"name": "energy_aware", "label": "exact",
      "search": {"method": "exact", "mode": "all", "rank": [[1, 0, 0, 0], [10, 0, 5, 2]]},
      "params": {"w1": {"range": [0, 15], "step": 1}, "w2": {"range": [0, 7], "step": 1},
                 "w3": {"range": [0, 7], "step": 1}, "w4": [0, 1, 2]}}],
    "robot": {"sensor": {"range_m": 30}, "energy": "distance", "battery": 600},
    "seed": 2016})";
  return path;
}

/// Every line of the journal is whole JSON; returns how many hold a behaviour.
std::size_t whole_journal_behaviours(const std::string& path) {
  const std::string text = read_all(path);
  EXPECT_TRUE(text.empty() || text.back() == '\n') << path << " ends in a torn line";
  std::size_t behaviours = 0;
  for (std::size_t begin = 0, end = text.find('\n'); end != std::string::npos;
       begin = end + 1, end = text.find('\n', begin)) {
    const json line = json::parse(text.substr(begin, end - begin), nullptr, false);
    EXPECT_FALSE(line.is_discarded()) << path << ": " << text.substr(begin, 80);
    if (line.is_object() && line.contains("cells")) ++behaviours;
  }
  return behaviours;
}

json manifest(const std::string& dir) { return json::parse(read_all(dir + "/manifest.json")); }

/// The MiB in "the process used <x> MiB" of a memory stop's message; 0 when it has none.
double used_mib(const std::string& output) {
  const std::string marker = "the process used ";
  const std::size_t at = output.find(marker);
  if (at == std::string::npos || output.find(" MiB", at) == std::string::npos) return 0.0;
  return std::strtod(output.c_str() + at + marker.size(), nullptr);
}

TEST(CliMaxMemory, SizesOtherThanBytesOrKMGTAreRefusedNamingTheOption) {
  const std::string dir = fsweep::testing::fresh_temp_dir("max_memory", "bad");
  const std::string sweep = write_small_search(dir);
  for (const char* bad : {"4X", "0", "1.5", "-1G", "4GB"}) {
    for (const std::string& command :
         {"run " + sweep + " --out " + dir + "/out --quiet", "merge " + dir + "/out"}) {
      const CliOutcome r = run_fsweep(command + " --max-memory=" + bad);
      EXPECT_EQ(r.code, 2) << command << " " << bad << "\n" << r.output;
      EXPECT_NE(r.output.find(
                    "fsweep: error: --max-memory: expected a size above 0: a number of bytes, or a number "
                    "with K, M, G or T (powers of 1024) such as 512M, 1.5G or 4G; got '" +
                    std::string(bad) + "'"),
                std::string::npos)
          << command << "\n"
          << r.output;
    }
  }
}

TEST(CliMaxMemory, ASearchStoppedAtTheLimitExits1AndTheRerunWithMoreMemoryFinishesIt) {
  const std::string dir = fsweep::testing::fresh_temp_dir("max_memory", "stop");
  const std::string sweep = write_small_search(dir);
  const std::string ref = dir + "/ref";
  ASSERT_EQ(run_fsweep("run " + sweep + " --out " + ref + " --quiet").code, 0);
  const std::size_t behaviours = whole_journal_behaviours(ref + "/search_journal.jsonl");

  // 1 MiB: less than any process holds, so the search does not start.
  const std::string before = dir + "/before";
  const CliOutcome refused = run_fsweep("run " + sweep + " --out " + before + " --quiet --max-memory 1M");
  EXPECT_EQ(refused.code, 1) << refused.output;
  EXPECT_NE(
      refused.output.find("fsweep: error: exact weight search 0 cannot start within the memory limit: before "
                          "it began, the process used "),
      std::string::npos)
      << refused.output;
  EXPECT_NE(refused.output.find("past 90% of the limit of 1 MiB (--max-memory 1M)"), std::string::npos)
      << refused.output;
  EXPECT_EQ(manifest(before)["status"], "failed");
  EXPECT_EQ(manifest(before)["max_memory"], (json{{"bytes", 1 << 20}, {"source", "--max-memory 1M"}}));
  const double start_mib = used_mib(refused.output);
  ASSERT_GT(start_mib, 1.0) << refused.output;

  // A limit whose 90% is 4 MiB above that: the search grows past it after a few dozen of its
  // behaviours (it holds about 8 MiB more at its end).
  const std::string limit = std::to_string((start_mib + 4.0) / 0.9) + "M";
  const std::string out = dir + "/out";
  const CliOutcome stopped = run_fsweep("run " + sweep + " --out " + out + " --quiet --max-memory " + limit);
  EXPECT_EQ(stopped.code, 1) << stopped.output;
  EXPECT_NE(stopped.output.find(
                "fsweep: error: exact weight search 0 stopped at the memory limit: the process used "),
            std::string::npos)
      << stopped.output;
  EXPECT_NE(stopped.output.find("search_journal.jsonl keeps what it finished"), std::string::npos);
  EXPECT_EQ(manifest(out)["status"], "failed");
  EXPECT_FALSE(std::filesystem::exists(out + "/searches.json"));
  const std::size_t kept = whole_journal_behaviours(out + "/search_journal.jsonl");
  EXPECT_LT(kept, behaviours);

  const CliOutcome resumed = run_fsweep("run " + sweep + " --out " + out + " --quiet");
  EXPECT_EQ(resumed.code, 0) << resumed.output;
  EXPECT_EQ(manifest(out)["status"], "complete");
  EXPECT_EQ(manifest(out)["max_memory"], manifest(ref)["max_memory"]) << "the default limit";
  const json record = json::parse(read_all(out + "/searches.json"))["searches"][0];
  EXPECT_EQ(record["resumed_behaviours"].get<std::size_t>(), kept);
  for (const char* f : {"behaviours.csv", "search_summary.csv", "search_best.csv", "search_ranks.csv",
                        "search_heatmaps.csv"}) {
    EXPECT_EQ(read_all(out + "/" + f), read_all(ref + "/" + f)) << f;
  }
}

}  // namespace test_cli_max_memory
