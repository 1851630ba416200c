#include "sweep/merge.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string_view>
#include <unordered_map>

#include "core/config_error.hpp"
#include "core/csv_format.hpp"
#include "core/csv_reader.hpp"
#include "core/files.hpp"
#include "core/json_text.hpp"
#include "report/aggregate.hpp"
#include "report/runs_schema.hpp"
#include "report/search_schema.hpp"
#include "sweep/csv_journal.hpp"
#include "sweep/done_runs.hpp"
#include "sweep/manifest.hpp"
#include "sweep/optimum_table.hpp"
#include "sweep/sweep_plan.hpp"
#include "sweep/weight_search_runner.hpp"

namespace fsweep {
inline namespace sweep {
namespace {

namespace fs = std::filesystem;

struct Shard {
  std::uint64_t index = 0;
  std::uint64_t count = 0;
  std::string dir;
  nlohmann::json manifest;
};

nlohmann::json read_json(const std::string& path) {
  const std::optional<std::string> text = read_file(path);
  if (!text) throw ConfigError(path, "cannot open the manifest");
  nlohmann::json j;
  try {
    j = parse_json_bounded(*text, path);
  } catch (const nlohmann::json::exception&) {
    j = nlohmann::json::value_t::discarded;
  }
  if (j.is_discarded() || !j.is_object() || !j.contains("sweep_hash") || !j["sweep_hash"].is_string()) {
    throw ConfigError(path, "not a sweep manifest (no sweep_hash)");
  }
  return j;
}

std::uint64_t parse_index(const std::string& cell, const CsvReader& r) {
  const auto v = parse_run_index(cell);
  if (!v) throw ConfigError(r.where(), "run_index '" + cell + "' is not a non-negative integer");
  return *v;
}

/// "sweep 'name' (sweep_hash H)" of a sweep manifest.
std::string describe_sweep(const nlohmann::json& manifest) {
  const nlohmann::json* name = manifest.contains("name") ? &manifest["name"] : nullptr;
  return std::string("sweep ") +
         (name != nullptr && name->is_string() ? "'" + name->get<std::string>() + "' " : "") +
         "(sweep_hash " + manifest["sweep_hash"].get<std::string>() + ")";
}

/// The first map whose label or content_hash differs between two shards' manifests ("map 'L':
/// content hash A, B"); empty when their "maps" agree.
std::string first_map_difference(const nlohmann::json& a, const nlohmann::json& b) {
  const nlohmann::json none = nlohmann::json::array();
  const nlohmann::json& ma = a.contains("maps") ? a["maps"] : none;
  const nlohmann::json& mb = b.contains("maps") ? b["maps"] : none;
  if (ma == mb) return {};
  for (std::size_t i = 0; i < std::min(ma.size(), mb.size()); ++i) {
    if (ma[i] == mb[i]) continue;
    return "map '" + ma[i].value("label", std::string()) + "': content hash " +
           ma[i].value("content_hash", std::string("none")) + ", " +
           mb[i].value("content_hash", std::string("none"));
  }
  return "the lists of maps (" + std::to_string(ma.size()) + " and " + std::to_string(mb.size()) + " maps)";
}

/// True when two manifests record the same sweep: the same hash, or sweep files that differ in
/// their description alone.
bool same_sweep_of(const nlohmann::json& a, const nlohmann::json& b) {
  return a["sweep_hash"] == b["sweep_hash"] ||
         same_sweep_but_description(a.value("sweep", nlohmann::json()), b.value("sweep", nlohmann::json()));
}

/// True when a session of a shard ran the sweep with hash `hash`: the shards extended it
/// (sweep_runner.hpp, Extending).
bool shards_ran(const std::vector<Shard>& shards, const nlohmann::json& hash) {
  return std::any_of(shards.begin(), shards.end(), [&](const Shard& s) {
    const nlohmann::json sessions = manifest_sessions(s.manifest);
    return std::any_of(sessions.begin(), sessions.end(), [&](const nlohmann::json& session) {
      return session.value("sweep_hash", nlohmann::json()) == hash;
    });
  });
}

/// Throws ConfigError when `dir` already holds the merged (or unsharded) results of another sweep
/// than the shards' (not same_sweep_of() the first shard's, and not of a sweep the shards
/// extended), as an unsharded run refuses.
void refuse_results_of_another_sweep(const std::string& dir, const std::vector<Shard>& shards) {
  const Shard& first = shards.front();
  const std::string path = dir + "/manifest.json";
  if (!fs::exists(path)) return;
  const nlohmann::json held = read_json(path);
  if (same_sweep_of(held, first.manifest) || shards_ran(shards, held["sweep_hash"])) return;
  throw ConfigError(dir, "holds the results of " + describe_sweep(held) + ", its shards are of " +
                             describe_sweep(first.manifest) + " (" + first.dir +
                             "); nothing written: merge the shards of one sweep into its own directory");
}

/// The shard folders of `dir`, their manifests read, checked to be shards of one split of one
/// sweep run on the same maps; a missing shard goes to `report`'s problems.
std::vector<Shard> read_shards(const std::string& dir, MergeReport& report) {
  std::vector<Shard> shards;
  for (ShardDir& d : shard_dirs(dir)) shards.push_back({d.index, d.count, std::move(d.path), {}});
  if (shards.empty()) throw ConfigError(dir, "no shard directories (shard-<i>-of-<n>) to merge");
  if (shards.front().count != shards.back().count) {
    throw ConfigError(dir, "shards of different shard counts: " + shards.front().dir + " and " +
                               shards.back().dir + " (merge the shards of one --shard i/N split only)");
  }
  const std::uint64_t n = shards.front().count;
  report.shard_count = n;
  for (const Shard& s : shards) {
    if (s.index >= n)
      throw ConfigError(s.dir,
                        "shard index " + std::to_string(s.index) + " is not below " + std::to_string(n));
  }
  for (Shard& s : shards) s.manifest = read_json(s.dir + "/manifest.json");
  for (const Shard& s : shards) {
    if (!same_sweep_of(s.manifest, shards.front().manifest)) {
      throw ConfigError(dir, "shards of different sweeps (sweep_hash " +
                                 s.manifest["sweep_hash"].get<std::string>() + " in " + s.dir + ", " +
                                 shards.front().manifest["sweep_hash"].get<std::string>() + " in " +
                                 shards.front().dir + ")");
    }
  }
  for (const Shard& s : shards) {
    const std::string differs = first_map_difference(shards.front().manifest, s.manifest);
    if (!differs.empty()) {
      throw ConfigError(dir,
                        "shards of the same sweep file run on different map contents (" + differs + " in " +
                            shards.front().dir + " and " + s.dir +
                            "; was a map file edited between them?): rerun one of them on the other's maps");
    }
  }
  refuse_results_of_another_sweep(dir, shards);
  std::size_t k = 0;
  for (std::uint64_t i = 0; i < n; ++i) {
    if (k < shards.size() && shards[k].index == i) {
      ++k;
    } else {
      report.problems.push_back("missing shard directory " + dir + "/" + shard_dir_name(i, n));
    }
  }
  return shards;
}

/// The whole sweep's plan from the first shard's manifest, for the total and the run keys; none
/// when it cannot be rebuilt here (then the total is the shards' totals).
std::optional<SweepPlan> whole_plan(const std::vector<Shard>& shards, MergeReport& report) {
  const nlohmann::json& first = shards.front().manifest;
  std::optional<SweepPlan> plan;
  try {
    if (first.contains("sweep"))
      plan.emplace(SweepPlan::from_json(first["sweep"], first.value("sweep_file", "")));
  } catch (const std::exception&) {
    plan.reset();
  }
  if (plan) {
    report.total = plan->run_count();
  } else {
    for (const Shard& s : shards)
      report.total += s.manifest.value("/runs/total"_json_pointer, std::uint64_t{0});
  }
  return plan;
}

/// The shards' runs.csv: its header, and the rows by run_index. Rows beyond the sweep, repeated
/// indices or keys, keys not the plan's and missing runs go to `report`'s problems.
std::pair<std::string, std::map<std::uint64_t, std::string>> merged_runs(const std::vector<Shard>& shards,
                                                                         const std::optional<SweepPlan>& plan,
                                                                         MergeReport& report) {
  std::string runs_header;
  std::map<std::uint64_t, std::string> runs;
  std::unordered_map<std::string, std::string> key_where;
  std::map<std::uint64_t, std::string> index_where;
  for (const Shard& s : shards) {
    CsvReader r(s.dir + "/runs.csv");
    const std::string header = csv_record(r.header());
    if (runs_header.empty()) runs_header = header;
    if (header != runs_header)
      throw ConfigError(r.path(), "runs.csv header differs from " + shards.front().dir + "'s");
    const std::size_t ci = r.require_column(kRunIndexColumn);
    const std::size_t ck = r.require_column(kRunKeyColumn);
    while (r.next()) {
      ++report.rows;
      const std::uint64_t idx = parse_index(r.fields()[ci], r);
      const std::string& key = r.fields()[ck];
      if (idx >= report.total) {
        report.problems.push_back(r.where() + ": run_index " + std::to_string(idx) +
                                  " is not below the sweep's " + std::to_string(report.total) + " runs");
        continue;
      }
      if (const auto it = index_where.find(idx); it != index_where.end()) {
        report.problems.push_back("duplicate run_index " + std::to_string(idx) + " (run_key " + key +
                                  ") at " + it->second + " and " + r.where());
        continue;
      }
      if (const auto it = key_where.find(key); it != key_where.end()) {
        report.problems.push_back("duplicate run_key " + key + " (run_index " + std::to_string(idx) +
                                  ") at " + it->second + " and " + r.where());
      }
      if (plan && plan->run_key(idx) != key) {
        report.problems.push_back(r.where() + ": run_index " + std::to_string(idx) + " has run_key " + key +
                                  ", the sweep's is " + plan->run_key(idx));
      }
      index_where[idx] = r.where();
      key_where[key] = r.where();
      runs[idx] = csv_record(r.fields());
    }
  }
  for (std::uint64_t i = 0; i < report.total; ++i) {
    if (runs.count(i) != 0) continue;
    report.problems.push_back("missing run_index " + std::to_string(i) +
                              (plan ? " (run_key " + plan->run_key(i) + ")" : std::string()));
  }
  return {runs_header, std::move(runs)};
}

/// The shards' progress.csv as one file's text, grouped by run_index (a run's rows keep their
/// order); rows of runs without a runs.csv row (a torn write) are dropped, as aggregate does.
std::string merged_progress(const std::vector<Shard>& shards,
                            const std::map<std::uint64_t, std::string>& runs) {
  std::string progress_header;
  std::map<std::uint64_t, std::string> progress;
  for (const Shard& s : shards) {
    CsvReader r(s.dir + "/progress.csv");
    const std::string header = csv_record(r.header());
    if (progress_header.empty()) progress_header = header;
    if (header != progress_header) {
      throw ConfigError(r.path(), "progress.csv header differs from " + shards.front().dir + "'s");
    }
    const std::size_t ci = r.require_column(kRunIndexColumn);
    while (r.next()) {
      const std::uint64_t idx = parse_index(r.fields()[ci], r);
      if (runs.count(idx) == 0) continue;
      progress[idx] += csv_record(r.fields()) + "\n";
    }
  }
  std::string text = progress_header + "\n";
  for (const auto& [idx, rows] : progress) text += rows;
  return text;
}

/// The merged folder's manifest: the first shard's (its sweep and description), with the
/// shards' counts summed, their sessions by start time, and the longest shard's wall time.
nlohmann::json merged_manifest(const std::vector<Shard>& shards, const MergeReport& report) {
  nlohmann::json manifest = shards.front().manifest;
  std::uint64_t failed = 0;
  std::uint64_t ran = 0;
  std::uint64_t skipped = 0;
  double wall = 0.0;
  nlohmann::json sessions = nlohmann::json::array();  // every shard's, by start time
  for (const Shard& s : shards) {
    failed += s.manifest.value("/runs/failed"_json_pointer, std::uint64_t{0});
    ran += s.manifest.value("/runs/ran"_json_pointer, std::uint64_t{0});
    skipped += s.manifest.value("/runs/skipped"_json_pointer, std::uint64_t{0});
    wall = std::max(wall, s.manifest.value("wall_s", 0.0));
    for (nlohmann::json& session : manifest_sessions(s.manifest)) sessions.push_back(std::move(session));
  }
  const auto start = [](const nlohmann::json& session) {  // ISO 8601 UTC: text order is time order
    const auto it = session.find("start_utc");
    return it != session.end() && it->is_string() ? it->get<std::string>() : std::string();
  };
  std::stable_sort(sessions.begin(), sessions.end(),
                   [&](const nlohmann::json& a, const nlohmann::json& b) { return start(a) < start(b); });
  manifest["runs"] = {{"total", report.total},
                      {"done", report.total},
                      {"skipped", skipped},
                      {"ran", ran},
                      {"failed", failed}};
  manifest["shard"] = {{"index", 0}, {"count", 1}, {"merged_from", report.shard_count}};
  manifest["status"] = "complete";
  manifest["wall_s"] = wall;  // the longest shard: the elapsed time if the shards ran at once
  manifest["runs_per_s"] = wall > 0.0 ? static_cast<double>(ran) / wall : 0.0;
  manifest["end_utc"] = utc_now_iso8601();
  if (!sessions.empty() && !start(sessions.front()).empty()) manifest["start_utc"] = start(sessions.front());
  manifest["sessions"] = std::move(sessions);
  return manifest;
}

}  // namespace

MergeReport merge_shards(const std::string& dir, const std::string& objective,
                         const SearchMemoryGuard& memory) {
  MergeReport report;
  if (!fs::is_directory(dir)) throw ConfigError(dir, "not a directory");
  const std::vector<Shard> shards = read_shards(dir, report);
  std::vector<std::string> dirs;
  std::vector<ShardDir> shard_list;
  dirs.reserve(shards.size());
  shard_list.reserve(shards.size());
  for (const Shard& s : shards) {
    dirs.push_back(s.dir);
    shard_list.push_back({s.index, s.count, s.dir});
  }
  const std::optional<SweepPlan> plan = whole_plan(shards, report);
  const auto [runs_header, runs] = merged_runs(shards, plan, report);
  if (!report.problems.empty()) {
    // Where the searches stand all the same, a missing shard's bound unknown (as at a Slurm
    // array's tasks still waiting).
    // Not over a complete merge's (its searches.json says the searches finished).
    if (plan && !plan->search_units().empty() && !fs::exists(dir + "/" + kSearchesFile)) {
      std::vector<std::string> all;
      all.reserve(report.shard_count);
      for (std::uint64_t i = 0; i < report.shard_count; ++i)
        all.push_back(dir + "/" + shard_dir_name(i, report.shard_count));
      report.search_status = join_search_statuses(*plan, dir, all);
    }
    return report;
  }

  std::string runs_text = runs_header + "\n";
  for (const auto& [idx, row] : runs) runs_text += row + "\n";
  const std::string progress_text = merged_progress(shards, runs);
  const nlohmann::json manifest = merged_manifest(shards, report);

  // The weight searches' parts (weight_search_runner.hpp): joined first, so that a shard whose
  // searches did not finish stops the merge before anything is written.
  if (!plan) {
    for (const Shard& s : shards) {
      if (fs::exists(s.dir + "/" + kSearchesFile)) {
        throw ConfigError(s.dir + "/" + kSearchesFile,
                          "the sweep's plan cannot be rebuilt from the manifest (is a map file not reachable "
                          "from the current directory?), so its weight searches cannot be merged; run the "
                          "merge where the sweep ran");
      }
    }
  } else if (!plan->search_units().empty()) {
    const SearchRunReport searches = merge_weight_searches(*plan, dir, shard_list, memory);
    if (searches.memory_stop) {
      report.memory_stop = searches.memory_stop->message;
      return report;
    }
    report.searches = searches.searches;
  }
  write_file_atomically(dir + "/runs.csv", runs_text);
  write_file_atomically(dir + "/progress.csv", progress_text);
  (void)merge_optima(dir, dirs);  // a resume in the merged folder reads them
  write_manifest(dir + "/manifest.json", manifest);
  aggregate(dir, AggregateOptions{objective});
  report.written = true;
  return report;
}

}  // namespace sweep
}  // namespace fsweep
