/// @file sweep_maps.cpp
/// The `maps` axis of a sweep: SPEC strings and JSON objects, "seeds" expansion, loading and
/// the canonical spec that run keys hash.

#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <map>

#include "core/config_error.hpp"
#include "sweep/sweep_axes.hpp"
#include "world/map_spec.hpp"

namespace fsweep {
inline namespace sweep {
namespace sweep_detail {
namespace {

using nlohmann::json;

/// A spec option's value as map_spec.cpp reads it: an integer, a number, true/false, or text.
json parse_option_value(const std::string& text) {
  const char* begin = text.data();
  const char* end = text.data() + text.size();
  std::uint64_t as_uint = 0;
  if (auto r = std::from_chars(begin, end, as_uint); r.ec == std::errc() && r.ptr == end) return as_uint;
  std::int64_t as_int = 0;
  if (auto r = std::from_chars(begin, end, as_int); r.ec == std::errc() && r.ptr == end) return as_int;
  double as_double = 0.0;
  if (auto r = std::from_chars(begin, end, as_double); r.ec == std::errc() && r.ptr == end) return as_double;
  if (text == "true") return true;
  if (text == "false") return false;
  return text;
}

/// The JSON object form of a SPEC string (map_spec.hpp), for run keys only: loading goes
/// through load_map_spec, which reports malformed specs.
json spec_to_object(const std::string& spec) {
  const std::size_t colon = spec.find(':');
  const std::string head = spec.substr(0, colon);
  json j = json::object();
  j[head.find_first_of("./") != std::string::npos ? "file" : "generator"] = head;
  if (colon == std::string::npos) return j;
  std::size_t begin = colon + 1;
  while (begin <= spec.size()) {
    const std::size_t comma = std::min(spec.find(',', begin), spec.size());
    const std::string option = spec.substr(begin, comma - begin);
    const std::size_t eq = option.find('=');
    if (eq != std::string::npos) j[option.substr(0, eq)] = parse_option_value(option.substr(eq + 1));
    begin = comma + 1;
  }
  return j;
}

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

}  // namespace

std::vector<SweepMap> parse_maps(const json& maps, std::vector<std::string>& problems) {
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
    // 1. The source without label and seeds, as an object; and the label.
    std::string spec_string;  // non-empty for SPEC strings and {"spec": ...}
    json base = json::object();
    std::string label;
    const std::size_t before = problems.size();
    if (item.is_string()) {
      spec_string = item.get<std::string>();
    } else {
      for (const auto& [k, v] : item.items()) {
        if (k != "label" && k != "seeds") base[k] = v;
      }
      if (item.contains("label")) {
        if (item["label"].is_string()) {
          label = item["label"].get<std::string>();
        } else {
          problems.push_back(where + "/label: expected a string, got " + value_text(item["label"]));
        }
      }
      if (base.contains("spec")) {
        if (base.size() != 1) {
          problems.push_back(where + ": with \"spec\" the only other keys allowed are label, seeds");
        } else if (!base["spec"].is_string()) {
          problems.push_back(where + "/spec: expected a SPEC string, got " + value_text(base["spec"]));
        } else {
          spec_string = base["spec"].get<std::string>();
        }
      }
    }
    if (!spec_string.empty()) base = spec_to_object(spec_string);

    // 2. Seeds: one map per seed, generators only.
    std::vector<std::uint64_t> seeds;
    const bool has_seeds = item.is_object() && item.contains("seeds");
    if (has_seeds) {
      if (!base.contains("generator")) {
        problems.push_back(where + "/seeds: seeds apply to generated maps only; this map is a file");
      } else if (base.contains("seed")) {
        problems.push_back(where + "/seeds: give either 'seed' or 'seeds', not both");
      } else {
        seeds = parse_seeds(item, where, problems);
      }
    }
    if (problems.size() != before) continue;

    // 3. Load each map; one problem per item (its first failing seed).
    const std::size_t n = has_seeds ? seeds.size() : 1;
    for (std::size_t k = 0; k < n; ++k) {
      json source = base;
      std::string spec_k = spec_string;
      if (has_seeds) {
        source["seed"] = seeds[k];
        if (!spec_k.empty())
          spec_k += (spec_k.find(':') == std::string::npos ? ":seed=" : ",seed=") + std::to_string(seeds[k]);
      }
      SweepMap m;
      try {
        m.map = std::make_shared<const WorldMap>(spec_k.empty() ? load_map_json(source, where)
                                                                : load_map_spec(spec_k));
      } catch (const ConfigError& e) {
        const std::string what = e.what();
        const std::string seed_note = has_seeds ? " (seed " + std::to_string(seeds[k]) + ")" : "";
        // NOLINTNEXTLINE(performance-inefficient-string-concatenation): once per failing map, then break
        problems.push_back(what.rfind(where, 0) == 0 ? what + seed_note : where + ": " + what + seed_note);
        break;
      }
      m.spec = canonical(source);
      m.free_space = source.value("generator", json("")) == "free";
      m.map_class = !label.empty() ? label : (spec_string.empty() ? spec_text(base) : spec_string);
      if (!label.empty()) {
        m.label = has_seeds ? label + " seed=" + std::to_string(seeds[k]) : label;
      } else {
        m.label = spec_k.empty() ? spec_text(source) : spec_k;
      }
      const std::string key = m.spec.dump();
      if (const auto it = seen.find(key); it != seen.end()) {
        problems.push_back(where + ": the same map as " + it->second + " (" + m.label +
                           "); allowed: each map once (repeated maps would be the same runs)");
        break;
      }
      seen.emplace(key, where);
      out.push_back(std::move(m));
    }
  }
  return out;
}

}  // namespace sweep_detail
}  // namespace sweep
}  // namespace fsweep
