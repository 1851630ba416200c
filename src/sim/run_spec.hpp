#pragma once
/// @file run_spec.hpp
/// Everything one simulation run depends on. A run is a pure function of its RunSpec.

#include <cstdint>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "planners/registry.hpp"
#include "sim/heuristics.hpp"
#include "strategies/registry.hpp"
#include "world/energy_model.hpp"
#include "world/sensor.hpp"
#include "world/world_map.hpp"

namespace fsweep {
inline namespace sim {

/// The robot: sensor, motion rules, energy and battery (docs/dev/architecture.md, "Robot, motion and
/// energy").
struct RobotParams {
  SensorParams sensor;
  EnergyModel energy;
  /// Battery capacity in the energy model's unit; +infinity = unlimited (never recharges).
  /// With the `distance` model this is the range per charge in metres.
  double battery_capacity = std::numeric_limits<double>::infinity();
  /// Dock cell; default: the map's start cell.
  std::optional<Cell> dock;
  /// Heading at the start, 0..7 (grid.hpp: 0 east, clockwise on screen).
  int start_heading = 0;
  /// Diagonal moves past an occupied orthogonal neighbour (default off: MovingAI rule).
  bool allow_corner_cutting = false;
};

/// The declared parameters (core/params.hpp) of {"sensor": {...}, "energy": "mei2006" | {...},
/// "battery": number | null, "dock": [x, y] | null, "start_heading": 0..7,
/// "allow_corner_cutting": bool}; `fsweep describe robot` prints them.
[[nodiscard]] const ParamDecl<RobotParams>& robot_params();
/// robot_params().read(j, where): every problem at its JSON path, as one ConfigError.
[[nodiscard]] RobotParams robot_params_from_json(const nlohmann::json& j, const std::string& where);
/// robot_params().write(r) with the sensor written by its own to_json (sensor.hpp: the beam
/// model's keys only when they are not defaults); run keys and runs.csv record this.
void to_json(nlohmann::json& j, const RobotParams& r);

/// Loop settings (docs/dev/architecture.md, "The simulation loop and metrics").
struct SimParams {
  /// Frontier clusters are split into pieces of at most this length (metres); <= 0: the
  /// sensor range (as Rappaport 2016 section 3.3).
  double cluster_max_length_m = 0.0;
  /// Hard cap on cell steps; 0: automatic, 100 x the reachable free cells + 1000.
  long max_steps = 0;
  /// End as `stuck` after this many consecutive decisions that revealed no cell.
  int stuck_decisions = 100;
  /// Progress curve sampling interval (metres of travel); <= 0: 10 x resolution.
  double progress_step_m = 0.0;
  /// JSON "stop_at_cell": [x, y] (cells) or "random"; absent (default): no stop cell, and the
  /// key is left out of to_json so run keys of configurations without it are unchanged.
  /// With a stop cell any strategy becomes a navigation baseline: a journey is cut short when
  /// the cell becomes known free; once it is known free and reachable through known free space
  /// the robot goes there by the shortest path (instead of asking the strategy), and the run
  /// ends `target_reached` on arrival (a cell never known free and reachable, e.g. in a wall,
  /// leaves the run to end as the strategy's would), with the
  /// navigation metrics (target_*) about this cell. "random" draws the cell as
  /// `"target": "random"` does (resolve_random_target(): same stream "target" of the run seed,
  /// so the same cell as a target_seeking run with that seed on that map).
  std::optional<Cell> stop_at_cell;
  bool stop_at_random = false;
  /// Holz 2010 section III's safety margin for goals (metres; 0, the default: none, and left out
  /// of to_json): a frontier cell whose centre is closer than this to a known occupied cell
  /// (to the nearest point of its square) is never offered to a strategy as a goal, as if
  /// dropped. Paths may still pass such cells: only goals keep the margin.
  double target_margin_m = 0.0;
  /// A coverage target, a share in (0, 1] (0, the default: none, and left out of to_json): the
  /// run ends `target_reached` at the scan that makes the known reachable free cells at least
  /// this share of the reachable free cells (RunMetrics::coverage >= it), and
  /// RunMetrics::distance_to_coverage_target_m records the distance then.
  double stop_at_coverage = 0.0;
};

/// The declared parameters of the sweep's "sim" object; `fsweep describe sim` prints them.
[[nodiscard]] const ParamDecl<SimParams>& sim_params();
/// sim_params().read(j, where): every problem at its JSON path, as one ConfigError.
[[nodiscard]] SimParams sim_params_from_json(const nlohmann::json& j, const std::string& where);
void to_json(nlohmann::json& j, const SimParams& s);

/// One run.
struct RunSpec {
  std::shared_ptr<const WorldMap> map;
  /// The strategy, resolved once (strategies/registry.hpp): name, resolved params, maker.
  StrategyConfig strategy = configure_strategy("closest_frontier", nullptr);
  /// The rr/seg heuristics (sim/heuristics.hpp). Empty: none, and none recorded (run keys
  /// and columns of configurations that never name heuristics stay as they were); given,
  /// even as none, they are recorded with the strategy's params (`strategy.heuristics`).
  std::optional<Heuristics> heuristics;
  /// The planner, resolved once (planners/registry.hpp): name, resolved params, maker.
  PlannerConfig planner = configure_planner("astar", nullptr);
  RobotParams robot;
  SimParams sim;
  std::uint64_t seed = 0;
};

/// The strategy parameters as run keys and output columns record them: the resolved params,
/// plus "heuristics" (canonical list) when RunSpec::heuristics is given.
[[nodiscard]] nlohmann::json recorded_strategy_params(const RunSpec& spec);

}  // namespace sim
}  // namespace fsweep
