#include "sim/simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/csv_format.hpp"
#include "core/random.hpp"
#include "planners/registry.hpp"
#include "strategies/registry.hpp"

namespace fsweep {
inline namespace sim {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

}  // namespace

std::string_view to_string(EndReason r) {
  switch (r) {
    case EndReason::Complete:
      return "complete";
    case EndReason::RangeLimited:
      return "range_limited";
    case EndReason::TargetReached:
      return "target_reached";
    case EndReason::TargetUnreachable:
      return "target_unreachable";
    case EndReason::StepLimit:
      return "step_limit";
    case EndReason::Stuck:
      return "stuck";
    case EndReason::BatteryDepleted:
      return "battery_depleted";
    case EndReason::Error:
      return "error";
  }
  return "error";
}

/// The goal of one decision and what step() noted before travelling toward it.
struct Simulation::Journey {
  Cell goal;
  /// `rr` applies to this journey, and whether the goal was a frontier cell when chosen.
  bool recheck = false;
  bool goal_was_frontier = false;
  /// Known cells, steps and whether the stop cell was known free before the journey.
  int known_before = 0;
  long steps_before = 0;
  bool stop_known_before = false;
};

Simulation::Simulation(const RunSpec& spec) {
  // The checks throw in this order: map, strategy, heuristics, planner, dock, sensor range,
  // stop cell.
  auto setup = std::make_shared<RunSetup>(spec);
  const WorldMap& map = setup->map();
  const nlohmann::json strategy_params =
      resolve_random_target(spec.strategy.params, setup->reachable, map.start, spec.seed);
  const StrategyConfig& strategy = strategy_params == spec.strategy.params
                                       ? spec.strategy
                                       : configure_strategy(spec.strategy.name, strategy_params);
  strategy_ = ClonePtr<Strategy>(strategy.make(derive_seed(spec.seed, "strategy")));
  heuristics_ = HeuristicsPolicy(spec.heuristics.value_or(Heuristics{}));
  planner_ = ClonePtr<Planner>(spec.planner.make());
  check_sensor_range(*setup);
  sensor_ = Sensor(spec.robot.sensor, setup->resolution_m);
  belief_ = Belief(*setup);
  robot_ = RobotState(*setup);
  setup->stop_cell = stop_cell_of(*setup);

  recorder_ = MetricsRecorder(robot_.position);
  RunMetrics& m = recorder_.metrics();
  m.reachable_area_m2 = setup->reachable_count * setup->resolution_m * setup->resolution_m;
  // Navigation metrics: the target cell (the strategy's, else the stop cell) and the shortest
  // start-target path on the fully known map.
  if (const std::optional<Cell> target = strategy_->target() ? strategy_->target() : setup->stop_cell) {
    m.target_x = target->x;
    m.target_y = target->y;
    m.target_shortest_m = shortest_path_from_start_m(*setup, *target);
  }
  setup_ = std::move(setup);

  sense();
  sample_progress();
}

void Simulation::sense() {
  if (belief_.sense(sensor_, *setup_, robot_.position, robot_.heading, robot_.dock) > 0) {
    recorder_.metrics().distance_to_final_coverage_m = recorder_.metrics().distance_m;
  }
  // sim.stop_at_coverage: the scan that reaches the target ends the run.
  const double share = setup_->spec.sim.stop_at_coverage;
  if (share > 0.0 && !recorder_.ended() &&
      belief_.known_reachable() >= share * static_cast<double>(setup_->reachable_count)) {
    RunMetrics& m = recorder_.metrics();
    m.distance_to_coverage_target_m = m.distance_m;
    recorder_.end(EndReason::TargetReached, "coverage target " + format_number(share) + " reached");
  }
}

void Simulation::sample_progress() {
  const double cell_area = setup_->resolution_m * setup_->resolution_m;
  recorder_.sample_progress(setup_->progress_step_m, belief_.known().free_count() * cell_area,
                            belief_.coverage(*setup_));
}

bool Simulation::move_to(Cell next) {
  const StepCost cost = robot_.step_cost(next, *setup_);
  RunMetrics& m = recorder_.metrics();
  if (!robot_.battery.draw(cost.energy, cost.metres)) {
    recorder_.end(EndReason::BatteryDepleted, "battery empty at " + cell_text(robot_.position));
    return false;
  }
  if (cost.turns != 0) {
    ++m.stops;
    ++m.turns;
    m.turned_deg += 45.0 * cost.turns;
  }
  recorder_.record_step(cost.heading, setup_->resolution_m);
  m.energy += cost.energy;
  ++m.steps;
  robot_.position = next;
  robot_.heading = cost.heading;
  recorder_.record_position(next);
  sense();
  sample_progress();
  return !recorder_.ended();
}

bool Simulation::stop_cell_known_free() const {
  const std::optional<Cell>& stop = setup_->stop_cell;
  return stop && belief_.known().in_bounds(*stop) && belief_.known().is_free(*stop);
}

bool Simulation::step() {
  return step_with([this](const Observation& obs, int /*call*/) { return strategy_->decide(obs); });
}

const Candidates* Simulation::choice(const WeightBounds& bounds) {
  pending_.reset();
  LinearScoredStrategy* linear = strategy_->linear_scored();
  if (linear == nullptr || recorder_.ended() || recorder_.metrics().steps >= setup_->max_steps)
    return nullptr;
  PendingChoice found;
  bool chose = false;
  // The decision as the strategy's own decide() makes it (LinearScoredStrategy::decide), noting the
  // candidates of the call whose choice it is.
  (void)decide(
      [&](const Observation& obs, int call) {
        chose = false;
        if (std::optional<Decision> fixed = linear->fixed_decision(obs)) return std::move(*fixed);
        Candidates c = linear->candidates_within(obs, bounds);
        chose = !c.cells.empty();
        if (!chose) return linear->on_no_candidate(obs);
        found = PendingChoice{std::move(c), call};
        return Decision::go_to(found.candidates.cells.front());
      },
      false);
  if (!chose) return nullptr;
  pending_ = std::move(found);
  return &pending_->candidates;
}

void Simulation::set_weights(std::span<const double> weights) {
  LinearScoredStrategy* linear = strategy_->linear_scored();
  if (linear == nullptr) throw std::logic_error("Simulation::set_weights: the strategy is not linear-scored");
  pending_.reset();
  linear->set_weights(weights);
}

bool Simulation::step_choosing(int candidate) {
  if (!pending_ || candidate < 0 ||
      static_cast<std::size_t>(candidate) >= pending_->candidates.cells.size()) {
    throw std::logic_error("Simulation::step_choosing: no candidate " + std::to_string(candidate) +
                           " of a choice() on this state");
  }
  const PendingChoice pending = std::move(*pending_);
  pending_.reset();
  LinearScoredStrategy* const scored = strategy_->linear_scored();
  if (scored == nullptr)
    throw std::logic_error("Simulation::step_choosing: the strategy is not linear-scored");
  LinearScoredStrategy& linear = *scored;
  return step_with([&](const Observation& obs, int call) {
    // The call before the pending one decided without the weights or found no candidate
    // (choice() saw it so).
    if (call != pending.call) {
      if (std::optional<Decision> fixed = linear.fixed_decision(obs)) return std::move(*fixed);
      return linear.on_no_candidate(obs);
    }
    return linear.choose(obs, pending.candidates.cells[static_cast<std::size_t>(candidate)]);
  });
}

template <typename Ask>
bool Simulation::step_with(Ask&& ask) {
  pending_.reset();
  if (recorder_.ended()) return false;
  ++steps_taken_;
  const auto t_start = Clock::now();
  const RunSetup& setup = *setup_;
  RunMetrics& m = recorder_.metrics();
  if (m.steps >= setup.max_steps) {
    recorder_.end(EndReason::StepLimit, "step cap " + std::to_string(setup.max_steps) + " reached");
    return false;
  }
  // 1. Observe and decide.
  const std::optional<Decision> decision = decide(ask, true);
  if (decision && decision->kind == Decision::Kind::Finish) {
    if (decision->outcome == Decision::Outcome::TargetReached) {
      recorder_.reach_target(decision->detail);
    } else if (decision->outcome == Decision::Outcome::TargetUnreachable) {
      recorder_.end(EndReason::TargetUnreachable, decision->detail);
    } else {
      finish();
    }
  } else if (decision && decision->kind == Decision::Kind::ReturnToDock && robot_.position == robot_.dock) {
    // Algorithm 1 finishes at the dock; a strategy asking to return while there is done.
    finish();
  } else if (decision) {
    Journey journey;
    journey.goal = decision->kind == Decision::Kind::GoTo ? decision->goal : robot_.dock;
    const KnownMap& known = belief_.known();
    journey.recheck = heuristics_.heuristics().recheck && decision->kind == Decision::Kind::GoTo &&
                      known.in_bounds(journey.goal);
    journey.goal_was_frontier = journey.recheck && belief_.frontiers().is_frontier(known.index(journey.goal));
    robot_.previous_position = robot_.position;
    robot_.previous_goal = journey.goal;
    journey.known_before = known.known_count();
    journey.steps_before = m.steps;
    journey.stop_known_before = stop_cell_known_free();
    // 2. Plan and travel. 3. Arrive.
    if (travel(*decision, journey)) arrive(*decision, journey);
  }
  m.wall_time_s += seconds_since(t_start);
  return !recorder_.ended();
}

template <typename Ask>
std::optional<Decision> Simulation::decide(Ask&& ask, bool commit) {
  const RunSetup& setup = *setup_;
  RunMetrics& m = recorder_.metrics();
  const std::vector<FrontierCluster>& clusters = belief_.clusters();
  const SegmentRestriction segment =
      heuristics_.restrict_to_segment(belief_.known(), robot_.position, clusters);
  if (commit) m.segmentation_time_s += segment.segmentation_time_s;
  GridDistanceOracle oracle = belief_.distance_oracle(setup, robot_.position, robot_.dock, scratch_);
  const auto observation = [&](const SegmentRestriction& restriction) {
    return Observation{belief_.known(),
                       belief_.frontiers(),
                       restriction.clusters != nullptr ? *restriction.clusters : clusters,
                       oracle,
                       setup.spec.robot.sensor,
                       robot_.position,
                       robot_.heading,
                       robot_.previous_position,
                       robot_.previous_goal,
                       robot_.dock,
                       robot_.battery_view(),
                       m.decisions,
                       restriction.mask};
  };
  const auto t_decide = Clock::now();
  // sim.stop_at_cell: arrived -> target_reached; known free and reachable -> go straight there.
  bool to_stop_cell = false;
  if (stop_cell_known_free()) {
    const Cell stop_cell = *setup.stop_cell;
    if (robot_.position == stop_cell) {
      if (commit) recorder_.reach_target("stop cell " + cell_text(stop_cell) + " reached");
      return std::nullopt;
    }
    const std::vector<int> stop{belief_.known().index(stop_cell)};
    to_stop_cell = std::isfinite(oracle.from_robot(stop, std::numeric_limits<double>::infinity()).front());
  }
  Decision decision = to_stop_cell ? Decision::go_to(*setup.stop_cell) : ask(observation(segment), 0);
  if (segment.mask != nullptr && decision.kind == Decision::Kind::Finish) {
    // Every candidate of the robot's room failed the strategy's own tests (e.g. unreachable):
    // the segment restriction holds only while the room offers a usable candidate.
    decision = ask(observation(SegmentRestriction{}), 1);
  }
  if (!commit) return decision;
  m.decision_time_s += seconds_since(t_decide);
  m.planner_expansions += oracle.expansions();
  ++m.decisions;
  for (const std::uint64_t field :
       {static_cast<std::uint64_t>(decision.kind), static_cast<std::uint64_t>(decision.goal.x),
        static_cast<std::uint64_t>(decision.goal.y), static_cast<std::uint64_t>(decision.max_steps),
        static_cast<std::uint64_t>(decision.outcome)}) {
    trace_ = mix64(trace_ ^ field);
  }
  return decision;
}

bool Simulation::travel(const Decision& decision, const Journey& journey) {
  const RunSetup& setup = *setup_;
  RunMetrics& m = recorder_.metrics();
  if (journey.goal == robot_.position) {
    sense();  // look again from here (a noisy sensor may have missed cells)
    if (!recorder_.ended()) look_around(decision);
    return !recorder_.ended();
  }
  PlanRequest request;
  request.start = robot_.position;
  request.goal = journey.goal;
  request.start_heading = robot_.heading;
  request.energy = setup.spec.robot.energy;
  request.allow_corner_cutting = setup.allow_corner_cutting();
  request.seed = derive_seed(setup.spec.seed, "planner") + static_cast<std::uint64_t>(m.decisions);
  const std::optional<SearchResult> probed =
      scratch_.probed_path(belief_.known(), robot_.position, journey.goal, request.allow_corner_cutting);
  if (probed) request.searched = &*probed;
  const PlanResult plan = planner_->plan(belief_.known(), request);
  m.planner_time_s += plan.time_s;
  m.planner_expansions += plan.expansions;
  if (plan.status != PlanStatus::Success) {
    ++m.plan_failures;
    if (decision.kind == Decision::Kind::ReturnToDock) {
      recorder_.end(EndReason::Error, "planner " + planner_->name() + " found no path to the dock: " +
                                          std::string(to_string(plan.status)));
      return false;
    }
    belief_.drop(journey.goal);
    ++m.dropped_goals;
    return true;
  }
  const double range_cells = setup.spec.robot.sensor.range_m / setup.resolution_m;
  for (std::size_t i = 1; i < plan.path.size(); ++i) {
    if (m.steps >= setup.max_steps) {
      recorder_.end(EndReason::StepLimit, "step cap " + std::to_string(setup.max_steps) + " reached");
      break;
    }
    if (!move_to(plan.path[i])) break;
    if (decision.max_steps > 0 && m.steps - journey.steps_before >= decision.max_steps) break;
    if (!journey.stop_known_before && stop_cell_known_free()) break;  // decide again: go to the stop cell
    if (journey.recheck && robot_.position != journey.goal &&
        !HeuristicsPolicy::goal_still_open(belief_.known(), belief_.frontiers(), journey.goal,
                                           journey.goal_was_frontier, range_cells)) {
      ++m.rr_redecisions;
      break;
    }
  }
  if (!recorder_.ended() && robot_.position == journey.goal) look_around(decision);
  return !recorder_.ended();
}

void Simulation::look_around(const Decision& decision) {
  const std::optional<Cell>& stop = setup_->stop_cell;
  if (setup_->spec.robot.sensor.fov_deg >= 360.0 || decision.kind != Decision::Kind::GoTo ||
      (stop && *stop == robot_.position)) {
    return;
  }
  const KnownMap& known = belief_.known();
  const EnergyModel& e = setup_->spec.robot.energy;
  unsigned faced = 1U << static_cast<unsigned>(robot_.heading);
  for (;;) {
    // The unfaced heading toward an unknown neighbour that is the smallest turn away, clockwise
    // first on a tie.
    int next = -1;
    for (int turn = 1; turn <= 4 && next < 0; ++turn) {
      for (const int h : {(robot_.heading + turn) & 7, (robot_.heading - turn) & 7}) {
        const Cell d = kDirections[static_cast<std::size_t>(h)];
        const Cell n{robot_.position.x + d.x, robot_.position.y + d.y};
        if ((faced & (1U << static_cast<unsigned>(h))) == 0 && known.in_bounds(n) &&
            known.state(n) == CellState::Unknown) {
          next = h;
          break;
        }
      }
    }
    if (next < 0) return;
    const int turns = heading_difference(next, robot_.heading);
    if (!robot_.battery.draw(e.turn(turns), 0.0)) {
      recorder_.end(EndReason::BatteryDepleted, "battery empty at " + cell_text(robot_.position));
      return;
    }
    RunMetrics& m = recorder_.metrics();
    ++m.stops;
    ++m.turns;
    m.turned_deg += 45.0 * turns;
    m.energy += e.turn(turns);
    robot_.heading = next;
    faced |= 1U << static_cast<unsigned>(next);
    sense();
    if (recorder_.ended()) return;
  }
}

void Simulation::arrive(const Decision& decision, const Journey& journey) {
  RunMetrics& m = recorder_.metrics();
  const KnownMap& known = belief_.known();
  if (robot_.position == robot_.dock && !robot_.battery.unlimited() && !robot_.battery.full()) {
    robot_.battery.recharge();
    recorder_.record_recharge();
  }
  const bool revealed = known.known_count() != journey.known_before;
  if (decision.kind == Decision::Kind::GoTo && robot_.position == journey.goal && !revealed &&
      belief_.frontiers().is_frontier(known.index(journey.goal))) {
    belief_.drop(journey.goal);
    ++m.dropped_goals;
  }
  // A journey cut short by Decision::max_steps after moving is not quiet: a strategy that
  // decides after every step crosses known space in many such decisions.
  const bool cut_short =
      decision.max_steps > 0 && robot_.position != journey.goal && m.steps != journey.steps_before;
  if (revealed) {
    robot_.quiet_decisions = 0;
  } else if (!cut_short) {
    ++robot_.quiet_decisions;
  }
  if (robot_.quiet_decisions >= setup_->spec.sim.stuck_decisions) {
    recorder_.end(EndReason::Stuck,
                  std::to_string(robot_.quiet_decisions) + " decisions in a row revealed nothing");
  }
}

void Simulation::finish() {
  // Complete when no (undropped) frontier cell is reachable from the robot at all.
  if (!belief_.frontier_reachable_from(robot_.position, robot_.dock, *setup_, scratch_)) {
    recorder_.end(EndReason::Complete);
  } else if (!robot_.battery.unlimited()) {
    recorder_.end(EndReason::RangeLimited);
  } else {
    recorder_.end(EndReason::Stuck,
                  "strategy " + strategy_->name() + " finished with reachable frontiers left");
  }
}

double Simulation::coverage_target_bound_m() const {
  const RunMetrics& m = recorder_.metrics();
  if (m.distance_to_coverage_target_m) return *m.distance_to_coverage_target_m;
  if (recorder_.ended()) return m.distance_m;
  // reveal_bound.hpp: the tube around the path still to travel must hold the cells still
  // needed, and the battery brings the robot back to the dock between trips to the far ones.
  const RunSetup& setup = *setup_;
  if (!(setup.spec.sim.stop_at_coverage > 0.0)) return m.distance_m;  // no target: nothing is needed
  TargetBound& cached = target_bound_;
  if (cached.distance_m == m.distance_m && cached.battery == robot_.battery.level() &&
      cached.known_reachable == belief_.known_reachable() && cached.robot == robot_.position) {
    return cached.value;
  }
  const RevealGeometry& reveal = setup.reveal(robot_.dock);
  RevealState s;
  s.needed_cells = setup.spec.sim.stop_at_coverage * static_cast<double>(setup.reachable_count) -
                   static_cast<double>(belief_.known_reachable());
  s.cell_area_m2 = setup.resolution_m * setup.resolution_m;
  s.reach_m = reveal.reach_m;
  s.dock_m = reveal.dock_m[static_cast<std::size_t>(setup.reachable.index(robot_.position))];
  s.bin_m = reveal.bin_m;
  const Charges charges = charges_m(robot_.battery, setup.spec.robot.energy, setup.resolution_m);
  s.first_charge_m = charges.first;
  s.charge_m = charges.full;
  cached = TargetBound{m.distance_m, robot_.battery.level(), belief_.known_reachable(), robot_.position,
                       m.distance_m + travel_to_reveal_m(s, belief_.unknown_by_bin(reveal))};
  return cached.value;
}

RunResult Simulation::result() const& { return completed(recorder_.result()); }

RunResult Simulation::result() && { return completed(std::move(recorder_).result()); }

RunResult Simulation::completed(RunResult recorded) const {
  const RunSetup& setup = *setup_;
  const KnownMap& known = belief_.known();
  RunResult r = std::move(recorded);
  const double distance_m = r.metrics.distance_m;
  const double cell_area = setup.resolution_m * setup.resolution_m;
  r.metrics.explored_area_m2 = known.free_count() * cell_area;
  r.metrics.known_area_m2 = known.known_count() * cell_area;
  r.metrics.area_per_metre = distance_m > 0.0 ? r.metrics.explored_area_m2 / distance_m : 0.0;
  r.metrics.coverage = belief_.coverage(setup);
  r.metrics.completeness = belief_.completeness(setup);
  r.metrics.residual_unknown_m2 = belief_.unknown_reachable(setup) * cell_area;
  r.metrics.frontier_cells_left = belief_.frontiers().count();
  // Close the curve with the final state at the exact final distance; a sample already there
  // was taken before what the robot revealed without moving since (a look around, a second look).
  const ProgressSample last{distance_m, r.metrics.explored_area_m2, r.metrics.coverage, r.metrics.energy};
  if (r.progress.empty() || r.progress.back().distance_m < distance_m) {
    r.progress.push_back(last);
  } else {
    r.progress.back() = last;
  }
  r.final_known = known;
  r.final_frontiers = belief_.frontiers().cells();
  r.dock = robot_.dock;
  return r;
}

RunResult Simulation::run() {
  while (step()) {
  }
  return result();
}

RunResult simulate(const RunSpec& spec) {
  Simulation sim(spec);
  while (sim.step()) {
  }
  return std::move(sim).result();
}

}  // namespace sim
}  // namespace fsweep
