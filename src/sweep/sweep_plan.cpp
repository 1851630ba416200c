/// @file sweep_plan.cpp
/// SweepPlan: top-level validation of a sweep file, and the lazy decode of run indices.

#include "sweep/sweep_plan.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <stdexcept>

#include "core/config_error.hpp"
#include "core/random.hpp"
#include "planners/registry.hpp"
#include "sim/heuristics.hpp"
#include "strategies/registry.hpp"
#include "sweep/entry_overlap.hpp"
#include "sweep/sweep_axes.hpp"
#include "sweep/sweep_json_reader.hpp"
#include "world/sensor.hpp"

namespace fsweep {
inline namespace sweep {
namespace {

using nlohmann::json;
using sweep_detail::value_text;

const std::vector<std::string> kTopLevelKeys = {
    "schema_version", "name", "description",     "maps",        "strategies", "baseline", "planners",
    "robot",          "sim",  "progress_step_m", "repetitions", "seed",       "output",   "competitive"};

bool valid_name(const std::string& name) {
  if (name.empty() || name == "." || name == "..") return false;
  return std::all_of(name.begin(), name.end(), [](unsigned char c) {
    return std::isalnum(c) != 0 || c == '_' || c == '.' || c == '-';
  });
}

bool is_uint(const json& v) {
  return v.is_number_unsigned() || (v.is_number_integer() && v.get<std::int64_t>() >= 0);
}

/// The override a problem ("<JSON path>: message") comes from: the one with the longest path
/// at or above the problem's path; null when none is.
const SweepOverride* origin_of(const std::string& problem, const std::vector<SweepOverride>& overrides) {
  const std::string path = problem.substr(0, problem.find(": "));
  const SweepOverride* found = nullptr;
  for (const SweepOverride& o : overrides) {
    const bool above =
        path.starts_with(o.pointer) && (path.size() == o.pointer.size() || path[o.pointer.size()] == '/');
    if (above && (found == nullptr || o.pointer.size() > found->pointer.size())) found = &o;
  }
  return found;
}

/// The sweep's top-level `key`, or null when the sweep has none (or is not an object).
const json& top_level(const json& sweep, const char* key) {
  static const json kAbsent;
  return sweep.is_object() && sweep.contains(key) ? sweep.at(key) : kAbsent;
}

/// Every top-level key of the sweep is one the format has (and the sweep is an object).
void check_top_level_keys(const json& sweep, std::vector<std::string>& problems) {
  if (!sweep.is_object()) {
    problems.push_back("/: expected a JSON object with schema_version, name, maps, strategies");
    return;
  }
  for (const auto& [key, value] : sweep.items()) {
    if (std::find(kTopLevelKeys.begin(), kTopLevelKeys.end(), key) == kTopLevelKeys.end()) {
      problems.push_back(sweep_detail::concat(
          {"/", key, ": unknown key '", key, "'; allowed: ", join_names(kTopLevelKeys)}));
    }
  }
}

/// The error of a sweep with problems: each on its line, with the file and the command-line
/// override it comes from.
ConfigError sweep_problems(const std::vector<std::string>& problems, const std::string& file,
                           const std::vector<SweepOverride>& overrides) {
  const std::string where = file.empty() ? "sweep" : file;
  std::string text =
      std::to_string(problems.size()) + (problems.size() == 1 ? " problem" : " problems") +
      (overrides.empty() ? " in the sweep:" : " in the sweep with its command-line overrides:");
  for (const auto& p : problems) {
    const SweepOverride* origin = origin_of(p, overrides);
    text += sweep_detail::concat(
        {"\n", where, ": ", origin != nullptr ? override_label(origin->text) + ": " : std::string(), p});
  }
  return {where, text};
}

}  // namespace

SweepPlan SweepPlan::from_json(const json& sweep, const std::string& file) {
  return build(sweep, file, {}, {});
}

SweepPlan SweepPlan::from_file(const std::string& path, const std::vector<std::string>& overrides) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw ConfigError(path, std::filesystem::exists(path, ec)
                                ? "cannot read the sweep file: not a regular file"
                                : "cannot read the sweep file: no such file");
  }
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  if (!in) throw ConfigError(path, "cannot read the sweep file");
  SweepJson parsed = parse_sweep_json(buffer.str(), path);
  if (!overrides.empty()) parsed = apply_sweep_overrides(std::move(parsed), overrides, path);
  return build(parsed.value, path, std::move(parsed.problems), parsed.overrides);
}

SweepPlan SweepPlan::build(const json& sweep, const std::string& file, std::vector<std::string> problems,
                           const std::vector<SweepOverride>& overrides) {
  SweepPlan plan;
  plan.source_ = sweep;
  for (const SweepOverride& o : overrides) plan.overrides_.push_back(o.text);
  const auto get = [&](const char* key) -> const json& { return top_level(sweep, key); };

  // 1. Keys, version, name and scalars.
  check_top_level_keys(sweep, problems);
  const bool competitive = plan.read_settings(sweep, problems);
  plan.output_dir_ = "results/" + plan.name_;
  plan.read_output(get("output"), problems);
  // 2. Loop settings; progress_step_m at the top level or in sim.
  json sim = get("sim");
  if (const json& step = get("progress_step_m"); !step.is_null()) {
    if (sim.is_object() && sim.contains("progress_step_m")) {
      problems.push_back("/progress_step_m: also given as /sim/progress_step_m; allowed: one of the two");
    } else if (sim.is_null() || sim.is_object()) {
      sim["progress_step_m"] = step;
    }
  }
  try {
    plan.sim_ = sim_params_from_json(sim, "/sim");
    if (plan.objective_ == "distance_to_coverage_target_m" && !(plan.sim_.stop_at_coverage > 0.0)) {
      problems.emplace_back(
          "/output/objective: distance_to_coverage_target_m needs a coverage target, /sim/stop_at_coverage "
          "in (0, 1] (without one no run has a distance to it)");
    }
  } catch (const ConfigError& e) {
    problems.emplace_back(e.what());
  }

  // 3. The axes.
  sweep_detail::SweepPaths paths(file);
  plan.maps_ = sweep_detail::parse_maps(get("maps"), paths, problems, plan.skipped_maps_, competitive);
  const std::size_t before_strategies = problems.size();
  plan.strategies_ = sweep_detail::parse_strategies(get("strategies"), paths, problems);
  if (problems.size() == before_strategies) sweep_detail::check_entry_overlaps(plan.strategies_, problems);
  plan.path_warnings_ = paths.warnings();
  plan.planners_ = sweep_detail::parse_planners(get("planners"), problems);
  plan.robots_ = sweep_detail::parse_robots(get("robot"), problems);
  plan.check_baseline(get("baseline"), problems);

  // 4. Robot against maps, 5. counts.
  plan.check_robots_on_maps(problems);
  plan.count_runs(problems);
  if (!problems.empty()) throw sweep_problems(problems, file, overrides);
  return plan;
}

bool SweepPlan::read_settings(const json& sweep, std::vector<std::string>& problems) {
  const auto get = [&](const char* key) -> const json& { return top_level(sweep, key); };
  const json& version = get("schema_version");
  if (version.is_null()) {
    problems.push_back("/schema_version: missing; allowed: " + std::to_string(kSweepSchemaVersion));
  } else if (!version.is_number_integer() || version.get<std::int64_t>() != kSweepSchemaVersion) {
    problems.push_back("/schema_version: value " + value_text(version) + " not supported; allowed: " +
                       std::to_string(kSweepSchemaVersion) + " (the version this build reads)");
  }
  const json& name = get("name");
  if (!name.is_string() || !valid_name(name.get<std::string>())) {
    problems.push_back(
        "/name: " + (name.is_null() ? std::string("missing") : "value " + value_text(name) + " not allowed") +
        "; allowed: a string of letters, digits, '_', '.', '-' (it names the output folder)");
  } else {
    name_ = name.get<std::string>();
  }
  if (const json& d = get("description"); d.is_string()) {
    description_ = d.get<std::string>();
  } else if (!d.is_null()) {
    problems.push_back("/description: expected a string, got " + value_text(d));
  }
  if (const json& r = get("repetitions"); !r.is_null()) {
    if (!r.is_number_integer() || r.get<std::int64_t>() < 1 || r.get<std::int64_t>() > kMaxRepetitions) {
      problems.push_back("/repetitions: value " + value_text(r) +
                         " not allowed; allowed: an integer from 1 to " + std::to_string(kMaxRepetitions) +
                         " (2^31 - 1, the repetition index is a 32-bit integer), written without a decimal "
                         "point or exponent");
    } else {
      repetitions_ = r.get<int>();
    }
  }
  if (const json& s = get("seed"); !s.is_null()) {
    if (!is_uint(s)) {
      problems.push_back("/seed: value " + value_text(s) + " not allowed; allowed: an integer in [0, 2^64)");
    } else {
      seed_ = s.get<std::uint64_t>();
    }
  }
  const json& c = get("competitive");
  if (c.is_null()) return false;
  if (!c.is_boolean()) {
    problems.push_back("/competitive: value " + value_text(c) +
                       " not allowed; allowed: true (compute the offline optimum of every map: the optimum_* "
                       "and competitive_ratio_min/max columns; a map item's own \"competitive\" wins) or "
                       "false");
    return false;
  }
  return c.get<bool>();
}

void SweepPlan::read_output(const json& o, std::vector<std::string>& problems) {
  if (o.is_null()) return;
  try {
    require_known_keys(o, {"dir", "objective"}, "/output");
    if (o.contains("dir")) {
      if (!o["dir"].is_string() || o["dir"].get<std::string>().empty()) {
        problems.push_back("/output/dir: value " + value_text(o["dir"]) +
                           " not allowed; allowed: a non-empty path");
      } else {
        output_dir_ = o["dir"].get<std::string>();
      }
    }
    if (o.contains("objective")) {
      const json& obj = o["objective"];
      if (!obj.is_string() || find_objective(obj.get<std::string>()) == nullptr) {
        problems.push_back("/output/objective: value " + value_text(obj) +
                           " not allowed; allowed: " + join_names(objective_names()));
      } else {
        objective_ = obj.get<std::string>();
      }
    }
  } catch (const ConfigError& e) {
    problems.emplace_back(e.what());
  }
}

void SweepPlan::check_baseline(const json& b, std::vector<std::string>& problems) const {
  if (b.is_null()) return;
  // A strategy entry's label, or for a search entry "<label>@best" or "<label>@w1,w2,..." (paired.hpp).
  std::vector<std::string> labels;
  bool known = false;
  for (const StrategyEntry& e : strategies_) {
    labels.push_back(e.search ? e.label + "@best" : e.label);
    known = known || (b.is_string() &&
                      (b == e.label || (e.search && b.get<std::string>().starts_with(e.label + "@"))));
  }
  if (!known) {
    problems.push_back(
        "/baseline: value " + value_text(b) +
        " not allowed; allowed: a strategy entry's label (the side fsweep paired and fsweep report "
        "compare the others with): " +
        join_names(labels));
  }
}

void SweepPlan::check_robots_on_maps(std::vector<std::string>& problems) const {
  std::set<std::pair<std::pair<int, int>, std::size_t>> docks_checked;
  std::set<std::pair<double, double>> ranges_checked;
  for (const auto& r : robots_) {
    for (std::size_t m = 0; m < maps_.size(); ++m) {
      const WorldMap& map = *maps_[m].map;
      if (r.params.dock && docks_checked.insert({{r.params.dock->x, r.params.dock->y}, m}).second &&
          !map.is_free(*r.params.dock)) {
        problems.push_back("/robot/dock: cell (" + std::to_string(r.params.dock->x) + ", " +
                           std::to_string(r.params.dock->y) + ") is outside or occupied in map " +
                           maps_[m].label + "; allowed: a free cell of every map");
      }
      const double range = r.params.sensor.range_m;
      const bool new_range = ranges_checked.insert({range, map.resolution_m}).second;
      if (new_range && range / map.resolution_m < std::sqrt(2.0)) {
        problems.push_back("/robot/sensor/range_m: value " + json(range).dump() +
                           " m is below one diagonal cell of map " + maps_[m].label +
                           "; allowed: >= sqrt(2) x resolution (" +
                           json(std::sqrt(2.0) * map.resolution_m).dump() + " m)");
      }
      if (new_range && !(range / map.resolution_m <= Sensor::kMaxRangeCells)) {
        problems.push_back("/robot/sensor/range_m: value " + json(range).dump() + " m is " +
                           json(range / map.resolution_m).dump() + " cells of map " + maps_[m].label +
                           "; allowed: at most " + std::to_string(Sensor::kMaxRangeCells) + " cells (" +
                           json(Sensor::kMaxRangeCells * map.resolution_m).dump() + " m)");
      }
    }
  }
}

void SweepPlan::count_runs(std::vector<std::string>& problems) {
  for (const auto& e : strategies_) {
    std::uint64_t total = 0;
    if (__builtin_add_overflow(strategy_offsets_.back(), e.count(), &total)) {
      problems.push_back("/strategies: more than 2^64 strategy configurations");
      break;
    }
    strategy_offsets_.push_back(total);
  }
  if (!problems.empty()) return;
  std::uint64_t n = 1;
  bool overflow = false;
  for (const std::uint64_t f :
       {static_cast<std::uint64_t>(maps_.size()), strategy_offsets_.back(),
        static_cast<std::uint64_t>(planners_.size()), static_cast<std::uint64_t>(robots_.size()),
        static_cast<std::uint64_t>(repetitions_)}) {
    overflow = overflow || __builtin_mul_overflow(n, f, &n);
  }
  if (overflow) problems.push_back("/: the sweep has more than 2^64 runs; allowed: fewer");
}

std::uint64_t SweepPlan::configuration_count() const {
  return static_cast<std::uint64_t>(maps_.size()) * strategy_offsets_.back() *
         static_cast<std::uint64_t>(planners_.size()) * static_cast<std::uint64_t>(robots_.size());
}

std::uint64_t SweepPlan::run_count() const {
  return configuration_count() * static_cast<std::uint64_t>(repetitions_);
}

RunCoordinates SweepPlan::coordinates(std::uint64_t index) const {
  if (index >= run_count()) {
    throw std::out_of_range("run index " + std::to_string(index) + " out of range; the sweep has " +
                            std::to_string(run_count()) + " runs");
  }
  RunCoordinates c;
  c.index = index;
  std::uint64_t rest = index;
  const auto take = [&rest](std::uint64_t radix) {
    const std::uint64_t digit = rest % radix;
    rest /= radix;
    return digit;
  };
  c.repetition = static_cast<int>(take(static_cast<std::uint64_t>(repetitions_)));
  c.robot = static_cast<std::size_t>(take(robots_.size()));
  c.planner = static_cast<std::size_t>(take(planners_.size()));
  const std::uint64_t strategy = take(strategy_offsets_.back());
  c.map = static_cast<std::size_t>(rest);
  // strategy_offsets_ = [0, n0, n0 + n1, ...]: the entry is the last offset <= strategy.
  const auto it = std::upper_bound(strategy_offsets_.begin(), strategy_offsets_.end(), strategy);
  c.strategy_entry = static_cast<std::size_t>(it - strategy_offsets_.begin() - 1);
  c.strategy_combo = strategy - strategy_offsets_[c.strategy_entry];
  return c;
}

RunSpec SweepPlan::spec_at(const RunCoordinates& c) const {
  RunSpec spec;
  spec.map = maps_[c.map].map;
  const StrategyEntry& entry = strategies_[c.strategy_entry];
  nlohmann::json params = entry.params_at(c.strategy_combo);
  if (params.is_object() && params.contains("heuristics")) {  // the entry's "heuristics" axis
    spec.heuristics = heuristics_from_json(params["heuristics"], "heuristics");
    params.erase("heuristics");
    if (params.empty()) params = nullptr;
  }
  spec.strategy = configure_strategy(entry.name, params, "/strategies/" + std::to_string(c.strategy_entry));
  spec.planner = configure_planner(planners_[c.planner].name, planners_[c.planner].params,
                                   "/planners/" + std::to_string(c.planner));
  spec.robot = robots_[c.robot].params;
  spec.sim = sim_;
  spec.seed = derive_seed(seed_, "repetition/" + std::to_string(c.repetition));
  if (const auto& regions = maps_[c.map].start_regions) {
    // A random start: the map with the start this run's seed draws (recorded as map.start).
    auto drawn = std::make_shared<WorldMap>(*spec.map);
    drawn->start = draw_region_cell((*regions)[spec.robot.allow_corner_cutting ? 1 : 0], spec.seed);
    spec.map = std::move(drawn);
  }
  return spec;
}

json SweepPlan::key_json_of(const RunCoordinates& c, const RunSpec& spec) const {
  json robot = spec.robot;
  if (!spec.robot.dock) robot["dock"] = json{spec.map->start.x, spec.map->start.y};
  return json{{"map", maps_[c.map].spec},
              {"map_content", maps_[c.map].content_hash},
              {"strategy", spec.strategy.name},
              {"strategy_params", recorded_strategy_params(spec)},
              {"planner", spec.planner.name},
              // The planner params as written (null when absent or empty), not the resolved ones:
              // run keys stay the same when a planner gains a parameter with a default.
              {"planner_params", planners_[c.planner].params},
              {"robot", robot},
              {"sim", spec.sim},
              {"seed", spec.seed}};
}

namespace {

std::string key_of(const json& key_json) { return hex64(fnv1a(key_json.dump())); }

}  // namespace

SweepRun SweepPlan::run(std::uint64_t index) const {
  SweepRun r;
  r.at = coordinates(index);
  r.spec = spec_at(r.at);
  r.key_json = key_json_of(r.at, r.spec);
  r.key = key_of(r.key_json);
  return r;
}

RunSpec SweepPlan::run_spec(std::uint64_t index) const { return spec_at(coordinates(index)); }

json SweepPlan::run_key_json(std::uint64_t index) const { return run(index).key_json; }

std::string SweepPlan::run_key(std::uint64_t index) const { return run(index).key; }

std::vector<SearchUnit> SweepPlan::search_units() const {
  std::vector<std::string> classes;
  for (const SweepMap& m : maps_) {
    if (std::find(classes.begin(), classes.end(), m.map_class) == classes.end())
      classes.push_back(m.map_class);
  }
  std::vector<SearchUnit> out;
  for (std::size_t e = 0; e < strategies_.size(); ++e) {
    if (!strategies_[e].search) continue;
    for (const std::string& c : classes) {
      SearchUnit u;
      u.entry = e;
      u.map_class = c;
      for (std::size_t m = 0; m < maps_.size(); ++m) {
        if (maps_[m].map_class == c) u.maps.push_back(m);
      }
      for (u.planner = 0; u.planner < planners_.size(); ++u.planner) {
        for (u.robot = 0; u.robot < robots_.size(); ++u.robot) out.push_back(u);
      }
    }
  }
  return out;
}

namespace {

RunCoordinates instance_coordinates(const SearchUnit& unit, std::size_t instance, int repetitions) {
  RunCoordinates c;
  c.map = unit.maps.at(instance / static_cast<std::size_t>(repetitions));
  c.strategy_entry = unit.entry;
  c.planner = unit.planner;
  c.robot = unit.robot;
  c.repetition = static_cast<int>(instance % static_cast<std::size_t>(repetitions));
  return c;
}

}  // namespace

RunSpec SweepPlan::search_instance(const SearchUnit& unit, std::size_t instance) const {
  return spec_at(instance_coordinates(unit, instance, repetitions_));
}

json SweepPlan::search_instance_json(const SearchUnit& unit, std::size_t instance) const {
  const RunCoordinates c = instance_coordinates(unit, instance, repetitions_);
  json out = key_json_of(c, spec_at(c));
  const WeightSearch& search = *strategies_.at(unit.entry).search;
  for (std::size_t k = 0; k < search.weights.size(); ++k) {
    const std::vector<double>& v = search.values[k];
    out["strategy_params"][search.weights[k]] =
        v.size() == 1 ? json(v.front()) : json{{"from", v.front()}, {"to", v.back()}, {"values", v.size()}};
  }
  return out;
}

bool SweepPlan::competitive() const {
  return std::any_of(maps_.begin(), maps_.end(), [](const SweepMap& m) { return m.competitive; });
}

std::vector<std::pair<std::string, std::uint64_t>> SweepPlan::axes() const {
  return {{"maps", maps_.size()},
          {"strategy configurations", strategy_offsets_.back()},
          {"planners", planners_.size()},
          {"robots", robots_.size()},
          {"repetitions", static_cast<std::uint64_t>(repetitions_)}};
}

}  // namespace sweep
}  // namespace fsweep
