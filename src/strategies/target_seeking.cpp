#include "strategies/target_seeking.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "core/config_error.hpp"
#include "strategies/geodesic.hpp"
#include "strategies/widest_frontier.hpp"
#include "world/cell_param.hpp"

namespace fsweep {
inline namespace strategies {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

std::string cell_text(Cell c) { return "(" + std::to_string(c.x) + ", " + std::to_string(c.y) + ")"; }

/// Steps 1-3 of choose_target_frontier(): the eligible frontiers with their features and goals,
/// none chosen.
FrontierChoice eligible_frontiers(const Observation& obs, const std::optional<Cell>& target_cell) {
  const KnownMap& known = obs.known;
  FrontierChoice choice;
  if (target_cell && !known.in_bounds(*target_cell)) return choice;
  const int target = target_cell ? known.index(*target_cell) : -1;

  // 1. Whole frontiers from the clusters' cells.
  std::vector<int> cells;
  for (const auto& c : obs.clusters) cells.insert(cells.end(), c.cells.begin(), c.cells.end());
  std::sort(cells.begin(), cells.end());
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  if (cells.empty()) return choice;
  const auto groups = frontier_groups(known, cells);

  // 2. Geodesic distances from the target through its region (all 0 without a target).
  std::vector<double>& from_target = choice.from_target_m;
  from_target.assign(static_cast<std::size_t>(known.size()), 0.0);
  if (target >= 0) {
    Grid<std::uint8_t> region = unknown_region(known, obs.frontiers);
    if (known.is_free(target)) {
      for (int i = 0; i < known.size(); ++i) region[i] = known.state(i) != CellState::Occupied ? 1 : 0;
    }
    const std::vector<int> source{target};
    from_target = geodesic_distances(region, source, known.resolution_m());
  }
  const std::vector<double> from_robot = obs.distances.from_robot(cells, kInf);
  const auto robot_distance = [&](int q) {
    const auto at = std::lower_bound(cells.begin(), cells.end(), q) - cells.begin();
    return from_robot[static_cast<std::size_t>(at)];
  };

  // 3. The eligible frontiers, their features and goals.
  for (const auto& g : groups) {
    ScoredFrontier f;
    f.cells = g;
    f.length_m = static_cast<double>(g.size()) * known.resolution_m();
    f.hg_target_m = geodesic_hausdorff(from_target, g);
    f.hg_robot_m = kInf;
    for (const int q : g) f.hg_robot_m = std::min(f.hg_robot_m, robot_distance(q));
    if (!std::isfinite(f.hg_target_m) || !std::isfinite(f.hg_robot_m)) continue;
    f.features = {1.0 / f.length_m, target >= 0 ? f.hg_target_m : 0.0, f.hg_robot_m};
    double best_route = kInf;
    for (const int q : g) {  // the route robot -> q -> target
      const double route = robot_distance(q) + from_target[static_cast<std::size_t>(q)];
      if (route < best_route) {  // members ascend: ties keep the lowest index
        best_route = route;
        f.goal = q;
      }
    }
    choice.frontiers.push_back(std::move(f));
  }
  return choice;
}

void require_resolved(const TargetSeekingParams& params) {
  if (params.random_target) {
    throw ConfigError(
        "strategy/params/target",
        "\"random\" must be resolved to a cell by the simulation (resolve_random_target) first");
  }
}

}  // namespace

ParamDecl<TargetSeekingParams> target_seeking_params() {
  ParamDecl<TargetSeekingParams> d;
  declare_cell_or_random(
      d, "target", &TargetSeekingParams::target, &TargetSeekingParams::random_target,
      "the cell to reach; null: pure exploration (phi = 1, section II-B); \"random\": drawn per run");
  d.number("w1", &TargetSeekingParams::w1, "weight of 1/L, L the frontier's length (Arvanitakis eq. 12)")
      .range(0, 1);
  d.number("w2", &TargetSeekingParams::w2,
           "weight of Hg(target, frontier), the geodesic Hausdorff distance (eq. 12)")
      .range(0, 1);
  d.number("w3", &TargetSeekingParams::w3, "weight of Hg(robot, frontier) (eq. 12)").range(0, 1);
  d.choice("motion", &TargetSeekingParams::motion,
           {{"shortest_path", TargetMotion::ShortestPath}, {"gradient", TargetMotion::Gradient}},
           "each motion: one step along a shortest path to the chosen frontier, or the gradient step of "
           "eq. 2, 10, 13-15");
  return d;
}

FrontierChoice choose_target_frontier(const Observation& obs, const TargetSeekingParams& params) {
  FrontierChoice choice = eligible_frontiers(obs, params.target);
  // 4. Equation 12.
  const std::array<double, 3> weights{params.w1, params.w2, params.w3};
  double best = kInf;
  for (std::size_t i = 0; i < choice.frontiers.size(); ++i) {
    ScoredFrontier& f = choice.frontiers[i];
    f.score = linear_cost(weights, f.features);
    if (f.score < best) {  // strict: ties keep the earlier frontier, as argmin_linear()
      best = f.score;
      choice.chosen = static_cast<int>(i);
    }
  }
  if (choice.chosen >= 0) choice.goal = choice.frontiers[static_cast<std::size_t>(choice.chosen)].goal;
  return choice;
}

ExplorationField exploration_field(const KnownMap& known, std::span<const int> chosen,
                                   std::span<const double> from_target_m) {
  ExplorationField out;
  GeodesicField to_frontier = geodesic_field(known_free_cells(known), chosen, known.resolution_m());
  out.weight.assign(static_cast<std::size_t>(known.size()), 0.0);
  for (std::size_t p = 0; p < out.weight.size(); ++p) {
    const int y = to_frontier.nearest_source[p];
    if (y < 0) continue;
    const double f = 1.0 / (to_frontier.distance_m[p] + 1.0);                     // equation 13
    const double phi = 1.0 / (from_target_m[static_cast<std::size_t>(y)] + 1.0);  // equations 14-15
    out.weight[p] = f * phi;
  }
  out.to_frontier_m = std::move(to_frontier.distance_m);
  return out;
}

WorldMap known_as_world(const KnownMap& known) {
  WorldMap view;
  view.occupied = Grid<std::uint8_t>(known.width(), known.height(), 1);
  for (int i = 0; i < known.size(); ++i) view.occupied[i] = known.is_free(i) ? 0 : 1;
  view.resolution_m = known.resolution_m();
  view.source = "known map";
  return view;
}

double exploration_objective(const WorldMap& view, const Sensor& sensor, Cell at, double heading_rad,
                             std::span<const double> weights) {
  const int r = static_cast<int>(std::floor(sensor.range_cells()));
  double h = 0.0;
  for (int y = std::max(0, at.y - r); y <= std::min(view.height() - 1, at.y + r); ++y) {
    for (int x = std::max(0, at.x - r); x <= std::min(view.width() - 1, at.x + r); ++x) {
      const Cell p{x, y};
      const int i = view.occupied.index(p);
      if (weights[static_cast<std::size_t>(i)] == 0.0 || !view.is_free(i)) continue;
      if (p == at || sensor.visible(view, at, p, heading_rad)) h += weights[static_cast<std::size_t>(i)];
    }
  }
  return h;
}

std::optional<Cell> gradient_step(const KnownMap& known, const Sensor& sensor, Cell robot,
                                  const ExplorationField& field) {
  if (!known.in_bounds(robot)) return std::nullopt;
  const WorldMap view = known_as_world(known);
  const double here = field.to_frontier_m[static_cast<std::size_t>(known.index(robot))];
  double best = -1.0;
  std::optional<Cell> step;
  for (int h = 0; h < 8; ++h) {
    const Cell d = kDirections[static_cast<std::size_t>(h)];
    const Cell n{robot.x + d.x, robot.y + d.y};
    if (!known.is_free(n)) continue;
    if ((h & 1) != 0 &&
        (!known.is_free(Cell{robot.x + d.x, robot.y}) || !known.is_free(Cell{robot.x, robot.y + d.y}))) {
      continue;
    }
    if (!(field.to_frontier_m[static_cast<std::size_t>(known.index(n))] < here)) continue;  // progress
    const double value = exploration_objective(view, sensor, n, heading_angle(h), field.weight);
    if (value > best) {  // strict: ties keep the lower heading
      best = value;
      step = n;
    }
  }
  return step;
}

std::optional<Decision> TargetSeeking::fixed_decision(const Observation& obs) {
  require_resolved(params_);
  if (!params_.target) return std::nullopt;  // 0: choose among the frontiers
  const KnownMap& known = obs.known;
  const Cell t = *params_.target;
  if (!known.in_bounds(t)) {  // 1
    return Decision::finish_with(Decision::Outcome::TargetUnreachable,
                                 "target " + cell_text(t) + " is outside the " +
                                     std::to_string(known.width()) + "x" + std::to_string(known.height()) +
                                     " map");
  }
  if (known.state(t) == CellState::Occupied) {
    return Decision::finish_with(Decision::Outcome::TargetUnreachable,
                                 "target " + cell_text(t) + " is an occupied cell");
  }
  if (obs.robot == t) {  // 2
    return Decision::finish_with(Decision::Outcome::TargetReached, {});
  }
  if (known.is_free(t)) {  // 3
    const std::vector<int> target{known.index(t)};
    if (std::isfinite(obs.distances.from_robot(target, kInf).front())) return Decision::go_to(t);
  }
  return std::nullopt;  // 4: choose among the frontiers
}

Candidates TargetSeeking::candidates(const Observation& obs) {
  require_resolved(params_);
  const FrontierChoice eligible = eligible_frontiers(obs, params_.target);
  Candidates c;
  c.feature_count = 3;
  for (const ScoredFrontier& f : eligible.frontiers) {
    c.cells.push_back(obs.known.cell(f.goal));
    c.features.insert(c.features.end(), f.features.begin(), f.features.end());
  }
  return c;
}

Decision TargetSeeking::choose(const Observation& obs, Cell cell) {
  require_resolved(params_);
  if (!params_.target) return Decision::go_to(cell);  // 0
  const KnownMap& known = obs.known;
  if (params_.motion == TargetMotion::Gradient) {  // 4, gradient: the field of the frontier of `cell`
    const FrontierChoice eligible = eligible_frontiers(obs, params_.target);
    const int goal = known.index(cell);
    const auto frontier = std::find_if(eligible.frontiers.begin(), eligible.frontiers.end(),
                                       [&](const ScoredFrontier& f) { return f.goal == goal; });
    if (frontier != eligible.frontiers.end()) {
      const Sensor sensor(obs.sensor, known.resolution_m());
      const auto step = gradient_step(known, sensor, obs.robot,
                                      exploration_field(known, frontier->cells, eligible.from_target_m));
      if (step) return Decision::go_toward(*step, 1);
    }
  }
  return Decision::go_toward(cell, 1);  // 4
}

Decision TargetSeeking::on_no_candidate(const Observation& /*obs*/) {
  require_resolved(params_);
  if (!params_.target) return Decision::finish();  // 0
  return Decision::finish_with(
      Decision::Outcome::TargetUnreachable,  // 4
      "no reachable frontier borders the unknown region of target " + cell_text(*params_.target));
}

void TargetSeeking::set_weights(std::span<const double> weights) {
  if (weights.size() != weights_.size()) {
    throw std::invalid_argument("target_seeking: " + std::to_string(weights.size()) +
                                " weights given; it has 3 (w1, w2, w3)");
  }
  for (std::size_t k = 0; k < weights.size(); ++k) {
    if (!(weights[k] >= 0.0 && weights[k] <= 1.0)) {
      throw std::invalid_argument("target_seeking: w" + std::to_string(k + 1) + " = " +
                                  std::to_string(weights[k]) + "; allowed: [0, 1]");
    }
  }
  std::copy(weights.begin(), weights.end(), weights_.begin());
  params_.w1 = weights_[0];
  params_.w2 = weights_[1];
  params_.w3 = weights_[2];
}

}  // namespace strategies
}  // namespace fsweep
