// A sweep's exact weight search against the brute-force sweep of the same box, in one sweep
// file: every vector's behaviour (vectors.csv, behaviours.csv) is its run in runs.csv, metric
// for metric; the ranking, ranks, heat maps and summary quantiles are the brute-force ones; a
// map class is searched jointly by its mean; bad search entries are refused with their path.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <functional>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "core/config_error.hpp"
#include "core/csv_reader.hpp"
#include "core/random.hpp"
#include "core/statistics.hpp"
#include "report/runs_schema.hpp"
#include "sweep/merge.hpp"
#include "sweep/search_anytime.hpp"
#include "sweep/sweep_plan.hpp"
#include "sweep/sweep_runner.hpp"
#include "sweep/sweep_table.hpp"
#include "sweep/sweep_test_files.hpp"
#include "sweep/sweep_test_run.hpp"
#include "sweep/weight_search_runner.hpp"
#include "weightsearch/search_journal.hpp"
#include "weightsearch/weight_grid.hpp"

namespace fsweep {
namespace test_weight_search_runner {  // not anonymous: unity builds

using nlohmann::json;

/// A whole CSV file.
struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  [[nodiscard]] std::size_t col(const std::string& name) const {
    const auto it = std::find(header.begin(), header.end(), name);
    if (it == header.end()) throw std::out_of_range("no column " + name);
    return static_cast<std::size_t>(it - header.begin());
  }
};

Table read_table(const std::string& path) {
  CsvReader in(path);
  Table t{in.header(), {}};
  while (in.next()) t.rows.push_back(in.fields());
  return t;
}

/// A sweep with a search entry and a brute-force entry ("grid") over the same box.
json search_and_grid(const json& maps, const json& box, const json& rank, int repetitions = 1,
                     const std::string& strategy = "energy_aware") {
  return json{{"schema_version", 1},
              {"name", "search_test"},
              {"maps", maps},
              {"strategies",
               {{{"name", strategy},
                 {"label", "exact"},
                 {"search", {{"method", "exact"}, {"mode", "all"}, {"write_vectors", true}, {"rank", rank}}},
                 {"params", box}},
                {{"name", strategy}, {"label", "grid"}, {"params", box}}}},
              {"robot", {{"sensor", {{"range_m", 3}}}, {"battery", 120}}},
              {"repetitions", repetitions},
              {"seed", 5}};
}

/// Runs `sweep` into a fresh directory and returns it.
std::string run(const json& sweep, const std::string& name) {
  const std::string dir = testing::fresh_dir("search", name);
  RunnerOptions o = testing::quiet_runner(dir);
  const RunnerReport r = run_sweep(SweepPlan::from_json(sweep, "search.json"), o);
  EXPECT_EQ(r.searches.searches, 1U);
  return dir;
}

using Vector = std::vector<std::string>;
const std::vector<std::string> kEnergyAwareWeights{"w1", "w2", "w3", "w4"};

/// The weights `names` of a runs.csv row, as written.
Vector weights_of(const Table& runs, std::size_t row,
                  const std::vector<std::string>& names = kEnergyAwareWeights) {
  Vector w;
  for (const std::string& name : names) w.push_back(runs.rows[row][runs.col("strategy." + name)]);
  return w;
}

/// vectors.csv: the behaviour of every vector of weights `names`.
std::map<Vector, std::string> owners(const Table& vectors,
                                     const std::vector<std::string>& names = kEnergyAwareWeights) {
  std::map<Vector, std::string> out;
  for (const auto& r : vectors.rows) {
    Vector w;
    for (const std::string& name : names) w.push_back(r[vectors.col(name)]);
    out[w] = r[vectors.col("behaviour_id")];
  }
  return out;
}

/// runs.csv, vectors.csv and behaviours.csv of a sweep with a search and its brute force.
struct SearchFiles {
  Table runs;
  Table vectors;
  Table behaviours;
};

SearchFiles read_search_files(const std::string& dir) {
  return {read_table(dir + "/runs.csv"), read_table(dir + "/vectors.csv"),
          read_table(dir + "/behaviours.csv")};
}

/// Every run of runs.csv (the brute-force entry) against the behaviour vectors.csv gives its
/// weights: the same seed, end reason and every metric but the effort ones; and every
/// behaviour's vector count is the number of runs that are it.
void expect_every_vector_is_its_run(const Table& runs, const Table& vectors, const Table& behaviours,
                                    const std::vector<std::string>& names) {
  const std::map<Vector, std::string> owner = owners(vectors, names);
  std::map<std::string, std::size_t> behaviour_row;
  for (std::size_t i = 0; i < behaviours.rows.size(); ++i) {
    behaviour_row[behaviours.rows[i][behaviours.col("behaviour_id")]] = i;
  }
  const std::size_t first_metric = behaviours.col(kEndReasonColumn);
  std::map<std::string, int> counted;
  for (std::size_t r = 0; r < runs.rows.size(); ++r) {
    const Vector w = weights_of(runs, r, names);
    const std::string id = owner.at(w);
    ++counted[id];
    const auto& b = behaviours.rows[behaviour_row.at(id)];
    EXPECT_EQ(b[behaviours.col("seed")], runs.rows[r][runs.col("seed")]);
    std::string at;
    for (const std::string& v : w) at += (at.empty() ? "(" : ", ") + v;
    for (std::size_t c = first_metric; c < behaviours.header.size(); ++c) {
      const std::string& name = behaviours.header[c];
      if (is_effort_column(name)) continue;
      EXPECT_EQ(b[c], runs.rows[r][runs.col(name)]) << name << " at " << at << ")";
    }
  }
  for (const auto& b : behaviours.rows) {
    EXPECT_EQ(std::to_string(counted[b[behaviours.col("behaviour_id")]]), b[behaviours.col("vectors")]);
  }
}

/// Checks the behaviour_id of every cell of search_heatmaps.csv in `dir` (a search with
/// vectors.csv, energy-aware weights): of the behaviours with a vector there and the cell's best
/// objective, the smallest id. Returns how many cells had more than one such behaviour.
int expect_heat_map_owners(const std::string& dir) {
  const Table vectors = read_table(dir + "/vectors.csv");
  const Table behaviours = read_table(dir + "/behaviours.csv");
  const Table heat = read_table(dir + "/search_heatmaps.csv");
  std::map<long, double> objective;
  for (const auto& row : behaviours.rows) {
    objective[std::stol(row[behaviours.col("behaviour_id")])] = std::stod(row[behaviours.col("objective")]);
  }
  int ties = 0;
  for (const auto& row : heat.rows) {
    const std::string& a = row[heat.col("weight_a")];
    const std::string& b = row[heat.col("weight_b")];
    std::set<long> there;
    for (const auto& v : vectors.rows) {
      if (v[vectors.col(a)] == row[heat.col("value_a")] && v[vectors.col(b)] == row[heat.col("value_b")])
        there.insert(std::stol(v[vectors.col("behaviour_id")]));
    }
    double best = INFINITY;
    for (const long id : there) best = std::min(best, objective.at(id));
    std::vector<long> first;
    for (const long id : there) {
      if (objective.at(id) == best) first.push_back(id);  // ascending: std::set
    }
    if (first.empty()) {
      ADD_FAILURE() << "a heat-map cell without vectors";
      continue;
    }
    if (first.size() > 1) ++ties;
    EXPECT_EQ(std::stol(row[heat.col("behaviour_id")]), first.front())
        << a << "=" << row[heat.col("value_a")] << ", " << b << "=" << row[heat.col("value_b")];
  }
  return ties;
}

double objective_of(const Table& runs, std::size_t row) {
  return std::stod(runs.rows[row][runs.col("distance_to_final_coverage_m")]);
}

TEST(WeightSearchRunner, AgreesWithABruteForceSweepOfTheSameBoxForEveryVector) {
  const json box = {{"w1", {{"range", {0, 3}}, {"step", 1}}},
                    {"w2", {0, 2}},
                    {"w3", {{"range", {0, 3}}, {"step", 1}}},
                    {"w4", {0, 1, 3}}};
  const std::string dir = run(
      search_and_grid(json::array({"office:w=32,h=32,seed=3"}), box, {{1, 0, 0, 0}, {3, 2, 1, 3}}), "brute");
  const auto [runs, vectors, behaviours] = read_search_files(dir);
  ASSERT_EQ(runs.rows.size(), 96U);
  ASSERT_EQ(vectors.rows.size(), 96U);
  ASSERT_GE(behaviours.rows.size(), 5U) << "weights that change nothing test nothing";
  // 1. Every vector's behaviour is its run, metric for metric (effort metrics aside).
  expect_every_vector_is_its_run(runs, vectors, behaviours, kEnergyAwareWeights);
  const std::map<Vector, std::string> owner = owners(vectors);
  // 2. The ranking: rank = 1 + vectors strictly better, by brute force.
  std::vector<double> objectives;
  for (std::size_t r = 0; r < runs.rows.size(); ++r) objectives.push_back(objective_of(runs, r));
  const auto better_than = [&](double v) {
    return std::count_if(objectives.begin(), objectives.end(), [&](double o) { return o < v; });
  };
  const Table best = read_table(dir + "/search_best.csv");
  ASSERT_EQ(best.rows.size(), behaviours.rows.size());
  EXPECT_EQ(std::stod(best.rows[0][best.col("objective")]),
            *std::min_element(objectives.begin(), objectives.end()));
  for (const auto& row : best.rows) {
    EXPECT_EQ(std::stol(row[best.col("rank")]), better_than(std::stod(row[best.col("objective")])) + 1);
  }
  const Table ranks = read_table(dir + "/search_ranks.csv");
  ASSERT_EQ(ranks.rows.size(), 2U);
  for (const auto& row : ranks.rows) {
    const Vector w{row[ranks.col("w1")], row[ranks.col("w2")], row[ranks.col("w3")], row[ranks.col("w4")]};
    std::size_t run_row = 0;
    while (weights_of(runs, run_row) != w) ++run_row;
    EXPECT_EQ(row[ranks.col("behaviour_id")], owner.at(w));
    EXPECT_EQ(std::stol(row[ranks.col("rank")]), better_than(objective_of(runs, run_row)) + 1);
    EXPECT_EQ(std::stol(row[ranks.col("vectors_tied")]),
              std::count(objectives.begin(), objectives.end(), objective_of(runs, run_row)));
  }
  // 3. Heat maps: per pair of values, the best objective of the runs with them.
  const Table heat = read_table(dir + "/search_heatmaps.csv");
  ASSERT_EQ(heat.rows.size(), 4U * 2 + 4 * 4 + 4 * 3 + 2 * 4 + 2 * 3 + 4 * 3);
  for (const auto& row : heat.rows) {
    const std::string a = "strategy." + row[heat.col("weight_a")];
    const std::string b = "strategy." + row[heat.col("weight_b")];
    double expected = INFINITY;
    for (std::size_t r = 0; r < runs.rows.size(); ++r) {
      if (runs.rows[r][runs.col(a)] == row[heat.col("value_a")] &&
          runs.rows[r][runs.col(b)] == row[heat.col("value_b")]) {
        expected = std::min(expected, objective_of(runs, r));
      }
    }
    EXPECT_EQ(std::stod(row[heat.col("best_objective")]), expected);
  }
  (void)expect_heat_map_owners(dir);
  // 4. The summary's quantiles are those of the runs.
  const Table summary = read_table(dir + "/search_summary.csv");
  ASSERT_EQ(summary.rows.size(), 1U);
  std::vector<double> distances;
  for (std::size_t r = 0; r < runs.rows.size(); ++r)
    distances.push_back(std::stod(runs.rows[r][runs.col("distance_m")]));
  std::sort(distances.begin(), distances.end());
  for (const auto& [column, q] : std::vector<std::pair<std::string, double>>{{"distance_m.min", 0.0},
                                                                             {"distance_m.q05", 0.05},
                                                                             {"distance_m.median", 0.5},
                                                                             {"distance_m.q95", 0.95}}) {
    EXPECT_EQ(std::stod(summary.rows[0][summary.col(column)]), quantile_sorted(distances, q)) << column;
  }
  EXPECT_EQ(summary.rows[0][summary.col("vectors")], "96");
}

TEST(WeightSearchRunner, AHeatMapCellNamesTheFirstOfTheBehavioursTiedAtItsBest) {
  // Free space is symmetric, so mirrored behaviours reach the same objective: heat-map cells
  // whose best objective several behaviours share. The cell names the smallest id, as a walk
  // over the behaviours in id order would, though they were noted in the order they finished.
  const json box = {{"w1", {{"range", {0, 3}}, {"step", 1}}},
                    {"w2", {{"range", {0, 3}}, {"step", 1}}},
                    {"w3", {{"range", {0, 3}}, {"step", 1}}},
                    {"w4", {{"range", {0, 3}}, {"step", 1}}}};
  json sweep = search_and_grid(json::array({{{"generator", "free"}, {"w", 15}, {"h", 15}, {"res", 1}}}), box,
                               json::array());
  sweep["strategies"].erase(1);  // the search alone
  sweep["robot"]["battery"] = 60;
  const std::string dir = run(sweep, "heat_ties");
  EXPECT_GT(expect_heat_map_owners(dir), 0) << "no tie: the test tests nothing";
  std::filesystem::remove_all(dir);
}

// Long (label long: make test-long, the nightly job).
TEST(WeightSearchLong, DISABLED_TargetSeekingIsSearchedAsEquationTwelveOverDecimalWeights) {
  // Arvanitakis' equation 12 is linear in (w1, w2, w3): a box of decimal weights, with a target
  // (one cell step per decision) and without (pure exploration), against the brute force.
  const std::vector<std::string> names{"w1", "w2", "w3"};
  for (const json& target : {json::array({json{60, 60}}), json(nullptr)}) {
    const json box = {{"target", target},
                      {"w1", {{"range", {0, 1}}, {"step", 0.5}}},
                      {"w2", {0, 0.3, 0.9}},
                      {"w3", {0.1, 0.4, 1}}};
    json sweep =
        search_and_grid(json::array({"office:w=64,h=64,seed=4"}), box, json::array(), 1, "target_seeking");
    sweep["robot"] = {{"sensor", {{"range_m", 4}}}};
    const std::string dir = run(sweep, target.is_null() ? "ts_explore" : "ts_target");
    const auto [runs, vectors, behaviours] = read_search_files(dir);
    ASSERT_EQ(runs.rows.size(), 27U);
    ASSERT_EQ(vectors.rows.size(), 27U);
    EXPECT_GE(behaviours.rows.size(), 3U) << "weights that change nothing test nothing";
    expect_every_vector_is_its_run(runs, vectors, behaviours, names);
  }
}

/// The lines of a journal, each with its newline (a torn last line, as a reader can see while the
/// search writes it, without); `behaviours`: how many hold a behaviour (the others a finished
/// subtree or, in mode best, a leaf branch and bound did not report: pruned or beaten).
std::vector<std::string> journal_lines(const std::string& journal, std::size_t* behaviours = nullptr) {
  std::vector<std::string> lines;
  for (std::size_t at = 0; at < journal.size();) {
    const std::size_t end = journal.find('\n', at);
    if (end == std::string::npos) {
      lines.push_back(journal.substr(at));
      break;
    }
    lines.push_back(journal.substr(at, end - at + 1));
    at = end + 1;
  }
  if (behaviours != nullptr) {
    *behaviours =
        static_cast<std::size_t>(std::count_if(lines.begin(), lines.end(), [](const std::string& l) {
          return l.find("\"cells\"") != std::string::npos;
        }));
  }
  return lines;
}

// Long (label long: make test-long, the nightly job).
TEST(WeightSearchLong, DISABLED_ShardsMergeIntoExactlyTheFilesOfOneSearch) {
  // A map class searched whole and as 3 shards (their parts of one behaviour joined by its
  // trace), in both modes: every CSV file of the merge is the unsharded one, byte for byte.
  const json box = {
      {"w1", {0, 1, 2}}, {"w2", {0, 2}}, {"w3", {{"range", {0, 9}}, {"step", 1}}}, {"w4", {0, 2}}};
  const json maps = json::array({{{"generator", "office"}, {"w", 32}, {"h", 32}, {"seeds", {3, 4}}}});
  // Mode all without vectors.csv keeps no region of a behaviour once its ranks and heat-map
  // cells are noted, in the shards as in the merge.
  std::string listed;  // the unsharded search of mode all with vectors.csv
  for (const std::string variant : {"all", "all_unlisted", "best"}) {
    const std::string mode = variant == "best" ? "best" : "all";
    json sweep = search_and_grid(maps, box, mode == "all" ? json{{1, 0, 2, 0}} : json::array());
    sweep["strategies"].erase(1);  // the search alone
    sweep["strategies"][0]["search"] = {{"mode", mode}, {"write_vectors", variant == "all"}};
    if (mode == "all") sweep["strategies"][0]["search"]["rank"] = {{1, 0, 2, 0}};
    const std::string whole = run(sweep, "unsharded_" + variant);
    if (variant == "all") listed = whole;
    if (variant == "all_unlisted") {
      EXPECT_FALSE(std::filesystem::exists(whole + "/vectors.csv"));
      for (const char* f : {"behaviours.csv", "search_best.csv", "search_summary.csv", "search_ranks.csv",
                            "search_heatmaps.csv"}) {
        EXPECT_EQ(testing::read_file(whole + "/" + f), testing::read_file(listed + "/" + f)) << f;
      }
    }
    const std::string dir = testing::fresh_dir("search", "sharded_" + variant);
    for (std::uint64_t i = 0; i < 3; ++i) {
      RunnerOptions o = testing::quiet_runner(dir);
      o.shard_index = i;
      o.shard_count = 3;
      (void)run_sweep(SweepPlan::from_json(sweep, "search.json"), o);
      EXPECT_FALSE(std::filesystem::exists(dir + "/shard-" + std::to_string(i) + "-of-3/behaviours.csv"))
          << "a shard writes its parts only";
    }
    // A shard whose search did not finish (no searches.json) stops the merge, naming it, before
    // anything is written.
    const std::string unfinished = dir + "/shard-1-of-3/searches.json";
    std::filesystem::rename(unfinished, unfinished + ".away");
    try {
      (void)merge_shards(dir);
      ADD_FAILURE() << "merged a shard whose search did not finish";
    } catch (const ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find(unfinished), std::string::npos) << e.what();
    }
    EXPECT_FALSE(std::filesystem::exists(dir + "/behaviours.csv"));
    EXPECT_FALSE(std::filesystem::exists(dir + "/runs.csv"));
    std::filesystem::rename(unfinished + ".away", unfinished);
    // A damaged line in a finished shard's journal stops it too, naming the line, and the merge
    // leaves the journal as it was.
    const std::string journal = dir + "/shard-0-of-3/search_journal.jsonl";
    const std::string whole_journal = testing::read_file(journal);
    testing::write_file(journal, "{not json\n" + whole_journal);
    try {
      (void)merge_shards(dir);
      ADD_FAILURE() << "merged a damaged journal";
    } catch (const ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find(journal + ":1"), std::string::npos) << e.what();
    }
    EXPECT_EQ(testing::read_file(journal), "{not json\n" + whole_journal);
    testing::write_file(journal, whole_journal);
    // So does a line that parses but whose region is not of the box (a block it does not have).
    const std::string other = dir + "/shard-1-of-3/search_journal.jsonl";
    const std::string other_journal = testing::read_file(other);
    const std::vector<std::string> other_lines = journal_lines(other_journal);
    const auto behaviour_line =
        std::find_if(other_lines.begin(), other_lines.end(),
                     [](const std::string& l) { return l.find("\"parts\":[[") != std::string::npos; });
    ASSERT_NE(behaviour_line, other_lines.end());
    json outside = json::parse(*behaviour_line);
    outside["parts"][0][0] = 1U << 20U;
    testing::write_file(other, outside.dump() + "\n" + other_journal);
    try {
      (void)merge_shards(dir);
      ADD_FAILURE() << "merged a region outside the box";
    } catch (const ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find(other + ":1"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("a region outside the search's box"), std::string::npos)
          << e.what();
    }
    testing::write_file(other, other_journal);
    const MergeReport merged = merge_shards(dir);
    ASSERT_TRUE(merged.written);
    EXPECT_EQ(merged.searches, 1U);
    std::vector<std::string> files{"behaviours.csv", "search_best.csv"};
    if (mode == "all") {
      for (const char* f : {"search_summary.csv", "search_ranks.csv", "search_heatmaps.csv"})
        files.emplace_back(f);
    }
    if (variant == "all") files.emplace_back("vectors.csv");
    for (const auto& f : files) {
      EXPECT_EQ(testing::read_file(dir + "/" + f), testing::read_file(whole + "/" + f))
          << variant << ": " << f;
    }
    const json one = json::parse(testing::read_file(whole + "/searches.json"))["searches"][0];
    const json joined = json::parse(testing::read_file(dir + "/searches.json"))["searches"][0];
    EXPECT_EQ(joined["behaviours"], one["behaviours"]) << mode;
    ASSERT_EQ(joined["merged_from_shards"].size(), 3U);
    if (mode == "best") {
      EXPECT_EQ(joined["certificate"]["optimum"], one["certificate"]["optimum"]);
      EXPECT_EQ(joined["certificate"]["optimal_vectors"], one["certificate"]["optimal_vectors"]);
      for (const json& shard : joined["merged_from_shards"]) EXPECT_TRUE(shard["certificate"].is_object());
    } else {
      // Some behaviour spans shards, or the test would not test the join.
      std::size_t parts = 0;
      for (const json& shard : joined["merged_from_shards"]) parts += shard["behaviours"].get<std::size_t>();
      EXPECT_GT(parts, joined["behaviours"].get<std::size_t>());
    }
  }
}

/// A behaviour's journal line (with its newline) with its parts' points as the 64 hexadecimal
/// words that journals held before 2026-12-04 instead of runs; another line as it is.
std::string with_hex_parts(const std::string& line) {
  json j = json::parse(line);
  if (!j.contains("parts")) return line;
  for (json& p : j["parts"]) {
    std::string hex;
    for (const std::uint64_t word : bits_of_runs(p[1].get<std::vector<std::uint32_t>>())) hex += hex64(word);
    p[1] = hex;
  }
  return j.dump() + "\n";
}

/// The search of mode best on one office map over 96 vectors that the resume tests stop and
/// rerun, with `probes` probes.
json small_best_search(int probes) {
  const json box = {
      {"w1", {0, 1, 2, 3}}, {"w2", {0, 2}}, {"w3", {{"range", {0, 5}}, {"step", 1}}}, {"w4", {0, 1}}};
  json sweep = search_and_grid(json::array({"office:w=32,h=32,seed=3"}), box, json::array());
  sweep["strategies"].erase(1);
  sweep["strategies"][0]["search"] = {{"mode", "best"}, {"probes", probes}};
  return sweep;
}

TEST(WeightSearchRunner, AKilledBestSearchResumesWithItsJournalAsIncumbent) {
  // Mode best journals the behaviours it finishes; a rerun after the files are lost keeps them,
  // starts from the best of them and writes the same optimal behaviours.
  // No probes: they would find the optimum first, leaving one behaviour to journal.
  const json sweep = small_best_search(0);
  const std::string dir = run(sweep, "best_resume");
  EXPECT_FALSE(std::filesystem::exists(dir + "/search_probes.jsonl")) << "a log without probes";
  const std::string behaviours = testing::read_file(dir + "/behaviours.csv");
  const std::string best = testing::read_file(dir + "/search_best.csv");
  const json record = json::parse(testing::read_file(dir + "/searches.json"))["searches"][0];
  std::size_t journaled = 0;
  const std::vector<std::string> lines =
      journal_lines(testing::read_file(dir + "/search_journal.jsonl"), &journaled);
  ASSERT_GE(journaled, 2U);
  ASSERT_GE(lines.size() - journaled, 2U) << "no finished subtree journaled";
  // Kills soon after the first journaled behaviour, and halfway (finished subtrees kept: the
  // rerun skips them, with their pruned regions, and still finds every optimal behaviour).
  const std::size_t first = static_cast<std::size_t>(
      std::find_if(lines.begin(), lines.end(),
                   [](const std::string& l) { return l.find("\"cells\"") != std::string::npos; }) -
      lines.begin());
  for (const std::size_t cut : {first + 1, lines.size() / 2}) {
    std::string kept;
    for (std::size_t i = 0; i < cut; ++i) kept += lines[i];
    std::size_t kept_behaviours = 0;
    (void)journal_lines(kept, &kept_behaviours);
    testing::write_file(dir + "/search_journal.jsonl", kept);
    for (const char* f : {"behaviours.csv", "search_best.csv", "searches.json"})
      std::filesystem::remove(dir + "/" + f);
    RunnerOptions o = testing::quiet_runner(dir);
    (void)run_sweep(SweepPlan::from_json(sweep, "search.json"), o);
    EXPECT_EQ(testing::read_file(dir + "/behaviours.csv"), behaviours) << cut;
    EXPECT_EQ(testing::read_file(dir + "/search_best.csv"), best) << cut;
    const json resumed = json::parse(testing::read_file(dir + "/searches.json"))["searches"][0];
    EXPECT_EQ(resumed["resumed_behaviours"], kept_behaviours) << cut;
    const json& c = resumed["certificate"];
    EXPECT_EQ(c["optimum"], record["certificate"]["optimum"]) << cut;
    // The journal's leaves and behaviours still partition the box: the certificate is written.
    EXPECT_EQ(c["file"], "search_certificate_0.jsonl") << cut << c.dump();
    EXPECT_GT(c["smallest_pruned_bound"].get<double>(), c["optimum"].get<double>()) << cut;
    if (cut > first + 1) {
      EXPECT_LT(resumed["forks"], record["forks"]) << cut;
    }
  }
}

TEST(WeightSearchRunner, AResumedBestSearchTakesUpItsFinishedProbesInsteadOfRunningThemAgain) {
  // Each finished probe is logged (search_probes.jsonl); a rerun takes them up as its first
  // incumbent, runs only the others, and reports every probe as the first run did.
  const json sweep = small_best_search(5);
  const std::string dir = run(sweep, "best_probes_resume");
  const std::string behaviours = testing::read_file(dir + "/behaviours.csv");
  const std::string best = testing::read_file(dir + "/search_best.csv");
  const json record = json::parse(testing::read_file(dir + "/searches.json"))["searches"][0];
  ASSERT_EQ(record["probes"], 5);
  ASSERT_TRUE(record["best_probe"].is_number());
  const auto probe_lines = [&] {
    std::vector<std::string> lines;
    std::istringstream in(testing::read_file(dir + "/search_probes.jsonl"));
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
  };
  const std::vector<std::string> logged = probe_lines();
  ASSERT_EQ(logged.size(), 5U);
  for (const std::string& line : logged) {
    const json j = json::parse(line);
    EXPECT_EQ(j["at"].size(), 4U) << line;
    EXPECT_TRUE(j["objective"].is_number()) << line;
  }
  // Killed after its probes: the journal lost, the probes' log kept but for one line torn into
  // text that does not parse, and a line of another search.
  std::string log = "{\"key\": \"another search\", \"at\": [0, 0, 0, 0], \"objective\": 1}\n";
  for (std::size_t i = 0; i + 1 < logged.size(); ++i) log += logged[i] + "\n";
  log += logged.back().substr(0, logged.back().size() / 2) + "\n";
  testing::write_file(dir + "/search_probes.jsonl", log);
  testing::write_file(dir + "/search_journal.jsonl", "");
  for (const char* f : {"behaviours.csv", "search_best.csv", "searches.json"})
    std::filesystem::remove(dir + "/" + f);
  RunnerOptions o = testing::quiet_runner(dir);
  (void)run_sweep(SweepPlan::from_json(sweep, "search.json"), o);
  EXPECT_EQ(testing::read_file(dir + "/behaviours.csv"), behaviours);
  EXPECT_EQ(testing::read_file(dir + "/search_best.csv"), best);
  const json resumed = json::parse(testing::read_file(dir + "/searches.json"))["searches"][0];
  EXPECT_EQ(resumed["probes"], 5);
  EXPECT_EQ(resumed["best_probe"], record["best_probe"]);
  // Only the torn probe ran again: one line more, the same as the one torn.
  const std::vector<std::string> after = probe_lines();
  ASSERT_EQ(after.size(), 7U);
  EXPECT_EQ(after.back(), logged.back());
}

TEST(WeightSearchRunner, AMapClassIsSearchedJointlyByItsMean) {
  // Two generated maps of one class: each behaviour has a row per map, its objective is the mean
  // of the two maps' runs, and the ranking is the brute-force ranking of the class means.
  const json box = {{"w1", {0, 1, 2}}, {"w2", {0, 2}}, {"w3", {0, 1, 2}}, {"w4", {0, 2}}};
  const json maps = json::array({{{"generator", "office"}, {"w", 32}, {"h", 32}, {"seeds", {3, 4}}}});
  const std::string dir = run(search_and_grid(maps, box, json::array()), "class");
  const auto [runs, vectors, behaviours] = read_search_files(dir);
  ASSERT_EQ(runs.rows.size(), 72U);
  const std::map<Vector, std::string> owner = owners(vectors);
  std::map<Vector, double> mean;
  for (std::size_t r = 0; r < runs.rows.size(); ++r) mean[weights_of(runs, r)] += objective_of(runs, r) / 2.0;
  std::map<std::string, double> objective;
  std::map<std::string, int> instances;
  for (const auto& b : behaviours.rows) {
    objective[b[behaviours.col("behaviour_id")]] = std::stod(b[behaviours.col("objective")]);
    ++instances[b[behaviours.col("behaviour_id")]];
  }
  for (const auto& [id, n] : instances) EXPECT_EQ(n, 2) << "behaviour " << id;
  for (const auto& [w, m] : mean) EXPECT_DOUBLE_EQ(objective.at(owner.at(w)), m);
  const Table best = read_table(dir + "/search_best.csv");
  for (const auto& row : best.rows) {
    const double o = std::stod(row[best.col("objective")]);
    const auto better_count = std::count_if(
        mean.begin(), mean.end(), [&](const auto& e) { return objective.at(owner.at(e.first)) < o; });
    EXPECT_EQ(std::stol(row[best.col("rank")]), better_count + 1);
  }
  ASSERT_GE(best.rows.size(), 3U);
}

TEST(WeightSearchRunner, BestModeFindsTheBruteForceOptimumWithEveryTieAndPrunes) {
  // A box with ties at the optimum (w2 and w4 that change nothing there), the objective the
  // default (distance to the final coverage), energy, and the distance to a coverage target
  // (runs that never reach it have none and rank after).
  const json box = {{"w1", {{"range", {0, 3}}, {"step", 1}}},
                    {"w2", {0, 2}},
                    {"w3", {{"range", {0, 3}}, {"step", 1}}},
                    {"w4", {0, 1, 3}}};
  for (const std::string objective :
       {"distance_to_final_coverage_m", "energy", "distance_to_coverage_target_m"}) {
    json sweep = search_and_grid(json::array({"office:w=32,h=32,seed=3"}), box, json::array());
    sweep["strategies"][0]["search"] = {{"mode", "best"}};
    sweep["output"] = {{"objective", objective}};
    if (objective == "distance_to_coverage_target_m") sweep["sim"] = {{"stop_at_coverage", 0.8}};
    const std::string dir = run(sweep, "best_" + objective);
    const Table runs = read_table(dir + "/runs.csv");
    std::vector<double> values;
    for (const auto& row : runs.rows) {
      const std::string& cell = row[runs.col(objective)];
      values.push_back(cell.empty() ? std::numeric_limits<double>::infinity() : std::stod(cell));
    }
    const double optimum = *std::min_element(values.begin(), values.end());
    const Table best = read_table(dir + "/search_best.csv");
    ASSERT_GE(best.rows.size(), 1U);
    long vectors = 0;
    for (const auto& row : best.rows) {
      EXPECT_EQ(std::stod(row[best.col("objective")]), optimum) << objective;
      EXPECT_EQ(row[best.col("rank")], "1");
      vectors += std::stol(row[best.col("vectors")]);
    }
    EXPECT_EQ(vectors, std::count(values.begin(), values.end(), optimum)) << objective << ": every tie";
    const json search = json::parse(testing::read_file(dir + "/searches.json"))["searches"][0];
    const json& certificate = search["certificate"];
    EXPECT_GT(certificate["pruned_regions"].get<int>(), 0) << objective << ": the bound has no teeth";
    EXPECT_GT(certificate["smallest_pruned_bound"].get<double>(), optimum);
    EXPECT_LE(certificate["pruned_vectors"].get<long>() + vectors, 96);
  }
}

/// Distinct outcomes counted from `dir`'s behaviours.csv: a behaviour's rows (one per instance),
/// every column from end_reason on but the effort ones; returns (behaviours, outcomes).
std::pair<std::size_t, std::size_t> behaviours_and_outcomes(const std::string& dir) {
  CsvReader in(dir + "/behaviours.csv");
  const std::size_t id = in.require_column("behaviour_id");
  const std::size_t first_metric = in.require_column("end_reason");
  std::map<std::string, std::string> outcome_of;
  while (in.next()) {
    for (std::size_t c = first_metric; c < in.header().size(); ++c) {
      if (!is_effort_column(in.header()[c])) outcome_of[in.fields()[id]] += in.fields()[c] + ',';
    }
    outcome_of[in.fields()[id]] += ';';
  }
  std::set<std::string> outcomes;
  for (const auto& [behaviour, outcome] : outcome_of) outcomes.insert(outcome);
  return {outcome_of.size(), outcomes.size()};
}

TEST(WeightSearchRunner, SearchesJsonCountsDistinctOutcomesBesideBehaviours) {
  // Free space, r = 300 m: some behaviours (decision sequences) end in the same outcome.
  const json sweep = json::parse(R"({
    "schema_version": 1, "name": "outcomes",
    "maps": [{"generator": "free", "w": 41, "h": 41, "res": 10}],
    "strategies": [{"name": "energy_aware", "search": {"method": "exact", "mode": "all"},
      "params": {"w1": [0, 1, 2, 3], "w2": [0, 1, 2, 3], "w3": [0, 1, 2, 3], "w4": [0, 1, 2]}}],
    "robot": {"sensor": {"range_m": 30}, "energy": "distance", "battery": 300}})");
  const std::string dir = run(sweep, "outcomes");
  const json record = json::parse(testing::read_file(dir + "/searches.json"))["searches"][0];
  const auto [behaviours, outcomes] = behaviours_and_outcomes(dir);
  EXPECT_EQ(record["behaviours"].get<std::size_t>(), behaviours);
  EXPECT_EQ(record["distinct_outcomes"].get<std::size_t>(), outcomes);
  EXPECT_LT(outcomes, behaviours);  // 53 of 56 when written
  EXPECT_GT(outcomes, 1U);
}

TEST(WeightSearchRunner, AKilledSearchResumesFromItsJournalWithTheSameFiles) {
  // A whole search of a map class, then its journal cut to its first lines and a torn one (as
  // a kill leaves it) and its files deleted: the rerun keeps the journaled behaviours, skips the
  // journaled subtrees, searches only the rest and writes the same files. Without vectors.csv
  // the rerun keeps no journaled behaviour's region, only its ranks and heat-map cells; that
  // journal is given in the format of before 2026-12-04 (a part's points in hexadecimal words).
  for (const bool listed : {true, false}) {
    const std::string what = listed ? "with vectors.csv" : "without vectors.csv";
    const json box = {{"w1", {0, 1, 2}}, {"w2", {0, 2}}, {"w3", {0, 1, 2}}, {"w4", {0, 2}}};
    const json maps = json::array({{{"generator", "office"}, {"w", 32}, {"h", 32}, {"seeds", {3, 4}}}});
    json sweep = search_and_grid(maps, box, {{1, 0, 2, 0}});
    sweep["strategies"].erase(1);  // the search alone
    sweep["strategies"][0]["search"]["write_vectors"] = listed;
    const std::string dir = run(sweep, listed ? "resume" : "resume_unlisted");
    std::vector<std::string> files{"behaviours.csv", "search_summary.csv", "search_best.csv",
                                   "search_ranks.csv", "search_heatmaps.csv"};
    if (listed) files.emplace_back("vectors.csv");
    std::map<std::string, std::string> first;
    for (const auto& f : files) first[f] = testing::read_file(dir + "/" + f);
    std::size_t behaviours = 0;
    const std::vector<std::string> lines =
        journal_lines(testing::read_file(dir + "/search_journal.jsonl"), &behaviours);
    const json record = json::parse(testing::read_file(dir + "/searches.json"))["searches"][0];
    ASSERT_EQ(behaviours, record["behaviours"].get<std::size_t>());
    ASSERT_GE(behaviours, 6U);
    ASSERT_GE(lines.size() - behaviours, 3U) << "no finished subtree journaled";
    std::string cut;
    std::size_t hex_parts = 0;
    for (std::size_t i = 0; i < lines.size() / 2; ++i) {
      cut += listed ? lines[i] : with_hex_parts(lines[i]);
      if (!listed && lines[i].find("\"parts\":[[") != std::string::npos) ++hex_parts;
    }
    ASSERT_EQ(hex_parts > 0, !listed) << "no part in the kept lines to write in hexadecimal";
    std::size_t kept = 0;
    (void)journal_lines(cut, &kept);
    ASSERT_LT(kept, lines.size() / 2) << "the kept lines hold a finished subtree";
    const std::string& torn = lines[lines.size() / 2];
    cut += torn.substr(0, torn.size() / 2);
    testing::write_file(dir + "/search_journal.jsonl", cut);
    for (const auto& f : files) std::filesystem::remove(dir + "/" + f);
    std::filesystem::remove(dir + "/searches.json");

    RunnerOptions o = testing::quiet_runner(dir);
    const RunnerReport again = run_sweep(SweepPlan::from_json(sweep, "search.json"), o);
    EXPECT_EQ(again.searches.behaviours, behaviours) << what;
    const json resumed = json::parse(testing::read_file(dir + "/searches.json"))["searches"][0];
    EXPECT_EQ(resumed["resumed_behaviours"].get<std::size_t>(), kept) << what;
    EXPECT_LT(resumed["forks"].get<std::size_t>(), record["forks"].get<std::size_t>()) << what;
    for (const auto& f : files) EXPECT_EQ(testing::read_file(dir + "/" + f), first[f]) << what << ": " << f;
    // The journal holds every behaviour again, each once.
    std::size_t rejournaled = 0;
    const std::vector<std::string> relines =
        journal_lines(testing::read_file(dir + "/search_journal.jsonl"), &rejournaled);
    EXPECT_EQ(rejournaled, behaviours) << what;
    std::set<std::string> distinct(relines.begin(), relines.end());
    EXPECT_EQ(distinct.size(), relines.size()) << what << ": a line journaled twice";
  }
}

/// `text` with every occurrence of `from` replaced by `to`.
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

TEST(WeightSearchRunner, AJournalOfTheRetiredFormatIsSearchedAgainAndNeverMerged) {
  // A class's lines an older build wrote (journal format 3) name subtrees of another region
  // tree: a resumed search says so and searches again, to the same files; a merge refuses such a
  // shard. A single map's tree is the same in both, and its search keeps format 3.
  const json box = {{"w1", {0, 1, 2}}, {"w2", {0, 2}}, {"w3", {0, 1, 2}}, {"w4", {0, 2}}};
  const json maps = json::array({{{"generator", "office"}, {"w", 32}, {"h", 32}, {"seeds", {3, 4}}}});
  json sweep = search_and_grid(maps, box, json::array());
  sweep["strategies"].erase(1);  // the search alone
  sweep["strategies"][0]["search"] = {{"mode", "best"}};
  const SweepPlan plan = SweepPlan::from_json(sweep, "search.json");
  const std::string current = weight_search_journal_key(plan, 0, SearchJournal::kFormat);
  const std::string retired = weight_search_journal_key(plan, 0, SearchJournal::kPreviousFormat);
  ASSERT_NE(current, retired);
  {
    json one_map = sweep;
    one_map["maps"][0]["seeds"] = {3};
    const SweepPlan single = SweepPlan::from_json(one_map, "search.json");
    const std::string journal =
        testing::read_file(run(one_map, "previous_format_one_map") + "/search_journal.jsonl");
    const std::string key = weight_search_journal_key(single, 0, SearchJournal::kPreviousFormat);
    EXPECT_NE(journal.find("\"key\":\"" + key + "\""), std::string::npos)
        << "a single map's search keeps format 3";
    EXPECT_EQ(journal.find(weight_search_journal_key(single, 0, SearchJournal::kFormat)), std::string::npos);
    // Its shards merge with the sum of their steps; a shard's record without them (an older
    // build's) leaves the merged `steps` null.
    const std::string shards = testing::fresh_dir("search", "previous_format_one_map_shards");
    std::uint64_t steps = 0;
    for (std::uint64_t i = 0; i < 2; ++i) {
      RunnerOptions o = testing::quiet_runner(shards);
      o.shard_index = i;
      o.shard_count = 2;
      (void)run_sweep(single, o);
      const std::string path = shards + "/shard-" + std::to_string(i) + "-of-2/searches.json";
      steps += json::parse(testing::read_file(path))["searches"][0]["steps"].get<std::uint64_t>();
    }
    ASSERT_GT(steps, 0U);
    (void)merge_shards(shards);
    EXPECT_EQ(json::parse(testing::read_file(shards + "/searches.json"))["searches"][0]["steps"],
              json(steps));
    const std::string first = shards + "/shard-0-of-2/searches.json";
    json record = json::parse(testing::read_file(first));
    record["searches"][0].erase("steps");
    testing::write_file(first, record.dump(2));
    (void)merge_shards(shards);
    EXPECT_TRUE(json::parse(testing::read_file(shards + "/searches.json"))["searches"][0]["steps"].is_null());
  }
  const auto retire = [&](const std::string& journal) {
    const std::string text = testing::read_file(journal);
    ASSERT_NE(text.find("\"key\":\"" + current + "\""), std::string::npos) << journal;
    testing::write_file(journal, replaced(text, current, retired));
  };

  const std::string dir = run(sweep, "retired_format");
  const std::vector<std::string> files{"behaviours.csv", "search_best.csv", "search_summary.csv"};
  std::map<std::string, std::string> first;
  for (const auto& f : files) first[f] = testing::read_file(dir + "/" + f);
  retire(dir + "/search_journal.jsonl");
  for (const auto& f : files) std::filesystem::remove(dir + "/" + f);
  std::filesystem::remove(dir + "/searches.json");
  ::testing::internal::CaptureStderr();
  (void)run_sweep(plan, testing::quiet_runner(dir));
  const std::string said = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(said.find("journal format 'journal 3' of an older build"), std::string::npos) << said;
  const json record = json::parse(testing::read_file(dir + "/searches.json"))["searches"][0];
  EXPECT_EQ(record["resumed_behaviours"].get<std::size_t>(), 0U);
  for (const auto& f : files) EXPECT_EQ(testing::read_file(dir + "/" + f), first[f]) << f;

  const std::string sharded = testing::fresh_dir("search", "retired_format_shards");
  for (std::uint64_t i = 0; i < 2; ++i) {
    RunnerOptions o = testing::quiet_runner(sharded);
    o.shard_index = i;
    o.shard_count = 2;
    (void)run_sweep(plan, o);
  }
  const std::string journal = sharded + "/shard-1-of-2/search_journal.jsonl";
  retire(journal);
  try {
    (void)merge_shards(sharded);
    ADD_FAILURE() << "merged a shard of the retired journal format";
  } catch (const ConfigError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(journal), std::string::npos) << what;
    EXPECT_NE(what.find("'journal 3'"), std::string::npos) << what;
  }
  EXPECT_FALSE(std::filesystem::exists(sharded + "/behaviours.csv"));
}

/// A search of the box [0, 3]^4 on an office map, without the grid entry.
json office_search_of_256() {
  const json box = {{"w1", {{"range", {0, 3}}, {"step", 1}}},
                    {"w2", {{"range", {0, 3}}, {"step", 1}}},
                    {"w3", {{"range", {0, 3}}, {"step", 1}}},
                    {"w4", {{"range", {0, 3}}, {"step", 1}}}};
  json sweep = search_and_grid(json::array({"office:w=32,h=32,seed=3"}), box, json::array());
  sweep["strategies"].erase(1);
  return sweep;
}

/// Runs `sweep`'s search into `dir` and interrupts it (SIGINT) once its journal holds `lines`
/// lines; the report of that first, stopped run.
RunnerReport run_until_journal_holds(const json& sweep, const std::string& dir, std::size_t lines) {
  const std::string journal = dir + "/search_journal.jsonl";
  testing::InterruptWhen interrupter([&] {
    return std::filesystem::exists(journal) && journal_lines(testing::read_file(journal)).size() >= lines;
  });
  RunnerOptions o = testing::quiet_runner(dir);
  const RunnerReport first = run_sweep(SweepPlan::from_json(sweep, "search.json"), o);
  interrupter.join();
  return first;
}

TEST(WeightSearchRunner, InterruptStopsTheSearchAndTheRerunResumesIt) {
  // SIGINT during a search (after the runs) stops it: the manifest says "interrupted", no search
  // file but the journal is written, the journal keeps what finished, and the same command
  // then resumes and writes the files of an uninterrupted search.
  json sweep = office_search_of_256();
  const std::string ref = run(sweep, "sigint_ref");
  const std::string dir = testing::fresh_dir("search", "sigint");
  const std::string journal = dir + "/search_journal.jsonl";
  const RunnerReport first = run_until_journal_holds(sweep, dir, 4);
  RunnerOptions o = testing::quiet_runner(dir);
  ASSERT_TRUE(first.interrupted) << "the search finished before the interrupt";
  EXPECT_TRUE(first.searches.interrupted);
  EXPECT_EQ(json::parse(testing::read_file(dir + "/manifest.json"))["status"], "interrupted");
  for (const char* f : {"searches.json", "behaviours.csv", "search_best.csv", "vectors.csv", "summary.csv"}) {
    EXPECT_FALSE(std::filesystem::exists(dir + "/" + f)) << f;
  }
  const std::string kept = testing::read_file(journal);
  ASSERT_FALSE(kept.empty());
  EXPECT_EQ(kept.back(), '\n') << "a journal line was left torn";

  const RunnerReport second = run_sweep(SweepPlan::from_json(sweep, "search.json"), o);
  EXPECT_FALSE(second.interrupted);
  EXPECT_EQ(json::parse(testing::read_file(dir + "/manifest.json"))["status"], "complete");
  const json record = json::parse(testing::read_file(dir + "/searches.json"))["searches"][0];
  EXPECT_GT(record["resumed_behaviours"].get<std::size_t>(), 0U);
  for (const char* f :
       {"behaviours.csv", "search_summary.csv", "search_best.csv", "search_heatmaps.csv", "vectors.csv"}) {
    EXPECT_EQ(testing::read_file(dir + "/" + f), testing::read_file(ref + "/" + f)) << f;
  }
  std::filesystem::remove_all(ref);
  std::filesystem::remove_all(dir);
}

TEST(WeightSearchRunner, AStoppedSearchResumesAfterItsSweepsDescriptionAloneChanged) {
  // The description is prose: a new one is the same sweep, so the stopped search resumes to
  // the files of an uninterrupted one. Any other change (here the seed) is still refused.
  json sweep = office_search_of_256();
  const std::string ref = run(sweep, "describe_ref");
  const std::string dir = testing::fresh_dir("search", "describe");
  ASSERT_TRUE(run_until_journal_holds(sweep, dir, 4).interrupted)
      << "the search finished before the interrupt";
  RunnerOptions o = testing::quiet_runner(dir);

  json reseeded = sweep;
  reseeded["seed"] = sweep.value("seed", 0) + 1;
  EXPECT_THROW((void)run_sweep(SweepPlan::from_json(reseeded, "search.json"), o), ConfigError);
  sweep["description"] = "the same search, described anew";
  const RunnerReport second = run_sweep(SweepPlan::from_json(sweep, "search.json"), o);
  EXPECT_FALSE(second.interrupted);
  const json record = json::parse(testing::read_file(dir + "/searches.json"))["searches"][0];
  EXPECT_GT(record["resumed_behaviours"].get<std::size_t>(), 0U);
  for (const char* f : {"behaviours.csv", "search_summary.csv", "search_best.csv", "vectors.csv"}) {
    EXPECT_EQ(testing::read_file(dir + "/" + f), testing::read_file(ref + "/" + f)) << f;
  }
  std::filesystem::remove_all(ref);
  std::filesystem::remove_all(dir);
}

TEST(WeightSearchRunner, AStoppedBestSearchSaysWhereItStandsAndResumesItsCurve) {
  // Mode best keeps its anytime state: a stop writes the best vector so far and a bound of the
  // optimum (search_status_0.json, a row of search_anytime.csv); the rerun finishes with bound
  // = best = the optimum, its curve going on in time.
  json sweep = office_search_of_256();
  for (const char* order : {"depth", "bound"}) {
    sweep["strategies"][0]["search"] = {{"mode", "best"}, {"order", order}};
    const std::string dir = testing::fresh_dir("search", std::string("anytime_") + order);
    const RunnerReport first = run_until_journal_holds(sweep, dir, 6);
    RunnerOptions o = testing::quiet_runner(dir);
    ASSERT_TRUE(first.searches.interrupted) << order << ": the search finished before the interrupt";
    ASSERT_EQ(first.searches.standings.size(), 1U);
    EXPECT_NE(first.searches.standings[0].find("search_status_0.json"), std::string::npos);
    const json stopped = json::parse(testing::read_file(dir + "/search_status_0.json"));
    EXPECT_EQ(stopped["status"], "stopped") << order;
    EXPECT_GT(stopped["open_branches"].get<std::size_t>(), 0U) << order;
    EXPECT_LT(stopped["resolved_vectors"].get<std::uint64_t>(), 256U) << order;

    const RunnerReport second = run_sweep(SweepPlan::from_json(sweep, "search.json"), o);
    ASSERT_FALSE(second.interrupted);
    const json done = json::parse(testing::read_file(dir + "/search_status_0.json"));
    const double optimum =
        json::parse(testing::read_file(dir + "/searches.json"))["searches"][0]["certificate"]["optimum"];
    EXPECT_EQ(done["status"], "finished") << order;
    EXPECT_EQ(done["best"]["objective"].get<double>(), optimum) << order;
    EXPECT_EQ(done["bound"].get<double>(), optimum) << order;
    EXPECT_EQ(done["gap"].get<double>(), 0.0) << order;
    EXPECT_EQ(done["resolved_vectors"], 256U) << order;
    ASSERT_FALSE(stopped["bound"].is_null()) << order << ": a stop knows the bounds of its open branches";
    EXPECT_LE(stopped["bound"].get<double>(), optimum) << order;
    if (!stopped["best"].is_null()) {
      EXPECT_GE(stopped["best"]["objective"].get<double>(), optimum) << order;
    }
    const Table curve = read_table(dir + "/search_anytime.csv");
    ASSERT_GE(curve.rows.size(), 2U);
    std::vector<std::string> statuses;
    double last = -1.0;
    for (const auto& row : curve.rows) {
      statuses.push_back(row[curve.col("status")]);
      const double elapsed = std::stod(row[curve.col("elapsed_s")]);
      EXPECT_GE(elapsed, last) << order << ": the resumed curve's time went back";
      last = elapsed;
    }
    EXPECT_EQ(std::count(statuses.begin(), statuses.end(), "stopped"), 1) << order;
    EXPECT_EQ(statuses.back(), "finished") << order;
    // --fresh starts the curve and the status over.
    o.fresh = true;
    (void)run_sweep(SweepPlan::from_json(sweep, "search.json"), o);
    const Table fresh = read_table(dir + "/search_anytime.csv");
    for (const auto& row : fresh.rows) EXPECT_NE(row[fresh.col("status")], "stopped") << order;
    EXPECT_EQ(fresh.rows.back()[fresh.col("status")], "finished") << order;
    std::filesystem::remove_all(dir);
  }
}

TEST(WeightSearchRunner, AResumeRepairsACutCurveDistrustsAnImpossibleTimeAndRefusesAForeignCurve) {
  json sweep = office_search_of_256();
  sweep["strategies"][0]["search"] = {{"mode", "best"}, {"order", "bound"}};
  const std::string dir = testing::fresh_dir("search", "anytime_damaged");
  ASSERT_TRUE(run_until_journal_holds(sweep, dir, 6).searches.interrupted);
  const std::string curve = dir + "/search_anytime.csv";
  const std::string status = dir + "/search_status_0.json";
  // The last row cut short, and the status's time set to one no search takes.
  std::string text = testing::read_file(curve);
  testing::write_file(curve, text.substr(0, text.size() - 5));
  json stopped = json::parse(testing::read_file(status));
  stopped["elapsed_s"] = -1000.0;
  testing::write_file(status, stopped.dump());
  // A copy whose curve is another file's.
  const std::string foreign = testing::fresh_dir("search", "anytime_foreign");
  std::filesystem::remove_all(foreign);
  std::filesystem::copy(dir, foreign, std::filesystem::copy_options::recursive);
  testing::write_file(foreign + "/search_anytime.csv", "a,b,c\n1,2,3\n");

  RunnerOptions o = testing::quiet_runner(dir);
  ASSERT_FALSE(run_sweep(SweepPlan::from_json(sweep, "search.json"), o).interrupted);
  const Table rows = read_table(curve);
  ASSERT_GE(rows.rows.size(), 2U);
  for (const auto& row : rows.rows) {
    ASSERT_EQ(row.size(), rows.header.size());
    EXPECT_GE(std::stod(row[rows.col("elapsed_s")]), 0.0);
  }
  EXPECT_EQ(rows.rows.back()[rows.col("status")], "finished");

  RunnerOptions f = testing::quiet_runner(foreign);
  try {
    (void)run_sweep(SweepPlan::from_json(sweep, "search.json"), f);
    ADD_FAILURE() << "a foreign curve was appended to";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("search_anytime.csv: not a search's curve"), std::string::npos)
        << e.what();
  }
  EXPECT_EQ(testing::read_file(foreign + "/search_anytime.csv"), "a,b,c\n1,2,3\n");
  std::filesystem::remove_all(dir);
  std::filesystem::remove_all(foreign);
}

TEST(WeightSearchRunner, AResumedBestSearchCountsWhatItsJournalResolvedFromItsStart) {
  // The curve of a search has a row where the search starts. A resumed search's says what the
  // stopped one had resolved (its journal), and no later row says less, though the resumed
  // search comes to the journal's finished subtrees again only as it re-walks its tree.
  json sweep = office_search_of_256();
  sweep["strategies"][0]["search"] = {{"mode", "best"}, {"order", "bound"}};
  const std::string dir = testing::fresh_dir("search", "resolved_resume");
  ASSERT_TRUE(run_until_journal_holds(sweep, dir, 6).searches.interrupted) << "finished before the stop";
  const auto resolved_then =
      json::parse(testing::read_file(dir + "/search_status_0.json"))["resolved_vectors"].get<std::uint64_t>();
  ASSERT_GT(resolved_then, 0U);
  RunnerOptions o = testing::quiet_runner(dir);
  ASSERT_FALSE(run_sweep(SweepPlan::from_json(sweep, "search.json"), o).interrupted);
  const Table curve = read_table(dir + "/search_anytime.csv");
  const auto resolved = [&](std::size_t row) {
    return std::stoull(curve.rows[row][curve.col("resolved_vectors")]);
  };
  const auto stop = static_cast<std::size_t>(
      std::find_if(curve.rows.begin(), curve.rows.end(),
                   [&](const auto& row) { return row[curve.col("status")] == "stopped"; }) -
      curve.rows.begin());
  ASSERT_GE(stop, 1U) << "no row where the first search started";
  EXPECT_EQ(resolved(0), 0U) << "the first search started with nothing resolved";
  ASSERT_LT(stop + 2, curve.rows.size() + 1) << "no row where the resumed search started";
  EXPECT_EQ(resolved(stop), resolved_then);
  EXPECT_EQ(resolved(stop + 1), resolved_then) << "the resumed search starts with what was resolved";
  for (std::size_t row = stop + 1; row < curve.rows.size(); ++row)
    EXPECT_GE(resolved(row), resolved_then) << row;
  EXPECT_EQ(resolved(curve.rows.size() - 1), 256U);
  std::filesystem::remove_all(dir);
}

TEST(WeightSearchRunner, TheShardsStatusesJoinIntoTheWholeSearchs) {
  // The best of the shards' best vectors, the weakest of their bounds, a shard without a status
  // (never started) leaving the bound unknown.
  const json finished = {{"status", "finished"},
                         {"resolved_vectors", 100},
                         {"bound", 10.0},
                         {"best", {{"objective", 10.0}, {"weights", {{"w1", 1.0}}}}}};
  const json stopped = {{"status", "stopped"},
                        {"resolved_vectors", 40},
                        {"bound", 7.5},
                        {"best", {{"objective", 12.0}, {"weights", {{"w1", 9.0}}}}}};
  const json joint = join_search_status(std::vector<json>{finished, stopped}, 200, 1.0);
  EXPECT_EQ(joint["status"], "stopped");
  EXPECT_EQ(joint["resolved_vectors"], 140U);
  EXPECT_EQ(joint["best"]["objective"], 10.0);
  EXPECT_EQ(joint["best"]["weights"]["w1"], 1.0);
  EXPECT_EQ(joint["bound"], 7.5);
  EXPECT_EQ(joint["gap"], 2.5);
  EXPECT_EQ(joint["relative_gap"], 0.25);
  EXPECT_NE(describe_search_status(joint, "m").find("the optimum is at least 7.5 m (gap 25%)"),
            std::string::npos)
      << describe_search_status(joint);
  const json unknown = join_search_status(std::vector<json>{finished, nullptr}, 200, 1.0);
  EXPECT_TRUE(unknown["bound"].is_null());
  EXPECT_TRUE(unknown["gap"].is_null());
  EXPECT_EQ(join_search_status(std::vector<json>{finished, finished}, 200, 1.0)["status"], "finished");
  // A finished shard of no vectors (past the box's blocks) has no bound; it leaves the optimum's.
  const json empty = {{"status", "finished"}, {"resolved_vectors", 0}, {"bound", nullptr}, {"best", nullptr}};
  const json complete = join_search_status(std::vector<json>{finished, empty}, 100, 1.0);
  EXPECT_EQ(complete["status"], "finished");
  EXPECT_EQ(complete["bound"], 10.0);
  EXPECT_EQ(complete["gap"], 0.0);
  // A maximised objective: the best is the largest, the bound an upper one.
  json up = stopped;
  up["bound"] = 15.0;
  const json max = join_search_status(std::vector<json>{finished, up}, 200, -1.0);
  EXPECT_EQ(max["best"]["objective"], 12.0);
  EXPECT_EQ(max["bound"], 15.0);
  EXPECT_EQ(max["gap"], 3.0);
}

/// A search of mode best over 256 vectors (4 blocks) of an office map run as `shards` shards into a fresh
/// directory named `name`; returns the directory.
std::string best_search_in_shards(const std::string& name, std::uint64_t shards) {
  const json box = {
      {"w1", {{"range", {0, 15}}, {"step", 1}}}, {"w2", {0, 2}}, {"w3", {0, 3}}, {"w4", {0, 1}}};
  json sweep = search_and_grid(json::array({"office:w=32,h=32,seed=3"}), box, json::array());
  sweep["strategies"].erase(1);
  sweep["strategies"][0]["search"] = {{"mode", "best"}};
  const std::string dir = testing::fresh_dir("search", name);
  for (std::uint64_t shard = 0; shard < shards; ++shard) {
    RunnerOptions o = testing::quiet_runner(dir);
    o.shard_index = shard;
    o.shard_count = shards;
    (void)run_sweep(SweepPlan::from_json(sweep, "search.json"), o);
  }
  return dir;
}

/// The message of the ConfigError merge_shards(`dir`) throws ("(merged)" when it merges).
std::string merge_refusal(const std::string& dir) {
  try {
    (void)merge_shards(dir);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "(merged)";
}

TEST(WeightSearchRunner, AMergeOfUnfinishedShardsWritesTheirJointStatus) {
  // Two shards ran; shard 1's search is then made unfinished (its searches.json removed): the
  // merge refuses (as before) but says what the shards found so far and writes their joint
  // status, its bound unknown while shard 1 has no status, else the weaker of the two.
  const std::string dir = best_search_in_shards("anytime_shards", 2);
  const std::string status1 = dir + "/shard-1-of-2/search_status_0.json";
  const json shard0 = json::parse(testing::read_file(dir + "/shard-0-of-2/search_status_0.json"));
  json shard1 = json::parse(testing::read_file(status1));
  EXPECT_EQ(shard0["status"], "finished");
  EXPECT_EQ(shard0["vectors"], 64U);
  EXPECT_EQ(shard0["gap"], 0.0);
  std::filesystem::remove(dir + "/shard-1-of-2/searches.json");
  std::filesystem::remove(status1);
  const auto refused = [&] { return merge_refusal(dir); };
  const std::string message = refused();
  EXPECT_NE(message.find("search 0 of the shards so far: best so far"), std::string::npos) << message;
  EXPECT_NE(message.find("no bound on the optimum yet"), std::string::npos) << message;
  json joint = json::parse(testing::read_file(dir + "/search_status_0.json"));
  EXPECT_EQ(joint["best"], shard0["best"]);
  EXPECT_TRUE(joint["bound"].is_null());
  EXPECT_EQ(joint["resolved_vectors"], 64U);
  // Shard 1 stopped with a bound below shard 0's optimum: the joint bound is it.
  shard1["status"] = "stopped";
  shard1["bound"] = shard0["bound"].get<double>() - 100.0;
  shard1["resolved_vectors"] = 10;
  testing::write_file(status1, shard1.dump());
  (void)refused();
  joint = json::parse(testing::read_file(dir + "/search_status_0.json"));
  EXPECT_EQ(joint["status"], "stopped");
  EXPECT_EQ(joint["bound"], shard1["bound"]);
  EXPECT_EQ(joint["resolved_vectors"], 74U);
  // Shard 1's directory missing altogether (a Slurm task not started yet): the merge lists it
  // and writes nothing else, but still the joint status, with no bound.
  std::filesystem::remove_all(dir + "/shard-1-of-2");
  std::filesystem::remove(dir + "/search_status_0.json");
  const MergeReport missing = merge_shards(dir);
  EXPECT_FALSE(missing.written);
  ASSERT_EQ(missing.problems.size(), 1U);
  EXPECT_NE(missing.problems[0].find("missing shard directory"), std::string::npos) << missing.problems[0];
  EXPECT_NE(missing.search_status.find("no bound on the optimum yet"), std::string::npos)
      << missing.search_status;
  joint = json::parse(testing::read_file(dir + "/search_status_0.json"));
  EXPECT_TRUE(joint["bound"].is_null());
  EXPECT_EQ(joint["resolved_vectors"], 64U);
  std::filesystem::remove_all(dir);
}

TEST(WeightSearchRunner, AShardPastTheBoxsBlocksLeavesTheCompleteMergesBoundTheOptimum) {
  // The box's 4 blocks in 5 shards: shard 0 holds none, finished with no bound; the merged
  // status is finished with the optimum as its bound.
  const std::string dir = best_search_in_shards("empty_shard", 5);
  const json empty = json::parse(testing::read_file(dir + "/shard-0-of-5/search_status_0.json"));
  EXPECT_EQ(empty["vectors"], 0U);
  EXPECT_TRUE(empty["bound"].is_null());
  ASSERT_TRUE(merge_shards(dir).written);
  const json joint = json::parse(testing::read_file(dir + "/search_status_0.json"));
  const json record = json::parse(testing::read_file(dir + "/searches.json"))["searches"][0];
  EXPECT_EQ(joint["status"], "finished");
  EXPECT_EQ(joint["bound"], record["certificate"]["optimum"]);
  EXPECT_EQ(joint["gap"], 0.0);
  // A merge again with a shard moved away fails, and leaves the complete merge's status as it was.
  std::filesystem::rename(dir + "/shard-4-of-5", dir + "/moved");
  const MergeReport again = merge_shards(dir);
  EXPECT_FALSE(again.written);
  EXPECT_TRUE(again.search_status.empty());
  EXPECT_EQ(json::parse(testing::read_file(dir + "/search_status_0.json")), joint);
  std::filesystem::remove_all(dir);
}

TEST(WeightSearchRunner, AMergeRefusesAShardWhoseJournalLostItsOptimumOrThatIsAnotherShard) {
  // Each would otherwise merge, exit 0, into a wrong optimum or wrong counts.
  const std::string source = best_search_in_shards("journal_lost", 2);
  std::string dir;  // the last variant's
  const auto variant = [&](const std::string& name, const std::function<void(const std::string&)>& change) {
    dir = testing::fresh_dir("search", name);
    std::filesystem::remove_all(dir);
    std::filesystem::copy(source, dir, std::filesystem::copy_options::recursive);
    change(dir);
    return merge_refusal(dir);
  };
  // The journal emptied after the shard finished (as by a user freeing space):
  std::string message = variant("journal_emptied", [](const std::string& emptied) {
    testing::write_file(emptied + "/shard-0-of-2/search_journal.jsonl", "");
  });
  EXPECT_NE(
      message.find("shard-0-of-2/search_journal.jsonl: holds no behaviour of search 0 with the optimum"),
      std::string::npos)
      << message;
  EXPECT_NE(message.find("--shard 0/2 --fresh"), std::string::npos) << message;
  // One pruned region's line lost: the optimum stands, so the merge writes its files, but the
  // regions no longer cover the box: no certificate, and searches.json says why.
  message = variant("journal_cut", [](const std::string& cut) {
    const std::string path = cut + "/shard-1-of-2/search_journal.jsonl";
    std::istringstream in(testing::read_file(path));
    std::string kept;
    bool dropped = false;
    for (std::string line; std::getline(in, line);) {
      if (!dropped && line.find("\"leaf\"") != std::string::npos) {
        dropped = true;
        continue;
      }
      kept += line + "\n";
    }
    ASSERT_TRUE(dropped) << "no pruned region in the shard's journal";
    testing::write_file(path, kept);
  });
  EXPECT_EQ(message, "(merged)");
  const json note = json::parse(testing::read_file(dir + "/searches.json"))["searches"][0]["certificate"];
  EXPECT_TRUE(note["file"].is_null()) << note.dump();
  EXPECT_NE(note.value("why_not", std::string()).find("lines are missing"), std::string::npos) << note.dump();
  // Shard 0 copied in place of shard 1:
  message = variant("journal_copied", [](const std::string& copied) {
    std::filesystem::remove_all(copied + "/shard-1-of-2");
    std::filesystem::copy(copied + "/shard-0-of-2", copied + "/shard-1-of-2",
                          std::filesystem::copy_options::recursive);
  });
  EXPECT_NE(message.find("shard-1-of-2/searches.json: search 0 is of shard {\"count\":2,\"index\":0}, its "
                         "directory's name says {\"count\":2,\"index\":1}"),
            std::string::npos)
      << message;
  EXPECT_EQ(variant("journal_whole", [](const std::string& /*dir*/) {}), "(merged)");
  std::filesystem::remove_all(source);
}

/// The message of the ConfigError for `sweep`.
std::string refusal(const json& sweep) {
  try {
    (void)SweepPlan::from_json(sweep, "s.json");
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(WeightSearchRunner, ASearchEntrysHeuristicsBesideItsParamsReachItsRuns) {
  // Given beside "params" as for any entry (they are a simulation setting, not a weight).
  json sweep = small_best_search(0);
  sweep["strategies"][0]["heuristics"] = json::array({"rr"});
  const std::string dir = testing::fresh_dir("search", "heuristics");
  (void)run_sweep(SweepPlan::from_json(sweep, "search.json"), testing::quiet_runner(dir));
  const json record = json::parse(testing::read_file(dir + "/searches.json"))["searches"][0];
  EXPECT_EQ(record["instances"][0]["strategy_params"]["heuristics"], json::array({"rr"})) << record.dump();
  EXPECT_TRUE(record["certificate"]["optimum"].is_number());
  std::filesystem::remove_all(dir);
}

TEST(WeightSearchRunner, ACompetitiveSweepWithASearchWarnsThatSearchesHaveNoRatios) {
  json sweep = small_best_search(0);
  const auto warned = [](const json& s) {
    for (const std::string& w : sweep_warnings(SweepPlan::from_json(s, "search.json")))
      if (w.starts_with("competitive: ")) return true;
    return false;
  };
  EXPECT_FALSE(warned(sweep));
  sweep["competitive"] = true;
  EXPECT_TRUE(warned(sweep));
}

TEST(WeightSearchRunner, BadSearchEntriesAreRefusedWithTheirPath) {
  const json box = {{"w1", {0, 1}}, {"w2", 0}, {"w3", 0}, {"w4", 0}};
  const json base = search_and_grid(json::array({"office:w=32,h=32,seed=3"}), box, json::array());
  const auto with = [&](const std::string& pointer, const json& value) {
    json s = base;
    s[json::json_pointer(pointer)] = value;
    return refusal(s);
  };
  EXPECT_NE(with("/strategies/0/search/mode", "fast")
                .find("/strategies/0/search/mode: value \"fast\"; allowed: "
                      "\"all\", \"best\""),
            std::string::npos);
  json best = base;
  best["/strategies/0/search/mode"_json_pointer] = "best";
  best["/strategies/0/search/write_vectors"_json_pointer] = true;
  best["/strategies/0/search/rank"_json_pointer] = json::array({{1, 0, 0, 0}});
  const std::string best_refusal = refusal(best);
  EXPECT_NE(best_refusal.find("/strategies/0/search/write_vectors: mode \"best\""), std::string::npos)
      << best_refusal;
  EXPECT_NE(best_refusal.find("/strategies/0/search/rank: mode \"best\""), std::string::npos) << best_refusal;
  EXPECT_NE(with("/strategies/0/search/method", "random").find("/strategies/0/search/method"),
            std::string::npos);
  EXPECT_NE(with("/strategies/0/search/speed", 1).find("/strategies/0/search"), std::string::npos);
  EXPECT_NE(with("/strategies/0/params/w1", json::array({0, "x"})).find("/strategies/0/params/w1"),
            std::string::npos);
  EXPECT_NE(with("/strategies/0/params/w2", json::array({0, 251})).find("/strategies/0/params/w2"),
            std::string::npos);
  EXPECT_NE(
      with("/strategies/0/params/distance", json::array({"path", "octile"})).find("sweeps only its weights"),
      std::string::npos);
  EXPECT_NE(
      with("/strategies/0/search/rank", json::array({{2, 0, 0, 0}})).find("/strategies/0/search/rank/0"),
      std::string::npos);
  EXPECT_NE(with("/strategies/0/search/rank", json::array({{1, 0, 0, 0}, {0, 0, 0, 0}, {1, 0, 0, 0}}))
                .find("/strategies/0/search/rank/2: value [1,0,0,0] repeats /strategies/0/search/rank/0"),
            std::string::npos);
  EXPECT_NE(best_refusal.find("/strategies/0/search/rank: mode \"best\""), std::string::npos) << best_refusal;
  // A box of more blocks than one process searches: refused before anything is searched, with the
  // shards that would take it (501 values per weight, 63^4 blocks); one of more blocks than a
  // grid holds is refused when the sweep is read (2,001 values per weight, 251^4 blocks).
  const json halves = {{"range", {0, 250}}, {"step", 0.5}};
  json huge = base;
  for (const char* w : {"w1", "w2", "w3", "w4"}) huge["strategies"][0]["params"][w] = halves;
  huge["strategies"].erase(1);
  huge["strategies"][0]["search"] = {{"mode", "best"}};
  try {
    (void)run_sweep(SweepPlan::from_json(huge, "search.json"),
                    testing::quiet_runner(testing::fresh_dir("search", "huge")));
    ADD_FAILURE() << "a box of 15,752,961 blocks was searched";
  } catch (const ConfigError& e) {
    EXPECT_NE(
        std::string(e.what()).find("/strategies/0/params: the part of the search box this process "
                                   "searches holds 15,752,961 blocks of 8 values per weight; allowed: at "
                                   "most 4,194,304 per process"),
        std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("search it in at least 4 shards"), std::string::npos) << e.what();
  }
  EXPECT_EQ(WeightGrid::shard_blocks(15'752'961, 3, 4), 3'938'241U);  // each of 4 shards within the limit
  const json eighths = {{"range", {0, 250}}, {"step", 0.125}};
  for (const char* w : {"w1", "w2", "w3", "w4"}) huge["strategies"][0]["params"][w] = eighths;
  EXPECT_NE(refusal(huge).find("/strategies/0/params: a search box of 3,969,126,001 blocks of 8 values per "
                               "weight; allowed: at most 2,147,483,648"),
            std::string::npos)
      << refusal(huge);
  // Search entries of different weights (their names head one set of files' columns).
  json two = base;
  two["strategies"][1] = {
      {"name", "target_seeking"}, {"search", {{"mode", "all"}}}, {"params", json::object()}};
  EXPECT_NE(
      refusal(two).find("/strategies/1/search: searches the weights w1, w2, w3, an earlier search entry "
                        "w1, w2, w3, w4"),
      std::string::npos)
      << refusal(two);
  json ordered = base;
  ordered["/strategies/0/search/order"_json_pointer] = "bound";
  ordered["/strategies/0/search/max_open"_json_pointer] = 0;
  const std::string order_refusal = refusal(ordered);
  EXPECT_NE(order_refusal.find("/strategies/0/search/order: only a search of mode \"best\""),
            std::string::npos)
      << order_refusal;
  EXPECT_NE(order_refusal.find("/strategies/0/search/max_open: value 0; allowed: integers 1 to 1000000"),
            std::string::npos)
      << order_refusal;
  ordered["/strategies/0/search/mode"_json_pointer] = "best";
  ordered["/strategies/0/search/probes"_json_pointer] = -1;
  EXPECT_NE(refusal(ordered).find("/strategies/0/search/probes: value -1; allowed: integers 0 to 10000"),
            std::string::npos)
      << refusal(ordered);
  ordered["/strategies/0/search/probes"_json_pointer] = 2;
  ordered["/strategies/0/search/order"_json_pointer] = "wide";
  ordered["/strategies/0/search/max_open"_json_pointer] = 8;
  EXPECT_NE(
      refusal(ordered).find("/strategies/0/search/order: value \"wide\"; allowed: \"depth\", \"bound\""),
      std::string::npos)
      << refusal(ordered);
  json random = base;
  random["/strategies/0/name"_json_pointer] = "random_frontier";
  random["/strategies/0/params"_json_pointer] = json::object();
  EXPECT_NE(
      refusal(random).find("/strategies/0/search: strategy 'random_frontier' does not score its candidates "
                           "linearly, so its weights cannot be searched; allowed: closest_frontier, "
                           "energy_aware"),
      std::string::npos)
      << refusal(random);
  // Closest frontier is energy-aware with the fixed weights (1, 0, 0, 0): a box of one vector.
  json cf = random;
  cf["/strategies/0/name"_json_pointer] = "closest_frontier";
  const SweepPlan cf_plan = SweepPlan::from_json(cf, "s.json");
  EXPECT_EQ(cf_plan.strategies()[0].search->values,
            (std::vector<std::vector<double>>{{1.0}, {0.0}, {0.0}, {0.0}}));
  // Every weight left out spans its whole declared range: 251^4 vectors, too many to list.
  json full = base;
  full["/strategies/0/params"_json_pointer] = json::object();
  EXPECT_NE(refusal(full).find("the box has 3,969,126,001 vectors"), std::string::npos) << refusal(full);
  full["/strategies/0/search/write_vectors"_json_pointer] = false;
  const SweepPlan plan = SweepPlan::from_json(full, "s.json");
  EXPECT_EQ(plan.strategies()[0].search->vectors(), 3'969'126'001U);
  EXPECT_EQ(plan.strategies()[0].count(), 0U);
  EXPECT_EQ(plan.run_count(), 2U) << "the grid entry's two runs; the search entry has none";
}

}  // namespace test_weight_search_runner
}  // namespace fsweep
