#pragma once
/// @file simulation.hpp
/// The exploration loop (docs/architecture.md, "The simulation loop and metrics"): sense, update frontiers,
/// ask the strategy, plan, move cell by cell sensing after every step, repeat until an end reason applies.

#include <cstdint>
#include <memory>
#include <vector>

#include "core/random.hpp"
#include "planners/planner.hpp"
#include "sim/battery.hpp"
#include "sim/grid_distance_oracle.hpp"
#include "sim/heuristics.hpp"
#include "sim/run_result.hpp"
#include "sim/run_spec.hpp"
#include "strategies/strategy.hpp"
#include "world/frontiers.hpp"
#include "world/known_map.hpp"
#include "world/segmentation.hpp"
#include "world/sensor.hpp"

namespace fsweep {
inline namespace sim {

/// Resolves `"target": "random"` in strategy params (any strategy with a "target" key, e.g.
/// target_seeking): returns a copy with "target" set to [x, y], a cell drawn uniformly among the
/// nonzero cells of `reachable` (free cells reachable from the start on the true map) other
/// than `start`, in row-major order, with the stream "target" of `seed` (src/core/random.hpp).
/// Params without that value are returned unchanged. Throws ConfigError
/// ("strategy/params/target") when no candidate cell exists.
[[nodiscard]] nlohmann::json resolve_random_target(const nlohmann::json& strategy_params,
                                                   const Grid<std::uint8_t>& reachable, Cell start,
                                                   std::uint64_t seed);

/// The state of one run, as a copyable value: copying a Simulation clones its strategy and
/// planner, so a run can be forked at a decision (docs/architecture.md, "Sweeps, keys, shards and the weight
/// search", weight search). No globals; every random stream comes from the run seed.
///
/// Rules of the loop:
/// - The robot senses at the start and after every cell step.
/// - Frontier goals are cluster representatives (split at `cluster_max_length_m`).
/// - A goal whose visit revealed nothing while it is still a frontier cell is dropped (it is
///   unobservable, e.g. behind a sensor blind spot); so is a goal the planner cannot reach.
/// - Arriving at the dock recharges the battery (a recharge is counted when it was not full).
/// - A move the battery cannot pay for ends the run with BatteryDepleted.
/// - A GoTo with Decision::max_steps > 0 travels at most that many cell steps, then the next
///   step() decides again (per-step re-decisions, e.g. target_seeking). Such a journey cut
///   short after moving is not counted as a quiet decision for `stuck_decisions` (it resets
///   the count when it revealed cells, as any decision).
/// - A Finish with a navigation outcome (Decision::Outcome) ends the run as TargetReached or
///   TargetUnreachable with the decision's detail; otherwise finish() checks for frontiers.
/// - Heuristics (RunSpec::heuristics, src/sim/heuristics.hpp):
///   - `rr`: after every cell step of a journey to a GoTo goal, before the goal is reached, the
///     goal is re-checked; the journey stops (and the next step() decides again, counted in
///     rr_redecisions) when it is no longer open. A goal that was a frontier cell when chosen
///     is open while it is still a frontier cell (the paper's test: it still borders unknown
///     space); any other goal (a sampled view point) while some frontier cell lies within the
///     sensor range of it (Euclidean, cell centres). Returns to the dock are never cut.
///   - `seg`: before every decision the known map is segmented (segmentation.hpp; recomputed
///     whenever cells were revealed since the last time). When the robot's segment is a room
///     (Segmentation::room; not a corridor) and the representative (the candidate goal) of
///     some cluster lies in it, only such clusters are passed to the strategy and
///     Observation::segment_mask flags the segment's cells; otherwise all clusters are passed
///     and the mask is null. (Restricting in corridors too, which in our segmentation form
///     one segment through the building, explored every corridor before the rooms: +9% distance
///     for closest_frontier on generated offices, against -2% when restricting in rooms only.)
class Simulation {
 public:
  /// Builds the run; throws ConfigError for a bad spec (unknown plugin, dock in an obstacle).
  explicit Simulation(const RunSpec& spec);
  Simulation(const Simulation& other);
  Simulation& operator=(const Simulation& other);
  Simulation(Simulation&&) noexcept = default;
  Simulation& operator=(Simulation&&) noexcept = default;
  ~Simulation() = default;

  /// One decision: decide, plan, travel. Returns false once the run has ended.
  bool step();
  /// Steps until the end and returns the result.
  [[nodiscard]] RunResult run();

  [[nodiscard]] bool ended() const { return ended_; }
  /// The result so far (final once ended()).
  [[nodiscard]] RunResult result() const;

  [[nodiscard]] const KnownMap& known() const { return known_; }
  [[nodiscard]] Cell robot() const { return robot_; }

 private:
  void sense();
  bool move_to(Cell next);
  void sample_progress();
  void end(EndReason reason, std::string detail = {});
  void finish();
  /// Ends the run TargetReached with `detail` and sets target_path_m and target_path_ratio.
  void reach_target(const std::string& detail);
  /// True when sim.stop_at_cell is set and that cell is known free.
  [[nodiscard]] bool stop_cell_known_free() const;
  [[nodiscard]] double coverage() const;
  [[nodiscard]] double completeness() const;
  /// `seg`: restricts `clusters` to the robot's segment; returns the mask for the Observation
  /// (null when nothing is restricted).
  const std::vector<std::uint8_t>* segment_candidates(std::vector<FrontierCluster>& clusters);
  /// `rr`: whether the journey to `goal` should go on (see the class comment).
  [[nodiscard]] bool goal_still_open(Cell goal, bool goal_was_frontier) const;

  RunSpec spec_;
  std::unique_ptr<Strategy> strategy_;
  std::unique_ptr<Planner> planner_;
  Sensor sensor_;
  KnownMap known_;
  FrontierMap frontiers_;
  Rng sensor_rng_;
  GridDistanceOracle oracle_;
  IncrementalDistanceField dock_field_;
  bool dock_field_ready_ = false;
  std::vector<int> dock_field_pending_;  // revealed since dock_field_ was last updated
  Grid<std::uint8_t> reachable_;
  int reachable_count_ = 0;
  int known_reachable_ = 0;
  std::vector<std::uint8_t> dropped_;
  Grid<std::uint8_t> observable_;
  int observable_count_ = 0;
  int known_observable_ = 0;
  Heuristics heuristics_;
  Segmentation segmentation_;
  int segmented_known_count_ = -1;  // known_.known_count() when segmentation_ was computed
  std::vector<std::uint8_t> segment_mask_;

  Cell robot_{};
  int heading_ = 0;
  Cell dock_{};
  Cell previous_position_{};
  std::optional<Cell> previous_goal_;
  /// SimParams::stop_at_cell, resolved ("random" drawn); empty without one.
  std::optional<Cell> stop_cell_;
  Battery battery_{0.0, 1.0};

  double resolution_m_ = 1.0;
  double cluster_max_length_m_ = 0.0;
  double progress_step_m_ = 1.0;
  long max_steps_ = 0;
  double next_progress_m_ = 0.0;
  int quiet_decisions_ = 0;

  RunMetrics metrics_;
  std::vector<ProgressSample> progress_;
  std::vector<Cell> trajectory_;
  std::vector<int> recharge_steps_;
  bool ended_ = false;
  EndReason end_ = EndReason::Error;
  std::string end_detail_;
};

/// The observable cells of `map` for a robot whose reachable free cells are `reachable`
/// (reachable_free()): those cells plus their 4-neighbours in the grid, flagged 1. Equals the
/// cells that a scan (sensor.hpp, range >= one diagonal cell, any heading) from some cell of
/// `reachable` can see; see RunMetrics::completeness. O(cells).
[[nodiscard]] Grid<std::uint8_t> observable_cells(const WorldMap& map, const Grid<std::uint8_t>& reachable);

/// Runs `spec` to the end: a pure function of the spec (and its seed).
[[nodiscard]] RunResult simulate(const RunSpec& spec);

}  // namespace sim
}  // namespace fsweep
