/// @file sweep_axes.cpp
/// The `strategies`, `planners` and `robot` axes of a sweep (format in sweep_plan.hpp).

#include "sweep/sweep_axes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>

#include "core/config_error.hpp"
#include "core/csv_reader.hpp"
#include "core/json_excerpt.hpp"
#include "planners/registry.hpp"
#include "sim/heuristics.hpp"
#include "sim/run_spec.hpp"
#include "strategies/registry.hpp"
#include "strategies/strategy.hpp"
#include "weightsearch/weight_grid.hpp"

namespace fsweep {
inline namespace sweep {
namespace sweep_detail {
namespace {

using nlohmann::json;

/// One swept parameter or leaf: where it is written, how, and its values.
struct Axis {
  std::string name;   ///< parameter name, or JSON pointer inside the robot object
  std::string where;  ///< JSON path of the written value
  json written;       ///< the value as written (scalar, list or range)
  std::vector<json> values;
};

/// The message of the ConfigError `make` throws, or nothing when it succeeds.
std::optional<std::string> failure(const std::function<void()>& make) {
  try {
    make();
  } catch (const ConfigError& e) {
    return std::string(e.what());
  } catch (const std::exception& e) {  // a plugin reading a value of the wrong JSON type
    return std::string(e.what());
  }
  return std::nullopt;
}

/// One problem for an axis whose values `bad` (index, message) failed: all of them at the
/// axis' path, else the first at its own path, with how many more fail.
void report_axis(const Axis& axis, const std::vector<std::pair<std::size_t, std::string>>& bad,
                 std::vector<std::string>& problems) {
  if (bad.empty()) return;
  const auto& [k, message] = bad.front();
  std::string text = strip_path(message, axis.where);
  const std::string value = value_text(axis.values[k]);
  if (axis.values.size() > 1 && text.find(value) == std::string::npos) text = "value " + value + ": " + text;
  if (bad.size() == axis.values.size()) {
    if (bad.size() > 1) text += " (all " + std::to_string(bad.size()) + " values of this axis fail)";
    problems.push_back(axis.where + ": " + text);
  } else {
    if (bad.size() > 1) text += " (and " + std::to_string(bad.size() - 1) + " more values of this axis)";
    problems.push_back(value_path(axis.written, axis.where, k) + ": " + text);
  }
}

/// The declaration (sim/run_spec.hpp, robot_params()) of the robot parameter at the JSON
/// pointer `pointer` ("/sensor/range_m"); null for an undeclared key or one inside an energy
/// model (its keys depend on its preset).
const ParamSpec* robot_spec(const std::string& pointer) {
  const ParamSpecs* specs = &robot_params().specs();
  const ParamSpec* spec = nullptr;
  for (std::size_t at = 1; at <= pointer.size();) {
    const std::size_t end = std::min(pointer.find('/', at), pointer.size());
    std::string key;
    for (std::size_t i = at; i < end; ++i) {  // RFC 6901: "~1" is '/', "~0" is '~'
      const bool escaped = pointer[i] == '~' && i + 1 < end;
      key += escaped ? (pointer[i + 1] == '1' ? '/' : '~') : pointer[i];
      i += escaped ? 1 : 0;
    }
    if (specs == nullptr) return nullptr;
    const auto it =
        std::find_if(specs->begin(), specs->end(), [&](const ParamSpec& s) { return s.name == key; });
    if (it == specs->end()) return nullptr;
    spec = &*it;
    specs = spec->fields.get();
    at = end + 1;
  }
  return spec;
}

/// robot_spec(pointer) when it alone decides whether a value is allowed: not for an object (the
/// sensor) or an energy model.
const ParamSpec* robot_leaf_spec(const std::string& pointer) {
  const ParamSpec* spec = robot_spec(pointer);
  return spec != nullptr && !spec->nested_problems ? spec : nullptr;
}

/// Escapes a key for a JSON pointer (RFC 6901).
std::string pointer_token(const std::string& key) {
  std::string out;
  for (const char c : key) {
    if (c == '~') {
      out += "~0";
    } else if (c == '/') {
      out += "~1";
    } else {
      out += c;
    }
  }
  return out;
}

/// Robot fields whose values are arrays: there only a list of arrays is a sweep.
bool array_valued(const std::string& pointer) { return pointer == "/dock" || pointer == "/energy/per_turn"; }

/// The swept leaves of the robot object, depth-first in key order. Where the robot takes an
/// object (the sensor, an energy model: declared with nested problems), an object is that
/// object, not a range; a key the declaration of its object does not have is no axis (the
/// reader names it with the keys allowed: a misspelt "range_m" is not a sweep range).
void collect_robot_axes(const json& node, const std::string& pointer, std::vector<Axis>& axes,
                        std::vector<std::string>& problems) {
  const ParamSpec* declared = pointer.empty() ? nullptr : robot_spec(pointer);
  const ParamSpecs* fields = pointer.empty()       ? &robot_params().specs()
                             : declared != nullptr ? declared->fields.get()
                                                   : nullptr;
  for (const auto& [key, value] : node.items()) {
    const std::string child = pointer + "/" + pointer_token(key);
    if (fields != nullptr && std::none_of(fields->begin(), fields->end(),
                                          [&key = key](const ParamSpec& s) { return s.name == key; })) {
      continue;
    }
    const ParamSpec* spec = robot_spec(child);
    const bool takes_object = spec != nullptr && spec->nested_problems;
    const bool range = value.is_object() && value.contains("range") && !takes_object;
    if (value.is_object() && !range) {
      collect_robot_axes(value, child, axes, problems);
      continue;
    }
    if (array_valued(child) && value.is_array() &&
        (value.empty() ||
         !std::all_of(value.begin(), value.end(), [](const json& e) { return e.is_array(); }))) {
      continue;  // one array value
    }
    if (value.is_array() || range) {
      const std::string where = concat({"/robot", child});
      Axis a{child, where, value, expand_values(value, where, problems)};
      if (!a.values.empty()) axes.push_back(std::move(a));
    }
  }
}

std::string robot_label(const std::vector<Axis>& axes, const std::vector<std::size_t>& digits) {
  std::string label;
  for (std::size_t a = 0; a < axes.size(); ++a) {
    std::string path = axes[a].name.substr(1);
    std::replace(path.begin(), path.end(), '/', '.');
    const json& v = axes[a].values[digits[a]];
    label += (label.empty() ? "" : " ") + path + "=" + (v.is_string() ? v.get<std::string>() : v.dump());
  }
  return label.empty() ? "-" : label;
}

/// The registered strategies that score candidates linearly (StrategyTraits::linear_scored).
std::vector<std::string> linear_scored_names() {
  std::vector<std::string> out;
  for (const std::string& name : strategy_names()) {
    if (strategy_traits(name).linear_scored) out.push_back(name);
  }
  return out;
}

/// The integer `key` of a search object, `fallback` when absent; anything but an integer in
/// [lo, hi] is a problem (and gives `fallback`).
std::size_t search_count(const json& search, const char* key, std::size_t fallback, std::size_t lo,
                         std::size_t hi, const std::string& at, std::vector<std::string>& problems) {
  const json v = search.value(key, json(fallback));
  if (v.is_number_integer() && (v.is_number_unsigned() || v.get<std::int64_t>() >= 0)) {
    const auto n = v.get<std::uint64_t>();
    if (n >= lo && n <= hi) return static_cast<std::size_t>(n);
  }
  problems.push_back(concat({at, "/", key, ": value ", value_text(v), "; allowed: integers ",
                             std::to_string(lo), " to ", std::to_string(hi)}));
  return fallback;
}

/// The search's method, mode and write_vectors (the search object's keys checked); false when
/// the object is not one.
bool read_search_settings(const json& search, const std::string& at, WeightSearch& ws,
                          std::vector<std::string>& problems) {
  try {
    if (!search.is_object())
      throw ConfigError(at, "expected an object {\"method\": \"exact\", \"mode\": ...}");
    require_known_keys(search, {"method", "mode", "write_vectors", "rank", "order", "max_open", "probes"},
                       at);
  } catch (const ConfigError& e) {  // its message starts with its path (at, or at/<key>)
    problems.emplace_back(e.what());
    return false;
  }
  const json method = search.value("method", json("exact"));
  if (method != json("exact")) {
    problems.push_back(at + "/method: value " + value_text(method) + "; allowed: \"exact\"");
  }
  const json mode = search.value("mode", json("all"));
  if (mode == json("all")) {
    ws.mode = WeightSearch::Mode::All;
  } else if (mode == json("best")) {
    ws.mode = WeightSearch::Mode::Best;
  } else {
    problems.push_back(at + "/mode: value " + value_text(mode) + "; allowed: \"all\", \"best\"");
  }
  const json order = search.value("order", json("depth"));
  if (order == json("depth")) {
    ws.order = SearchOrder::Depth;
  } else if (order == json("bound")) {
    ws.order = SearchOrder::Bound;
  } else {
    problems.push_back(at + "/order: value " + value_text(order) + "; allowed: \"depth\", \"bound\"");
  }
  if (search.contains("order") && ws.mode != WeightSearch::Mode::Best) {
    problems.push_back(
        at + "/order: only a search of mode \"best\" has an order; remove it or set \"mode\": \"best\"");
  }
  ws.max_open =
      search_count(search, "max_open", kDefaultMaxOpenBranches, 1, kMaxOpenBranchesLimit, at, problems);
  if (search.contains("max_open") && ws.order != SearchOrder::Bound) {
    problems.push_back(at +
                       "/max_open: only a search of order \"bound\" keeps branches waiting; remove it or set "
                       "\"order\": \"bound\"");
  }
  ws.probes = search_count(search, "probes", kDefaultProbes, 0, kMaxProbes, at, problems);
  if (search.contains("probes") && ws.mode != WeightSearch::Mode::Best) {
    problems.push_back(
        at + "/probes: only a search of mode \"best\" runs probes; remove it or set \"mode\": \"best\"");
  }
  const json write_vectors = search.value("write_vectors", json(false));
  if (!write_vectors.is_boolean()) {
    problems.push_back(at + "/write_vectors: value " + value_text(write_vectors) + "; allowed: true, false");
  } else {
    ws.write_vectors = write_vectors.get<bool>();
  }
  return true;
}

/// The entry's groups that are not weights (each must have one value); a weight zipped with
/// another parameter is a problem.
std::vector<StrategyEntry::Group> non_weight_groups(StrategyEntry& entry,
                                                    const std::vector<std::string>& weights,
                                                    const std::string& where,
                                                    std::vector<std::string>& problems) {
  std::vector<StrategyEntry::Group> others;
  for (auto& group : entry.groups) {
    const auto weight =
        std::find_first_of(group.names.begin(), group.names.end(), weights.begin(), weights.end());
    if (weight == group.names.end()) {
      if (group.combos.size() != 1) {
        problems.push_back(
            concat({where, "/params/", group.names.front(), ": a search entry sweeps only its weights (",
                    join_names(weights), "); this parameter has ", std::to_string(group.combos.size()),
                    " values; allowed: one"}));
      }
      others.push_back(std::move(group));
    } else if (group.names.size() > 1) {
      problems.push_back(concat({where, "/zip: weight '", *weight,
                                 "' is zipped; a search covers the whole box of its weights, allowed: no zip "
                                 "groups with weights"}));
    }
  }
  return others;
}

/// The values of weight `w` (of the strategy `linear`) in the search's box: its group's values,
/// sorted; without a group every integer its declaration allows, or the value the strategy fixes.
/// Nothing when that fails (a problem said why).
std::optional<std::vector<double>> weight_values(const StrategyEntry& entry, const std::string& w,
                                                 std::size_t k, const LinearScoredStrategy& linear,
                                                 const ParamSpecs& specs, const std::string& where,
                                                 std::vector<std::string>& problems) {
  std::vector<double> values;
  const auto group = std::find_if(entry.groups.begin(), entry.groups.end(),
                                  [&](const StrategyEntry::Group& g) { return g.names == std::vector{w}; });
  if (group != entry.groups.end()) {
    for (const auto& combo : group->combos) {
      const json& v = combo.front();
      if (!v.is_number()) {
        const std::string allowed = "; allowed: numbers, lists or ranges of numbers";
        problems.push_back(concat({where, "/params/", w, ": value ", value_text(v), allowed}));
        break;
      }
      values.push_back(v.get<double>());
    }
    std::sort(values.begin(), values.end());
    return values;
  }
  const auto spec = std::find_if(specs.begin(), specs.end(), [&](const ParamSpec& p) { return p.name == w; });
  if (spec == specs.end()) {  // a weight the strategy fixes (closest_frontier: (1, 0, 0, 0))
    values.push_back(linear.weights()[k]);
  } else if (!spec->min || !spec->max || spec->max_open || spec->min_open) {
    problems.push_back(
        concat({where, "/params/", w, ": missing; a search needs the values of every weight"}));
    return std::nullopt;
  } else {
    for (double v = std::ceil(*spec->min); v <= *spec->max; v += 1.0) values.push_back(v);
  }
  return values;
}

/// The combinations write_vectors and rank allow with the box and the mode.
void check_search_outputs(const json& search, const std::string& at, const WeightSearch& ws,
                          std::vector<std::string>& problems) {
  if (ws.write_vectors && ws.vectors() > kMaxListedVectors) {
    problems.push_back(at + "/write_vectors: the box has " + with_thousands(ws.vectors()) +
                       " vectors; allowed: true only for boxes of at most " +
                       with_thousands(kMaxListedVectors));
  }
  if (ws.mode == WeightSearch::Mode::Best && ws.write_vectors) {
    problems.push_back(at +
                       "/write_vectors: mode \"best\" finds the optimal vectors only; allowed: "
                       "write_vectors with mode \"all\"");
  }
  if (ws.mode == WeightSearch::Mode::Best && search.contains("rank")) {
    problems.push_back(at +
                       "/rank: mode \"best\" ranks no vector but the optimal ones; allowed: rank with "
                       "mode \"all\"");
  }
}

/// The vectors to rank (search.rank): each a list of one value of the box per weight.
void read_rank_vectors(const json& search, const std::string& at, WeightSearch& ws,
                       std::vector<std::string>& problems) {
  const json rank = search.value("rank", json::array());
  if (!rank.is_array()) {
    problems.push_back(at + "/rank: expected a list of weight vectors, e.g. [[10, 0, 9, 20]], got " +
                       value_text(rank));
  }
  for (std::size_t i = 0; rank.is_array() && i < rank.size(); ++i) {
    const std::string rat = at + "/rank/" + std::to_string(i);
    const json& v = rank[i];
    bool ok = v.is_array() && v.size() == ws.weights.size();
    std::vector<double> vector;
    for (std::size_t k = 0; ok && k < v.size(); ++k) {
      const auto& box = ws.values[k];
      ok = v[k].is_number() && std::binary_search(box.begin(), box.end(), v[k].get<double>());
      if (ok) vector.push_back(v[k].get<double>());
    }
    for (double& w : vector) w += 0.0;  // -0.0 is the value 0, written "0"
    if (!ok) {
      problems.push_back(rat + ": value " + value_text(v) + "; allowed: a list of " +
                         std::to_string(ws.weights.size()) + " weights (" + join_names(ws.weights) +
                         "), each one of the search's values");
    } else if (const auto seen = std::find(ws.rank.begin(), ws.rank.end(), vector); seen != ws.rank.end()) {
      problems.push_back(concat({rat, ": value ", value_text(v), " repeats ", at, "/rank/",
                                 std::to_string(seen - ws.rank.begin()), "; allowed: each vector once"}));
    } else {
      ws.rank.push_back(std::move(vector));
    }
  }
}

/// Makes `entry` (validated, its groups built) a search entry by its "search" object: the weight
/// groups become the search's box (the values a regular sweep would run; every integer of the
/// declared range when a weight is not given),
/// every other group must have one value. `specs`: the strategy's declarations.
void make_search_entry(const json& search, const std::string& where, const ParamSpecs& specs,
                       StrategyEntry& entry, std::vector<std::string>& problems) {
  const std::string at = where + "/search";
  WeightSearch ws;
  if (!read_search_settings(search, at, ws, problems)) return;
  // The strategy's weights.
  std::unique_ptr<Strategy> probe;
  try {
    json params = entry.params_at(0);
    if (params.is_object()) params.erase("heuristics");  // the entry's heuristics axis, not a parameter
    probe = configure_strategy(entry.name, params.empty() ? json() : params, where).make(0);
  } catch (const std::exception& e) {
    problems.push_back(where + "/params: " + e.what());
    return;
  }
  const LinearScoredStrategy* linear = probe->linear_scored();
  if (!strategy_traits(entry.name).linear_scored || linear == nullptr) {
    problems.push_back(
        at + ": strategy '" + entry.name +
        "' does not score its candidates linearly, so its weights cannot be searched; allowed: " +
        join_names(linear_scored_names()));
    return;
  }
  ws.weights = linear->weight_names();
  std::vector<StrategyEntry::Group> others = non_weight_groups(entry, ws.weights, where, problems);
  for (std::size_t k = 0; k < ws.weights.size(); ++k) {
    if (auto values = weight_values(entry, ws.weights[k], k, *linear, specs, where, problems)) {
      ws.values.push_back(std::move(*values));
    }
  }
  if (ws.values.size() != ws.weights.size()) return;
  if (const std::uint64_t blocks = WeightGrid::blocks_of(ws.values); blocks > WeightGrid::kMaxBlocks) {
    problems.push_back(
        concat({where, "/params: a search box of ", with_thousands(blocks), " blocks of ",
                std::to_string(WeightGrid::kBlockEdge), " values per weight; allowed: at most ",
                with_thousands(WeightGrid::kMaxBlocks), ": fewer values per weight"}));
    return;
  }
  entry.groups = std::move(others);
  check_search_outputs(search, at, ws, problems);
  read_rank_vectors(search, at, ws, problems);
  entry.search = std::move(ws);
}

/// The entry's name (a registered strategy) and label (the name when not given).
void read_name_and_label(const json& item, const std::string& where, const std::vector<std::string>& known,
                         StrategyEntry& entry, std::vector<std::string>& problems) {
  if (!item.contains("name") || !item["name"].is_string()) {
    problems.push_back(where + "/name: expected a strategy name; known: " + join_names(known));
  } else {
    entry.name = item["name"].get<std::string>();
    if (std::find(known.begin(), known.end(), entry.name) == known.end()) {
      problems.push_back(where + "/name: unknown strategy '" + entry.name + "'; known: " + join_names(known));
    }
  }
  entry.label = entry.name;
  if (item.contains("label")) {
    if (item["label"].is_string()) {
      entry.label = item["label"].get<std::string>();
    } else {
      problems.push_back(where + "/label: expected a string, got " + value_text(item["label"]));
    }
  }
}

/// A CSV cell of a vectors file as the JSON number it reads as (so 10 stays an integer, as a
/// sweep file's list would hold it, and run keys agree); else a number by parse_number() (such as
/// "+1"), as a double; nullopt when it is no finite number.
std::optional<json> csv_number(const std::string& cell) {
  const json v = json::parse(cell, nullptr, false);
  if (!v.is_discarded() && v.is_number())
    return std::isfinite(v.get<double>()) ? std::optional<json>(v) : std::nullopt;
  const std::optional<double> d = parse_number(cell);
  if (!d || !std::isfinite(*d)) return std::nullopt;
  return json(*d);
}

/// The tuples of `"vectors": {"file": ...}`: a CSV file whose header names the parameters.
void read_vectors_file(const std::string& path, const std::string& where, std::vector<std::string>& names,
                       std::vector<std::vector<json>>& tuples, std::vector<std::string>& problems) {
  try {
    CsvReader in(path);
    names = in.header();
    std::size_t line = 1;
    while (in.next()) {
      ++line;
      std::vector<json> tuple;
      for (std::size_t c = 0; c < in.fields().size(); ++c) {
        const std::optional<json> v = csv_number(in.fields()[c]);
        if (!v) {
          problems.push_back(concat({where, ": ", path, ":", std::to_string(line), ": column ", names[c],
                                     ": '", in.fields()[c], "' is not a number"}));
          return;
        }
        tuple.push_back(*v);
      }
      tuples.push_back(std::move(tuple));
    }
  } catch (const ConfigError& e) {
    problems.push_back(concat({where, ": ", e.what()}));
  }
}

/// The weight names of linear-scored strategy `name` (the shorthand `"vectors": [[...], ...]`),
/// or empty when it is not one.
std::vector<std::string> linear_weight_names(const std::string& name) {
  if (!strategy_traits(name).linear_scored) return {};
  const std::unique_ptr<Strategy> probe = configure_strategy(name, nullptr).make(0);
  const LinearScoredStrategy* linear = probe->linear_scored();
  return linear != nullptr ? linear->weight_names() : std::vector<std::string>{};
}

/// The entry's `"vectors"`: whole parameter tuples, as one axis per parameter (each tuple's
/// value at the same index) that the caller zips into one group. Forms: a list of tuples (a
/// linear-scored strategy's weights in its order), {"params": [names], "values": [tuples]}, or
/// {"file": "tuples.csv"} (relative to the sweep file's folder; its header names the
/// parameters). Returns the names, in order; empty when absent or bad (a problem then).
std::vector<std::string> vector_axes(const json& item, const std::string& where, SweepPaths& paths,
                                     std::map<std::string, Axis>& axes, std::vector<std::string>& problems) {
  if (!item.contains("vectors")) return {};
  const std::string at = where + "/vectors";
  const json& v = item["vectors"];
  std::vector<std::string> names;
  std::vector<std::vector<json>> tuples;
  const std::string forms =
      "allowed: a list of weight vectors ([[w1, w2, ...], ...], a linear-scored strategy's weights in "
      "its order), {\"params\": [names], \"values\": [[...], ...]} or {\"file\": \"tuples.csv\"} whose "
      "header names the parameters";
  if (v.is_array()) {
    names = linear_weight_names(item.value("name", std::string()));
    if (names.empty()) {
      problems.push_back(at + ": a list of vectors names no parameters and this strategy has no weights; " +
                         forms);
      return {};
    }
    tuples = std::vector<std::vector<json>>();
    for (const json& t : v)
      tuples.push_back(t.is_array() ? t.get<std::vector<json>>() : std::vector<json>{t});
  } else if (v.is_object() && v.contains("file") && v.size() == 1 && v["file"].is_string()) {
    const std::optional<std::string> path =
        paths.resolve(v["file"].get<std::string>(), SweepPaths::Kind::File, at + "/file", problems);
    if (!path) return {};
    read_vectors_file(*path, at + "/file", names, tuples, problems);
  } else if (v.is_object() && v.size() == 2 && v.contains("params") && v.contains("values") &&
             v["params"].is_array() && v["values"].is_array() &&
             std::all_of(v["params"].begin(), v["params"].end(),
                         [](const json& n) { return n.is_string(); })) {
    names = v["params"].get<std::vector<std::string>>();
    for (const json& t : v["values"])
      tuples.push_back(t.is_array() ? t.get<std::vector<json>>() : std::vector<json>{t});
  } else {
    problems.push_back(at + ": value " + value_text(v) + " not allowed; " + forms);
    return {};
  }
  if (names.empty() || tuples.empty() || tuples.size() > kMaxAxisValues) {
    problems.push_back(concat({at, ": ", std::to_string(tuples.size()), " vectors of ",
                               std::to_string(names.size()), " parameters; allowed: 1 to ",
                               std::to_string(kMaxAxisValues), " vectors of at least one parameter"}));
    return {};
  }
  for (std::size_t k = 0; k < tuples.size(); ++k) {
    if (tuples[k].size() != names.size()) {
      problems.push_back(concat({at, "/", std::to_string(k), ": value ", value_text(json(tuples[k])),
                                 " not allowed; allowed: one value for each of ", join_names(names)}));
      return {};
    }
  }
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (axes.contains(names[i])) {
      problems.push_back(concat(
          {at, ": parameter '", names[i], "' is also in params; allowed: each parameter in one place"}));
      return {};
    }
    Axis a{names[i], at, v, {}};
    a.values.reserve(tuples.size());
    for (const std::vector<json>& t : tuples) a.values.push_back(t[i]);
    axes.emplace(names[i], std::move(a));
  }
  return names;
}

/// The entry's parameter axes, in key order, and its heuristics (a simulation setting,
/// src/sim/heuristics.hpp) beside them: one list of names, or a list of such lists to sweep
/// them, an axis named "heuristics" that orders and zips like a parameter.
std::map<std::string, Axis> strategy_axes(const json& item, const std::string& where,
                                          std::vector<std::string>& problems) {
  std::map<std::string, Axis> axes;
  const json params = item.value("params", json::object());
  // A zipped parameter may repeat values; its group's tuples may not (zip_groups()).
  std::set<std::string> zipped;
  for (const json& group : item.value("zip", json::array())) {
    if (!group.is_array()) continue;
    for (const json& name : group) {
      if (name.is_string()) zipped.insert(name.get<std::string>());
    }
  }
  if (!params.is_object()) {
    problems.push_back(where + "/params: expected an object {parameter: value, list or range}, got " +
                       value_text(params));
  } else {
    for (const auto& [key, value] : params.items()) {
      const std::string path = concat({where, "/params/", key});
      Axis a{key, path, value, expand_values(value, path, problems, zipped.contains(key))};
      axes.emplace(key, std::move(a));
    }
  }
  if (item.contains("heuristics")) {
    const std::string path = where + "/heuristics";
    const json& h = item["heuristics"];
    const bool swept = h.is_array() && !h.empty() &&
                       std::all_of(h.begin(), h.end(), [](const json& e) { return e.is_array(); });
    Axis a{"heuristics", path, h,
           swept ? expand_values(h, path, problems, zipped.contains("heuristics")) : std::vector<json>{h}};
    for (std::size_t k = 0; k < a.values.size(); ++k) {
      try {
        (void)heuristics_from_json(a.values[k], swept ? value_path(h, path, k) : path);
      } catch (const ConfigError& e) {
        problems.emplace_back(e.what());
      }
    }
    if (axes.count("heuristics") == 0) axes.emplace("heuristics", std::move(a));
  }
  return axes;
}

/// The entry's zip groups: known parameters, each in one group, equal numbers of values.
struct ZipGroups {
  std::map<std::string, std::size_t> group_of;  ///< parameter -> its group
  std::vector<std::vector<std::string>> zips;
};

/// A problem for the first tuple of zip group `names` (equal-length axes) that repeats an
/// earlier one: they would be the same runs.
void check_distinct_tuples(const std::vector<std::string>& names, const std::map<std::string, Axis>& axes,
                           const std::string& where, std::vector<std::string>& problems) {
  std::map<std::vector<json>, std::size_t> first_at;
  const std::size_t count = axes.at(names.front()).values.size();
  for (std::size_t k = 0; k < count; ++k) {
    std::vector<json> tuple;
    tuple.reserve(names.size());
    for (const std::string& n : names) tuple.push_back(axes.at(n).values[k]);
    const auto [at, fresh] = first_at.emplace(tuple, k);
    if (fresh) continue;
    std::string text;
    for (std::size_t i = 0; i < names.size(); ++i) {
      text += concat({i == 0 ? "" : ", ", names[i], " = ", value_text(tuple[i])});
    }
    problems.push_back(concat({where, ": tuple ", std::to_string(k), " (", text, ") repeats tuple ",
                               std::to_string(at->second),
                               "; allowed: distinct tuples (repeated ones would be the same runs)"}));
    return;
  }
}

ZipGroups zip_groups(const json& item, const std::string& where, const std::map<std::string, Axis>& axes,
                     const std::vector<std::string>& vectors, std::vector<std::string>& problems) {
  ZipGroups out;
  if (!vectors.empty()) {
    for (const std::string& name : vectors) out.group_of.emplace(name, 0);
    out.zips.push_back(vectors);
    check_distinct_tuples(vectors, axes, where + "/vectors", problems);
  }
  const json zip = item.value("zip", json::array());
  if (!zip.is_array()) problems.push_back(where + "/zip: expected a list of lists of parameter names");
  for (std::size_t g = 0; zip.is_array() && g < zip.size(); ++g) {
    const std::string gwhere = where + "/zip/" + std::to_string(g);
    if (!zip[g].is_array() || zip[g].empty()) {
      problems.push_back(gwhere + ": expected a non-empty list of parameter names, got " +
                         value_text(zip[g]));
      continue;
    }
    std::vector<std::string> names;
    std::string counts;
    std::set<std::size_t> sizes;
    for (std::size_t m = 0; m < zip[g].size(); ++m) {
      const json& n = zip[g][m];
      const std::string name = n.is_string() ? n.get<std::string>() : json_excerpt(n);
      if (!n.is_string() || !axes.count(name)) {
        std::string names_given;
        for (const auto& [k, a] : axes) names_given += (names_given.empty() ? "" : ", ") + k;
        problems.push_back(concat({gwhere, "/", std::to_string(m), ": '", name,
                                   "' is not a parameter of this entry; allowed: ", names_given}));
      } else if (!out.group_of.emplace(name, out.zips.size()).second) {
        problems.push_back(concat({gwhere, "/", std::to_string(m), ": '", name,
                                   "' is already in another zip group or in the entry's vectors"}));
      } else {
        names.push_back(name);
        sizes.insert(axes.at(name).values.size());
        counts += (counts.empty() ? "" : ", ") + name + ": " + std::to_string(axes.at(name).values.size());
      }
    }
    if (sizes.size() > 1) {
      problems.push_back(concat(
          {gwhere, ": zipped parameters vary together and need equal numbers of values; got ", counts}));
    } else if (!names.empty()) {
      check_distinct_tuples(names, axes, gwhere, problems);
    }
    out.zips.push_back(std::move(names));
  }
  return out;
}

/// The entry's groups: singletons and zips, ordered by their smallest name (axes are in key
/// order); a problem when their combinations exceed 2^64.
void build_groups(const std::map<std::string, Axis>& axes, const ZipGroups& zips, const std::string& where,
                  StrategyEntry& entry, std::vector<std::string>& problems) {
  for (const auto& [key, axis] : axes) {
    const auto z = zips.group_of.find(key);
    std::vector<std::string> names =
        z == zips.group_of.end() ? std::vector<std::string>{key} : zips.zips[z->second];
    if (z != zips.group_of.end() && *std::min_element(names.begin(), names.end()) != key) continue;
    StrategyEntry::Group group;
    group.names = names;
    for (std::size_t k = 0; k < axis.values.size(); ++k) {
      std::vector<json> combo;
      combo.reserve(names.size());
      for (const auto& n : names) combo.push_back(axes.at(n).values[k]);
      group.combos.push_back(std::move(combo));
    }
    entry.groups.push_back(std::move(group));
  }
  std::uint64_t count = 1;
  for (const auto& g : entry.groups) {
    if (__builtin_mul_overflow(count, static_cast<std::uint64_t>(g.combos.size()), &count)) {
      problems.push_back(where + "/params: more than 2^64 parameter combinations");
      break;
    }
  }
}

/// Every value of every parameter axis against the strategy's declaration `specs`
/// (core/params.hpp); parameters are independent, so no combination needs checking.
void check_declared(const std::string& name, const std::map<std::string, Axis>& axes, const ParamSpecs& specs,
                    const std::string& where, std::vector<std::string>& problems) {
  for (const auto& [key, axis] : axes) {
    if (axis.where == where + "/heuristics") continue;
    if (key == "heuristics") {
      try {
        (void)configure_strategy(name, json{{key, nullptr}}, where);
      } catch (const ConfigError& e) {
        problems.emplace_back(e.what());
      }
      continue;
    }
    const auto spec =
        std::find_if(specs.begin(), specs.end(), [&key = key](const ParamSpec& s) { return s.name == key; });
    if (spec == specs.end()) {
      std::vector<std::string> names;
      for (const auto& s : specs) names.push_back(s.name);
      problems.push_back(axis.where + ": unknown key '" + key +
                         "'; allowed: " + (names.empty() ? std::string("none") : join_names(names)));
      continue;
    }
    std::vector<std::pair<std::size_t, std::string>> bad;
    for (std::size_t k = 0; k < axis.values.size(); ++k) {
      if (auto problem = spec->check(axis.values[k])) bad.emplace_back(k, std::move(*problem));
    }
    report_axis(axis, bad, problems);
  }
}

/// Strategy entry `item` at `where`, or nothing when it has problems (added to `problems`).
std::optional<StrategyEntry> parse_strategy(const json& item, const std::string& where,
                                            const std::vector<std::string>& known, SweepPaths& paths,
                                            std::vector<std::string>& problems) {
  const std::size_t before = problems.size();
  try {
    require_known_keys(item, {"name", "label", "params", "heuristics", "zip", "vectors", "search"}, where);
  } catch (const ConfigError& e) {
    problems.emplace_back(e.what());
    return std::nullopt;
  }
  StrategyEntry entry;
  // 1. Name and label, 2. parameter axes, 3. zip groups.
  read_name_and_label(item, where, known, entry, problems);
  if (problems.size() != before) return std::nullopt;
  std::map<std::string, Axis> axes = strategy_axes(item, where, problems);
  const std::vector<std::string> vectors = vector_axes(item, where, paths, axes, problems);
  if (!vectors.empty() && item.contains("search")) {
    problems.push_back(where +
                       "/vectors: a search covers the whole box of its weights; allowed: vectors or "
                       "search, not both");
  }
  const ZipGroups zips = zip_groups(item, where, axes, vectors, problems);
  if (problems.size() != before) return std::nullopt;
  // 4. Groups.
  build_groups(axes, zips, where, entry, problems);
  if (problems.size() != before) return std::nullopt;
  // 5. Values against the declaration; the search.
  if (strategy_registry().contains(entry.name)) {
    const ParamSpecs& specs = strategy_registry().params(entry.name);
    check_declared(entry.name, axes, specs, where, problems);
    if (item.contains("search") && problems.size() == before) {
      make_search_entry(item["search"], where, specs, entry, problems);
    }
  }
  return entry;
}

}  // namespace

std::vector<StrategyEntry> parse_strategies(const json& strategies, SweepPaths& paths,
                                            std::vector<std::string>& problems) {
  std::vector<StrategyEntry> out;
  if (!strategies.is_array() || strategies.empty()) {
    problems.push_back("/strategies: expected a non-empty list of {\"name\", \"params\"} objects, got " +
                       value_text(strategies));
    return out;
  }
  const std::vector<std::string> known = strategy_names();
  std::optional<std::size_t> first_search;  // every search entry's weights head one set of files' columns
  for (std::size_t i = 0; i < strategies.size(); ++i) {
    const std::string where = "/strategies/" + std::to_string(i);
    if (auto entry = parse_strategy(strategies[i], where, known, paths, problems)) {
      if (entry->search && !first_search) {
        first_search = out.size();
      } else if (entry->search && entry->search->weights != out.at(*first_search).search->weights) {
        const std::string allowed =
            "; allowed: the same weights in every search entry of a sweep (their names "
            "head the columns of one set of search files): one sweep per strategy";
        problems.push_back(concat({where, "/search: searches the weights ",
                                   join_names(entry->search->weights), ", an earlier search entry ",
                                   join_names(out.at(*first_search).search->weights), allowed}));
      }
      out.push_back(std::move(*entry));
    }
  }
  return out;
}

std::vector<SweepPlanner> parse_planners(const json& planners, std::vector<std::string>& problems) {
  std::vector<SweepPlanner> out;
  if (planners.is_null()) return {SweepPlanner{"astar", nullptr}};
  if (!planners.is_array() || planners.empty()) {
    problems.push_back(
        "/planners: expected a non-empty list of {\"type\": name, \"params\": {...}} or names, got " +
        value_text(planners));
    return out;
  }
  const std::vector<std::string> known = planner_names();
  std::set<json> seen;
  for (std::size_t i = 0; i < planners.size(); ++i) {
    const std::string where = "/planners/" + std::to_string(i);
    const json& item = planners[i];
    SweepPlanner p;
    std::string name_path = where;
    if (item.is_string()) {
      p.name = item.get<std::string>();
    } else if (item.is_object()) {
      try {
        require_known_keys(item, {"type", "params"}, where);
      } catch (const ConfigError& e) {
        problems.emplace_back(e.what());
        continue;
      }
      name_path = where + "/type";
      if (item.contains("type") && item["type"].is_string()) p.name = item["type"].get<std::string>();
      if (item.contains("params") && !(item["params"].is_object() && item["params"].empty()))
        p.params = item["params"];
    } else {
      problems.push_back(where + ": expected a planner name or {\"type\": name, \"params\": {...}}, got " +
                         value_text(item));
      continue;
    }
    if (std::find(known.begin(), known.end(), p.name) == known.end()) {
      problems.push_back(name_path + ": unknown planner '" + p.name + "'; known: " + join_names(known));
      continue;
    }
    if (const auto e = failure([&] { (void)configure_planner(p.name, p.params, where); })) {
      problems.push_back(*e);
      continue;
    }
    if (!seen.insert(json{p.name, p.params}).second) {
      problems.push_back(where + ": planner " + value_text(item) +
                         " is listed twice; allowed: each planner once");
      continue;
    }
    out.push_back(std::move(p));
  }
  return out;
}

std::vector<RobotVariant> parse_robots(const json& robot_in, std::vector<std::string>& problems) {
  const json robot = robot_in.is_null() ? json::object() : robot_in;
  if (!robot.is_object()) {
    problems.push_back(
        "/robot: expected an object (sensor, energy, battery, dock, start_heading, "
        "allow_corner_cutting), got " +
        value_text(robot));
    return {};
  }
  // 1. Axes and their count.
  const std::size_t before = problems.size();
  std::vector<Axis> axes;
  collect_robot_axes(robot, "", axes, problems);
  if (problems.size() != before) return {};
  std::uint64_t count = 1;
  for (const auto& a : axes) {
    if (__builtin_mul_overflow(count, static_cast<std::uint64_t>(a.values.size()), &count) ||
        count > kMaxRobotVariants) {
      problems.push_back("/robot: more than " + with_thousands(kMaxRobotVariants) +
                         " robot variants; allowed: at most " + with_thousands(kMaxRobotVariants));
      return {};
    }
  }
  // 2. Each axis value: by the declaration of its parameter, or (an energy model's keys) by the
  //    reader, alone (no other swept leaf) and with the first value of the others, bad when both
  //    fail. Then the first variant itself (values may interact).
  json bare = robot;
  json base = robot;
  for (const auto& a : axes) {
    const json::json_pointer p(a.name);
    bare[p.parent_pointer()].erase(p.back());
    base[p] = a.values[0];
  }
  auto check = [](const json& j) { return failure([&] { (void)robot_params_from_json(j, "/robot"); }); };
  for (const auto& a : axes) {
    std::vector<std::pair<std::size_t, std::string>> bad;
    if (const ParamSpec* spec = robot_leaf_spec(a.name)) {  // its declaration decides
      for (std::size_t k = 0; k < a.values.size(); ++k) {
        if (auto problem = spec->check(a.values[k])) bad.emplace_back(k, std::move(*problem));
      }
      report_axis(a, bad, problems);
      continue;
    }
    for (std::size_t k = 0; k < a.values.size(); ++k) {
      json alone = bare;
      alone[json::json_pointer(a.name)] = a.values[k];
      const auto e = check(alone);
      if (!e) continue;
      json with_base = base;
      with_base[json::json_pointer(a.name)] = a.values[k];
      if (check(with_base)) bad.emplace_back(k, *e);
    }
    report_axis(a, bad, problems);
  }
  if (problems.size() != before) return {};
  if (const auto e = check(base)) {
    problems.push_back(*e);
    return {};
  }

  // 3. Every variant, last axis fastest; each validated (values may interact).
  std::vector<RobotVariant> out;
  out.reserve(count);
  std::vector<std::size_t> digits(axes.size(), 0);
  std::set<json> seen;
  for (std::uint64_t v = 0; v < count; ++v) {
    std::uint64_t rest = v;
    for (std::size_t a = axes.size(); a-- > 0;) {
      digits[a] = static_cast<std::size_t>(rest % axes[a].values.size());
      rest /= axes[a].values.size();
    }
    RobotVariant rv;
    rv.json = base;
    for (std::size_t a = 0; a < axes.size(); ++a)
      rv.json[json::json_pointer(axes[a].name)] = axes[a].values[digits[a]];
    rv.label = robot_label(axes, digits);
    try {
      rv.params = robot_params_from_json(rv.json, "/robot");
    } catch (const ConfigError& e) {
      problems.push_back("/robot: variant " + std::to_string(v) + " (" + rv.label + "): " + e.what());
      return {};
    }
    if (!seen.insert(json(rv.params)).second) {
      problems.push_back(
          "/robot: variant " + std::to_string(v) + " (" + rv.label +
          ") equals an earlier variant; allowed: distinct robots (equal ones would be the same runs)");
      return {};
    }
    out.push_back(std::move(rv));
  }
  return out;
}

}  // namespace sweep_detail
}  // namespace sweep
}  // namespace fsweep
