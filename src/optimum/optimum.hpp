#pragma once
/// @file optimum.hpp
/// Certified bounds on the offline exploration optimum of one map and robot (docs/competitive.md):
/// the shortest route, in trips from the dock with a battery, that reveals every explorable
/// target cell (coverage_instance.hpp), measured to the moment the last one is revealed.
///
/// solve_optimum() runs, in this order, with deterministic budgets only (unless a deadline is
/// given):
/// 1. the witness lower bound from the start (lower_bound.hpp);
/// 2. a covering route (cover_route.hpp), replayed through the simulation's sensor and energy
///    model: its distance to final coverage is the upper bound;
/// 3. on instances with at most kExactMaxTargets explorable targets, the exact search
///    (exact_cover.hpp) within its expansion budget: solved, it gives the optimum (the lower
///    bound; the upper bound too when its route passes the replay with the battery); stopped,
///    its open list's smallest f may raise the lower bound.
/// `exact` is true only when lower and upper are equal (within the rounding margin) and both are
/// proven: the lower bound by the arguments above, the upper by the replay.

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "optimum/cover_route.hpp"
#include "optimum/coverage_instance.hpp"
#include "optimum/exact_cover.hpp"
#include "optimum/lower_bound.hpp"
#include "sim/run_spec.hpp"

namespace fsweep {
inline namespace optimum {

struct OptimumOptions {
  LowerBoundOptions lower;
  RouteOptions route;
  ExactOptions exact;
};

struct OptimumResult {
  /// Certified bounds (metres); upper is +infinity when no route was found that the replay
  /// accepts, lower is +infinity when no route can exist (a target no usable node sees).
  double lower_m = 0.0;
  double upper_m = 0.0;
  bool exact = false;
  /// The upper bound's route (grid indices from the start) and its trips.
  std::vector<int> route;
  int trips = 0;
  /// Sizes: reachable free cells (nodes), targets, targets out of the battery's reach,
  /// witnesses, viewpoints of the covering route.
  int nodes = 0;
  int targets = 0;
  int out_of_reach = 0;
  int witnesses = 0;
  int viewpoints = 0;
  /// Which method gave each bound: "witness bound", "sweep bound", "trip bound", "exact search",
  /// "exact search (open list)"; "covering route", "exact search", or "none: " and why no route
  /// was built (RouteOptions::max_field_cells).
  std::string lower_method;
  std::string upper_method;
  long exact_expansions = 0;
  /// True when a deadline (not a budget) stopped some part: the bounds are valid but depend on
  /// the machine's speed.
  bool stopped_by_time = false;
  double time_s = 0.0;
  /// (upper - lower) / lower; 0 when exact, +infinity without an upper bound.
  [[nodiscard]] double gap() const;
};

/// Bounds for `spec`'s map, start and robot (its strategy, planner and sim settings are not
/// read). Throws ConfigError as build_coverage_instance() does.
[[nodiscard]] OptimumResult solve_optimum(const RunSpec& spec, const OptimumOptions& options = {});

/// The same from a built instance (the instance's spec must be `spec`).
[[nodiscard]] OptimumResult solve_optimum(const CoverageInstance& instance, const RunSpec& spec,
                                          const OptimumOptions& options = {});

}  // namespace optimum
}  // namespace fsweep
