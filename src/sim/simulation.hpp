#pragma once
/// @file simulation.hpp
/// The exploration loop (docs/dev/architecture.md, "The simulation loop and metrics"): sense, update
/// frontiers, ask the strategy, plan, move cell by cell sensing after every step, repeat until an end reason
/// applies.

#include <cstdint>
#include <memory>
#include <optional>
#include <span>

#include "planners/planner.hpp"
#include "sim/belief.hpp"
#include "sim/clone_ptr.hpp"
#include "sim/heuristics_policy.hpp"
#include "sim/metrics_recorder.hpp"
#include "sim/robot_state.hpp"
#include "sim/run_result.hpp"
#include "sim/run_setup.hpp"
#include "sim/run_spec.hpp"
#include "strategies/strategy.hpp"
#include "world/known_map.hpp"
#include "world/sensor.hpp"

namespace fsweep {
inline namespace sim {

/// The state of one run, as a copyable value, so a run can be forked at a decision
/// (docs/dev/architecture.md, "Sweeps, keys, shards and the weight search"). It is made of value parts that
/// refer to nothing outside themselves between calls: RobotState, Belief, MetricsRecorder, HeuristicsPolicy,
/// the sensor (whose ray tables are shared), the strategy and the planner (copied by clone()), and the
/// distance oracle's search arrays (scratch: a copy starts empty, as a cloned planner's). What never changes
/// during a run (the spec, the true map, the reachable and observable cells: RunSetup) is shared between a
/// run and its forks, and so is the dock's distance field until one of them updates it (DockField,
/// copy-on-write). Copies are therefore `= default` and independent of each other; a fork copies about 3
/// bytes per map cell (the known map, the frontier flags, the dropped goals) plus the trajectory and the
/// progress curve. No globals; every random stream comes from the run seed.
///
/// Rules of the loop:
/// - The robot senses at the start and after every cell step.
/// - Frontier goals are cluster representatives (split at `cluster_max_length_m`).
/// - A goal whose visit revealed nothing while it is still a frontier cell is dropped (it is
///   unobservable, e.g. behind a sensor blind spot); so is a goal the planner cannot reach.
/// - A robot whose field of view is narrower than 360 degrees looks around (look_around()) at
///   the goal of each GoTo journey it reaches, also when it stands on the goal already (the
///   first decision of a run that starts facing a wall); not at the dock or the stop cell.
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
  /// A fork: an independent copy of the run's state (strategy and planner cloned, RunSetup
  /// shared). Stepping one never changes the other.
  Simulation(const Simulation&) = default;
  Simulation& operator=(const Simulation&) = default;
  Simulation(Simulation&&) noexcept = default;
  Simulation& operator=(Simulation&&) noexcept = default;
  ~Simulation() = default;

  /// Keeps what the sensor sees from each cell of the map once a scan from it has swept
  /// (RunSetup::keep_sight), for this run and all its forks, made before or after: for callers
  /// that run one map many times, as the weight search does. A single run scans too few cells
  /// twice to gain by it (callgrind of one Manhattan run: 10% more instructions). The results are
  /// the same.
  void keep_sight() const { setup_->keep_sight(sensor_); }

  /// One decision: decide, plan, travel. Returns false once the run has ended.
  bool step();
  /// Steps until the end and returns the result.
  [[nodiscard]] RunResult run();

  /// The exact weight search's hooks (weightsearch/exact_search.hpp).
  ///
  /// choice(): when the run's strategy is linear-scored (LinearScoredStrategy) and the next step()
  /// chooses by its weights, the candidates of that choice, as
  /// LinearScoredStrategy::candidates_within(bounds) gives them for the weight vectors the
  /// caller asks about (segment restriction included; possibly just one). Null when the next
  /// step's decision does not depend on the weights: the run ended or is at its step cap, the stop
  /// cell, a decision the strategy makes without its weights (fixed_decision()), no candidate, another
  /// kind of strategy. Changes nothing in the run's result (its
  /// searches warm the distance caches). The candidates stay valid until the next call of a
  /// non-const member.
  [[nodiscard]] const Candidates* choice(const WeightBounds& bounds);
  /// step(), with the strategy's choice replaced by candidate `candidate` of the candidates the last
  /// choice() returned (on this simulation or on the one it was copied from since): the step a run
  /// whose weights make argmin_linear() choose that candidate takes. Throws std::logic_error
  /// without such candidates.
  bool step_choosing(int candidate);
  /// The candidates the last choice() returned on this state (on this simulation or on the one it
  /// was copied from since), or null when there are none: what step_choosing() chooses among.
  [[nodiscard]] const Candidates* pending_choice() const {
    return pending_ ? &pending_->candidates : nullptr;
  }

  /// Makes the run's linear-scored strategy score by `weights` from now on
  /// (LinearScoredStrategy::set_weights). Throws std::logic_error for another kind of strategy and
  /// std::invalid_argument for weights the strategy does not allow.
  void set_weights(std::span<const double> weights);

  /// A hash of every decision made so far (kind, goal, step limit, outcome, in order): runs with
  /// equal traces decided alike (but for a 64-bit collision). The exact search identifies
  /// behaviours by it (Behaviour::trace).
  [[nodiscard]] std::uint64_t decision_trace() const { return trace_; }
  /// How many calls of step() or step_choosing() found the run going (each one decision, or the
  /// end at the step cap): a run's state is a function of its spec, its weights and this count.
  /// The weight search's certificate names the state where it pruned a region by it.
  [[nodiscard]] std::uint64_t steps_taken() const { return steps_taken_; }

  [[nodiscard]] bool ended() const { return recorder_.ended(); }
  /// The metrics counted so far, without the map-dependent ones result() completes (areas,
  /// coverage): what the exact search's branch and bound reads.
  [[nodiscard]] const RunMetrics& metrics_so_far() const { return recorder_.metrics(); }
  /// With a coverage target (SimParams::stop_at_coverage), a lower bound of the distance at
  /// which this run reaches it, for the weight search's branch and bound: the distance then
  /// once reached; distance_m once ended without reaching it (it never will: any value
  /// bounds it); else distance_m plus the travel that can reveal the cells still needed from
  /// where the robot stands with what its battery holds (travel_to_reveal_m(), reveal_bound.hpp).
  /// The first call builds the map's RevealGeometry (RunSetup::reveal) and counts the unknown
  /// cells by it; the last value is kept for the state it was taken in. Unlike the other const
  /// calls it writes those caches: not to be called from two threads at once on one Simulation.
  [[nodiscard]] double coverage_target_bound_m() const;
  /// The result so far (final once ended()).
  [[nodiscard]] RunResult result() const&;
  /// The same, moving the trajectory and the progress curve out of a simulation that is done
  /// (simulate(): a long run's trajectory is not copied at its end).
  [[nodiscard]] RunResult result() &&;

  [[nodiscard]] const KnownMap& known() const { return belief_.known(); }
  /// What never changes during the run, shared with its forks (RunSetup).
  [[nodiscard]] const RunSetup& setup() const { return *setup_; }
  [[nodiscard]] Cell robot() const { return robot_.position; }

 private:
  /// One decision's journey toward its goal (step()).
  struct Journey;

  /// The candidates choice() found, and which of the decision's strategy calls they came from (0:
  /// the first; 1: the second, without the segment restriction).
  struct PendingChoice {
    Candidates candidates;
    int call = 0;
  };

  /// step() with the strategy's decision made by `ask(observation, call)` (call: 0 for the first
  /// strategy call of the decision, 1 for the second, see decide()).
  template <typename Ask>
  bool step_with(Ask&& ask);
  /// Decides (step 1 of step()) by `ask` as step_with() says; empty when the run ended instead
  /// (the stop cell reached). `commit`: count the decision in the metrics and end the run at the
  /// stop cell; without it (choice()) nothing but caches changes.
  template <typename Ask>
  std::optional<Decision> decide(Ask&& ask, bool commit);
  /// `recorded` (the recorder's result) completed with what depends on the map: areas, coverage,
  /// the final map and frontiers (result()).
  [[nodiscard]] RunResult completed(RunResult recorded) const;
  /// Plans and travels toward `journey.goal` (step 2 of step()); false when the run ended.
  bool travel(const Decision& decision, const Journey& journey);
  /// At the goal of a GoTo `decision` the robot reached or stands on (not the stop cell of
  /// sim.stop_at_cell), with a field of view narrower than 360 degrees: turns in place toward
  /// each unknown neighbour of its cell it has not faced, the smallest turn first (clockwise on
  /// a tie), scanning after each turn, until none is left; each turn costs a stop and the
  /// turn's energy (EnergyModel::turn), as in a path.
  void look_around(const Decision& decision);
  /// After a journey (step 3 of step()): recharge, drop an unobservable goal, the stuck rule.
  void arrive(const Decision& decision, const Journey& journey);
  /// Ends the run on a Finish decision (or a ReturnToDock at the dock).
  void finish();
  void sense();
  bool move_to(Cell next);
  void sample_progress();
  /// True when sim.stop_at_cell is set and that cell is known free.
  [[nodiscard]] bool stop_cell_known_free() const;

  std::shared_ptr<const RunSetup> setup_;
  ClonePtr<Strategy> strategy_;
  ClonePtr<Planner> planner_;
  Sensor sensor_;
  RobotState robot_;
  Belief belief_;
  MetricsRecorder recorder_;
  HeuristicsPolicy heuristics_;
  /// The distance oracle's search arrays (scratch: a fork starts with empty ones).
  DistanceScratch scratch_;
  /// What the last choice() found, until the next step.
  std::optional<PendingChoice> pending_;
  /// coverage_target_bound_m()'s last value and the state it was for (the branch and bound asks
  /// for the bound of every run of a branch at each of its decisions, and most did not move).
  struct TargetBound {
    double distance_m = -1.0;
    double battery = 0.0;
    int known_reachable = -1;
    Cell robot{};
    double value = 0.0;
  };
  mutable TargetBound target_bound_;
  /// decision_trace().
  std::uint64_t trace_ = 0;
  std::uint64_t steps_taken_ = 0;
};

/// Runs `spec` to the end: a pure function of the spec (and its seed).
[[nodiscard]] RunResult simulate(const RunSpec& spec);

}  // namespace sim
}  // namespace fsweep
