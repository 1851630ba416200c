#include "sim/run_spec.hpp"

#include <cmath>
#include <limits>

#include "core/config_error.hpp"
#include "core/json_excerpt.hpp"
#include "world/cell_param.hpp"

namespace fsweep {
inline namespace sim {
namespace {

/// [x, y] with two integers in [lo, INT_MAX], or nothing (a dock may lie outside the map's
/// first quadrant in JSON: the simulation says it is outside the map).
std::optional<Cell> cell_of(const nlohmann::json& v, long long lo) {
  const auto coordinate = [lo](const nlohmann::json& c) {
    return c.is_number_integer() && c.get<long long>() >= lo &&
           c.get<long long>() <= std::numeric_limits<int>::max();
  };
  if (!v.is_array() || v.size() != 2 || !coordinate(v[0]) || !coordinate(v[1])) return std::nullopt;
  return Cell{v[0].get<int>(), v[1].get<int>()};
}

nlohmann::json cell_json(const std::optional<Cell>& c) {
  return c ? nlohmann::json{c->x, c->y} : nlohmann::json();
}

ParamDecl<RobotParams> make_robot_params() {
  using P = RobotParams;
  ParamDecl<P> d;
  d.object("sensor", &P::sensor, sensor_params(), "the range sensor");
  ParamSpec energy;
  energy.name = "energy";
  energy.type = ParamType::Custom;
  energy.doc = "the energy model: a preset (fsweep describe energy) with optional overrides";
  energy.allowed_text = "a preset name (" + join_names(energy_registry().names()) +
                        ") or an object {\"preset\": name, overrides...}";
  energy.nested_problems = [](const nlohmann::json& v, const std::string& path) -> std::vector<std::string> {
    try {
      (void)energy_model_from_json(v, path);
    } catch (const ConfigError& e) {
      return {e.what()};
    }
    return {};
  };
  d.custom(
      std::move(energy),
      [](P& p, const nlohmann::json& v) { p.energy = energy_model_from_json(v, "robot/energy"); },
      [](const P& p) { return nlohmann::json(p.energy); });
  d.number_or_none("battery", &P::battery_capacity,
                   "battery capacity in the energy model's unit (with `distance`: metres per charge); null: "
                   "unlimited, never recharges")
      .above(0);
  ParamSpec dock;
  dock.name = "dock";
  dock.type = ParamType::Custom;
  dock.nullable = true;
  dock.unit = "cells";
  dock.doc = "the dock cell, where the battery is recharged; null: the map's start cell";
  dock.allowed_text = "[x, y], two integers";
  dock.custom_check = [](const nlohmann::json& v) -> std::vector<std::string> {
    if (cell_of(v, std::numeric_limits<int>::min())) return {};
    return {"value " + json_excerpt(v) + " not allowed; allowed: [x, y], two integers"};
  };
  d.custom(
      std::move(dock),
      [](P& p, const nlohmann::json& v) {
        p.dock = v.is_null() ? std::nullopt : cell_of(v, std::numeric_limits<int>::min());
      },
      [](const P& p) { return cell_json(p.dock); });
  d.integer("start_heading", &P::start_heading,
            "heading at the start: 0 east, then clockwise on screen in 45 degree steps")
      .range(0, 7);
  d.boolean("allow_corner_cutting", &P::allow_corner_cutting,
            "diagonal moves past an occupied orthogonal neighbour (off: the MovingAI rule)");
  return d;
}

ParamDecl<SimParams> make_sim_params() {
  using P = SimParams;
  ParamDecl<P> d;
  d.number("cluster_max_length_m", &P::cluster_max_length_m,
           "frontier clusters are split into pieces of at most this length; <= 0: the sensor range "
           "(Rappaport 2016 section 3.3)")
      .unit("m");
  d.integer("max_steps", &P::max_steps, "cap on cell steps; 0: 100 x the reachable free cells + 1000")
      .at_least(0);
  d.integer("stuck_decisions", &P::stuck_decisions,
            "end as `stuck` after this many consecutive decisions that revealed no cell")
      .at_least(1);
  d.number("progress_step_m", &P::progress_step_m,
           "progress curve sampling interval in metres of travel; <= 0: 10 x the resolution")
      .unit("m");
  declare_cell_or_random(
      d, "stop_at_cell", &P::stop_at_cell, &P::stop_at_random,
      "a cell that ends the run `target_reached` once reached (any strategy becomes a navigation "
      "baseline); \"random\": drawn from the run seed as target_seeking's \"target\": "
      "\"random\"; null: none");
  d.number("target_margin_m", &P::target_margin_m,
           "frontier cells closer than this to a known obstacle are not offered as goals (Holz 2010 "
           "section III: 0.3 m); 0: none")
      .range(0, 100)
      .unit("m")
      .omitted_at_default();
  d.number("stop_at_coverage", &P::stop_at_coverage,
           "a coverage target: the run ends `target_reached` at the scan that makes the known "
           "reachable free area this share of the reachable free area, and distance_to_coverage_target_m "
           "records the distance then; 0: none")
      .range(0, 1)
      .omitted_at_default();
  return d;
}

}  // namespace

const ParamDecl<RobotParams>& robot_params() {
  static const ParamDecl<RobotParams> kDecl = make_robot_params();
  return kDecl;
}

RobotParams robot_params_from_json(const nlohmann::json& j, const std::string& where) {
  return robot_params().read(j, where);
}

void to_json(nlohmann::json& j, const RobotParams& r) {
  j = robot_params().write(r);
  j["sensor"] = r.sensor;  // world's to_json: the beam keys only when they are not defaults
}

const ParamDecl<SimParams>& sim_params() {
  static const ParamDecl<SimParams> kDecl = make_sim_params();
  return kDecl;
}

SimParams sim_params_from_json(const nlohmann::json& j, const std::string& where) {
  return sim_params().read(j, where);
}

void to_json(nlohmann::json& j, const SimParams& s) {
  j = sim_params().write(s);
  // Absent unless given, so that run keys of configurations without a stop cell stay as they were.
  if (j["stop_at_cell"].is_null()) j.erase("stop_at_cell");
}

nlohmann::json recorded_strategy_params(const RunSpec& spec) {
  nlohmann::json params = spec.strategy.params;
  if (spec.heuristics) params["heuristics"] = heuristics_to_json(*spec.heuristics);
  return params;
}

}  // namespace sim
}  // namespace fsweep
