#include "sim/simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "core/config_error.hpp"
#include "planners/registry.hpp"
#include "strategies/registry.hpp"

namespace fsweep {
inline namespace sim {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

std::string cell_text(Cell c) { return "(" + std::to_string(c.x) + ", " + std::to_string(c.y) + ")"; }

// A cell drawn uniformly among the nonzero cells of `reachable` other than `start` (row-major
// candidates, stream "target" of `seed`); ConfigError at `where` when there is none.
Cell draw_random_target(const Grid<std::uint8_t>& reachable, Cell start, std::uint64_t seed,
                        const std::string& where) {
  std::vector<Cell> candidates;  // row-major order: the draw depends only on the map and the seed
  for (int y = 0; y < reachable.height(); ++y) {
    for (int x = 0; x < reachable.width(); ++x) {
      if (reachable.at(Cell{x, y}) != 0 && !(Cell{x, y} == start)) candidates.push_back(Cell{x, y});
    }
  }
  if (candidates.empty()) {
    throw ConfigError(where,
                      "\"random\": no free cell other than the start " + cell_text(start) + " is reachable");
  }
  Rng rng = make_rng(seed, "target");
  return candidates[static_cast<std::size_t>(uniform_below(rng, candidates.size()))];
}

}  // namespace

nlohmann::json resolve_random_target(const nlohmann::json& strategy_params,
                                     const Grid<std::uint8_t>& reachable, Cell start, std::uint64_t seed) {
  if (!strategy_params.is_object()) return strategy_params;
  const auto it = strategy_params.find("target");
  if (it == strategy_params.end() || *it != nlohmann::json("random")) return strategy_params;
  const Cell t = draw_random_target(reachable, start, seed, "strategy/params/target");
  nlohmann::json resolved = strategy_params;
  resolved["target"] = nlohmann::json{t.x, t.y};
  return resolved;
}

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

Simulation::Simulation(const RunSpec& spec) : spec_(spec) {
  if (!spec_.map) throw ConfigError("map", "no map given");
  const WorldMap& map = *spec_.map;
  resolution_m_ = map.resolution_m;
  if (!map.is_free(map.start)) {
    throw ConfigError("map start",
                      "start cell " + cell_text(map.start) + " is not a free cell of " + map.source);
  }
  reachable_ = reachable_free(map, map.start, spec_.robot.allow_corner_cutting);
  for (const auto v : reachable_.data()) reachable_count_ += v;
  const nlohmann::json strategy_params =
      resolve_random_target(spec_.strategy.params, reachable_, map.start, spec_.seed);
  const StrategyConfig& strategy = strategy_params == spec_.strategy.params
                                       ? spec_.strategy
                                       : configure_strategy(spec_.strategy.name, strategy_params);
  strategy_ = strategy.make(derive_seed(spec_.seed, "strategy"));
  heuristics_ = spec_.heuristics.value_or(Heuristics{});
  planner_ = spec_.planner.make();
  sensor_ = Sensor(spec_.robot.sensor, resolution_m_);
  sensor_rng_ = make_rng(spec_.seed, "sensor");
  known_ = KnownMap(map.width(), map.height(), resolution_m_);
  frontiers_ = FrontierMap(known_);
  dropped_.assign(static_cast<std::size_t>(known_.size()), 0);

  robot_ = map.start;
  dock_ = spec_.robot.dock.value_or(map.start);
  if (!map.is_free(dock_)) {
    throw ConfigError("robot/dock", "dock cell " + cell_text(dock_) + " is outside the map or occupied in " +
                                        map.source + "; allowed: a free cell");
  }
  if (spec_.robot.sensor.range_m / resolution_m_ < kSqrt2) {
    throw ConfigError(
        "robot/sensor/range_m",
        "value " + std::to_string(spec_.robot.sensor.range_m) + " m is below one diagonal cell (" +
            std::to_string(kSqrt2 * resolution_m_) +
            " m at this resolution); allowed: >= sqrt(2) x resolution, so a robot sees its 8 neighbours");
  }
  heading_ = spec_.robot.start_heading;
  previous_position_ = robot_;

  observable_ = observable_cells(map, reachable_);
  for (const auto v : observable_.data()) observable_count_ += v;

  const EnergyModel& e = spec_.robot.energy;
  battery_ = Battery(spec_.robot.battery_capacity, e.per_metre + e.per_cell / resolution_m_);
  cluster_max_length_m_ =
      spec_.sim.cluster_max_length_m > 0.0 ? spec_.sim.cluster_max_length_m : spec_.robot.sensor.range_m;
  progress_step_m_ = spec_.sim.progress_step_m > 0.0 ? spec_.sim.progress_step_m : 10.0 * resolution_m_;
  max_steps_ = spec_.sim.max_steps > 0 ? spec_.sim.max_steps : 100L * reachable_count_ + 1000L;
  metrics_.reachable_area_m2 = reachable_count_ * resolution_m_ * resolution_m_;

  stop_cell_ = spec_.sim.stop_at_random
                   ? draw_random_target(reachable_, map.start, spec_.seed, "sim/stop_at_cell")
                   : spec_.sim.stop_at_cell;
  // Navigation metrics: the target cell (the strategy's, else the stop cell) and the shortest
  // start-target path on the fully known map.
  const std::optional<Cell> nav_target = strategy_->target() ? strategy_->target() : stop_cell_;
  if (nav_target) {
    metrics_.target_x = nav_target->x;
    metrics_.target_y = nav_target->y;
  }
  if (const auto target = nav_target; target && map.is_free(*target)) {
    DistanceField field;
    DistanceQuery q;
    q.allow_corner_cutting = spec_.robot.allow_corner_cutting;
    const std::vector<int> stop{map.occupied.index(*target)};
    q.stop_at_first_of = stop;
    field.compute(fully_known(map), map.start, q);
    if (field.reached(stop.front())) metrics_.target_shortest_m = field.distance_m(stop.front());
  }

  trajectory_.push_back(robot_);
  sense();
  sample_progress();
}

Simulation::Simulation(const Simulation& other)
    : spec_(other.spec_),
      strategy_(other.strategy_ ? other.strategy_->clone() : nullptr),
      planner_(other.planner_ ? other.planner_->clone() : nullptr),
      sensor_(other.sensor_),
      known_(other.known_),
      frontiers_(other.frontiers_),
      sensor_rng_(other.sensor_rng_),
      dock_field_(other.dock_field_),
      dock_field_ready_(other.dock_field_ready_),
      dock_field_pending_(other.dock_field_pending_),
      reachable_(other.reachable_),
      reachable_count_(other.reachable_count_),
      known_reachable_(other.known_reachable_),
      dropped_(other.dropped_),
      observable_(other.observable_),
      observable_count_(other.observable_count_),
      known_observable_(other.known_observable_),
      heuristics_(other.heuristics_),
      segmentation_(other.segmentation_),
      segmented_known_count_(other.segmented_known_count_),
      segment_mask_(other.segment_mask_),
      robot_(other.robot_),
      heading_(other.heading_),
      dock_(other.dock_),
      previous_position_(other.previous_position_),
      previous_goal_(other.previous_goal_),
      stop_cell_(other.stop_cell_),
      battery_(other.battery_),
      resolution_m_(other.resolution_m_),
      cluster_max_length_m_(other.cluster_max_length_m_),
      progress_step_m_(other.progress_step_m_),
      max_steps_(other.max_steps_),
      next_progress_m_(other.next_progress_m_),
      quiet_decisions_(other.quiet_decisions_),
      metrics_(other.metrics_),
      progress_(other.progress_),
      trajectory_(other.trajectory_),
      recharge_steps_(other.recharge_steps_),
      ended_(other.ended_),
      end_(other.end_),
      end_detail_(other.end_detail_) {}

Simulation& Simulation::operator=(const Simulation& other) {
  if (this != &other) {
    Simulation copy(other);
    *this = std::move(copy);
  }
  return *this;
}

void Simulation::sense() {
  const auto revealed = sensor_.scan(*spec_.map, known_, robot_, heading_angle(heading_), sensor_rng_);
  frontiers_.update(known_, revealed);
  if (dock_field_ready_) {
    dock_field_pending_.insert(dock_field_pending_.end(), revealed.begin(), revealed.end());
  } else if (known_.is_free(dock_)) {
    dock_field_.reset(known_, dock_, spec_.robot.allow_corner_cutting);
    dock_field_ready_ = true;
  }
  for (const int i : revealed) {
    if (known_.is_free(i) && reachable_[i] != 0) ++known_reachable_;
    if (observable_[i] != 0) ++known_observable_;
  }
  if (!revealed.empty()) metrics_.distance_to_final_coverage_m = metrics_.distance_m;
}

double Simulation::coverage() const {
  return reachable_count_ > 0 ? static_cast<double>(known_reachable_) / reachable_count_ : 1.0;
}

double Simulation::completeness() const {
  return observable_count_ > 0 ? static_cast<double>(known_observable_) / observable_count_ : 1.0;
}

const std::vector<std::uint8_t>* Simulation::segment_candidates(std::vector<FrontierCluster>& clusters) {
  if (known_.known_count() != segmented_known_count_) {
    const auto t0 = Clock::now();
    segmentation_ = segment_free_space(known_);
    segmented_known_count_ = known_.known_count();
    metrics_.segmentation_time_s += seconds_since(t0);
  }
  const int mine = segmentation_.label[static_cast<std::size_t>(known_.index(robot_))];
  const auto in_mine = [&](int i) { return segmentation_.label[static_cast<std::size_t>(i)] == mine; };
  // The candidate of a cluster is its representative (the goal strategies choose).
  const auto inside = [&](const FrontierCluster& c) { return in_mine(c.representative); };
  // Only inside a room: the corridors of a building form one left-over segment, and keeping
  // the robot in it would explore every corridor before any room (section IV-D2 wants rooms
  // one by one).
  if (mine < 0 || segmentation_.room[static_cast<std::size_t>(mine)] == 0 ||
      std::none_of(clusters.begin(), clusters.end(), inside)) {
    return nullptr;
  }
  std::erase_if(clusters, [&](const FrontierCluster& c) { return !inside(c); });
  segment_mask_.assign(segmentation_.label.size(), 0);
  for (std::size_t i = 0; i < segment_mask_.size(); ++i)
    segment_mask_[i] = segmentation_.label[i] == mine ? 1 : 0;
  return &segment_mask_;
}

bool Simulation::goal_still_open(Cell goal, bool goal_was_frontier) const {
  if (goal_was_frontier) return frontiers_.is_frontier(known_.index(goal));
  const double r = spec_.robot.sensor.range_m / resolution_m_;
  const double r2 = r * r * (1.0 + 1e-9) + 1e-9;  // inclusive, as the sensor's range (sensor.hpp)
  for (const int i : frontiers_.cells()) {
    const Cell c = known_.cell(i);
    const double dx = c.x - goal.x;
    const double dy = c.y - goal.y;
    if (dx * dx + dy * dy <= r2) return true;
  }
  return false;
}

void Simulation::sample_progress() {
  while (metrics_.distance_m + 1e-9 >= next_progress_m_) {
    progress_.push_back(ProgressSample{next_progress_m_, known_.free_count() * resolution_m_ * resolution_m_,
                                       coverage(), metrics_.energy});
    next_progress_m_ += progress_step_m_;
  }
}

bool Simulation::move_to(Cell next) {
  const int h = heading_of(next.x - robot_.x, next.y - robot_.y);
  const int change = heading_difference(h, heading_);
  const EnergyModel& e = spec_.robot.energy;
  const double cells = step_length(h);
  const double energy = e.turn(change) + e.travel(cells, resolution_m_);
  const double metres = cells * resolution_m_;
  if (!battery_.draw(energy, metres)) {
    end(EndReason::BatteryDepleted, "battery empty at " + cell_text(robot_));
    return false;
  }
  if (change != 0) {
    ++metrics_.stops;
    ++metrics_.turns;
    metrics_.turned_deg += 45.0 * change;
  }
  metrics_.distance_m += metres;
  metrics_.energy += energy;
  ++metrics_.steps;
  robot_ = next;
  heading_ = h;
  trajectory_.push_back(robot_);
  sense();
  sample_progress();
  return true;
}

void Simulation::reach_target(const std::string& detail) {
  end(EndReason::TargetReached, detail);
  metrics_.target_path_m = metrics_.distance_m;
  if (metrics_.target_shortest_m > 0.0) {
    metrics_.target_path_ratio = metrics_.target_path_m / metrics_.target_shortest_m;
  }
}

bool Simulation::stop_cell_known_free() const {
  return stop_cell_ && known_.in_bounds(*stop_cell_) && known_.is_free(*stop_cell_);
}

bool Simulation::step() {
  if (ended_) return false;
  const auto t_start = Clock::now();
  if (metrics_.steps >= max_steps_) {
    end(EndReason::StepLimit, "step cap " + std::to_string(max_steps_) + " reached");
    return false;
  }

  // 1. Observe and decide.
  auto clusters =
      frontiers_.clusters(known_, cluster_max_length_m_, spec_.robot.allow_corner_cutting, dropped_);
  const std::vector<std::uint8_t>* segment_mask =
      heuristics_.segment ? segment_candidates(clusters) : nullptr;
  oracle_.reset(known_, robot_, dock_, spec_.robot.allow_corner_cutting,
                dock_field_ready_ ? &dock_field_ : nullptr, &dock_field_pending_);
  const BatteryView battery{battery_.level(), battery_.capacity(), battery_.remaining_range_m()};
  const Observation obs{known_,  frontiers_,         clusters,           oracle_,        spec_.robot.sensor,
                        robot_,  heading_,           previous_position_, previous_goal_, dock_,
                        battery, metrics_.decisions, segment_mask};
  const auto t_decide = Clock::now();
  // sim.stop_at_cell: arrived -> target_reached; known free and reachable -> go straight there.
  bool to_stop_cell = false;
  if (stop_cell_known_free()) {
    if (robot_ == *stop_cell_) {
      reach_target("stop cell " + cell_text(robot_) + " reached");
      metrics_.wall_time_s += seconds_since(t_start);
      return false;
    }
    const std::vector<int> stop{known_.index(*stop_cell_)};
    to_stop_cell = std::isfinite(oracle_.from_robot(stop, std::numeric_limits<double>::infinity()).front());
  }
  Decision decision = to_stop_cell ? Decision::go_to(*stop_cell_) : strategy_->decide(obs);
  if (segment_mask != nullptr && decision.kind == Decision::Kind::Finish) {
    // Every candidate of the robot's room failed the strategy's own tests (e.g. unreachable):
    // the segment restriction holds only while the room offers a usable candidate.
    clusters = frontiers_.clusters(known_, cluster_max_length_m_, spec_.robot.allow_corner_cutting, dropped_);
    const Observation everywhere{known_,
                                 frontiers_,
                                 clusters,
                                 oracle_,
                                 spec_.robot.sensor,
                                 robot_,
                                 heading_,
                                 previous_position_,
                                 previous_goal_,
                                 dock_,
                                 battery,
                                 metrics_.decisions,
                                 nullptr};
    decision = strategy_->decide(everywhere);
  }
  metrics_.decision_time_s += seconds_since(t_decide);
  metrics_.planner_expansions += oracle_.expansions();
  ++metrics_.decisions;
  if (decision.kind == Decision::Kind::Finish) {
    if (decision.outcome == Decision::Outcome::TargetReached) {
      reach_target(decision.detail);
    } else if (decision.outcome == Decision::Outcome::TargetUnreachable) {
      end(EndReason::TargetUnreachable, decision.detail);
    } else {
      finish();
    }
    metrics_.wall_time_s += seconds_since(t_start);
    return false;
  }
  const Cell goal = decision.kind == Decision::Kind::GoTo ? decision.goal : dock_;
  const bool recheck = heuristics_.recheck && decision.kind == Decision::Kind::GoTo && known_.in_bounds(goal);
  const bool goal_was_frontier = recheck && frontiers_.is_frontier(known_.index(goal));
  if (decision.kind == Decision::Kind::ReturnToDock && robot_ == dock_) {
    // Algorithm 1 finishes at the dock; a strategy asking to return while there is done.
    finish();
    metrics_.wall_time_s += seconds_since(t_start);
    return false;
  }
  previous_position_ = robot_;
  previous_goal_ = goal;
  const int known_before = known_.known_count();
  const long steps_before = metrics_.steps;
  const bool stop_known_before = stop_cell_known_free();

  // 2. Plan and travel.
  if (goal == robot_) {
    sense();  // look again from here (a noisy sensor may have missed cells)
  } else {
    PlanRequest request;
    request.start = robot_;
    request.goal = goal;
    request.start_heading = heading_;
    request.energy = spec_.robot.energy;
    request.allow_corner_cutting = spec_.robot.allow_corner_cutting;
    request.seed = derive_seed(spec_.seed, "planner") + static_cast<std::uint64_t>(metrics_.decisions);
    const PlanResult plan = planner_->plan(known_, request);
    metrics_.planner_time_s += plan.time_s;
    metrics_.planner_expansions += plan.expansions;
    if (plan.status != PlanStatus::Success) {
      ++metrics_.plan_failures;
      if (decision.kind == Decision::Kind::ReturnToDock) {
        end(EndReason::Error, "planner " + planner_->name() +
                                  " found no path to the dock: " + std::string(to_string(plan.status)));
        metrics_.wall_time_s += seconds_since(t_start);
        return false;
      }
      dropped_[static_cast<std::size_t>(known_.index(goal))] = 1;
      ++metrics_.dropped_goals;
    } else {
      for (std::size_t i = 1; i < plan.path.size(); ++i) {
        if (metrics_.steps >= max_steps_) {
          end(EndReason::StepLimit, "step cap " + std::to_string(max_steps_) + " reached");
          break;
        }
        if (!move_to(plan.path[i])) break;
        if (decision.max_steps > 0 && metrics_.steps - steps_before >= decision.max_steps) break;
        if (!stop_known_before && stop_cell_known_free()) break;  // decide again: go to the stop cell
        if (recheck && robot_ != goal && !goal_still_open(goal, goal_was_frontier)) {
          ++metrics_.rr_redecisions;
          break;
        }
      }
      if (ended_) {
        metrics_.wall_time_s += seconds_since(t_start);
        return false;
      }
    }
  }

  // 3. Arrival: recharge at the dock, drop unobservable goals, watch for lack of progress.
  if (robot_ == dock_ && !battery_.unlimited() && !battery_.full()) {
    battery_.recharge();
    ++metrics_.recharges;
    recharge_steps_.push_back(static_cast<int>(trajectory_.size()) - 1);
  }
  const bool revealed = known_.known_count() != known_before;
  if (decision.kind == Decision::Kind::GoTo && robot_ == goal && !revealed &&
      frontiers_.is_frontier(known_.index(goal))) {
    dropped_[static_cast<std::size_t>(known_.index(goal))] = 1;
    ++metrics_.dropped_goals;
  }
  // A journey cut short by Decision::max_steps after moving is not quiet: a strategy that
  // decides after every step crosses known space in many such decisions.
  const bool cut_short = decision.max_steps > 0 && robot_ != goal && metrics_.steps != steps_before;
  if (revealed) {
    quiet_decisions_ = 0;
  } else if (!cut_short) {
    ++quiet_decisions_;
  }
  if (quiet_decisions_ >= spec_.sim.stuck_decisions) {
    end(EndReason::Stuck, std::to_string(quiet_decisions_) + " decisions in a row revealed nothing");
  }
  metrics_.wall_time_s += seconds_since(t_start);
  return !ended_;
}

void Simulation::finish() {
  // Complete when no (undropped) frontier cell is reachable from the robot at all.
  std::vector<int> open;
  for (const int i : frontiers_.cells()) {
    if (dropped_[static_cast<std::size_t>(i)] == 0) open.push_back(i);
  }
  DistanceField field;
  DistanceQuery q;
  q.allow_corner_cutting = spec_.robot.allow_corner_cutting;
  q.stop_at_first_of = open;
  bool reachable = false;
  if (!open.empty()) {
    field.compute(known_, robot_, q);
    for (const int i : open) reachable = reachable || field.reached(i);
  }
  if (!reachable) {
    end(EndReason::Complete);
  } else if (!battery_.unlimited()) {
    end(EndReason::RangeLimited);
  } else {
    end(EndReason::Stuck, "strategy " + strategy_->name() + " finished with reachable frontiers left");
  }
}

void Simulation::end(EndReason reason, std::string detail) {
  ended_ = true;
  end_ = reason;
  end_detail_ = std::move(detail);
}

RunResult Simulation::result() const {
  RunResult r;
  r.end = end_;
  r.end_detail = end_detail_;
  r.metrics = metrics_;
  const double cell_area = resolution_m_ * resolution_m_;
  r.metrics.explored_area_m2 = known_.free_count() * cell_area;
  r.metrics.known_area_m2 = known_.known_count() * cell_area;
  r.metrics.area_per_metre =
      metrics_.distance_m > 0.0 ? r.metrics.explored_area_m2 / metrics_.distance_m : 0.0;
  r.metrics.coverage = coverage();
  r.metrics.completeness = completeness();
  r.metrics.residual_unknown_m2 = (reachable_count_ - known_reachable_) * cell_area;
  r.metrics.frontier_cells_left = frontiers_.count();
  r.progress = progress_;
  // Close the curve with the final state at the exact final distance.
  if (progress_.empty() || progress_.back().distance_m < metrics_.distance_m) {
    r.progress.push_back(
        ProgressSample{metrics_.distance_m, r.metrics.explored_area_m2, r.metrics.coverage, metrics_.energy});
  }
  r.trajectory = trajectory_;
  r.recharge_steps = recharge_steps_;
  r.final_known = known_;
  r.final_frontiers = frontiers_.cells();
  r.dock = dock_;
  return r;
}

RunResult Simulation::run() {
  while (step()) {
  }
  return result();
}

Grid<std::uint8_t> observable_cells(const WorldMap& map, const Grid<std::uint8_t>& reachable) {
  Grid<std::uint8_t> out(map.width(), map.height(), 0);
  for (int i = 0; i < reachable.size(); ++i) {
    if (reachable[i] == 0) continue;
    const Cell c = reachable.cell(i);
    out[i] = 1;
    for (int h = 0; h < 8; h += 2) {  // the 4-neighbours
      const Cell n{c.x + kDirections[static_cast<std::size_t>(h)].x,
                   c.y + kDirections[static_cast<std::size_t>(h)].y};
      if (out.in_bounds(n)) out.at(n) = 1;
    }
  }
  return out;
}

RunResult simulate(const RunSpec& spec) { return Simulation(spec).run(); }

}  // namespace sim
}  // namespace fsweep
