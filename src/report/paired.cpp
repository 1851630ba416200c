/// @file paired.cpp
/// Paired comparisons (paired.hpp): the sides and pairs of runs.csv and of exact weight
/// searches, the statistics of each row, and paired.csv / paired.json.

#include "report/paired.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <unordered_map>

#include "core/config_error.hpp"
#include "core/csv_format.hpp"
#include "core/csv_reader.hpp"
#include "core/files.hpp"
#include "core/json_text.hpp"
#include "core/random.hpp"
#include "core/statistics.hpp"
#include "report/config_names.hpp"
#include "report/runs_schema.hpp"
#include "report/search_schema.hpp"

namespace fsweep {
inline namespace report {
namespace {

constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();
constexpr char kRunsSource[] = "runs";

/// One run of a side, as pairing needs it.
struct SideRun {
  std::string end;
  std::vector<double> values;  ///< per compared metric; NaN: no value
};

/// The runs of every side on one map instance and repetition.
struct PairSlot {
  std::string instance;                  ///< the map instance (the bootstrap's cluster)
  std::map<std::size_t, SideRun> sides;  ///< side index -> its run
};

/// Runs that may be paired: one map class and variant of one source.
struct Group {
  std::string map_class;
  std::vector<std::string> variant;
  std::string energy_unit;      ///< the robot's energy unit (runs.csv's robot.energy.unit)
  std::vector<PairSlot> slots;  ///< by first appearance
  std::unordered_map<std::string, std::size_t> index;  ///< pair key -> slot
};

/// The sides and groups of runs.csv or of one exact search.
struct Source {
  std::string name;
  std::vector<std::size_t> sides;  ///< indices into PairedTable::sides, in order of appearance
  std::vector<Group> groups;
  std::string default_baseline;  ///< the side compared with when the baseline asked for is not one
};

/// A side's run, added to `group` under `pair_key`; false (and nothing added) when the side has a
/// run under that key already.
bool add_run(Group& group, const std::string& pair_key, const std::string& instance, std::size_t side,
             SideRun run) {
  auto [it, added] = group.index.try_emplace(pair_key, group.slots.size());
  if (added) group.slots.push_back(PairSlot{instance, {}});
  return group.slots[it->second].sides.emplace(side, std::move(run)).second;
}

/// The group of `key`, created with `map_class` and `variant` when new.
Group& group_of(Source& source, std::unordered_map<std::string, std::size_t>& groups, const std::string& key,
                const std::string& map_class, const std::vector<std::string>& variant) {
  auto [it, added] = groups.try_emplace(key, source.groups.size());
  if (added) source.groups.push_back(Group{map_class, variant, {}, {}, {}});
  return source.groups[it->second];
}

/// The value of each compared metric in `fields` (columns `columns`, -1: absent).
std::vector<double> metric_values(const std::vector<std::string>& fields, const std::vector<int>& columns,
                                  const std::vector<std::string>& names, const CsvReader& in) {
  std::vector<double> values;
  values.reserve(columns.size());
  for (std::size_t m = 0; m < columns.size(); ++m) {
    const auto v = columns[m] < 0 ? std::nullopt
                                  : metric_value(fields[static_cast<std::size_t>(columns[m])], names[m], in);
    values.push_back(v ? *v : kNoValue);
  }
  return values;
}

/// The compared metrics: the options', each a metric column of `available` given once (else
/// ConfigError at --metric listing them), or the defaults the file has.
std::vector<std::string> chosen_metrics(const PairedOptions& o, const std::vector<std::string>& available,
                                        const std::string& file) {
  if (o.metrics.empty()) {
    std::vector<std::string> out;
    for (const char* m : kDefaultPairedMetrics) {
      if (std::find(available.begin(), available.end(), m) != available.end()) out.emplace_back(m);
    }
    return out;
  }
  for (auto m = o.metrics.begin(); m != o.metrics.end(); ++m) {
    if (std::find(available.begin(), available.end(), *m) == available.end()) {
      throw ConfigError("--metric", "'" + *m + "' is not a metric column of " + file +
                                        "; allowed: " + join_names(available));
    }
    if (std::find(o.metrics.begin(), m, *m) != m)
      throw ConfigError("--metric", "'" + *m + "' is given twice");
  }
  return o.metrics;
}

/// The runs.csv side columns: strategy_label, strategy and strategy.*.
bool is_side_column(const std::string& name) {
  return name == kStrategyLabelColumn || name == "strategy" || name.starts_with("strategy.");
}

/// runs.csv as a source (paired.hpp, "Sides and pairs").
Source read_runs_source(const std::string& path, PairedTable& table, const PairedOptions& o) {
  CsvReader in(path);
  const RunsHeader header(in.header(), path);
  table.metrics = chosen_metrics(o, header.names_of(header.metrics()), path);
  std::vector<int> metric_columns;
  for (const auto& m : table.metrics) metric_columns.push_back(header.column(m));
  std::vector<std::size_t> side_cols, group_cols, instance_cols;
  for (const std::size_t c : header.config())
    (is_side_column(header.names()[c]) ? side_cols : group_cols).push_back(c);
  for (std::size_t c = 0; c < header.names().size(); ++c) {
    if (header.role(c) == ColumnRole::Instance) instance_cols.push_back(c);
  }
  const int map_class = header.column(kMapClassColumn);
  const int map = header.column(kMapColumn);
  const int label = header.column(kStrategyLabelColumn);
  const int energy_unit = header.column("robot.energy.unit");

  Source source{kRunsSource, {}, {}, {}};
  std::unordered_map<std::string, std::size_t> side_of, group_of_key;
  std::vector<std::vector<std::string>> side_values;  // parallel to source.sides: the side columns' cells
  while (in.next()) {
    const auto& f = in.fields();
    const std::string side_key = config_key(f, std::vector<int>(side_cols.begin(), side_cols.end()));
    auto [side, added] = side_of.try_emplace(side_key, table.sides.size());
    if (added) {
      table.sides.push_back(
          PairedSide{{}, kRunsSource, label < 0 ? "" : f[static_cast<std::size_t>(label)], {}});
      source.sides.push_back(side->second);
      side_values.emplace_back();
      for (const std::size_t c : side_cols) side_values.back().push_back(f[c]);
    }
    std::vector<std::string> variant;
    for (std::size_t g = 0; g < group_cols.size(); ++g) {
      if (static_cast<int>(group_cols[g]) != map_class) variant.push_back(f[group_cols[g]]);
    }
    Group& group =
        group_of(source, group_of_key, config_key(f, std::vector<int>(group_cols.begin(), group_cols.end())),
                 map_class < 0 ? "" : f[static_cast<std::size_t>(map_class)], variant);
    if (energy_unit >= 0) group.energy_unit = f[static_cast<std::size_t>(energy_unit)];
    const std::string pair_key = config_key(f, std::vector<int>(instance_cols.begin(), instance_cols.end()));
    SideRun run{f[header.end_reason()], metric_values(f, metric_columns, table.metrics, in)};
    if (!add_run(group, pair_key, map < 0 ? "" : f[static_cast<std::size_t>(map)], side->second,
                 std::move(run))) {
      throw ConfigError(in.where(), "a second run of strategy '" + table.sides[side->second].label +
                                        "' on the same map instance, seed and variant (run_key " +
                                        f[header.run_key()] + ")");
    }
  }
  // Variant columns: the group columns but map_class that differ in the file, without those that
  // another shown column determines (robot.energy.per_metre by robot.energy.preset).
  // map_class (last here) names the groups itself, but tells what it determines (the maps' resolution).
  std::vector<std::string> names;
  for (const std::size_t g : group_cols) {
    if (static_cast<int>(g) != map_class) names.push_back(header.names()[g]);
  }
  names.emplace_back(kMapClassColumn);
  std::vector<std::vector<std::string>> variants;
  for (const Group& group : source.groups) {
    variants.push_back(group.variant);
    variants.back().push_back(group.map_class);
  }
  std::vector<std::size_t> shown = telling_columns(names, variants);
  std::erase(shown, names.size() - 1);
  for (const std::size_t c : shown) table.variant_columns.push_back(names[c]);
  for (Group& group : source.groups) {
    std::vector<std::string> values;
    values.reserve(shown.size());
    for (const std::size_t c : shown) values.push_back(group.variant[c]);
    group.variant = std::move(values);
  }
  const std::vector<std::string> side_names = strategy_names(header.names_of(side_cols), side_values);
  for (std::size_t k = 0; k < source.sides.size(); ++k) {
    PairedSide& side = table.sides[source.sides[k]];
    side.name = side_names[k];
    for (std::size_t c = 0; c < side_cols.size(); ++c) {
      const std::string& column = header.names()[side_cols[c]];
      if (column.starts_with("strategy.") && !side_values[k][c].empty())
        side.params.emplace_back(column.substr(9), side_values[k][c]);
    }
  }
  return source;
}

/// The columns of `in`'s header named `names`, each required.
std::vector<std::size_t> require_columns(const CsvReader& in, std::initializer_list<const char*> names) {
  std::vector<std::size_t> out;
  for (const char* n : names) out.push_back(in.require_column(n));
  return out;
}

/// A search's weight vector "w1,w2,..." and its (name, value) pairs, from `fields` at `columns`.
std::pair<std::string, std::vector<std::pair<std::string, std::string>>> weights_of(
    const std::vector<std::string>& fields, const std::vector<std::string>& header,
    const std::vector<std::size_t>& columns) {
  std::string text;
  std::vector<std::pair<std::string, std::string>> params;
  for (const std::size_t c : columns) {
    text += (text.empty() ? "" : ",") + fields[c];
    params.emplace_back(header[c], fields[c]);
  }
  return {text, params};
}

/// The weight columns of a search file: the w<k> columns (behaviours.csv's and search_ranks.csv's
/// representative, search_best.csv's).
std::vector<std::size_t> weight_columns(const std::vector<std::string>& header) {
  std::vector<std::size_t> out;
  for (std::size_t c = 0; c < header.size(); ++c) {
    const std::string& h = header[c];
    if (h.size() >= 2 && h[0] == 'w' &&
        std::all_of(h.begin() + 1, h.end(), [](char ch) { return ch >= '0' && ch <= '9'; }))
      out.push_back(c);
  }
  return out;
}

/// One exact search of searches.json: what naming its sides needs.
struct SearchInfo {
  std::string id;
  std::string label;
  std::string map_class;
  std::string mode;
  std::string energy_unit;
};

std::vector<SearchInfo> read_searches_records(const std::string& path) {
  const auto text = read_file(path);
  if (!text) throw ConfigError(path, "cannot read the file");
  const nlohmann::json j = parse_json_bounded(*text, path);
  if (!j.is_object() || !j.contains("searches") || !j["searches"].is_array())
    throw ConfigError(path, "expected an object with a 'searches' array");
  std::vector<SearchInfo> out;
  for (const auto& s : j["searches"]) {
    if (!s.is_object() || !s.contains(kSearchIdColumn) || !s[kSearchIdColumn].is_number_unsigned())
      throw ConfigError(path, "a search without a search_id");
    const auto unit = nlohmann::json::json_pointer("/instances/0/robot/energy/unit");
    out.push_back(
        SearchInfo{std::to_string(s[kSearchIdColumn].get<std::uint64_t>()), s.value("strategy_label", ""),
                   s.value("map_class", ""), s.value("mode", ""),
                   s.contains(unit) && s.at(unit).is_string() ? s.at(unit).get<std::string>() : ""});
  }
  return out;
}

std::vector<SearchInfo> read_searches_json(const std::string& path) {
  try {
    return read_searches_records(path);
  } catch (const nlohmann::json::exception& e) {  // not JSON, or a field of another type
    throw ConfigError(path, std::string("not a searches file of fsweep run: ") + e.what() +
                                "; `fsweep run` on the same sweep and directory writes it again from "
                                "search_journal.jsonl (`fsweep merge` from the shards', for a merge)");
  }
}

/// Adds the sides of the searches: `<label>@best` (rank 1 of search_best.csv) and a side per
/// vector of search_ranks.csv; returns search_id -> behaviour_id -> the sides that are it.
std::map<std::string, std::map<std::string, std::vector<std::size_t>>> add_search_sides(
    const std::string& dir, const std::vector<SearchInfo>& searches, PairedTable& table,
    std::vector<Source>& sources) {
  std::map<std::string, std::size_t> source_of;
  for (const SearchInfo& s : searches) {
    source_of[s.id] = sources.size();
    sources.push_back(Source{"search " + s.id, {}, {}, s.label + "@best"});
  }
  std::map<std::string, std::map<std::string, std::vector<std::size_t>>> wanted;
  const auto add = [&](const std::string& search, const std::string& behaviour, PairedSide side) {
    const auto it = source_of.find(search);
    if (it == source_of.end()) return;
    sources[it->second].sides.push_back(table.sides.size());
    wanted[search][behaviour].push_back(table.sides.size());
    table.sides.push_back(std::move(side));
  };
  const auto label_of = [&](const std::string& id) {
    const auto it =
        std::find_if(searches.begin(), searches.end(), [&](const SearchInfo& s) { return s.id == id; });
    return it == searches.end() ? std::string() : it->label;
  };
  {
    CsvReader in(dir + "/" + kSearchBestFile);
    const auto cols = require_columns(in, {kSearchIdColumn, kRankColumn, kBehaviourIdColumn});
    const auto w = weight_columns(in.header());
    std::set<std::string> seen;
    while (in.next()) {
      const auto& f = in.fields();
      if (!seen.insert(f[cols[0]]).second) continue;  // rank 1 comes first in each search
      auto [text, params] = weights_of(f, in.header(), w);
      const std::string label = label_of(f[cols[0]]);
      add(f[cols[0]], f[cols[2]], PairedSide{label + "@best", "search " + f[cols[0]], label, params});
    }
  }
  if (std::filesystem::exists(dir + "/" + kSearchRanksFile)) {
    CsvReader in(dir + "/" + kSearchRanksFile);
    const auto cols = require_columns(in, {kSearchIdColumn, kBehaviourIdColumn});
    const auto w = weight_columns(in.header());
    while (in.next()) {
      const auto& f = in.fields();
      auto [text, params] = weights_of(f, in.header(), w);
      const std::string label = label_of(f[cols[0]]);
      std::string name = label;
      name.append("@").append(text);
      add(f[cols[0]], f[cols[1]], PairedSide{name, "search " + f[cols[0]], label, params});
    }
  }
  return wanted;
}

/// The exact weight searches of `dir` as sources, one group each (none without searches.json).
std::vector<Source> read_search_sources(const std::string& dir, PairedTable& table) {
  std::vector<Source> sources;
  if (!std::filesystem::exists(dir + "/" + kSearchesFile)) return sources;
  const std::vector<SearchInfo> searches = read_searches_json(dir + "/" + kSearchesFile);
  const auto wanted = add_search_sides(dir, searches, table, sources);
  for (std::size_t k = 0; k < searches.size(); ++k) {
    sources[k].groups.push_back(Group{searches[k].map_class, {}, searches[k].energy_unit, {}, {}});
    if (searches[k].mode != "all") {
      table.notes.push_back(
          "search " + searches[k].id + " (" + searches[k].label + ") ran in mode '" + searches[k].mode +
          "': its files hold only the optimal behaviours, so it has nothing "
          "to compare; mode all with a \"rank\" list compares those vectors with the optimum");
    }
  }
  CsvReader in(dir + "/" + kBehavioursFile);
  const auto cols = require_columns(
      in, {kSearchIdColumn, kBehaviourIdColumn, kInstanceColumn, kMapColumn, kEndReasonColumn});
  std::vector<int> metric_columns;
  for (const auto& m : table.metrics) metric_columns.push_back(in.column(m));
  while (in.next()) {
    const auto& f = in.fields();
    const auto search = wanted.find(f[cols[0]]);
    if (search == wanted.end()) continue;
    const auto behaviour = search->second.find(f[cols[1]]);
    if (behaviour == search->second.end()) continue;
    const auto k =
        static_cast<std::size_t>(std::find_if(searches.begin(), searches.end(),
                                              [&](const SearchInfo& s) { return s.id == f[cols[0]]; }) -
                                 searches.begin());
    for (const std::size_t side : behaviour->second) {
      SideRun run{f[cols[4]], metric_values(f, metric_columns, table.metrics, in)};
      (void)add_run(sources[k].groups[0], f[cols[2]], f[cols[3]], side, std::move(run));
    }
  }
  return sources;
}

/// True when `a` and `b` are equal within kTieRelative.
bool tie(double a, double b) { return std::abs(a - b) <= kTieRelative * std::max(std::abs(a), std::abs(b)); }

/// The median of `values` (sorted here), NaN for none.
double median(std::vector<double> values) {
  if (values.empty()) return kNoValue;
  std::sort(values.begin(), values.end());
  return quantile_sorted(values, 0.5);
}

/// What a row is computed from: one group, one metric, the side and its baseline.
struct RowInput {
  const Source& source;
  const Group& group;
  std::size_t metric;
  std::size_t side;
  std::size_t baseline;
};

/// The counts, differences and per-instance clusters of a row's pairs.
struct Pairs {
  std::vector<double> diffs;
  std::vector<double> tested;  ///< the differences the signed-rank test sees: near-ties as 0
  std::vector<double> rel_pct;
  std::vector<std::vector<double>> clusters;  ///< differences per map instance
};

Pairs collect_pairs(const RowInput& in, Direction direction, PairedRow& row) {
  Pairs p;
  std::unordered_map<std::string, std::size_t> cluster_of;
  for (const PairSlot& slot : in.group.slots) {
    const auto s = slot.sides.find(in.side);
    const auto b = slot.sides.find(in.baseline);
    if (s == slot.sides.end() || b == slot.sides.end()) {
      row.unpaired +=
          static_cast<std::size_t>(s != slot.sides.end()) + static_cast<std::size_t>(b != slot.sides.end());
      continue;
    }
    const double x = s->second.values[in.metric];
    const double y = b->second.values[in.metric];
    if (s->second.end != b->second.end) {
      ++row.mixed_end;
    } else if (!std::isfinite(x) || !std::isfinite(y)) {
      ++row.no_value;
    } else {
      const double d = x - y;
      p.diffs.push_back(d);
      p.tested.push_back(tie(x, y) ? 0.0 : d);
      if (y != 0.0 || x == 0.0) p.rel_pct.push_back(y == 0.0 ? 0.0 : 100.0 * d / std::abs(y));
      const bool better = direction == Direction::Minimize ? x < y : x > y;
      (tie(x, y) ? row.ties : better ? row.wins : row.losses) += 1;
      auto [c, added] = cluster_of.try_emplace(slot.instance, p.clusters.size());
      if (added) p.clusters.emplace_back();
      p.clusters[c->second].push_back(d);
    }
  }
  return p;
}

PairedRow compute_row(const RowInput& in, const PairedTable& table, const PairedOptions& o) {
  PairedRow row;
  row.source = in.source.name;
  row.map_class = in.group.map_class;
  row.variant = in.group.variant;
  row.side = table.sides[in.side].name;
  row.baseline = table.sides[in.baseline].name;
  row.metric = table.metrics[in.metric];
  row.unit = row.metric == "energy" ? in.group.energy_unit : std::string(metric_unit(row.metric));
  const Pairs p = collect_pairs(in, metric_direction(row.metric), row);
  row.n_pairs = p.diffs.size();
  row.instances = p.clusters.size();
  row.mean_diff = row.median_diff = row.rel_diff_pct = kNoValue;
  if (p.diffs.empty()) return row;
  double sum = 0.0;
  for (const double d : p.diffs) sum += d;
  row.mean_diff = sum / static_cast<double>(p.diffs.size());
  row.median_diff = median(p.diffs);
  row.rel_diff_pct = median(p.rel_pct);
  row.wilcoxon = wilcoxon_signed_rank(p.tested);
  std::string identity = row.source + '\x1f' + row.map_class;
  for (const auto& v : row.variant) identity += '\x1f' + v;
  Rng rng = make_rng(o.seed, "paired" + identity + '\x1f' + row.side + '\x1f' + row.metric);
  row.ci = cluster_bootstrap_mean(p.clusters, o.resamples, kPairedLevel, rng);
  return row;
}

/// The rows of one source against `baseline`, Holm-adjusted per group and metric.
void compare_source(const Source& source, std::size_t baseline, PairedTable& table, const PairedOptions& o) {
  for (const Group& group : source.groups) {
    for (std::size_t m = 0; m < table.metrics.size(); ++m) {
      const std::size_t first = table.rows.size();
      for (const std::size_t side : source.sides) {
        if (side != baseline)
          table.rows.push_back(compute_row(RowInput{source, group, m, side, baseline}, table, o));
      }
      std::vector<std::optional<double>> p;
      for (std::size_t r = first; r < table.rows.size(); ++r) {
        const auto& w = table.rows[r].wilcoxon;
        p.push_back(w ? std::optional<double>(w->p_value) : std::nullopt);
      }
      const auto adjusted = holm_adjust(p);
      for (std::size_t r = first; r < table.rows.size(); ++r) table.rows[r].p_holm = adjusted[r - first];
    }
  }
}

/// The side named `name`: a side's name, or a label with one side. Throws ConfigError at `where`
/// listing the sides (or the label's) otherwise.
std::size_t find_side(const PairedTable& table, const std::string& name, const std::string& where) {
  for (std::size_t s = 0; s < table.sides.size(); ++s) {
    if (table.sides[s].name == name) return s;
  }
  std::vector<std::string> of_label, all;
  for (const PairedSide& side : table.sides) {
    all.push_back(side.name);
    if (side.label == name) of_label.push_back(side.name);
  }
  if (!of_label.empty()) {
    throw ConfigError(where, "label '" + name + "' holds " + std::to_string(of_label.size()) +
                                 " strategy configurations; name one: " + join_names(of_label));
  }
  throw ConfigError(where, "no side '" + name + "' in the results; sides: " + join_names(all));
}

/// The baseline when none is asked for: the sweep's "baseline", else its first strategy entry's
/// label (`<label>@best` for a search); where it came from for messages.
std::pair<std::string, std::string> default_baseline(const std::string& dir) {
  const std::string path = dir + "/manifest.json";
  const auto text = read_file(path);
  if (!text) throw ConfigError(path, "cannot read the file (not a sweep result directory?)");
  const nlohmann::json m = parse_json_bounded(*text, path);
  const nlohmann::json sweep = m.is_object() ? m.value("sweep", nlohmann::json()) : nlohmann::json();
  if (sweep.is_object() && sweep.contains("baseline") && sweep["baseline"].is_string())
    return {sweep["baseline"].get<std::string>(), path + ": /sweep/baseline"};
  if (sweep.is_object() && sweep.contains("strategies") && sweep["strategies"].is_array() &&
      !sweep["strategies"].empty() && sweep["strategies"][0].is_object()) {
    const nlohmann::json& e = sweep["strategies"][0];
    const std::string label = e.contains("label") && e["label"].is_string() ? e["label"].get<std::string>()
                                                                            : e.value("name", std::string());
    return {e.contains("search") ? label + "@best" : label, path + ": /sweep/strategies/0"};
  }
  throw ConfigError("--baseline", "not given, and " + path + " names no strategy; give --baseline LABEL");
}

}  // namespace
PairedTable paired_comparison(const std::string& dir, const PairedOptions& options) {
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) throw ConfigError(dir, "not a directory");
  const std::string runs = dir + "/runs.csv";
  if (!std::filesystem::exists(runs, ec)) {
    throw ConfigError(runs,
                      "not found: not a sweep result directory (fsweep run writes it; shards are joined "
                      "first by fsweep merge)");
  }
  PairedTable table;
  table.dir = dir;
  std::vector<Source> sources;
  sources.push_back(read_runs_source(runs, table, options));
  for (Source& s : read_search_sources(dir, table)) sources.push_back(std::move(s));
  const auto [wanted, where] = options.baseline.empty()
                                   ? default_baseline(dir)
                                   : std::pair{options.baseline, std::string("--baseline")};
  const std::size_t baseline = find_side(table, wanted, where);
  table.baseline = table.sides[baseline].name;
  for (const Source& source : sources) {
    std::size_t b = baseline;
    if (std::find(source.sides.begin(), source.sides.end(), baseline) == source.sides.end()) {
      const auto own = std::find_if(source.sides.begin(), source.sides.end(), [&](std::size_t s) {
        return table.sides[s].name == source.default_baseline;
      });
      if (own == source.sides.end()) {
        if (!source.sides.empty()) {
          table.notes.push_back("the strategies of runs.csv are not compared: the baseline '" +
                                table.baseline +
                                "' is a weight search's; give one of runs.csv's to compare them");
        }
        continue;
      }
      b = *own;
    }
    if (source.sides.size() < 2) {
      table.notes.push_back((source.name == kRunsSource ? std::string("runs.csv") : source.name) +
                            " has one strategy configuration: nothing to compare it with");
      continue;
    }
    compare_source(source, b, table, options);
  }
  return table;
}

void write_paired(const std::string& out_dir, const PairedTable& table, const PairedOptions& options) {
  std::ostringstream csv;
  std::vector<std::string> header{"source", "map_class"};
  header.insert(header.end(), table.variant_columns.begin(), table.variant_columns.end());
  for (const char* c : {"label", "baseline", "metric", "n_pairs", "unpaired", "mixed_end", "no_value",
                        "instances", "mean_diff", "median_diff", "rel_diff_pct", "ci95_lo", "ci95_hi",
                        "wilcoxon_p", "wilcoxon_method", "wilcoxon_p_holm", "wins", "ties", "losses"})
    header.emplace_back(c);
  csv << csv_record(header) << '\n';
  for (const PairedRow& r : table.rows) {
    std::vector<std::string> f{r.source, r.map_class};
    for (std::size_t v = 0; v < table.variant_columns.size(); ++v)
      f.push_back(v < r.variant.size() ? r.variant[v] : "");
    const auto count = [](std::size_t n) { return std::to_string(n); };
    f.insert(f.end(),
             {r.side, r.baseline, r.metric, count(r.n_pairs), count(r.unpaired), count(r.mixed_end),
              count(r.no_value), count(r.instances), number_cell(r.mean_diff), number_cell(r.median_diff),
              number_cell(r.rel_diff_pct), r.ci ? number_cell(r.ci->lo) : "",
              r.ci ? number_cell(r.ci->hi) : "", r.wilcoxon ? number_cell(r.wilcoxon->p_value) : "",
              r.wilcoxon ? std::string(to_string(r.wilcoxon->method)) : "",
              r.p_holm ? number_cell(*r.p_holm) : "", count(r.wins), count(r.ties), count(r.losses)});
    csv << csv_record(f) << '\n';
  }
  nlohmann::json j;
  j["dir"] = table.dir;
  j["baseline"] = table.baseline;
  j["metrics"] = table.metrics;
  for (const auto& m : table.metrics)
    j["better"][m] = metric_direction(m) == Direction::Minimize ? "lower" : "higher";
  j["bootstrap"] = {{"resamples", options.resamples},
                    {"seed", options.seed},
                    {"level", kPairedLevel},
                    {"resampled", "map instances (the map column), each with all its pairs"},
                    {"interval", "percentile, type-7 quantiles"}};
  j["tie_relative"] = kTieRelative;
  j["wilcoxon"] =
      "two-sided signed-rank, as R's wilcox.test: exact below 50 pairs without zeros or ties, "
      "else normal with tie and continuity corrections; Holm over the sides of a group and metric";
  j["variant_columns"] = table.variant_columns;
  j["sides"] = nlohmann::json::array();
  for (const PairedSide& s : table.sides) {
    nlohmann::json params = nlohmann::json::object();
    for (const auto& [k, v] : s.params) params[k] = v;
    j["sides"].push_back({{"name", s.name}, {"source", s.source}, {"label", s.label}, {"params", params}});
  }
  j["notes"] = table.notes;
  nlohmann::json inputs = nlohmann::json::array();
  for (const char* f : {"runs.csv", "manifest.json", kBehavioursFile, kSearchRanksFile, kSearchBestFile}) {
    std::error_code ec;
    const auto bytes = std::filesystem::file_size(table.dir + "/" + f, ec);
    if (!ec) inputs.push_back({{"file", f}, {"bytes", bytes}});
  }
  j["inputs"] = inputs;
  write_file_atomically(out_dir + "/paired.csv", csv.str());
  write_file_atomically(out_dir + "/paired.json", j.dump(2) + "\n");
}

}  // namespace report
}  // namespace fsweep
