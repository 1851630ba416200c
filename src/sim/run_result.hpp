#pragma once
/// @file run_result.hpp
/// What a run measured.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "world/grid.hpp"
#include "world/known_map.hpp"

namespace fsweep {
inline namespace sim {

/// Why a run ended.
enum class EndReason {
  Complete,           ///< no reachable frontier left
  RangeLimited,       ///< frontiers left, but none in the battery's reach from the dock
  TargetReached,      ///< navigation runs: the target cell was reached
  TargetUnreachable,  ///< navigation runs: the target is known to be out of reach (detail says why)
  StepLimit,          ///< the step cap was hit
  Stuck,              ///< too many decisions in a row revealed nothing
  BatteryDepleted,    ///< the battery ran out away from the dock (the reach estimate failed)
  Error,              ///< a planner could not reach the dock, or another broken invariant
};

[[nodiscard]] std::string_view to_string(EndReason r);

/// Per-run metrics (docs/dev/architecture.md, "The simulation loop and metrics"). Areas in m^2, distances in
/// metres, energy in the energy model's unit. Fields added later are declared last, so that CSV columns (in
/// declaration order, report/runs_schema.hpp) are only ever appended.
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
  /// Map completeness (Holz et al. 2010, section V), in [0, 1]: |K & O| / |O| (1 when O is
  /// empty), where K is the set of known cells (free or occupied) and O the observable cells:
  /// those a scan from some reachable free cell could see, with the run's sensor and any
  /// heading. Under the sensor's ray rules (sensor.hpp) and a range of at least one diagonal
  /// cell (checked by the Simulation), O is exactly R plus the 4-neighbours of R, R = the free
  /// cells reachable from the start (observable_cells() in run_setup.hpp, checked against the
  /// rays in tests/sim/test_completeness.cpp): every cell a clear ray reaches is entered from
  /// a free cell beside it that is 4-connected to the robot, and a 4-neighbour is always in
  /// view. The robot only stands on cells of R, so K is inside O and completeness is
  /// known / observable. Unlike `coverage` (free cells only) it counts the walls too: a wall
  /// face never scanned, e.g. in a corner a re-checking robot skipped, lowers it; with
  /// sensor misses (miss_probability) so do the missed cells.
  /// Relation to the paper: with cell probabilities 0, 0.5 or 1, a cell's entropy is 0 bits if
  /// known and 1 bit if unknown, so a map's entropy over O is the count of its unknown cells.
  /// The share of the removable entropy removed, (H_0 - H_expl) / (H_0 - H_full) with H_0 the
  /// empty map's and H_full the fully explored map's (0 over O), is exactly |K & O| / |O|.
  /// (The paper prints c = (1 - H_full / H_expl) * 100, which would be 0 for a complete map;
  /// we read it as this ratio.) Without corner cutting an unknown observable cell always leaves
  /// a frontier cell next to it, so a `complete` run without dropped goals and without a target
  /// margin (SimParams::target_margin_m, which keeps cells near walls from being goals) has
  /// completeness exactly 1. With corner cutting R also holds free cells reached only through a
  /// diagonal gap between two occupied cells, which no ray passes and no frontier marks: a
  /// `complete` run can end below 1 (docs/model.md, "Completeness").
  double completeness = 0.0;
  /// `rr` heuristic (src/sim/heuristics.hpp): journeys cut short because the goal stopped
  /// being worth reaching, each followed by a new decision. 0 without `rr`.
  int rr_redecisions = 0;
  /// `seg` heuristic: time spent segmenting the known map (src/world/segmentation.hpp), in
  /// seconds (not part of decision_time_s). 0 without `seg`.
  double segmentation_time_s = 0.0;
  /// Navigation runs (a strategy with a target, e.g. target_seeking): the distance travelled
  /// to the target (metres), distance_m of a run that ended `target_reached`; 0 otherwise.
  double target_path_m = 0.0;
  /// The shortest path from the start to the target on the fully known map (metres, the
  /// run's corner rule, octile steps); 0 without a target or when the target is not reachable.
  double target_shortest_m = 0.0;
  /// target_path_m / target_shortest_m, >= 1 (a competitive ratio for navigation); 0 when the
  /// target was not reached or target_shortest_m is 0 (the robot started on the target).
  double target_path_ratio = 0.0;
  /// The target cell of a navigation run (as given, or as drawn for `"target": "random"`);
  /// -1 and -1 without a target.
  int target_x = -1;
  int target_y = -1;
  /// With a coverage target (SimParams::stop_at_coverage): distance_m when the coverage
  /// reached it, which ended the run `target_reached`; empty without a target or when the run
  /// ended before reaching it.
  std::optional<double> distance_to_coverage_target_m;

  /// Every field equal (doubles exactly; the timing fields too).
  friend bool operator==(const RunMetrics&, const RunMetrics&) = default;
};

/// One point of the progress curve.
struct ProgressSample {
  double distance_m = 0.0;
  double explored_area_m2 = 0.0;
  double coverage = 0.0;
  double energy = 0.0;
  friend bool operator==(const ProgressSample&, const ProgressSample&) = default;
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
  friend bool operator==(const RunResult&, const RunResult&) = default;
};

}  // namespace sim
}  // namespace fsweep
