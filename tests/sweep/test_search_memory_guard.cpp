// The exact weight search's memory guard: a search whose memory in use reaches 90% of the limit
// stops as at a Ctrl-C, its journal whole and the manifest "failed", with a message naming the
// limit, the memory and the behaviours held; a rerun with enough memory resumes to the files of
// an uninterrupted search. A resume whose journal alone reaches the threshold stops before
// searching, its journal untouched; one whose files' formatting would pass it stops before
// formatting them, its journal holding the whole search. The memory in use is the test's own reader, which
// passes the limit at a point of the search's choosing (the guard reads it every 16 behaviours).
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "sweep/merge.hpp"
#include "sweep/sweep_plan.hpp"
#include "sweep/sweep_runner.hpp"
#include "sweep/sweep_test_files.hpp"
#include "sweep/sweep_test_run.hpp"

namespace fsweep {
namespace test_search_memory_guard {  // not anonymous: unity builds

using nlohmann::json;

/// The limit the tests give; the reader says the process is far below it or past it.
constexpr std::uint64_t kLimit = 1000;
constexpr std::uint64_t kBelow = 100;
constexpr std::uint64_t kPast = 950;  // past 90% of kLimit

/// A search of mode all over [0, 3]^4 on an office map (a few hundred behaviours).
json search_of_256(const std::string& mode = "all") {
  const json range = {{"range", {0, 3}}, {"step", 1}};
  return json{{"schema_version", 1},
              {"name", "memory_guard"},
              {"maps", {"office:w=32,h=32,seed=3"}},
              {"strategies",
               {{{"name", "energy_aware"},
                 {"label", "exact"},
                 {"search", {{"method", "exact"}, {"mode", mode}}},
                 {"params", {{"w1", range}, {"w2", range}, {"w3", range}, {"w4", range}}}}}},
              {"robot", {{"sensor", {{"range_m", 3}}}, {"battery", 120}}},
              {"seed", 5}};
}

/// The search files an uninterrupted search of mode all writes.
const std::vector<std::string> kSearchFiles{"behaviours.csv", "search_summary.csv", "search_best.csv",
                                            "search_heatmaps.csv"};

/// How many lines of the journal at `path` hold a behaviour.
std::size_t journaled_behaviours(const std::string& path) {
  const std::string text = testing::read_file(path);
  std::size_t n = 0;
  for (std::size_t at = text.find("\"cells\""); at != std::string::npos; at = text.find("\"cells\"", at + 1))
    ++n;
  return n;
}

/// Every line of the journal at `path` is whole and parses.
void expect_whole_journal(const std::string& path) {
  const std::string text = testing::read_file(path);
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n') << "a journal line was left torn";
  std::size_t line = 0;
  for (std::size_t at = 0; at < text.size(); ++line) {
    const std::size_t end = text.find('\n', at);
    EXPECT_TRUE(json::accept(text.substr(at, end - at))) << path << ":" << line + 1;
    at = end == std::string::npos ? text.size() : end + 1;
  }
}

/// Runs `sweep` into `dir` quietly, under the limit kLimit with `resident` as the memory in use
/// (empty: with no limit given, the default one and the process's own memory).
RunnerReport run_guarded(const json& sweep, const std::string& dir,
                         std::function<std::optional<std::uint64_t>()> resident) {
  RunnerOptions o = testing::quiet_runner(dir);
  if (resident) {
    o.max_memory = MemoryLimit{kLimit, "test"};
    o.resident_memory = std::move(resident);
  }
  return run_sweep(SweepPlan::from_json(sweep, "memory_guard.json"), o);
}

json manifest(const std::string& dir) { return json::parse(testing::read_file(dir + "/manifest.json")); }

TEST(SearchMemoryGuard, AModeAllSearchStopsPastTheLimitWithItsJournalWholeAndResumes) {
  const json sweep = search_of_256();
  const std::string ref = testing::fresh_dir("memory_guard", "ref");
  (void)run_guarded(sweep, ref, {});
  const std::size_t behaviours = journaled_behaviours(ref + "/search_journal.jsonl");
  ASSERT_GT(behaviours, 64U) << "too few behaviours for the guard to stop the search before its end";

  // The memory passes the limit once 20 behaviours are journaled: the guard's next read, at the
  // 32nd behaviour or within 50 ms, stops the search.
  const std::string dir = testing::fresh_dir("memory_guard", "stopped");
  const std::string journal = dir + "/search_journal.jsonl";
  const RunnerReport first = run_guarded(sweep, dir, [&]() -> std::optional<std::uint64_t> {
    return journaled_behaviours(journal) >= 20 ? kPast : kBelow;
  });
  ASSERT_TRUE(first.searches.memory_stop) << "the search was not stopped";
  const MemoryStop& stop = *first.searches.memory_stop;
  EXPECT_TRUE(first.interrupted);
  EXPECT_EQ(stop.stage, MemoryStop::Stage::Searching);
  EXPECT_EQ(stop.in_use_bytes, kPast);
  EXPECT_EQ(stop.limit.bytes, kLimit);
  EXPECT_GE(stop.held_behaviours, 20U);
  EXPECT_LT(stop.held_behaviours, behaviours);
  EXPECT_NE(
      stop.message.find("exact weight search 0 stopped at the memory limit: the process used 950 B, past "
                        "90% of the limit of 1,000 B (test), holding " +
                        std::to_string(stop.held_behaviours) + " behaviours"),
      std::string::npos)
      << stop.message;
  for (const char* part : {"search_journal.jsonl keeps what it finished", "a larger --max-memory",
                           "\"mode\": \"best\"", "fsweep run --shard i/N"}) {
    EXPECT_NE(stop.message.find(part), std::string::npos) << part << " not in: " << stop.message;
  }
  EXPECT_EQ(manifest(dir)["status"], "failed");
  EXPECT_EQ(manifest(dir)["max_memory"], (json{{"bytes", kLimit}, {"source", "test"}}));
  EXPECT_FALSE(std::filesystem::exists(dir + "/searches.json"));
  for (const std::string& f : kSearchFiles) EXPECT_FALSE(std::filesystem::exists(dir + "/" + f)) << f;
  expect_whole_journal(journal);
  EXPECT_GE(journaled_behaviours(journal), stop.held_behaviours) << "a behaviour held but not journaled";

  // Rerun with enough memory: it resumes from the journal to the uninterrupted search's files.
  const RunnerReport second = run_guarded(sweep, dir, {});
  EXPECT_FALSE(second.interrupted);
  EXPECT_FALSE(second.searches.memory_stop);
  EXPECT_EQ(manifest(dir)["status"], "complete");
  const json record = json::parse(testing::read_file(dir + "/searches.json"))["searches"][0];
  EXPECT_GE(record["resumed_behaviours"].get<std::size_t>(), stop.held_behaviours);
  for (const std::string& f : kSearchFiles) {
    EXPECT_EQ(testing::read_file(dir + "/" + f), testing::read_file(ref + "/" + f)) << f;
  }
}

TEST(SearchMemoryGuard, ASearchWhoseFilesWouldPassTheLimitStopsBeforeFormattingThem) {
  const json sweep = search_of_256();
  const std::string ref = testing::fresh_dir("memory_guard", "ref_writing");
  (void)run_guarded(sweep, ref, {});
  const std::size_t behaviours = journaled_behaviours(ref + "/search_journal.jsonl");

  // The memory stays below the threshold while searching; formatting its files (2 KB a row of
  // behaviours.csv, one instance here) would pass it.
  const std::string dir = testing::fresh_dir("memory_guard", "writing");
  const RunnerReport first = run_guarded(sweep, dir, [] { return std::optional<std::uint64_t>(kBelow); });
  ASSERT_TRUE(first.searches.memory_stop) << "the search was not stopped";
  const MemoryStop& stop = *first.searches.memory_stop;
  EXPECT_TRUE(first.interrupted);
  EXPECT_EQ(stop.stage, MemoryStop::Stage::Writing);
  EXPECT_EQ(stop.held_behaviours, behaviours);
  EXPECT_EQ(stop.in_use_bytes, kBelow);
  EXPECT_EQ(stop.needed_bytes, behaviours * 2048);
  EXPECT_NE(
      stop.message.find("exact weight search 0 finished, but formatting its files would pass the memory "
                        "limit: the process used 100 B and would need about"),
      std::string::npos)
      << stop.message;
  EXPECT_NE(stop.message.find("search_journal.jsonl holds the whole search"), std::string::npos)
      << stop.message;
  EXPECT_EQ(manifest(dir)["status"], "failed");
  EXPECT_FALSE(std::filesystem::exists(dir + "/searches.json"));
  for (const std::string& f : kSearchFiles) EXPECT_FALSE(std::filesystem::exists(dir + "/" + f)) << f;
  expect_whole_journal(dir + "/search_journal.jsonl");
  EXPECT_EQ(journaled_behaviours(dir + "/search_journal.jsonl"), behaviours);

  // With the memory, the rerun searches nothing and writes the uninterrupted search's files.
  const RunnerReport second = run_guarded(sweep, dir, {});
  EXPECT_FALSE(second.searches.memory_stop);
  EXPECT_EQ(manifest(dir)["status"], "complete");
  const json record = json::parse(testing::read_file(dir + "/searches.json"))["searches"][0];
  EXPECT_EQ(record["resumed_behaviours"].get<std::size_t>(), behaviours);
  for (const std::string& f : kSearchFiles) {
    EXPECT_EQ(testing::read_file(dir + "/" + f), testing::read_file(ref + "/" + f)) << f;
  }
}

TEST(SearchMemoryGuard, ABestSearchCountsOnlyTheOptimalBehavioursItFormats) {
  // Mode best holds behaviours that were the best when they finished but formats only the
  // optimal ones: a limit with room for those rows (and not for a row per behaviour held) lets
  // it write its files.
  const json sweep = search_of_256("best");
  const std::string ref = testing::fresh_dir("memory_guard", "ref_best_rows");
  (void)run_guarded(sweep, ref, {});
  const json record = json::parse(testing::read_file(ref + "/searches.json"))["searches"][0];
  const auto optimal = record["behaviours"].get<std::uint64_t>();
  const std::size_t finished = journaled_behaviours(ref + "/search_journal.jsonl");
  ASSERT_GT(finished, optimal + 2) << "the search should finish non-optimal behaviours first";

  const std::string dir = testing::fresh_dir("memory_guard", "best_rows");
  RunnerOptions o = testing::quiet_runner(dir);
  o.max_memory = MemoryLimit{(kBelow + (optimal + 1) * 2048) * 10 / 9 + 1, "test"};
  o.resident_memory = [] { return std::optional<std::uint64_t>(kBelow); };
  const RunnerReport r = run_sweep(SweepPlan::from_json(sweep, "memory_guard.json"), o);
  EXPECT_FALSE(r.searches.memory_stop) << r.searches.memory_stop->message;
  for (const char* f : {"behaviours.csv", "search_best.csv"}) {
    EXPECT_EQ(testing::read_file(dir + "/" + f), testing::read_file(ref + "/" + f)) << f;
  }
}

TEST(SearchMemoryGuard, AMergeOfShardsPastTheLimitWritesNothingAndAMergeWithTheMemoryWritesTheWhole) {
  const json sweep = search_of_256();
  const std::string ref = testing::fresh_dir("memory_guard", "ref_merge");
  (void)run_guarded(sweep, ref, {});
  const std::string dir = testing::fresh_dir("memory_guard", "merge");
  for (std::uint64_t i = 0; i < 2; ++i) (void)testing::run_test_shard(sweep, dir, i, 2);

  // Past the threshold from the start: the guard's first read (its thread's, or the one at the
  // 16th behaviour read back) stops it.
  SearchMemoryGuard past{MemoryLimit{kLimit, "test"}, [] { return std::optional<std::uint64_t>(kPast); }};
  const MergeReport stopped = merge_shards(dir, {}, past);
  EXPECT_FALSE(stopped.written);
  for (const char* part :
       {"merging exact weight search 0's shards reached the memory limit: the process used "
        "950 B, past 90% of the limit of 1,000 B (test), holding ",
        " behaviours; nothing was written. To go on: rerun fsweep merge with a larger "
        "--max-memory"}) {
    EXPECT_NE(stopped.memory_stop.find(part), std::string::npos) << stopped.memory_stop;
  }
  for (const std::string& f : kSearchFiles) EXPECT_FALSE(std::filesystem::exists(dir + "/" + f)) << f;
  EXPECT_FALSE(std::filesystem::exists(dir + "/runs.csv"));
  EXPECT_FALSE(std::filesystem::exists(dir + "/manifest.json"));

  // Below it, but formatting the whole search's files would pass it: stopped before formatting.
  SearchMemoryGuard below{MemoryLimit{kLimit, "test"}, [] { return std::optional<std::uint64_t>(kBelow); }};
  const MergeReport formatting = merge_shards(dir, {}, below);
  EXPECT_FALSE(formatting.written);
  EXPECT_NE(formatting.memory_stop.find("the process used 100 B and would need about"), std::string::npos)
      << formatting.memory_stop;
  EXPECT_FALSE(std::filesystem::exists(dir + "/searches.json"));

  const MergeReport merged = merge_shards(dir);
  EXPECT_TRUE(merged.written);
  EXPECT_TRUE(merged.memory_stop.empty());
  for (const std::string& f : kSearchFiles) {
    EXPECT_EQ(testing::read_file(dir + "/" + f), testing::read_file(ref + "/" + f)) << f;
  }
}

TEST(SearchMemoryGuard, AResumeWhoseJournalPassesTheLimitStopsBeforeSearching) {
  // The journal of a whole search, its files deleted: the rerun reads every behaviour back
  // before searching. The memory passes the limit at the guard's second read on this thread (the
  // first is before the journal is read; the next at the 16th behaviour read back); its reads
  // on the guard's own thread, which come at times of their own, see the memory below it.
  const json sweep = search_of_256();
  const std::string dir = testing::fresh_dir("memory_guard", "resume");
  (void)run_guarded(sweep, dir, {});
  const std::string ref_behaviours = testing::read_file(dir + "/behaviours.csv");
  const std::size_t behaviours = journaled_behaviours(dir + "/search_journal.jsonl");
  for (const char* f : {"searches.json", "behaviours.csv", "search_summary.csv", "search_best.csv",
                        "search_heatmaps.csv", "search_ranks.csv"}) {
    std::filesystem::remove(dir + "/" + f);
  }
  const std::string journal = testing::read_file(dir + "/search_journal.jsonl");

  const std::thread::id searching = std::this_thread::get_id();
  std::atomic<int> reads{0};
  const RunnerReport refused = run_guarded(sweep, dir, [&]() -> std::optional<std::uint64_t> {
    if (std::this_thread::get_id() != searching) return kBelow;
    return ++reads >= 2 ? kPast : kBelow;
  });
  ASSERT_TRUE(refused.searches.memory_stop) << "the resume was not stopped";
  const MemoryStop& stop = *refused.searches.memory_stop;
  EXPECT_EQ(stop.stage, MemoryStop::Stage::Resuming);
  EXPECT_GT(stop.held_behaviours, 0U);
  EXPECT_LT(stop.held_behaviours, behaviours);
  EXPECT_NE(
      stop.message.find("exact weight search 0 cannot resume within the memory limit: reading its journal "
                        "back, the process used 950 B"),
      std::string::npos)
      << stop.message;
  EXPECT_EQ(testing::read_file(dir + "/search_journal.jsonl"), journal) << "the journal changed";
  EXPECT_FALSE(std::filesystem::exists(dir + "/searches.json"));
  EXPECT_EQ(manifest(dir)["status"], "failed");

  const RunnerReport resumed = run_guarded(sweep, dir, {});
  EXPECT_FALSE(resumed.interrupted);
  const json record = json::parse(testing::read_file(dir + "/searches.json"))["searches"][0];
  EXPECT_EQ(record["resumed_behaviours"].get<std::size_t>(), behaviours);
  EXPECT_EQ(testing::read_file(dir + "/behaviours.csv"), ref_behaviours);
}

TEST(SearchMemoryGuard, AProcessAlreadyPastTheLimitSearchesNothing) {
  // Mode best, order bound: the advice names the order and max_open instead of mode best.
  json sweep = search_of_256("best");
  sweep["strategies"][0]["search"]["order"] = "bound";
  const std::string dir = testing::fresh_dir("memory_guard", "start");
  const RunnerReport r = run_guarded(sweep, dir, [] { return std::optional<std::uint64_t>(kPast); });
  ASSERT_TRUE(r.searches.memory_stop);
  const MemoryStop& stop = *r.searches.memory_stop;
  EXPECT_EQ(stop.stage, MemoryStop::Stage::Starting);
  EXPECT_NE(
      stop.message.find("exact weight search 0 cannot start within the memory limit: before it began, the "
                        "process used 950 B, past 90% of the limit of 1,000 B (test);"),
      std::string::npos)
      << stop.message;
  EXPECT_NE(stop.message.find("\"order\": \"depth\""), std::string::npos) << stop.message;
  EXPECT_EQ(stop.message.find("\"mode\": \"best\""), std::string::npos) << stop.message;
  EXPECT_EQ(journaled_behaviours(dir + "/search_journal.jsonl"), 0U);
  EXPECT_EQ(manifest(dir)["status"], "failed");
}

TEST(SearchMemoryGuard, TheDefaultLimitIsRecordedOnlyInSweepsWithSearches) {
  const std::string dir = testing::fresh_dir("memory_guard", "default");
  json sweep = search_of_256();
  sweep["strategies"][0]["params"] = {{"w1", {0, 1}}, {"w2", 0}, {"w3", 0}, {"w4", 0}};
  const RunnerReport r = run_guarded(sweep, dir, {});
  ASSERT_TRUE(r.max_memory) << "no limit read on this machine";
  const json m = manifest(dir);
  EXPECT_EQ(m["max_memory"]["bytes"], r.max_memory->bytes);
  EXPECT_EQ(m["max_memory"]["source"], r.max_memory->source);
  EXPECT_EQ(m["sessions"].back()["max_memory"], m["max_memory"]);

  const std::string plain = testing::fresh_dir("memory_guard", "no_search");
  sweep["strategies"][0].erase("search");
  (void)run_guarded(sweep, plain, {});
  EXPECT_FALSE(manifest(plain).contains("max_memory"));
}

}  // namespace test_search_memory_guard
}  // namespace fsweep
