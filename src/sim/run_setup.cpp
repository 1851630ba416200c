#include "sim/run_setup.hpp"

#include <vector>

#include "core/config_error.hpp"
#include "core/random.hpp"
#include "search/distance_field.hpp"
#include "world/known_map.hpp"

namespace fsweep {
inline namespace sim {
namespace {

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

int count_flagged(const Grid<std::uint8_t>& grid) {
  int n = 0;
  for (const auto v : grid.data()) n += v;
  return n;
}

// The checked map of `spec` (ConfigError "map" / "map start").
const WorldMap& checked_map(const RunSpec& spec) {
  if (!spec.map) throw ConfigError("map", "no map given");
  const WorldMap& map = *spec.map;
  if (!map.is_free(map.start)) {
    throw ConfigError("map start",
                      "start cell " + cell_text(map.start) + " is not a free cell of " + map.source);
  }
  return map;
}

}  // namespace

std::string cell_text(Cell c) { return "(" + std::to_string(c.x) + ", " + std::to_string(c.y) + ")"; }

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

RunSetup::RunSetup(const RunSpec& run_spec) : spec(run_spec) {
  const WorldMap& truth = checked_map(spec);
  resolution_m = truth.resolution_m;
  reachable = reachable_free(truth, truth.start, spec.robot.allow_corner_cutting);
  reachable_count = count_flagged(reachable);
  observable = observable_cells(truth, reachable);
  observable_count = count_flagged(observable);
  cluster_max_length_m =
      spec.sim.cluster_max_length_m > 0.0 ? spec.sim.cluster_max_length_m : spec.robot.sensor.range_m;
  progress_step_m = spec.sim.progress_step_m > 0.0 ? spec.sim.progress_step_m : 10.0 * resolution_m;
  max_steps = spec.sim.max_steps > 0 ? spec.sim.max_steps : 100L * reachable_count + 1000L;
}

const RevealGeometry& RunSetup::reveal(Cell dock) const {
  std::call_once(reveal_->once, [&] { reveal_->geometry = reveal_geometry(*this, dock); });
  return reveal_->geometry;
}

void RunSetup::keep_sight(const Sensor& sensor) const {
  std::call_once(sight_->once, [&] {
    sight_->owned = sensor.sight_table(map());
    sight_->table.store(sight_->owned.get(), std::memory_order_release);
  });
}

std::optional<Cell> stop_cell_of(const RunSetup& setup) {
  if (!setup.spec.sim.stop_at_random) return setup.spec.sim.stop_at_cell;
  return draw_random_target(setup.reachable, setup.map().start, setup.spec.seed, "sim/stop_at_cell");
}

void check_sensor_range(const RunSetup& setup) {
  const double range_m = setup.spec.robot.sensor.range_m;
  if (range_m / setup.resolution_m < kSqrt2) {
    throw ConfigError(
        "robot/sensor/range_m",
        "value " + std::to_string(range_m) + " m is below one diagonal cell (" +
            std::to_string(kSqrt2 * setup.resolution_m) +
            " m at this resolution); allowed: >= sqrt(2) x resolution, so a robot sees its 8 neighbours");
  }
  if (!(range_m / setup.resolution_m <= Sensor::kMaxRangeCells)) {
    throw ConfigError(
        "robot/sensor/range_m",
        "value " + std::to_string(range_m) + " m is " + std::to_string(range_m / setup.resolution_m) +
            " cells at this resolution; allowed: at most " + std::to_string(Sensor::kMaxRangeCells) +
            " cells (" + std::to_string(Sensor::kMaxRangeCells * setup.resolution_m) + " m)");
  }
}

double shortest_path_from_start_m(const RunSetup& setup, Cell target) {
  const WorldMap& truth = setup.map();
  if (!truth.is_free(target)) return 0.0;
  DistanceField field;
  DistanceQuery q;
  q.allow_corner_cutting = setup.allow_corner_cutting();
  const std::vector<int> stop{truth.occupied.index(target)};
  q.stop_at_first_of = stop;
  field.compute(fully_known(truth), truth.start, q);
  return field.reached(stop.front()) ? field.distance_m(stop.front()) : 0.0;
}

}  // namespace sim
}  // namespace fsweep
