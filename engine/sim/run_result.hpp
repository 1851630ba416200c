#pragma once
/// @file run_result.hpp
/// What a run measured.

#include <string>
#include <string_view>
#include <vector>

#include "engine/world/grid.hpp"
#include "engine/world/known_map.hpp"

namespace fsweep {

/// Why a run ended.
enum class EndReason {
  Complete,         ///< no reachable frontier left
  RangeLimited,     ///< frontiers left, but none in the battery's reach from the dock
  TargetReached,    ///< navigation runs: the target cell was reached
  StepLimit,        ///< the step cap was hit
  Stuck,            ///< too many decisions in a row revealed nothing
  BatteryDepleted,  ///< the battery ran out away from the dock (the reach estimate failed)
  Error,            ///< a planner could not reach the dock, or another broken invariant
};

[[nodiscard]] std::string_view to_string(EndReason r);

/// Per-run metrics (DESIGN.md section 6). Areas in m^2, distances in metres, energy in the
/// energy model's unit.
struct RunMetrics {
  double distance_m = 0.0;
  double energy = 0.0;
  int stops = 0;
  int turns = 0;
  double turned_deg = 0.0;
  int decisions = 0;
  int recharges = 0;
  long steps = 0;
  /// Distance travelled when the last cell was revealed: what it took to reach the final
  /// coverage (the travel after it, e.g. the way back to the dock, excluded).
  double distance_to_final_coverage_m = 0.0;
  /// Known free area.
  double explored_area_m2 = 0.0;
  /// explored_area_m2 / distance_m (0 when the robot did not move).
  double area_per_metre = 0.0;
  /// Known free and occupied area.
  double known_area_m2 = 0.0;
  /// Free area reachable from the start (ground truth, same motion rule).
  double reachable_area_m2 = 0.0;
  /// Known reachable free cells / reachable free cells, in [0, 1].
  double coverage = 0.0;
  /// Reachable free area still unknown at the end.
  double residual_unknown_m2 = 0.0;
  /// Frontier cells left at the end.
  int frontier_cells_left = 0;
  /// Goals dropped because arriving revealed nothing, or because no path was found.
  int dropped_goals = 0;
  int plan_failures = 0;
  long planner_expansions = 0;
  double planner_time_s = 0.0;
  double decision_time_s = 0.0;
  double wall_time_s = 0.0;
};

/// One point of the progress curve.
struct ProgressSample {
  double distance_m = 0.0;
  double explored_area_m2 = 0.0;
  double coverage = 0.0;
  double energy = 0.0;
};

struct RunResult {
  EndReason end = EndReason::Error;
  /// Free text for Error/Stuck, empty otherwise.
  std::string end_detail;
  RunMetrics metrics;
  std::vector<ProgressSample> progress;
  /// Every cell the robot occupied, in order (the start first).
  std::vector<Cell> trajectory;
  /// Indices into trajectory where a recharge happened.
  std::vector<int> recharge_steps;
  KnownMap final_known;
  std::vector<int> final_frontiers;
  Cell dock;
};

}  // namespace fsweep
