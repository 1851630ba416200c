#include "world/energy_model.hpp"

#include <cmath>
#include <nlohmann/json.hpp>

#include "core/config_error.hpp"

namespace fsweep {
inline namespace world {
namespace {

/// Rappaport 2016, eq. 2-3 and section 3.1 (Pioneer 3-DX).
struct PioneerParams {
  double moving_power_w = 22.38;
  double standing_power_w = 13.50;
  double speed_mps = 1.2;
  double stop_time_s = 1.0;
  double turn_rate_deg_s = 90.0;
};

constexpr double kJoulesPerWh = 3600.0;

EnergyModel pioneer_model(const PioneerParams& p) {
  EnergyModel m;
  m.preset = "pioneer3dx";
  m.unit = "Wh";
  m.per_metre = p.moving_power_w / p.speed_mps / kJoulesPerWh;
  m.per_cell = 0.0;
  m.per_stop = p.standing_power_w * p.stop_time_s / kJoulesPerWh;
  for (int k = 0; k < 4; ++k) {
    const double seconds = 45.0 * (k + 1) / p.turn_rate_deg_s;
    m.per_turn[static_cast<std::size_t>(k)] = p.moving_power_w * seconds / kJoulesPerWh;
  }
  return m;
}

/// Checks one number `v` found at `where`/`key`.
double checked(const nlohmann::json& v, const std::string& key, const std::string& where, bool allow_zero) {
  if (!v.is_number()) throw ConfigError(where + "/" + key, "expected a number, got " + v.dump());
  const double x = v.get<double>();
  if (!std::isfinite(x) || x < 0.0 || (!allow_zero && x == 0.0)) {
    throw ConfigError(where + "/" + key,
                      "value " + v.dump() + " out of range; allowed: " + (allow_zero ? ">= 0" : "> 0"));
  }
  return x;
}

double positive(const nlohmann::json& j, const std::string& key, const std::string& where, bool allow_zero) {
  return checked(j.at(key), key, where, allow_zero);
}

}  // namespace

EnergyModel energy_preset(const std::string& name) {
  if (name == "distance") return EnergyModel{};
  if (name == "mei2006") {
    EnergyModel m;
    m.preset = "mei2006";
    m.unit = "units";
    m.per_metre = 0.0;
    m.per_cell = 1.0;
    m.per_stop = 0.5;
    m.per_turn = {0.4, 0.6, 0.8, 1.0};
    return m;
  }
  if (name == "pioneer3dx") return pioneer_model(PioneerParams{});
  throw ConfigError("energy preset", "unknown preset '" + name + "'; allowed: distance, mei2006, pioneer3dx");
}

EnergyModel energy_model_from_json(const nlohmann::json& j, const std::string& where) {
  if (j.is_string()) {
    try {
      return energy_preset(j.get<std::string>());
    } catch (const ConfigError& e) {
      throw ConfigError(where, e.what());
    }
  }
  require_known_keys(j,
                     {"preset", "per_metre", "per_cell", "per_stop", "per_turn", "moving_power_w",
                      "standing_power_w", "speed_mps", "stop_time_s", "turn_rate_deg_s"},
                     where);
  const std::string preset = j.contains("preset") ? j.at("preset").get<std::string>() : "distance";
  EnergyModel m;
  try {
    m = energy_preset(preset);
  } catch (const ConfigError& e) {
    throw ConfigError(where + "/preset", e.what());
  }
  const bool pioneer_keys = j.contains("moving_power_w") || j.contains("standing_power_w") ||
                            j.contains("speed_mps") || j.contains("stop_time_s") ||
                            j.contains("turn_rate_deg_s");
  if (pioneer_keys) {
    if (preset != "pioneer3dx") {
      throw ConfigError(where, "power/speed/time keys apply only to preset 'pioneer3dx'");
    }
    PioneerParams p;
    if (j.contains("moving_power_w")) p.moving_power_w = positive(j, "moving_power_w", where, false);
    if (j.contains("standing_power_w")) p.standing_power_w = positive(j, "standing_power_w", where, true);
    if (j.contains("speed_mps")) p.speed_mps = positive(j, "speed_mps", where, false);
    if (j.contains("stop_time_s")) p.stop_time_s = positive(j, "stop_time_s", where, true);
    if (j.contains("turn_rate_deg_s")) p.turn_rate_deg_s = positive(j, "turn_rate_deg_s", where, false);
    m = pioneer_model(p);
  }
  if (j.contains("per_metre")) m.per_metre = positive(j, "per_metre", where, true);
  if (j.contains("per_cell")) m.per_cell = positive(j, "per_cell", where, true);
  if (j.contains("per_stop")) m.per_stop = positive(j, "per_stop", where, true);
  if (j.contains("per_turn")) {
    const auto& t = j.at("per_turn");
    if (!t.is_array() || t.size() != 4) {
      throw ConfigError(where + "/per_turn",
                        "expected 4 numbers (45, 90, 135, 180 degrees), got " + t.dump());
    }
    for (std::size_t k = 0; k < 4; ++k) {
      m.per_turn[k] = checked(t[k], std::to_string(k), where + "/per_turn", true);
    }
  }
  if (m.per_metre == 0.0 && m.per_cell == 0.0) {
    throw ConfigError(where, "travel must cost energy: per_metre or per_cell must be > 0");
  }
  return m;
}

void to_json(nlohmann::json& j, const EnergyModel& m) {
  j = nlohmann::json{{"preset", m.preset},     {"per_metre", m.per_metre}, {"per_cell", m.per_cell},
                     {"per_stop", m.per_stop}, {"per_turn", m.per_turn},   {"unit", m.unit}};
}

}  // namespace world
}  // namespace fsweep
