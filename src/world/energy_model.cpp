#include "world/energy_model.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>

#include "core/config_error.hpp"
#include "core/json_excerpt.hpp"

namespace fsweep {
inline namespace world {
namespace {

constexpr double kJoulesPerWh = 3600.0;

/// Overrides every preset takes; empty: the preset's value.
struct Overrides {
  std::optional<double> per_metre;
  std::optional<double> per_cell;
  std::optional<double> per_stop;
  std::optional<std::array<double, 4>> per_turn;
};

/// Rappaport 2016, eq. 2-3 and section 3.1 (Pioneer 3-DX), plus the overrides.
struct PioneerParams : Overrides {
  double moving_power_w = 22.38;
  double standing_power_w = 13.50;
  double speed_mps = 1.2;
  double stop_time_s = 1.0;
  double turn_rate_deg_s = 90.0;
};

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

EnergyModel mei_model() {
  EnergyModel m;
  m.preset = "mei2006";
  m.unit = "units";
  m.per_metre = 0.0;
  m.per_cell = 1.0;
  m.per_stop = 0.5;
  m.per_turn = {0.4, 0.6, 0.8, 1.0};
  return m;
}

/// An optional number >= 0 overriding the preset's `field`.
template <class P>
void declare_override(ParamDecl<P>& d, const char* name, std::optional<double> Overrides::*member,
                      double preset_value, const char* doc) {
  ParamSpec spec;
  spec.name = name;
  spec.type = ParamType::Number;
  spec.min = 0.0;
  spec.nullable = true;
  spec.doc = std::string(doc) + " (null: the preset's, " + nlohmann::json(preset_value).dump() + ")";
  d.custom(
      std::move(spec),
      [member](P& p, const nlohmann::json& v) {
        if (v.is_number()) p.*member = v.get<double>();
      },
      [member](const P& p) { return p.*member ? nlohmann::json(*(p.*member)) : nlohmann::json(); });
}

template <class P>
void declare_overrides(ParamDecl<P>& d, const EnergyModel& preset) {
  declare_override(d, "per_metre", &Overrides::per_metre, preset.per_metre, "energy per metre travelled");
  declare_override(d, "per_cell", &Overrides::per_cell, preset.per_cell, "energy per cell length travelled");
  declare_override(d, "per_stop", &Overrides::per_stop, preset.per_stop,
                   "energy of one stop (before every turn)");
  ParamSpec turn;
  turn.name = "per_turn";
  turn.type = ParamType::Custom;
  turn.nullable = true;
  turn.doc = "energy of a turn of 45, 90, 135, 180 degrees, stop excluded (null: the preset's, " +
             nlohmann::json(preset.per_turn).dump() + ")";
  turn.allowed_text = "4 numbers >= 0 (45, 90, 135, 180 degrees)";
  turn.custom_check = [](const nlohmann::json& t) -> std::vector<std::string> {
    const bool ok =
        t.is_array() && t.size() == 4 && std::all_of(t.begin(), t.end(), [](const nlohmann::json& x) {
          return x.is_number() && std::isfinite(x.get<double>()) && x.get<double>() >= 0.0;
        });
    if (ok) return {};
    return {"expected 4 numbers >= 0 (45, 90, 135, 180 degrees), got " + json_excerpt(t)};
  };
  d.custom(
      std::move(turn),
      [](P& p, const nlohmann::json& t) {
        if (t.is_array()) p.per_turn = t.get<std::array<double, 4>>();
      },
      [](const P& p) { return p.per_turn ? nlohmann::json(*p.per_turn) : nlohmann::json(); });
}

/// `m` with the overrides applied; throws when travel costs nothing.
EnergyModel with_overrides(EnergyModel m, const Overrides& o) {
  if (o.per_metre) m.per_metre = *o.per_metre;
  if (o.per_cell) m.per_cell = *o.per_cell;
  if (o.per_stop) m.per_stop = *o.per_stop;
  if (o.per_turn) m.per_turn = *o.per_turn;
  if (m.per_metre == 0.0 && m.per_cell == 0.0) {
    throw ConfigError("", "travel must cost energy: per_metre or per_cell must be > 0");
  }
  return m;
}

EnergyRegistry make_energy_registry() {
  EnergyRegistry r("energy preset");
  ParamDecl<Overrides> distance;
  declare_overrides(distance, EnergyModel{});
  r.add<Overrides>("distance", "1 unit per metre, nothing else (battery as a range in metres)", distance,
                   [](const Overrides& o) { return with_overrides(EnergyModel{}, o); });
  ParamDecl<Overrides> mei;
  declare_overrides(mei, mei_model());
  r.add<Overrides>("mei2006", "Mei et al. 2006 Fig. 6: 1 per cell length, stop 0.5, turns 0.4/0.6/0.8/1.0",
                   mei, [](const Overrides& o) { return with_overrides(mei_model(), o); });
  ParamDecl<PioneerParams> pioneer;
  pioneer.number("moving_power_w", &PioneerParams::moving_power_w, "power while moving or turning (eq. 2)")
      .above(0)
      .unit("W");
  pioneer.number("standing_power_w", &PioneerParams::standing_power_w, "power while standing (eq. 3)")
      .at_least(0)
      .unit("W");
  pioneer.number("speed_mps", &PioneerParams::speed_mps, "travel speed").above(0).unit("m/s");
  pioneer.number("stop_time_s", &PioneerParams::stop_time_s, "time standing still per stop")
      .at_least(0)
      .unit("s");
  pioneer.number("turn_rate_deg_s", &PioneerParams::turn_rate_deg_s, "turning rate").above(0).unit("deg/s");
  declare_overrides(pioneer, pioneer_model(PioneerParams{}));
  r.add<PioneerParams>("pioneer3dx", "Rappaport 2016 eq. 2-3: Pioneer 3-DX power model, energy in Wh",
                       pioneer, [](const PioneerParams& p) { return with_overrides(pioneer_model(p), p); });
  return r;
}

}  // namespace

const EnergyRegistry& energy_registry() {
  static const EnergyRegistry kRegistry = make_energy_registry();
  return kRegistry;
}

EnergyModel energy_preset(const std::string& name) {
  return energy_registry().configure(name, nullptr, "energy preset").make();
}

EnergyModel energy_model_from_json(const nlohmann::json& j, const std::string& where) {
  if (j.is_string()) return energy_registry().configure(j.get<std::string>(), nullptr, where).make();
  if (!j.is_object()) {
    throw ConfigError(where, "expected a preset name (" + join_names(energy_registry().names()) +
                                 ") or an object {\"preset\": name, overrides...}, got " + json_excerpt(j));
  }
  const nlohmann::json preset = j.value("preset", nlohmann::json("distance"));
  if (!preset.is_string()) {
    throw ConfigError(where + "/preset",
                      "expected a preset name; known: " + join_names(energy_registry().names()));
  }
  nlohmann::json overrides = j;
  overrides.erase("preset");
  const auto configured =
      energy_registry().configure(preset.get<std::string>(), overrides, where + "/preset", where);
  try {
    return configured.make();
  } catch (const ConfigError& e) {
    throw ConfigError(where, e.what());
  }
}

void to_json(nlohmann::json& j, const EnergyModel& m) {
  j = nlohmann::json{{"preset", m.preset},     {"per_metre", m.per_metre}, {"per_cell", m.per_cell},
                     {"per_stop", m.per_stop}, {"per_turn", m.per_turn},   {"unit", m.unit}};
}

}  // namespace world
}  // namespace fsweep
