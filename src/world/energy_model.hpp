#pragma once
/// @file energy_model.hpp
/// What motion costs: per distance, per stop, per turn (docs/dev/architecture.md, "Robot, motion and
/// energy").
///
/// The model lives in `world`, below planners and sim: planners report path energy under the
/// run's model and the lattice planner searches on it. Battery stays in sim.
///
/// Accounting rule used by every planner and by the simulator: a path costs its travel
/// energy plus, for every heading change (including the change from the start heading to the
/// first step), one stop and one turn of that angle. Arriving at the goal costs no final stop.

#include <array>
#include <nlohmann/json_fwd.hpp>
#include <string>

#include "core/registry.hpp"

namespace fsweep {
inline namespace world {

struct EnergyModel {
  /// Preset this model came from: "distance", "mei2006", "pioneer3dx".
  std::string preset = "distance";
  /// Energy per metre travelled.
  double per_metre = 1.0;
  /// Energy per cell length travelled (Mei 2006 counts cells, not metres).
  double per_cell = 0.0;
  /// Energy of one stop (a stop precedes every turn).
  double per_stop = 0.0;
  /// Energy of a turn of 45, 90, 135 and 180 degrees (excluding the stop).
  std::array<double, 4> per_turn{0.0, 0.0, 0.0, 0.0};
  /// Unit of the energy numbers, for outputs: "m", "units", "Wh".
  std::string unit = "m";

  /// Energy of moving `length_cells` cells (a step is 1 or sqrt(2)) at `resolution_m`.
  [[nodiscard]] double travel(double length_cells, double resolution_m) const {
    return length_cells * (per_metre * resolution_m + per_cell);
  }
  /// Energy of changing heading by `steps` 45-degree steps (0..4): a stop plus the turn.
  [[nodiscard]] double turn(int steps) const {
    return steps == 0 ? 0.0 : per_stop + per_turn[static_cast<std::size_t>(steps - 1)];
  }
  /// Cheapest energy per cell length of travel (for admissible heuristics).
  [[nodiscard]] double travel_per_cell(double resolution_m) const {
    return per_metre * resolution_m + per_cell;
  }
};

/// The energy presets (core/registry.hpp), each with its declared overrides:
/// - `distance`: 1 per metre, nothing else;
/// - `mei2006`: 1 per cell length, stop 0.5, turns 0.4/0.6/0.8/1.0 (Mei et al. 2006, Fig. 6);
/// - `pioneer3dx`: Rappaport 2016 eq. 2-3 (moving 22.38 W at 1.2 m/s, standing 13.5 W), in Wh;
///   a stop stands still for `stop_time_s` (1 s), a turn rotates at `turn_rate_deg_s`
///   (90 deg/s) drawing the moving power.
/// Every preset takes per_metre, per_cell, per_stop and per_turn overrides; travel must cost
/// energy (per_metre or per_cell > 0).
using EnergyRegistry = Registry<EnergyModel>;
[[nodiscard]] const EnergyRegistry& energy_registry();

/// Preset `name` with its defaults. Throws ConfigError for an unknown name, listing the known.
[[nodiscard]] EnergyModel energy_preset(const std::string& name);

/// Reads "mei2006" or `{"preset": "mei2006", "per_stop": 0.7, ...}` (preset default
/// "distance", then its declared overrides). Throws one ConfigError naming `where`/key for
/// every unknown key or bad value.
[[nodiscard]] EnergyModel energy_model_from_json(const nlohmann::json& j, const std::string& where);

void to_json(nlohmann::json& j, const EnergyModel& m);

}  // namespace world
}  // namespace fsweep
