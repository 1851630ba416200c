#include "strategies/target_seeking.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

#include "core/config_error.hpp"
#include "strategies/geodesic.hpp"
#include "strategies/widest_frontier.hpp"
#include "world/cell_param.hpp"

namespace fsweep {
inline namespace strategies {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

std::string cell_text(Cell c) { return "(" + std::to_string(c.x) + ", " + std::to_string(c.y) + ")"; }

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
  const KnownMap& known = obs.known;
  FrontierChoice choice;
  if (params.target && !known.in_bounds(*params.target)) return choice;
  const int target = params.target ? known.index(*params.target) : -1;

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
  const double w2 = target >= 0 ? params.w2 : 0.0;
  const std::vector<double> from_robot = obs.distances.from_robot(cells, kInf);

  // 3. Score the eligible frontiers (equation 12).
  double best = kInf;
  for (const auto& g : groups) {
    ScoredFrontier f;
    f.cells = g;
    f.length_m = static_cast<double>(g.size()) * known.resolution_m();
    f.hg_target_m = geodesic_hausdorff(from_target, g);
    f.hg_robot_m = kInf;
    for (const int q : g) {
      const auto at = std::lower_bound(cells.begin(), cells.end(), q) - cells.begin();
      f.hg_robot_m = std::min(f.hg_robot_m, from_robot[static_cast<std::size_t>(at)]);
    }
    if (!std::isfinite(f.hg_target_m) || !std::isfinite(f.hg_robot_m)) continue;
    f.score = params.w1 / f.length_m + w2 * f.hg_target_m + params.w3 * f.hg_robot_m;
    if (f.score < best) {  // strict: ties keep the earlier frontier
      best = f.score;
      choice.chosen = static_cast<int>(choice.frontiers.size());
    }
    choice.frontiers.push_back(std::move(f));
  }
  if (choice.chosen < 0) return choice;

  // The goal: the member on the shortest estimated route robot -> q -> target.
  double best_route = kInf;
  for (const int q : choice.frontiers[static_cast<std::size_t>(choice.chosen)].cells) {
    const auto at = std::lower_bound(cells.begin(), cells.end(), q) - cells.begin();
    const double route = from_robot[static_cast<std::size_t>(at)] + from_target[static_cast<std::size_t>(q)];
    if (route < best_route) {  // cells ascend: ties keep the lowest index
      best_route = route;
      choice.goal = q;
    }
  }
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

Decision TargetSeeking::decide(const Observation& obs) {
  const KnownMap& known = obs.known;
  if (params_.random_target) {
    throw ConfigError(
        "strategy/params/target",
        "\"random\" must be resolved to a cell by the simulation (resolve_random_target) first");
  }
  if (!params_.target) {  // 0
    const FrontierChoice choice = choose_target_frontier(obs, params_);
    if (choice.goal < 0) return Decision::finish();
    return Decision::go_to(known.cell(choice.goal));
  }
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
  const FrontierChoice choice = choose_target_frontier(obs, params_);  // 4
  if (choice.goal < 0) {
    return Decision::finish_with(
        Decision::Outcome::TargetUnreachable,
        "no reachable frontier borders the unknown region of target " + cell_text(t));
  }
  if (params_.motion == TargetMotion::Gradient) {
    const auto& chosen = choice.frontiers[static_cast<std::size_t>(choice.chosen)].cells;
    const Sensor sensor(obs.sensor, known.resolution_m());
    const auto step =
        gradient_step(known, sensor, obs.robot, exploration_field(known, chosen, choice.from_target_m));
    if (step) return Decision::go_toward(*step, 1);
  }
  return Decision::go_toward(known.cell(choice.goal), 1);
}

}  // namespace strategies
}  // namespace fsweep
