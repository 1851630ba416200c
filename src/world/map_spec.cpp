#include "world/map_spec.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>
#include <string_view>
#include <vector>

#include "core/config_error.hpp"
#include "core/json_excerpt.hpp"
#include "world/map_generators.hpp"
#include "world/map_loaders.hpp"

namespace fsweep {
inline namespace world {
namespace {

using nlohmann::json;

/// Where messages point: a JSON path (keys appended as `/key`) or a spec string (kept whole,
/// the key is named in the message).
struct Where {
  std::string base;
  bool json_path = false;
  [[nodiscard]] std::string key(const std::string& k) const { return json_path ? base + "/" + k : base; }
};

/// Map file formats by lower-case extension, and the keys each accepts besides `file`.
struct FileKind {
  const char* extension;
  std::vector<std::string> keys;
};
std::vector<FileKind> file_kinds() {
  return {{".map", {"res", "start"}},
          {".txt", {"res", "start"}},
          {".json", {"res", "start"}},
          {".yaml", {"start"}},
          {".yml", {"start"}},
          {".png", {"res", "start", "threshold", "mpp", "size"}},
          {".pgm", {"res", "start", "threshold", "mpp", "size"}}};
}

void require_keys(const json& j, const std::string& source_key, const std::vector<std::string>& allowed,
                  const std::string& what, const Where& where) {
  for (const auto& [key, value] : j.items()) {
    if (key != source_key && std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
      std::string message = "unknown key '" + key + "' for ";
      message += what;
      message += "; allowed: ";
      message += join_names(allowed);
      throw ConfigError(where.key(key), message);
    }
  }
}

int get_int(const json& j, const std::string& key, const Where& where) {
  const json& v = j.at(key);
  bool fits = false;
  if (v.is_number_unsigned()) {
    fits = v.get<std::uint64_t>() <= static_cast<std::uint64_t>(std::numeric_limits<int>::max());
  } else if (v.is_number_integer()) {
    fits = v.get<std::int64_t>() >= std::numeric_limits<int>::min() &&
           v.get<std::int64_t>() <= std::numeric_limits<int>::max();
  }
  if (!fits) throw ConfigError(where.key(key), "'" + key + "' must be an integer, got " + json_excerpt(v));
  return v.get<int>();
}

double get_number(const json& j, const std::string& key, const Where& where) {
  const json& v = j.at(key);
  if (!v.is_number())
    throw ConfigError(where.key(key), "'" + key + "' must be a number, got " + json_excerpt(v));
  return v.get<double>();
}

double get_positive(const json& j, const std::string& key, const Where& where) {
  const double v = get_number(j, key, where);
  if (!(v > 0.0) || !std::isfinite(v)) {
    throw ConfigError(where.key(key),
                      "'" + key + "' = " + json_excerpt(j.at(key)) + " is out of range; allowed: > 0");
  }
  return v;
}

/// Two numbers from [a, b] or from the string "a<sep>b".
std::pair<double, double> get_pair(const json& j, const std::string& key, char sep, const Where& where) {
  const json& v = j.at(key);
  const std::string expected =
      "'" + key + "' must be [a, b] or \"a" + std::string(1, sep) + "b\", got " + json_excerpt(v);
  if (v.is_array() && v.size() == 2 && v[0].is_number() && v[1].is_number()) {
    return {v[0].get<double>(), v[1].get<double>()};
  }
  if (v.is_string()) {
    const std::string s = v.get<std::string>();
    const std::size_t cut = s.find(sep);
    double a = 0.0;
    double b = 0.0;
    if (cut != std::string::npos) {
      const char* begin = s.data();
      const char* mid = s.data() + cut;
      const char* end = s.data() + s.size();
      const auto ra = std::from_chars(begin, mid, a);
      const auto rb = std::from_chars(mid + 1, end, b);
      if (ra.ec == std::errc() && ra.ptr == mid && rb.ec == std::errc() && rb.ptr == end) return {a, b};
    }
  }
  throw ConfigError(where.key(key), expected);
}

Cell get_start(const json& j, const Where& where) {
  const auto [x, y] = get_pair(j, "start", ';', where);
  if (x != std::floor(x) || y != std::floor(y) || x < 0 || y < 0 || x > 1e9 || y > 1e9) {
    throw ConfigError(where.key("start"), "start must be two non-negative integer cell coordinates, got " +
                                              json_excerpt(j.at("start")));
  }
  return Cell{static_cast<int>(x), static_cast<int>(y)};
}

WorldMap generate(const json& j, const Where& where) {
  const json& kind_json = j.at("generator");
  if (!kind_json.is_string()) {
    throw ConfigError(where.key("generator"), "'generator' must be a string naming a kind; allowed: " +
                                                  join_names(generator_kinds()));
  }
  GeneratorParams p;
  p.kind = kind_json.get<std::string>();
  const std::vector<std::string> kinds = generator_kinds();
  if (std::find(kinds.begin(), kinds.end(), p.kind) == kinds.end()) {
    throw ConfigError(where.key("generator"),
                      "unknown map kind '" + p.kind + "'; allowed generators: " + join_names(kinds) +
                          "; or a file ending in .map, .txt, .json, .yaml, .yml, .png, .pgm");
  }
  json params = j;
  params.erase("generator");
  // The declared keys of this kind (map_generators.hpp, generator_registry()); a spec string
  // names the key after the spec, a JSON object by its path.
  const auto configured = generator_registry().configure(
      p.kind, params, where.key("generator"),
      where.json_path ? where.base : where.base + " (generator '" + p.kind + "')");
  const std::optional<Cell> start = j.contains("start") ? parse_cell_pair(j.at("start")) : std::nullopt;
  WorldMap map;
  try {
    map = configured.make();
  } catch (const ConfigError& e) {
    throw ConfigError(where.base, e.what());
  }
  // generate_map names the map "<kind>:w=..,h=..,seed=.."; add every other option given, in key
  // order, so that maps differing only in, say, min_room have different names in the outputs.
  for (const auto& [key, value] : j.items()) {
    if (key == "generator" || key == "w" || key == "h" || key == "seed") continue;
    std::string text = value.is_string() ? value.get<std::string>() : value.dump();
    if (key == "start") {
      if (!start) continue;  // null: the default start
      text = std::to_string(start->x) + ";" + std::to_string(start->y);
    }
    map.source.append(",").append(key).append("=").append(text);
  }
  return map;
}

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

WorldMap load_file(const json& j, const Where& where) {
  const json& file_json = j.at("file");
  if (!file_json.is_string() || file_json.get<std::string>().empty()) {
    throw ConfigError(where.key("file"),
                      "'file' must be a non-empty path string, got " + json_excerpt(file_json));
  }
  const std::string path = file_json.get<std::string>();
  const std::string ext = lower_extension(path);
  const std::vector<FileKind> kinds = file_kinds();
  const auto kind =
      std::find_if(kinds.begin(), kinds.end(), [&](const FileKind& k) { return ext == k.extension; });
  if (kind == kinds.end()) {
    std::vector<std::string> names;
    names.reserve(kinds.size());
    for (const auto& k : kinds) names.emplace_back(k.extension);
    throw ConfigError(where.key("file"), "map file '" + path +
                                             "' has an unknown extension; allowed: " + join_names(names) +
                                             "; or a generator: " + join_names(generator_kinds()));
  }
  require_keys(j, "file", kind->keys, "a " + ext + " map file", where);
  const double res = j.contains("res") ? get_positive(j, "res", where) : 0.0;
  WorldMap map;
  try {
    if (ext == ".map") {
      map = load_movingai_map(path, res > 0.0 ? res : 1.0);
    } else if (ext == ".txt") {
      map = load_ascii_map(path, res > 0.0 ? res : 1.0);
    } else if (ext == ".json") {
      map = load_houseexpo(path, res > 0.0 ? res : kHouseExpoResolution);
    } else if (ext == ".yaml" || ext == ".yml") {
      map = load_ros_map(path);
    } else {
      // Bitmap: threshold 127 (Stage); scale from mpp or size, else one pixel = one cell of res
      // (default 1 m); res resamples (max-pooling) when a scale is given.
      int threshold = 127;
      if (j.contains("threshold")) threshold = get_int(j, "threshold", where);
      BitmapScale scale;
      if (j.contains("mpp") && j.contains("size")) {
        throw ConfigError(where.key("size"), "give either 'mpp' or 'size' for a bitmap, not both");
      }
      double cell_res = res;
      if (j.contains("mpp")) {
        scale.metres_per_pixel = get_positive(j, "mpp", where);
      } else if (j.contains("size")) {
        const auto [w, h] = get_pair(j, "size", 'x', where);
        if (!(w > 0.0) || !(h > 0.0)) {
          throw ConfigError(where.key("size"), "'size' must be two positive lengths in metres, got " +
                                                   json_excerpt(j.at("size")));
        }
        scale.width_m = w;
        scale.height_m = h;
      } else {
        scale.metres_per_pixel = res > 0.0 ? res : 1.0;
        cell_res = 0.0;
      }
      map = load_bitmap(path, scale, threshold, cell_res);
    }
  } catch (const ConfigError& e) {
    throw ConfigError(where.base, e.what());
  }
  if (j.contains("start")) {
    const Cell s = get_start(j, where);
    const std::string cell = "start cell (" + std::to_string(s.x) + ", " + std::to_string(s.y) + ")";
    if (!map.occupied.in_bounds(s)) {
      throw ConfigError(where.key("start"), cell + " is outside the " + std::to_string(map.width()) + "x" +
                                                std::to_string(map.height()) + " map " + path);
    }
    if (!map.is_free(s)) {
      throw ConfigError(where.key("start"), cell + " is occupied in " + path + "; choose a free cell");
    }
    map.start = s;
  }
  return map;
}

bool is_random_start(const json& j) {
  return j.is_object() && j.contains("start") && j.at("start").is_string() &&
         j.at("start").get<std::string>() == "random";
}

WorldMap build(const json& j, const Where& where) {
  if (is_random_start(j)) {
    throw ConfigError(
        where.key("start"),
        "start \"random\" is drawn per run, from the run seed; allowed here: a cell x;y (random "
        "starts are for sweeps and fsweep sim)");
  }
  if (!j.is_object()) {
    throw ConfigError(where.base,
                      "a map must be a JSON object with 'generator' or 'file', got " + json_excerpt(j));
  }
  const bool has_generator = j.contains("generator");
  const bool has_file = j.contains("file");
  if (has_generator == has_file) {
    throw ConfigError(where.base, "a map needs exactly one of 'generator' (" + join_names(generator_kinds()) +
                                      ") or 'file'");
  }
  return has_generator ? generate(j, where) : load_file(j, where);
}

RunMap build_run_map(const json& j, const Where& where) {
  RunMap out;
  if (is_random_start(j)) {
    json rest = j;
    rest.erase("start");
    out.map = build(rest, where);
    out.random_start = true;
  } else {
    out.map = build(j, where);
  }
  return out;
}

/// A spec option value: an integer, a number, true/false, or else the text itself.
json parse_value(const std::string& text) {
  const char* begin = text.data();
  const char* end = text.data() + text.size();
  long long as_int = 0;
  if (auto r = std::from_chars(begin, end, as_int); r.ec == std::errc() && r.ptr == end) {
    return as_int >= 0 ? json(static_cast<std::uint64_t>(as_int)) : json(as_int);
  }
  std::uint64_t as_uint = 0;
  if (auto r = std::from_chars(begin, end, as_uint); r.ec == std::errc() && r.ptr == end)
    return json(as_uint);
  double as_double = 0.0;
  if (auto r = std::from_chars(begin, end, as_double); r.ec == std::errc() && r.ptr == end)
    return json(as_double);
  if (text == "true") return json(true);
  if (text == "false") return json(false);
  return json(text);
}

/// The JSON object form of a SPEC string (options parsed as values), reporting malformed specs.
json spec_object(const std::string& spec, const Where& where) {
  // The source ends at the first ':'; file paths therefore must not contain ':'.
  const std::size_t colon = spec.find(':');
  const std::string head = spec.substr(0, colon);
  if (head.empty()) {
    throw ConfigError(where.base, "empty map source; allowed: a generator (" + join_names(generator_kinds()) +
                                      ") or a file path");
  }
  json j = json::object();
  const bool is_file = head.find('.') != std::string::npos || head.find('/') != std::string::npos;
  j[is_file ? "file" : "generator"] = head;
  if (colon != std::string::npos) {
    std::string_view rest(spec);
    rest.remove_prefix(colon + 1);
    std::set<std::string> seen;
    while (true) {
      const std::size_t comma = rest.find(',');
      const std::string option(rest.substr(0, comma));
      const std::size_t eq = option.find('=');
      if (eq == std::string::npos || eq == 0) {
        throw ConfigError(where.base,
                          "option '" + option + "' is not key=value (options are comma-separated)");
      }
      const std::string key = option.substr(0, eq);
      if (key == "file" || key == "generator" || !seen.insert(key).second) {
        throw ConfigError(where.base, "key '" + key + "' is repeated or reserved");
      }
      j[key] = parse_value(option.substr(eq + 1));
      if (comma == std::string_view::npos) break;
      rest.remove_prefix(comma + 1);
    }
  }
  return j;
}

Where spec_where(const std::string& spec) { return Where{"map spec '" + spec + "'", false}; }

}  // namespace

nlohmann::json map_spec_object(const std::string& spec) { return spec_object(spec, spec_where(spec)); }

WorldMap load_map_spec(const std::string& spec) {
  const Where where = spec_where(spec);
  return build(spec_object(spec, where), where);
}

WorldMap load_map_json(const nlohmann::json& j, const std::string& where) {
  return build(j, Where{where, true});
}

RunMap load_run_map_spec(const std::string& spec) {
  const Where where = spec_where(spec);
  return build_run_map(spec_object(spec, where), where);
}

RunMap load_run_map_json(const nlohmann::json& j, const std::string& where) {
  return build_run_map(j, Where{where, true});
}

}  // namespace world
}  // namespace fsweep
