#include "report/result_dir.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <unordered_map>
#include <utility>

#include "core/config_error.hpp"
#include "core/csv_reader.hpp"
#include "core/files.hpp"
#include "core/json_text.hpp"
#include "core/readable_number.hpp"
#include "core/shard_dirs.hpp"
#include "report/aggregate.hpp"
#include "report/search_schema.hpp"

namespace fsweep {
inline namespace report {
namespace {

namespace fs = std::filesystem;

/// The first and the last row of one search in search_best.csv.
struct SearchRanking {
  std::size_t id = 0;  ///< search_id
  std::vector<std::string> first, last;
};

/// Aggregates `dir` when a summary file is missing or summary.csv is older than runs.csv.
void aggregate_if_stale(ResultDir& r) {
  const std::string runs = r.dir + "/runs.csv";
  for (const char* name : {"summary.csv", "progress_summary.csv", "best.csv"}) {
    if (!fs::exists(r.dir + "/" + name)) {
      aggregate(r.dir, AggregateOptions{});
      r.notes.push_back(r.dir + " had no " + name + ": aggregated it first (fsweep aggregate)");
      return;
    }
  }
  if (fs::last_write_time(r.dir + "/summary.csv") < fs::last_write_time(runs)) {
    aggregate(r.dir, AggregateOptions{});
    r.notes.push_back(r.dir + "/summary.csv was older than runs.csv: aggregated it first (fsweep aggregate)");
  }
}

nlohmann::json read_manifest(const std::string& dir) {
  const std::string path = dir + "/manifest.json";
  const std::optional<std::string> text = read_file(path);
  if (!text) {
    const bool shards = !shard_dirs(dir).empty();
    throw ConfigError(
        path,
        std::string("not found: not a sweep result directory (fsweep run writes "
                    "manifest.json, runs.csv and the summaries)") +
            (shards ? "; it holds shard directories: join them with `fsweep merge " + dir + "` first" : ""));
  }
  nlohmann::json j = parse_json_or_discard(*text);
  if (j.is_discarded() || !j.is_object() || !j.contains("sweep") || !j["sweep"].is_object()) {
    throw ConfigError(path, "not a sweep manifest (a JSON object with the sweep, as fsweep run writes)");
  }
  return j;
}

/// The value of column `name` in `row` of a file with `header` (empty when absent).
std::string cell(const std::vector<std::string>& header, const std::vector<std::string>& row,
                 const std::string& name) {
  for (std::size_t i = 0; i < header.size() && i < row.size(); ++i) {
    if (header[i] == name) return row[i];
  }
  return {};
}

/// A configuration of best.csv whose first run the page shows.
struct WantedConfig {
  const std::vector<std::string>* row;  ///< its row in best.csv
  std::string role;
  std::optional<ShownRun> run;  ///< found in runs.csv
};

/// Counts a run's end reason.
void count_end(ResultDir& r, const std::string& reason) {
  const auto it = std::find_if(r.end_reasons.begin(), r.end_reasons.end(),
                               [&](const auto& e) { return e.first == reason; });
  if (it == r.end_reasons.end()) {
    r.end_reasons.emplace_back(reason, 1);
  } else {
    ++it->second;
  }
}

/// Finds the first runs of the best and the worst configuration of best.csv in runs.csv (file
/// comment) and counts the runs and their end reasons.
void read_runs(ResultDir& r) {
  CsvReader in(r.dir + "/runs.csv");
  const RunsHeader header(in.header(), in.path());
  const int index_column = header.column(kRunIndexColumn);
  std::vector<WantedConfig> wanted;
  const std::size_t ranked = r.best.total_rows;
  if (ranked == 1) {
    wanted.push_back({&r.best.rows.front(), "the only configuration: its first run", std::nullopt});
  } else if (ranked > 1) {
    const std::string n = std::to_string(ranked);
    wanted.push_back({&r.best.rows.front(),
                      "best configuration (rank 1 of " + n + " in best.csv): its first run", std::nullopt});
    wanted.push_back({&r.best.last_row,
                      "worst configuration (rank " + n + " of " + n + " in best.csv): its first run",
                      std::nullopt});
  }
  std::unordered_map<std::string, std::size_t> config_ids;  // config key -> config_id
  while (in.next()) {
    const auto& f = in.fields();
    ++r.runs;
    count_end(r, f[header.end_reason()]);
    const auto [at, added] = config_ids.emplace(header.config_key(f), config_ids.size());
    if (!added) continue;  // not the configuration's first run
    const std::string id = std::to_string(at->second);
    for (WantedConfig& w : wanted) {
      if (cell(r.best.header, *w.row, "config_id") != id) continue;
      for (const std::size_t c : header.config()) {
        const std::string& name = header.names()[c];
        if (cell(r.best.header, *w.row, name) != f[c]) {
          std::string message = "config_id " + id;
          message.append(" has ").append(name).append(" '").append(cell(r.best.header, *w.row, name));
          message.append("', runs.csv's configuration ").append(id).append(" has '").append(f[c]);
          message.append("': best.csv is not runs.csv's (run fsweep aggregate ").append(r.dir).append(")");
          throw ConfigError(r.best.path, message);
        }
      }
      ShownRun run;
      run.role = w.role + " (config_id " + id;
      for (const char* name : {kStrategyLabelColumn, kMapClassColumn}) {
        if (const std::string value = cell(r.best.header, *w.row, name); !value.empty()) {
          run.role.append(", ").append(value);
        }
      }
      run.role += ")";
      if (index_column >= 0) {
        const auto index = parse_number(f[static_cast<std::size_t>(index_column)]);
        if (!index || *index < 0) throw ConfigError(in.where(), "run_index is not a run index");
        run.run_index = static_cast<std::uint64_t>(*index);
      }
      run.run_key = f[header.run_key()];
      for (const std::size_t c : header.quality()) run.recorded.emplace_back(header.names()[c], f[c]);
      w.run = std::move(run);
    }
  }
  for (WantedConfig& w : wanted) {
    if (!w.run) {
      throw ConfigError(r.best.path, "config_id " + cell(r.best.header, *w.row, "config_id") +
                                         " is not a configuration of runs.csv (run fsweep aggregate " +
                                         r.dir + ")");
    }
    r.shown.push_back(std::move(*w.run));
  }
}

/// The behaviours to show of the exact weight searches (file comment), from search_best.csv,
/// behaviours.csv and (for their labels) searches.json.
void read_searches(ResultDir& r) {
  const std::string dir = r.dir;
  std::vector<SearchRanking> searches;  // in the file's order
  {
    CsvReader in(dir + "/" + kSearchBestFile);
    const std::size_t id = in.require_column(kSearchIdColumn);
    while (in.next()) {
      const auto number = parse_number(in.fields()[id]);
      if (!number || *number < 0 || *number != static_cast<double>(static_cast<std::size_t>(*number))) {
        throw ConfigError(in.where(), "search_id '" + in.fields()[id] + "' is not a search's index");
      }
      const auto search = static_cast<std::size_t>(*number);
      if (searches.empty() || searches.back().id != search) searches.push_back({search, in.fields(), {}});
      searches.back().last = in.fields();
    }
  }
  nlohmann::json records;
  if (const auto text = read_file(dir + "/" + kSearchesFile)) records = parse_json_or_discard(*text);
  const std::vector<std::string>& h = r.search_best->header;
  const std::vector<std::string> weight_names = search_best_weights(h);
  std::vector<ShownRun> shown;
  for (std::size_t k = 0; k < searches.size() && k < kShownSearches; ++k) {
    const SearchRanking& s = searches[k];
    std::string label = "search " + std::to_string(s.id);
    if (records.is_object() && records.contains("searches") && records["searches"].is_array()) {
      for (const auto& rec : records["searches"]) {
        if (rec.is_object() && rec.contains(kSearchIdColumn) && rec[kSearchIdColumn] == s.id) {
          const auto text = [&](const char* key) {  // a damaged record's field: left out
            return rec.contains(key) && rec[key].is_string() ? rec[key].get<std::string>() : std::string("?");
          };
          label += " (" + text("strategy_label") + " on " + text("map_class") + ")";
        }
      }
    }
    for (const auto* row : {&s.first, &s.last}) {
      if (row == &s.last && cell(h, s.last, kBehaviourIdColumn) == cell(h, s.first, kBehaviourIdColumn))
        continue;
      ShownRun run;
      run.search_id = s.id;
      run.behaviour_id = cell(h, *row, kBehaviourIdColumn);
      std::string vector;
      for (const auto& w : weight_names) {
        const auto v = parse_number(cell(h, *row, w));
        if (!v)
          throw ConfigError(dir + "/" + kSearchBestFile,
                            "weight " + w + " of behaviour " + run.behaviour_id + " is not a number");
        run.weights.push_back(*v);
        vector += (vector.empty() ? "" : ", ") + w + "=" + cell(h, *row, w);
      }
      const bool tied = row == &s.last && cell(h, s.last, kRankColumn) == cell(h, s.first, kRankColumn);
      run.role = label + ": " + (row == &s.first ? "best" : tied ? "last of the equally best" : "worst");
      run.role.append(" behaviour (rank ")
          .append(cell(h, *row, kRankColumn))
          .append(", behaviour ")
          .append(run.behaviour_id);
      run.role.append(", ").append(cell(h, *row, kVectorsColumn)).append(" vectors, objective ");
      const auto objective = parse_number(cell(h, *row, kObjectiveColumn));
      run.role.append(objective ? readable_number(*objective, 6) : cell(h, *row, kObjectiveColumn))
          .append("), its first instance with the representative weights ");
      run.role.append(vector);
      shown.push_back(std::move(run));
    }
  }
  // The recorded outcome: the behaviour's row of instance 0 in behaviours.csv.
  CsvReader in(dir + "/" + kBehavioursFile);
  const std::size_t search = in.require_column(kSearchIdColumn);
  const std::size_t behaviour = in.require_column(kBehaviourIdColumn);
  const std::size_t instance = in.require_column(kInstanceColumn);
  const std::size_t first_metric = in.require_column(kSeedColumn) + 1;
  while (in.next()) {
    const auto& f = in.fields();
    if (f[instance] != "0") continue;
    for (ShownRun& run : shown) {
      if (std::to_string(*run.search_id) != f[search] || run.behaviour_id != f[behaviour]) continue;
      for (std::size_t c = first_metric; c < f.size(); ++c) {
        if (!is_effort_column(in.header()[c])) run.recorded.emplace_back(in.header()[c], f[c]);
      }
    }
  }
  for (ShownRun& run : shown) {
    if (run.recorded.empty()) {
      throw ConfigError(dir + "/" + kBehavioursFile, "no row of instance 0 of behaviour " + run.behaviour_id +
                                                         " of search " + std::to_string(*run.search_id) +
                                                         " (search_best.csv lists it)");
    }
    r.shown.push_back(std::move(run));
  }
}

/// The rankings per map class (ResultDir::rankings): best.csv's order split by map_class, the
/// first `max_rows` of each class with their summary.csv rows.
void read_rankings(ResultDir& r, std::size_t max_rows) {
  std::unordered_map<std::string, std::size_t> class_index;
  std::unordered_map<std::string, std::pair<std::size_t, std::size_t>> wanted;  // config_id -> (class, row)
  {
    CsvReader in(r.dir + "/best.csv");
    const std::size_t id = in.require_column("config_id");
    const int map_class = in.column(kMapClassColumn);
    while (in.next()) {
      const auto& f = in.fields();
      const std::string name = map_class < 0 ? std::string() : f[static_cast<std::size_t>(map_class)];
      const auto [it, added] = class_index.try_emplace(name, r.rankings.size());
      if (added) r.rankings.push_back(ClassRanking{name, {}, {}, 0});
      ClassRanking& c = r.rankings[it->second];
      if (++c.total > max_rows) continue;
      c.ranks.push_back(c.total);
      c.rows.emplace_back();
      wanted.emplace(f[id], std::pair{it->second, c.rows.size() - 1});
    }
  }
  CsvReader in(r.dir + "/summary.csv");
  const std::size_t id = in.require_column("config_id");
  std::size_t found = 0;
  while (in.next()) {
    const auto it = wanted.find(in.fields()[id]);
    if (it == wanted.end()) continue;
    r.rankings[it->second.first].rows[it->second.second] = in.fields();
    ++found;
  }
  if (found != wanted.size()) {
    throw ConfigError(r.dir + "/best.csv",
                      "ranks configurations summary.csv does not have (run fsweep aggregate " + r.dir + ")");
  }
}

}  // namespace

CsvExcerpt read_csv_excerpt(const std::string& path, std::size_t max_rows) {
  if (!fs::exists(path)) throw ConfigError(path, "not found");
  CsvReader in(path);
  CsvExcerpt out;
  out.path = path;
  out.header = in.header();
  while (in.next()) {
    if (out.rows.size() < max_rows) out.rows.push_back(in.fields());
    out.last_row = in.fields();
    ++out.total_rows;
  }
  return out;
}

ResultDir read_result_dir(const std::string& dir, std::size_t max_rows) {
  if (!fs::is_directory(dir))
    throw ConfigError(dir, "not a directory (a sweep result directory is expected)");
  ResultDir r;
  r.dir = dir;
  r.manifest = read_manifest(dir);
  if (!fs::exists(dir + "/runs.csv")) {
    throw ConfigError(dir + "/runs.csv", "not found: not a sweep result directory (fsweep run writes it)");
  }
  aggregate_if_stale(r);
  r.best = read_csv_excerpt(dir + "/best.csv", std::max<std::size_t>(max_rows, 1));
  r.summary = read_csv_excerpt(dir + "/summary.csv", max_rows);
  read_rankings(r, max_rows);
  read_runs(r);
  if (fs::exists(dir + "/" + kSearchBestFile)) {
    r.search_best = read_csv_excerpt(dir + "/" + kSearchBestFile, max_rows);
    read_searches(r);
  }
  return r;
}

}  // namespace report
}  // namespace fsweep
