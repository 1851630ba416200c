#include "optimum/coverage_instance.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/config_error.hpp"
#include "core/csv_format.hpp"
#include "core/random.hpp"
#include "search/grid_search.hpp"
#include "search/octile_grid.hpp"
#include "sim/run_setup.hpp"
#include "world/sensor.hpp"

namespace fsweep {
inline namespace optimum {
namespace {

void check_sensor(const SensorParams& s) {
  if (s.model != SensorModel::Grid) {
    throw ConfigError(
        "robot/sensor/model",
        "the offline optimum models the grid sensor only (what a beam lidar sees depends on the "
        "heading a route arrives with); allowed: \"grid\"");
  }
}

/// Rows from (row, item) pairs sorted by row then item.
CompressedRows rows_of(int row_count, std::vector<std::pair<int, int>>& pairs) {
  std::sort(pairs.begin(), pairs.end());
  CompressedRows r;
  r.begin.assign(static_cast<std::size_t>(row_count) + 1, 0);
  r.items.reserve(pairs.size());
  for (const auto& [row, item] : pairs) {
    ++r.begin[static_cast<std::size_t>(row) + 1];
    r.items.push_back(item);
  }
  for (int i = 0; i < row_count; ++i)
    r.begin[static_cast<std::size_t>(i) + 1] += r.begin[static_cast<std::size_t>(i)];
  return r;
}

}  // namespace

CoverageInstance build_coverage_instance(const RunSpec& spec, std::size_t max_visibility_pairs) {
  check_sensor(spec.robot.sensor);
  const RunSetup setup(spec);
  check_sensor_range(setup);
  const WorldMap& map = setup.map();
  CoverageInstance in;
  in.width = map.width();
  in.height = map.height();
  in.resolution_m = map.resolution_m;
  in.allow_corner_cutting = spec.robot.allow_corner_cutting;
  in.start = map.start;
  in.start_heading = spec.robot.start_heading;
  in.dock = spec.robot.dock.value_or(map.start);
  in.truth = KnownMap(in.width, in.height, in.resolution_m);
  const int cells = in.width * in.height;
  for (int i = 0; i < cells; ++i) in.truth.reveal(i, !map.is_free(i));

  in.node_of_cell.assign(static_cast<std::size_t>(cells), -1);
  in.target_of_cell.assign(static_cast<std::size_t>(cells), -1);
  for (int i = 0; i < cells; ++i) {
    if (setup.reachable[i] != 0) {
      in.node_of_cell[static_cast<std::size_t>(i)] = static_cast<int>(in.node_cell.size());
      in.node_cell.push_back(i);
    }
    if (setup.observable[i] != 0) {
      in.target_of_cell[static_cast<std::size_t>(i)] = static_cast<int>(in.target_cell.size());
      in.target_cell.push_back(i);
    }
  }
  in.start_node = in.node_at(in.start);
  in.dock_node = in.node_at(in.dock);
  if (in.dock_node < 0) {
    throw ConfigError("robot/dock",
                      "the dock " + cell_text(in.dock) + " is not a free cell reachable from the start");
  }

  // What each node sees: one noiseless scan on an empty copy of the map, then forgotten; with a
  // narrower field of view, the 360-degree scan (what the node sees facing any way).
  in.fov_deg = spec.robot.sensor.fov_deg;
  SensorParams noiseless = spec.robot.sensor;
  noiseless.miss_probability = 0.0;
  noiseless.fov_deg = 360.0;
  Sensor sensor(noiseless, in.resolution_m);
  KnownMap scratch(in.width, in.height, in.resolution_m);
  Rng unused(0);
  std::vector<std::pair<int, int>> sees;
  std::vector<std::pair<int, int>> seen;
  for (int node = 0; node < in.nodes(); ++node) {
    const Cell at = in.cell_of_node(node);
    const std::span<const int> revealed = sensor.scan(map, scratch, at, 0.0, unused);
    for (const int cell : revealed) {
      const int target = in.target_of_cell[static_cast<std::size_t>(cell)];
      if (target >= 0) {  // always, by RunMetrics::completeness's argument; kept safe
        sees.emplace_back(node, target);
        seen.emplace_back(target, node);
      }
    }
    if (sees.size() > max_visibility_pairs) {
      throw ConfigError(
          "map", "too large for the offline optimum: the scans from the first " + std::to_string(node + 1) +
                     " of " + std::to_string(in.nodes()) + " reachable cells already see " +
                     std::to_string(sees.size()) + " cells in all, above the limit of " +
                     std::to_string(max_visibility_pairs) +
                     "; allowed: maps whose cells times the cells in sensor range stay below it (a "
                     "coarser resolution or a shorter sensor range)");
    }
    const std::vector<int> forget(revealed.begin(), revealed.end());
    for (const int cell : forget) scratch.forget(cell);
  }
  in.sees = rows_of(in.nodes(), sees);
  in.seen_from = rows_of(in.targets(), seen);

  // The battery's reach.
  in.node_usable.assign(static_cast<std::size_t>(in.nodes()), 1);
  if (spec.robot.battery_capacity < std::numeric_limits<double>::infinity()) {
    const double per_metre = spec.robot.energy.travel_per_cell(in.resolution_m) / in.resolution_m;
    in.range_per_charge_m = spec.robot.battery_capacity / per_metre;
    const int dock_cell = in.truth.index(in.dock);
    const std::vector<double> from_dock = node_distances_m(in, std::span<const int>(&dock_cell, 1));
    for (int node = 0; node < in.nodes(); ++node) {
      // A small slack for the rounding of the lengths (exact octile sums, then one product).
      in.node_usable[static_cast<std::size_t>(node)] =
          2.0 * from_dock[static_cast<std::size_t>(node)] <= in.range_per_charge_m * (1.0 + 1e-12) ? 1 : 0;
    }
  }
  in.explorable.assign(static_cast<std::size_t>(in.targets()), 0);
  for (int t = 0; t < in.targets(); ++t) {
    const auto from = in.seen_from.row(t);
    const bool reachable = std::any_of(from.begin(), from.end(), [&](int node) {
      return in.node_usable[static_cast<std::size_t>(node)] != 0;
    });
    in.explorable[static_cast<std::size_t>(t)] = reachable ? 1 : 0;
    if (!reachable) ++in.out_of_reach;
  }
  return in;
}

std::vector<double> node_distances_m(const CoverageInstance& instance, std::span<const int> sources) {
  const OctileFieldEnvironment env(instance.truth, instance.allow_corner_cutting);
  OctileDistanceSearch search;
  std::vector<SearchSeedT<OctileCost>> seeds;
  seeds.reserve(sources.size());
  for (const int s : sources) seeds.push_back({s, OctileCost{}});
  (void)search.run(env, std::span<const SearchSeedT<OctileCost>>(seeds));
  std::vector<double> out(static_cast<std::size_t>(instance.nodes()),
                          std::numeric_limits<double>::infinity());
  for (int node = 0; node < instance.nodes(); ++node) {
    const int cell = instance.node_cell[static_cast<std::size_t>(node)];
    if (search.settled(cell)) out[static_cast<std::size_t>(node)] = search.g(cell) * instance.resolution_m;
  }
  return out;
}

std::vector<int> shortest_path_cells(const CoverageInstance& instance, int from, int to) {
  OctileGoalEnvironment<true> env(instance.truth, instance.truth.cell(to), instance.allow_corner_cutting);
  OctileSearch search;
  const SearchOutcome outcome = search.run(env, from);
  std::vector<int> path;
  if (outcome.goal != to) return path;
  search.trace_back(to, [&](int s) { path.push_back(s); });
  std::reverse(path.begin(), path.end());
  return path;
}

}  // namespace optimum
}  // namespace fsweep
