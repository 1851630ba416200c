#pragma once
/// @file cover_route.hpp
/// Routes that reveal every explorable target (the upper bound of the offline optimum), and their
/// replay through the simulation's sensor, which is what certifies them.
///
/// A route is built in these steps:
/// 1. viewpoints: a greedy set cover of the explorable targets by usable nodes (the node that
///    reveals the most targets not yet covered first; ties by node id), what the start's own scan
///    reveals counted as covered;
/// 2. order: a path from the start through the viewpoints, nearest neighbour first, then
///    improved by 2-opt and Or-opt moves (segments of 1-3 viewpoints) on the shortest-path
///    lengths between them until no move shortens it (RouteOptions::max_passes);
/// 3. pruning: a viewpoint whose targets the rest of the route already sees on its way (the
///    cells of the shortest paths between the other viewpoints) is dropped, and the order
///    improved again;
/// 3b. moves (RouteOptions::max_relocations rounds): each viewpoint moves to the usable node that
///    sees every target only its two legs see and is nearest its two neighbours on the route
///    (relocate()); the order is then improved and pruned again, while that shortens the path;
/// 4. trips, with a battery: the order is cut into trips from the dock by an optimal split
///    (a shortest path over cut points, each trip's travel with its way back to the dock within
///    one charge; the last trip's way back is not counted, as a run's distance to final coverage
///    does not count it). A leg home replaces a leg between two viewpoints that pruning or a move
///    may have counted on: targets the trips' replay leaves unrevealed get viewpoints back, each the
///    usable node that sees it with the cheapest insertion into the order, and the order is split
///    again (a few rounds).
/// The steps run from RouteOptions::restarts different covers (step 1 with seeded random gains),
/// and the shortest route whose replay covers is kept.
/// The route is the cells of the shortest paths between consecutive points. replay_route() walks
/// it with the run's Sensor (noiseless) and energy model: the upper bound is its distance to final
/// coverage, and only a route whose replay reveals every explorable target within the battery
/// is an upper bound.

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "optimum/coverage_instance.hpp"
#include "sim/run_spec.hpp"
#include "world/known_map.hpp"

namespace fsweep {
inline namespace optimum {

struct RouteOptions {
  /// Most improvement passes (2-opt then Or-opt over the whole order) per improvement.
  int max_passes = 200;
  /// Most rounds of step 3b (viewpoints moved, then the order improved and pruned again).
  int max_relocations = 20;
  /// Routes built (>= 1), each from its own cover: the first from the plain greedy cover, the
  /// others from greedy covers whose gains are scaled by seeded random factors in
  /// [1 - restart_noise, 1 + restart_noise); the shortest whose replay covers is kept.
  int restarts = 64;
  double restart_noise = 0.3;
  /// No restart begins once the distance fields computed so far hold this many nodes in all (a
  /// deterministic budget: on a map of 7,000 free cells about 30,000 fields, on one of 26,000
  /// about 8,000).
  std::uint64_t restart_work = 200'000'000;
  /// Most distance-field entries one route may need (8 bytes each: 2 GB): a route holds a field of
  /// every node per viewpoint, so a plain greedy cover of V viewpoints on a map of N nodes needs
  /// about V x N. Above it no route is built (CoverRoute::refused says why).
  std::uint64_t max_field_cells = 250'000'000;
};

struct CoverRoute {
  /// Grid indices of the route's cells, from the start, one per step (consecutive cells are
  /// 8-neighbours).
  std::vector<int> cells;
  /// Viewpoints (nodes) in visiting order.
  std::vector<int> viewpoints;
  /// Positions in `cells` where each trip starts (0, then the dock after each recharge).
  std::vector<std::size_t> trip_starts;
  /// Why no route was built (RouteOptions::max_field_cells), empty when one was.
  std::string refused;
};

/// What replaying a route shows.
struct RouteReplay {
  /// The route is a walk of allowed moves (octile_step_allowed) from the start.
  bool valid = false;
  /// Explorable targets (not out of reach) the replay revealed, and how many there are.
  int revealed = 0;
  int explorable = 0;
  /// Metres walked when the last target was revealed (a run's distance_to_final_coverage_m),
  /// and in all.
  double distance_to_final_coverage_m = 0.0;
  double length_m = 0.0;
  /// Trips (1 + recharges at the dock before the final coverage), and whether every stretch
  /// between recharges stayed within one charge by the run's energy model (turns included).
  int trips = 1;
  bool battery_ok = true;
  /// The steps (positions in the route) at which it arrives at the dock and recharges, with
  /// steps still to go.
  std::vector<int> recharge_steps;
  /// What the route revealed (up to the final coverage).
  KnownMap known;
  [[nodiscard]] bool covers() const { return valid && revealed == explorable && battery_ok; }
};

/// Walks `cells` (grid indices, the first the start) with the run's noiseless Sensor and energy
/// model, recharging on every arrival at the dock.
[[nodiscard]] RouteReplay replay_route(const CoverageInstance& instance, const RunSpec& spec,
                                       std::span<const int> cells);

/// The best route the steps above find over the restarts (deterministic); none (`refused`) when the
/// plain greedy cover's viewpoints times the nodes exceed RouteOptions::max_field_cells.
[[nodiscard]] CoverRoute cover_route(const CoverageInstance& instance, const RunSpec& spec,
                                     const RouteOptions& options = {});

}  // namespace optimum
}  // namespace fsweep
