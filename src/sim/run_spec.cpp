#include "sim/run_spec.hpp"

#include <cmath>
#include <limits>

#include "core/config_error.hpp"

namespace fsweep {
inline namespace sim {
namespace {

double number_at(const nlohmann::json& j, const char* key, const std::string& where) {
  const auto& v = j.at(key);
  if (!v.is_number()) throw ConfigError(where + "/" + key, "expected a number, got " + v.dump());
  return v.get<double>();
}

}  // namespace

RobotParams robot_params_from_json(const nlohmann::json& j, const std::string& where) {
  RobotParams r;
  if (j.is_null()) return r;
  require_known_keys(j, {"sensor", "energy", "battery", "dock", "start_heading", "allow_corner_cutting"},
                     where);
  if (j.contains("sensor")) r.sensor = sensor_params_from_json(j.at("sensor"), where + "/sensor");
  if (j.contains("energy")) r.energy = energy_model_from_json(j.at("energy"), where + "/energy");
  if (j.contains("battery") && !j.at("battery").is_null()) {
    const double b = number_at(j, "battery", where);
    if (!(b > 0.0)) {
      throw ConfigError(where + "/battery",
                        "value " + j.at("battery").dump() +
                            " out of range; allowed: > 0 (energy units), or null for unlimited");
    }
    r.battery_capacity = b;
  }
  if (j.contains("dock")) {
    const auto& d = j.at("dock");
    if (!d.is_array() || d.size() != 2 || !d[0].is_number_integer() || !d[1].is_number_integer()) {
      throw ConfigError(where + "/dock", "expected [x, y] in cells, got " + d.dump());
    }
    r.dock = Cell{d[0].get<int>(), d[1].get<int>()};
  }
  if (j.contains("start_heading")) {
    const auto& h = j.at("start_heading");
    if (!h.is_number_integer() || h.get<int>() < 0 || h.get<int>() > 7) {
      throw ConfigError(where + "/start_heading",
                        "value " + h.dump() + " out of range; allowed: an integer 0..7");
    }
    r.start_heading = h.get<int>();
  }
  if (j.contains("allow_corner_cutting")) {
    const auto& c = j.at("allow_corner_cutting");
    if (!c.is_boolean())
      throw ConfigError(where + "/allow_corner_cutting", "expected true or false, got " + c.dump());
    r.allow_corner_cutting = c.get<bool>();
  }
  return r;
}

void to_json(nlohmann::json& j, const RobotParams& r) {
  j = nlohmann::json{{"sensor", r.sensor},
                     {"energy", r.energy},
                     {"battery", std::isinf(r.battery_capacity) ? nlohmann::json(nullptr)
                                                                : nlohmann::json(r.battery_capacity)},
                     {"dock", r.dock ? nlohmann::json{r.dock->x, r.dock->y} : nlohmann::json(nullptr)},
                     {"start_heading", r.start_heading},
                     {"allow_corner_cutting", r.allow_corner_cutting}};
}

SimParams sim_params_from_json(const nlohmann::json& j, const std::string& where) {
  SimParams s;
  if (j.is_null()) return s;
  require_known_keys(
      j, {"cluster_max_length_m", "max_steps", "stuck_decisions", "progress_step_m", "stop_at_cell"}, where);
  if (j.contains("stop_at_cell")) {
    const auto& v = j.at("stop_at_cell");
    if (v.is_string() && v.get<std::string>() == "random") {
      s.stop_at_random = true;
    } else if (v.is_array() && v.size() == 2 && v[0].is_number_integer() && v[1].is_number_integer() &&
               v[0].get<long long>() >= 0 && v[1].get<long long>() >= 0 &&
               v[0].get<long long>() <= std::numeric_limits<int>::max() &&
               v[1].get<long long>() <= std::numeric_limits<int>::max()) {
      s.stop_at_cell = Cell{v[0].get<int>(), v[1].get<int>()};
    } else {
      throw ConfigError(
          where + "/stop_at_cell",
          "value " + v.dump() + " is not a cell; allowed: [x, y], two integers >= 0, or \"random\"");
    }
  }
  if (j.contains("cluster_max_length_m"))
    s.cluster_max_length_m = number_at(j, "cluster_max_length_m", where);
  if (j.contains("progress_step_m")) s.progress_step_m = number_at(j, "progress_step_m", where);
  if (j.contains("max_steps")) {
    const auto& v = j.at("max_steps");
    if (!v.is_number_integer() || v.get<long>() < 0) {
      throw ConfigError(where + "/max_steps",
                        "value " + v.dump() + " out of range; allowed: an integer >= 0 (0 = auto)");
    }
    s.max_steps = v.get<long>();
  }
  if (j.contains("stuck_decisions")) {
    const auto& v = j.at("stuck_decisions");
    if (!v.is_number_integer() || v.get<int>() < 1) {
      throw ConfigError(where + "/stuck_decisions",
                        "value " + v.dump() + " out of range; allowed: an integer >= 1");
    }
    s.stuck_decisions = v.get<int>();
  }
  return s;
}

void to_json(nlohmann::json& j, const SimParams& s) {
  j = nlohmann::json{{"cluster_max_length_m", s.cluster_max_length_m},
                     {"max_steps", s.max_steps},
                     {"stuck_decisions", s.stuck_decisions},
                     {"progress_step_m", s.progress_step_m}};
  if (s.stop_at_random) {
    j["stop_at_cell"] = "random";
  } else if (s.stop_at_cell) {
    j["stop_at_cell"] = nlohmann::json{s.stop_at_cell->x, s.stop_at_cell->y};
  }
}

nlohmann::json recorded_strategy_params(const RunSpec& spec) {
  nlohmann::json params = spec.strategy.params;
  if (spec.heuristics) params["heuristics"] = heuristics_to_json(*spec.heuristics);
  return params;
}

}  // namespace sim
}  // namespace fsweep
