/// @file sweep_maps.cpp
/// The `maps` axis of a sweep: SPEC strings and JSON objects, "seeds" expansion, loading (relative
/// paths found by SweepPaths) and the canonical spec that run keys hash.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include "core/config_error.hpp"
#include "core/random.hpp"
#include "sweep/sweep_axes.hpp"
#include "world/map_spec.hpp"

namespace fsweep {
inline namespace sweep {
namespace sweep_detail {
namespace {

using nlohmann::json;

/// Canonical form for run keys: integral floats become integers, file paths are lexically
/// normal, so equal maps written differently hash alike.
json canonical(const json& j) {
  if (j.is_object()) {
    json out = json::object();
    for (const auto& [k, v] : j.items()) out[k] = canonical(v);
    if (out.contains("file") && out["file"].is_string()) {
      out["file"] = std::filesystem::path(out["file"].get<std::string>()).lexically_normal().generic_string();
    }
    return out;
  }
  if (j.is_array()) {
    json out = json::array();
    for (const auto& v : j) out.push_back(canonical(v));
    return out;
  }
  if (j.is_number_float()) {
    const double d = j.get<double>();
    if (d == std::floor(d) && std::abs(d) < 9.0e15) {
      return d >= 0 ? json(static_cast<std::uint64_t>(d)) : json(static_cast<std::int64_t>(d));
    }
  }
  return j;
}

/// An object map source written as a SPEC string, for labels: "rooms:door=3,h=80,w=120".
std::string spec_text(const json& obj) {
  std::string head =
      obj.contains("generator") ? obj["generator"].dump() : obj.value("file", json("?")).dump();
  if (head.size() >= 2 && head.front() == '"') head = head.substr(1, head.size() - 2);
  std::string options;
  for (const auto& [k, v] : obj.items()) {
    if (k == "generator" || k == "file") continue;
    std::string text;
    if (v.is_string()) {
      text = v.get<std::string>();
    } else if (v.is_array()) {
      for (const auto& e : v) text += (text.empty() ? "" : ";") + e.dump();
    } else {
      text = v.dump();
    }
    options.append(options.empty() ? "" : ",").append(k).append("=").append(text);
  }
  return options.empty() ? head : head + ":" + options;
}

/// The seeds of a map item (null when it has none); problems at `where`/seeds.
std::vector<std::uint64_t> parse_seeds(const json& item, const std::string& where,
                                       std::vector<std::string>& problems) {
  std::vector<std::uint64_t> seeds;
  const std::vector<json> values = expand_values(item.at("seeds"), where + "/seeds", problems);
  for (std::size_t k = 0; k < values.size(); ++k) {
    const json& v = values[k];
    if (!v.is_number_unsigned() && !(v.is_number_integer() && v.get<std::int64_t>() >= 0)) {
      problems.push_back(value_path(item.at("seeds"), where + "/seeds", k) + ": seed " + value_text(v) +
                         " not allowed; allowed: integers >= 0");
      return {};
    }
    seeds.push_back(v.get<std::uint64_t>());
  }
  return seeds;
}

/// The regions a random start draws from (SweepMap::start_regions).
std::shared_ptr<const std::array<Grid<std::uint8_t>, 2>> start_regions_of(const WorldMap& map) {
  return std::make_shared<const std::array<Grid<std::uint8_t>, 2>>(
      std::array<Grid<std::uint8_t>, 2>{largest_free_region(map, false), largest_free_region(map, true)});
}

/// Puts a loaded map into `m`: the map, its content hash and, for a random start, its regions.
/// `opened` is the file read for `written` (a path as the sweep gives it): the map's source
/// (runs.csv's `map` column, the manifest) names the path as written.
void take_loaded(SweepMap& m, RunMap loaded, const std::string& opened = {},
                 const std::string& written = {}) {
  if (!opened.empty() && loaded.map.source == opened) loaded.map.source = written;
  if (loaded.random_start) m.start_regions = start_regions_of(loaded.map);
  m.content_hash = hex64(content_hash(loaded.map));
  m.map = std::make_shared<const WorldMap>(std::move(loaded.map));
}

/// Keys of a dataset item (besides `dataset`).
const std::vector<std::string>& dataset_keys() {
  static const std::vector<std::string> kKeys{"ids",   "sample",     "sample_seed", "res",
                                              "start", "on_bad_map", "label",       "competitive"};
  return kKeys;
}

/// A map item's `competitive` (sweep_plan.hpp): its value, else `otherwise` (the sweep's); a value
/// that is not a boolean is a problem.
bool item_competitive(const json& item, const std::string& where, bool otherwise,
                      std::vector<std::string>& problems) {
  if (!item.is_object() || !item.contains("competitive")) return otherwise;
  const json& v = item.at("competitive");
  if (!v.is_boolean()) {
    problems.push_back(where + "/competitive: value " + value_text(v) +
                       " not allowed; allowed: true (compute the offline optimum of the item's maps: the "
                       "optimum_* and competitive_ratio_min/max columns) or false");
    return otherwise;
  }
  return v.get<bool>();
}

/// A plan of a dataset: its file as the sweep names it (the dataset folder as written, then the
/// plan's name) and the path to open.
struct DatasetPlan {
  std::string file;
  std::string opened;
};

/// A dataset item's plan files: `<dataset>/<id>.json` for each id of the `ids` file (blank
/// lines and surrounding spaces ignored), else every `*.json` of the folder in name order; then
/// a seeded sample of `sample` of them, kept in list order. Problems at `where`.
std::vector<DatasetPlan> dataset_plans(const json& item, const std::string& where, SweepPaths& paths,
                                       std::vector<std::string>& problems) {
  namespace fs = std::filesystem;
  const json& dir_json = item.at("dataset");
  if (!dir_json.is_string() || dir_json.get<std::string>().empty()) {
    problems.push_back(where + "/dataset: expected a folder path, got " + value_text(dir_json));
    return {};
  }
  const fs::path dir = dir_json.get<std::string>();
  const std::optional<std::string> opened_dir =
      paths.resolve(dir.string(), SweepPaths::Kind::Folder, where + "/dataset", problems);
  if (!opened_dir) return {};
  std::error_code ec;
  if (!fs::is_directory(*opened_dir, ec)) {
    problems.push_back(where + "/dataset: '" + dir.string() + "' is not a folder (a HouseExpo json folder)");
    return {};
  }
  // Plans by their names inside the folder (an id may hold a '/').
  std::vector<std::string> names;
  if (item.contains("ids")) {
    const json& ids = item.at("ids");
    const std::optional<std::string> list =
        ids.is_string()
            ? paths.resolve(ids.get<std::string>(), SweepPaths::Kind::File, where + "/ids", problems)
            : std::optional<std::string>(std::string());
    if (!list) return {};
    std::ifstream in(*list);
    if (!ids.is_string() || !in) {
      problems.push_back(where + "/ids: cannot read the id list " + value_text(ids) +
                         "; allowed: a text file with one plan id per line (HouseExpo's map_id_*.txt)");
      return {};
    }
    std::string line;
    while (std::getline(in, line)) {
      const std::size_t begin = line.find_first_not_of(" \t\r");
      if (begin == std::string::npos) continue;
      names.push_back(line.substr(begin, line.find_last_not_of(" \t\r") - begin + 1) + ".json");
    }
  } else {
    for (const auto& entry : fs::directory_iterator(*opened_dir, ec)) {
      if (entry.path().extension() == ".json") names.push_back(entry.path().filename().string());
    }
  }
  std::vector<DatasetPlan> plans;
  plans.reserve(names.size());
  for (const std::string& name : names) {
    plans.push_back(DatasetPlan{(dir / name).lexically_normal().generic_string(),
                                (fs::path(*opened_dir) / name).string()});
  }
  if (!item.contains("ids")) {
    std::sort(plans.begin(), plans.end(),
              [](const DatasetPlan& a, const DatasetPlan& b) { return a.file < b.file; });
  }
  if (plans.empty()) {
    problems.push_back(
        where + ": the dataset has no plans" +
        (item.contains("ids") ? std::string(" (the id list is empty)") : " (no .json file in the folder)"));
    return {};
  }
  if (!item.contains("sample")) return plans;
  const json& sample = item.at("sample");
  if (!sample.is_number_integer() || sample.get<std::int64_t>() < 1 ||
      sample.get<std::uint64_t>() > plans.size()) {
    problems.push_back(where + "/sample: " + value_text(sample) +
                       " not allowed; allowed: an integer from 1 to " + std::to_string(plans.size()) +
                       " (the dataset's plans)");
    return {};
  }
  std::uint64_t seed = 0;
  if (item.contains("sample_seed")) {
    const json& v = item.at("sample_seed");
    if (!v.is_number_unsigned() && !(v.is_number_integer() && v.get<std::int64_t>() >= 0)) {
      problems.push_back(where + "/sample_seed: " + value_text(item.at("sample_seed")) +
                         " not allowed; allowed: an integer >= 0");
      return {};
    }
    seed = item.at("sample_seed").get<std::uint64_t>();
  }
  // The first `sample` positions of a Fisher-Yates shuffle (stream "dataset/sample"), sorted.
  std::vector<std::size_t> order(plans.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  Rng rng = make_rng(seed, "dataset/sample");
  const auto n = static_cast<std::size_t>(sample.get<std::uint64_t>());
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = i + static_cast<std::size_t>(uniform_below(rng, order.size() - i));
    std::swap(order[i], order[j]);
  }
  order.resize(n);
  std::sort(order.begin(), order.end());
  std::vector<DatasetPlan> chosen;
  chosen.reserve(n);
  for (const std::size_t i : order) chosen.push_back(plans[i]);
  return chosen;
}

/// A dataset item (sweep_plan.hpp, "maps"): one map class of HouseExpo plans. Appends its maps
/// to `out`; plans that fail to load are problems, or skipped with `"on_bad_map": "skip"`.
void parse_dataset(const json& item, const std::string& where, SweepPaths& paths, std::vector<SweepMap>& out,
                   std::vector<std::string>& problems, std::vector<SkippedMap>& skipped, bool competitive) {
  const std::size_t before = problems.size();
  competitive = item_competitive(item, where, competitive, problems);
  for (const auto& [key, value] : item.items()) {
    if (key != "dataset" &&
        std::find(dataset_keys().begin(), dataset_keys().end(), key) == dataset_keys().end()) {
      std::string allowed;
      for (const std::string& k : dataset_keys()) allowed += (allowed.empty() ? "" : ", ") + k;
      problems.push_back(
          concat({where, "/", key, ": unknown key for a dataset (HouseExpo plans); allowed: dataset, ",
                  allowed, key == "seeds" ? " (seeds apply to generated maps only)" : ""}));
    }
  }
  bool skip = false;
  if (item.contains("on_bad_map")) {
    const json& v = item.at("on_bad_map");
    skip = v == "skip";
    if (!skip && v != "refuse") {
      problems.push_back(where + "/on_bad_map: " + value_text(v) +
                         " not allowed; allowed: \"refuse\" (the "
                         "default: the sweep does not start), \"skip\"");
    }
  }
  std::string label;
  if (item.contains("label")) {
    if (item.at("label").is_string()) {
      label = item.at("label").get<std::string>();
    } else {
      problems.push_back(where + "/label: expected a string, got " + value_text(item.at("label")));
    }
  }
  const std::vector<DatasetPlan> plans = dataset_plans(item, where, paths, problems);
  if (problems.size() != before) return;
  json options = json::object();  // what every plan's source gets besides its file
  for (const char* key : {"res", "start"}) {
    if (item.contains(key)) options[key] = item.at(key);
  }
  const std::string map_class =
      !label.empty() ? label
                     : "dataset " + item.at("dataset").get<std::string>() +
                           (item.contains("sample") ? " sample=" + item.at("sample").dump() : "");
  std::size_t bad = 0;
  constexpr std::size_t kListedBadPlans = 20;
  for (const auto& [file, opened] : plans) {
    json source = options;
    source["file"] = file;
    json opened_source = options;
    opened_source["file"] = opened;
    SweepMap m;
    try {
      take_loaded(m, load_run_map_json(opened_source, where), opened, file);
    } catch (const ConfigError& e) {
      const std::string reason = strip_path(e.what(), where);
      if (skip) {
        skipped.push_back(SkippedMap{where, file, reason});
      } else if (++bad <= kListedBadPlans) {
        problems.push_back(concat({where, ": plan ", file, " does not load: ", reason,
                                   " (or give \"on_bad_map\": \"skip\" to leave it out)"}));
      }
      continue;
    }
    m.spec = canonical(source);
    m.competitive = competitive;
    m.map_class = map_class;
    m.label = spec_text(source);
    out.push_back(std::move(m));
  }
  if (bad > kListedBadPlans) {
    problems.push_back(where + ": " + std::to_string(bad - kListedBadPlans) + " more plans do not load");
  }
  if (problems.size() == before && out.empty()) {
    problems.push_back(where + ": every plan of the dataset was skipped; allowed: at least one that loads");
  }
}

}  // namespace

SweepPaths::SweepPaths(const std::string& sweep_file)
    : folder_(std::filesystem::path(sweep_file).parent_path()) {
  std::error_code ec;
  folder_is_cwd_ =
      folder_.empty() || std::filesystem::equivalent(folder_, std::filesystem::current_path(ec), ec);
}

std::optional<std::string> SweepPaths::resolve(const std::string& written, Kind kind,
                                               const std::string& where, std::vector<std::string>& problems) {
  namespace fs = std::filesystem;
  const fs::path path(written);
  if (written.empty() || path.is_absolute()) return written;
  const auto there = [kind](const fs::path& p) {
    std::error_code ec;
    return kind == Kind::Folder ? fs::is_directory(p, ec) : fs::exists(p, ec) && !fs::is_directory(p, ec);
  };
  const auto absolute = [](const fs::path& p) {
    std::error_code ec;
    return fs::absolute(p, ec).lexically_normal().string();
  };
  const std::string what = kind == Kind::Folder ? "folder" : "file";
  if (folder_is_cwd_) {
    if (there(path)) return written;
    problems.push_back(concat({where, ": no such ", what, " '", written, "' (tried ", absolute(path), ")"}));
    return std::nullopt;
  }
  const fs::path beside = folder_ / path;
  if (there(beside)) return beside.string();
  if (there(path)) {
    const std::string relative =
        fs::path(absolute(path)).lexically_relative(absolute(folder_)).generic_string();
    warnings_.push_back(
        concat({where, ": '", written, "' is not beside the sweep file (no ", absolute(beside),
                "); read from the working directory instead (", absolute(path),
                "), which is tried when a relative path is not beside the sweep file",
                relative.empty() ? "" : "; write '", relative, relative.empty() ? "" : "'"}));
    return written;
  }
  problems.push_back(
      concat({where, ": no such ", what, " '", written, "': tried ", absolute(beside),
              " (beside the sweep file) and ", absolute(path), " (in the working directory)"}));
  return std::nullopt;
}

namespace {

/// A map item of /maps (not a dataset), read: its source without label and seeds as an object,
/// its SPEC string (for SPEC strings and {"spec": ...}), label, seeds and file.
struct MapItem {
  std::string where;
  std::string spec_string;
  json base = json::object();
  std::string label;
  bool competitive = false;
  bool has_seeds = false;
  std::vector<std::uint64_t> seeds;
  /// A file: the path as written, and the one to open (the sweep file's folder first).
  std::string written;
  std::string opened;
};

/// Map item `item` at `where`, or nothing when it has problems (added to `problems`).
std::optional<MapItem> read_map_item(const json& item, const std::string& where, SweepPaths& paths,
                                     bool competitive, std::vector<std::string>& problems) {
  MapItem m;
  m.where = where;
  const std::size_t before = problems.size();
  m.competitive = item_competitive(item, where, competitive, problems);
  if (item.is_string()) {
    m.spec_string = item.get<std::string>();
  } else {
    for (const auto& [k, v] : item.items()) {
      if (k != "label" && k != "seeds" && k != "competitive") m.base[k] = v;
    }
    if (item.contains("label")) {
      if (item["label"].is_string()) {
        m.label = item["label"].get<std::string>();
      } else {
        problems.push_back(where + "/label: expected a string, got " + value_text(item["label"]));
      }
    }
    if (m.base.contains("spec")) {
      if (m.base.size() != 1) {
        problems.push_back(where +
                           ": with \"spec\" the only other keys allowed are label, seeds, competitive");
      } else if (!m.base["spec"].is_string()) {
        problems.push_back(where + "/spec: expected a SPEC string, got " + value_text(m.base["spec"]));
      } else {
        m.spec_string = m.base["spec"].get<std::string>();
      }
    }
  }
  if (!m.spec_string.empty()) {
    try {
      m.base = map_spec_object(m.spec_string);
    } catch (const ConfigError& e) {
      problems.push_back(where + ": " + e.what());
      return std::nullopt;
    }
  }
  // Seeds: one map per seed, generators only.
  m.has_seeds = item.is_object() && item.contains("seeds");
  if (m.has_seeds) {
    if (!m.base.contains("generator")) {
      problems.push_back(where + "/seeds: seeds apply to generated maps only; this map is a file");
    } else if (m.base.contains("seed")) {
      problems.push_back(where + "/seeds: give either 'seed' or 'seeds', not both");
    } else {
      m.seeds = parse_seeds(item, where, problems);
    }
  }
  if (m.base.contains("file") && m.base["file"].is_string() && !m.base["file"].get<std::string>().empty()) {
    m.written = m.base["file"].get<std::string>();
    m.opened = paths
                   .resolve(m.written, SweepPaths::Kind::File,
                            m.spec_string.empty() ? where + "/file" : where, problems)
                   .value_or(m.written);
  }
  if (problems.size() != before) return std::nullopt;
  return m;
}

/// The map of `item`'s seed `k` (its only map without seeds), loaded; a problem and nothing when
/// it fails to load or is a free map with random starts.
std::optional<SweepMap> load_instance(const MapItem& item, std::size_t k,
                                      std::vector<std::string>& problems) {
  json source = item.base;
  std::string spec_k = item.spec_string;
  if (item.has_seeds) {
    source["seed"] = item.seeds[k];
    if (!spec_k.empty())
      spec_k += (spec_k.find(':') == std::string::npos ? ":seed=" : ",seed=") + std::to_string(item.seeds[k]);
  }
  // What is opened: the spec or source with the file found for the one written (a spec names
  // it up to its first ':', so a path holding one goes as the JSON source).
  json opened_source = source;
  if (item.opened != item.written) opened_source["file"] = item.opened;
  std::string opened_spec = spec_k;
  if (item.opened != item.written && !spec_k.empty()) {
    opened_spec = item.opened.find(':') == std::string::npos
                      ? item.opened + spec_k.substr(item.written.size())
                      : std::string();
  }
  SweepMap m;
  try {
    take_loaded(
        m,
        opened_spec.empty() ? load_run_map_json(opened_source, item.where) : load_run_map_spec(opened_spec),
        item.opened, item.written);
  } catch (const ConfigError& e) {
    const std::string what = e.what();
    const std::string seed_note = item.has_seeds ? " (seed " + std::to_string(item.seeds[k]) + ")" : "";
    // NOLINTNEXTLINE(performance-inefficient-string-concatenation): once per failing map
    problems.push_back(what.rfind(item.where, 0) == 0 ? what + seed_note
                                                      : item.where + ": " + what + seed_note);
    return std::nullopt;
  }
  m.spec = canonical(source);
  m.competitive = item.competitive;
  m.free_space = source.value("generator", json("")) == "free";
  if (m.free_space && m.start_regions) {
    problems.push_back(item.where +
                       "/start: \"random\" is not allowed on a free map: its optimum (the star "
                       "pattern) is computed from the map's start; allowed: a cell x;y");
    return std::nullopt;
  }
  m.map_class =
      !item.label.empty() ? item.label : (item.spec_string.empty() ? spec_text(item.base) : item.spec_string);
  if (!item.label.empty()) {
    m.label = item.has_seeds ? item.label + " seed=" + std::to_string(item.seeds[k]) : item.label;
  } else {
    m.label = spec_k.empty() ? spec_text(source) : spec_k;
  }
  return m;
}

}  // namespace

std::vector<SweepMap> parse_maps(const json& maps, SweepPaths& paths, std::vector<std::string>& problems,
                                 std::vector<SkippedMap>& skipped, bool competitive) {
  std::vector<SweepMap> out;
  if (!maps.is_array() || maps.empty()) {
    problems.push_back("/maps: expected a non-empty list of maps (SPEC strings or objects), got " +
                       value_text(maps));
    return out;
  }
  std::map<std::string, std::string> seen;  // canonical spec -> its path, for duplicates
  for (std::size_t i = 0; i < maps.size(); ++i) {
    const std::string where = "/maps/" + std::to_string(i);
    const json& item = maps[i];
    if (!item.is_string() && !item.is_object()) {
      problems.push_back(where + ": expected a SPEC string or an object, got " + value_text(item));
      continue;
    }
    if (item.is_object() && item.contains("dataset")) {
      const std::size_t first = out.size();
      parse_dataset(item, where, paths, out, problems, skipped, competitive);
      for (std::size_t k = first; k < out.size(); ++k) {
        if (!seen.emplace(out[k].spec.dump(), where).second) {
          problems.push_back(where + ": plan " + out[k].label +
                             " is listed twice or also elsewhere in /maps; " +
                             "allowed: each map once (repeated maps would be the same runs)");
          break;
        }
      }
      continue;
    }
    const std::optional<MapItem> read = read_map_item(item, where, paths, competitive, problems);
    if (!read) continue;
    // One problem per item (its first failing seed).
    for (std::size_t k = 0; k < (read->has_seeds ? read->seeds.size() : 1); ++k) {
      std::optional<SweepMap> m = load_instance(*read, k, problems);
      if (!m) break;
      const std::string key = m->spec.dump();
      if (const auto it = seen.find(key); it != seen.end()) {
        problems.push_back(where + ": the same map as " + it->second + " (" + m->label +
                           "); allowed: each map once (repeated maps would be the same runs)");
        break;
      }
      seen.emplace(key, where);
      out.push_back(std::move(*m));
    }
  }
  return out;
}

}  // namespace sweep_detail
}  // namespace sweep
}  // namespace fsweep
