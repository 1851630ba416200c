#pragma once
/// @file coverage_instance.hpp
/// The offline coverage problem of one map and robot: which cells must be revealed, from which
/// cells each can be seen, and the distances between them. Built once per map instance and robot;
/// the lower bound (lower_bound.hpp), the routes (cover_route.hpp) and the exact search
/// (exact_cover.hpp) read it.
///
/// The problem (docs/competitive.md): the robot knows the whole map, starts at the map's start
/// with the run's heading, moves by the planners' rule (8-connected, octile costs, the run's
/// corner rule) and senses after every step exactly as the simulation does (Sensor::scan, the
/// same range and ray rules) but without misses. It must reveal every target cell; its cost is
/// the distance travelled when the last target is revealed, which is what a run's
/// `distance_to_final_coverage_m` measures.
///
/// Targets: the observable cells O of the run (RunSetup::observable, RunMetrics::completeness):
/// the free cells R reachable from the start and their 4-neighbours. Every cell a run reveals is
/// in O, and a run that ends `complete` with completeness 1 has revealed all of O, so its
/// distance to final coverage is the length of a route that reveals O: it is at least the
/// optimum, and the lower bound must never exceed it (tests/optimum). Runs that end otherwise
/// get no ratio.
///
/// Viewpoints ("nodes"): the cells of R, the only cells a robot stands on. What a node sees is
/// one scan from it on the true map (sensor.hpp's grid model) with a 360-degree field of view.
/// With a narrower one (fov_deg), that is what the node sees facing every way, so the tables
/// describe a relaxation: a route of the narrower sensor reveals no more than the same route
/// with the 360-degree one, and the lower bounds, computed on the tables, hold for it. Routes
/// (cover_route.hpp) then turn round on their viewpoints, and only their replay with the run's
/// own sensor certifies them. The beam model is refused: what it sees between its beams is not
/// what a grid scan sees.
///
/// Battery: the robot recharges at the dock as runs do. Its range per charge is the capacity
/// divided by the cheapest energy per metre (turns cost extra energy, never less), so a node
/// farther than half that range from the dock can never be stood on (node_usable); targets seen
/// only from such nodes are out of reach, and a run on such a map cannot end complete.

#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "sim/run_spec.hpp"
#include "world/grid.hpp"
#include "world/known_map.hpp"

namespace fsweep {
inline namespace optimum {

/// +infinity: no bound, no route, unreachable.
inline constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// Compressed rows: row r is items[begin[r] .. begin[r + 1]), ascending.
struct CompressedRows {
  std::vector<int> begin{0};
  std::vector<int> items;
  [[nodiscard]] std::span<const int> row(int r) const {
    return {items.data() + begin[static_cast<std::size_t>(r)],
            static_cast<std::size_t>(begin[static_cast<std::size_t>(r) + 1] -
                                     begin[static_cast<std::size_t>(r)])};
  }
  [[nodiscard]] int rows() const { return static_cast<int>(begin.size()) - 1; }
};

struct CoverageInstance {
  int width = 0;
  int height = 0;
  double resolution_m = 1.0;
  bool allow_corner_cutting = false;
  Cell start{};
  int start_heading = 0;
  /// The run's field of view (degrees); the tables are those of a 360-degree scan.
  double fov_deg = 360.0;
  Cell dock{};
  /// The true map, every cell known: the searches and the replays run on it.
  KnownMap truth;
  /// Nodes: the reachable free cells, row-major; node_of_cell: grid index -> node or -1.
  std::vector<int> node_cell;
  std::vector<int> node_of_cell;
  /// Targets: the observable cells, row-major; target_of_cell: grid index -> target or -1.
  std::vector<int> target_cell;
  std::vector<int> target_of_cell;
  /// sees.row(node): the targets a scan from the node reveals. seen_from.row(target): the nodes
  /// whose scan reveals it.
  CompressedRows sees;
  CompressedRows seen_from;
  int start_node = -1;
  int dock_node = -1;
  /// Metres of travel one charge allows (capacity / cheapest energy per metre); +infinity
  /// without a battery.
  double range_per_charge_m = std::numeric_limits<double>::infinity();
  /// Per node: 1 when a round trip dock -> node -> dock fits in one charge (all 1 without a
  /// battery).
  std::vector<std::uint8_t> node_usable;
  /// Per target: 1 when some usable node sees it (the explorable targets, those a route must
  /// reveal); the others, out_of_reach of them, nothing can reveal.
  std::vector<std::uint8_t> explorable;
  int out_of_reach = 0;

  [[nodiscard]] int nodes() const { return static_cast<int>(node_cell.size()); }
  [[nodiscard]] int targets() const { return static_cast<int>(target_cell.size()); }
  [[nodiscard]] Cell cell_of_node(int node) const {
    return truth.cell(node_cell[static_cast<std::size_t>(node)]);
  }
  [[nodiscard]] int node_at(Cell c) const {
    return truth.in_bounds(c) ? node_of_cell[static_cast<std::size_t>(truth.index(c))] : -1;
  }
  [[nodiscard]] bool is_explorable(int target) const {
    return explorable[static_cast<std::size_t>(target)] != 0;
  }
  [[nodiscard]] int explorable_count() const { return targets() - out_of_reach; }
  [[nodiscard]] bool limited_battery() const {
    return range_per_charge_m < std::numeric_limits<double>::infinity();
  }
};

/// Most (node, target) visibility pairs an instance holds (8 bytes each, twice): about 640 MB.
inline constexpr std::size_t kMaxVisibilityPairs = 40'000'000;

/// Builds the instance of `spec` (map, start, robot). Throws ConfigError: the map's checks of a
/// run (RunSetup), an instance above `max_visibility_pairs` ("map"), the beam sensor
/// ("robot/sensor/model"), a sensor range below one diagonal cell.
/// miss_probability is ignored (the offline sensor is noiseless). Cost: one scan per reachable free cell.
[[nodiscard]] CoverageInstance build_coverage_instance(
    const RunSpec& spec, std::size_t max_visibility_pairs = kMaxVisibilityPairs);

/// Shortest path lengths (metres) over the true map from the nearest of `sources` (grid indices of
/// free cells) to every node; +infinity where unreachable. The planners' moves and costs (exact
/// octile sums, search/grid_search.hpp), on `instance.truth`.
[[nodiscard]] std::vector<double> node_distances_m(const CoverageInstance& instance,
                                                   std::span<const int> sources);

/// One shortest path (grid indices, from `from` to `to`, both included) on the true map; empty
/// when `to` is unreachable.
[[nodiscard]] std::vector<int> shortest_path_cells(const CoverageInstance& instance, int from, int to);

}  // namespace optimum
}  // namespace fsweep
