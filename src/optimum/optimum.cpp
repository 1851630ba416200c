#include "optimum/optimum.hpp"

#include <cmath>
#include <limits>

namespace fsweep {
inline namespace optimum {
namespace {}  // namespace

double OptimumResult::gap() const {
  if (exact) return 0.0;
  if (!(upper_m < kInfinity)) return kInfinity;
  if (lower_m <= 0.0) return upper_m > 0.0 ? kInfinity : 0.0;
  return (upper_m - lower_m) / lower_m;
}

OptimumResult solve_optimum(const RunSpec& spec, const OptimumOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  const CoverageInstance instance = build_coverage_instance(spec);
  OptimumResult r = solve_optimum(instance, spec, options);
  r.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

OptimumResult solve_optimum(const CoverageInstance& in, const RunSpec& spec, const OptimumOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  OptimumResult r;
  r.nodes = in.nodes();
  r.targets = in.targets();
  r.out_of_reach = in.out_of_reach;
  const CoverageLowerBound bound(in, options.lower);
  r.witnesses = static_cast<int>(bound.witnesses().size());
  r.lower_m = bound.at_start();
  r.lower_method = "witness bound";
  if (bound.start_sweep_bound() > 0.0 && bound.start_sweep_bound() >= bound.at_start())
    r.lower_method = "sweep bound";
  if (bound.start_trip_bound() > 0.0 && bound.start_trip_bound() >= bound.at_start())
    r.lower_method = "trip bound";
  r.upper_m = kInfinity;

  const CoverRoute route = cover_route(in, spec, options.route);
  const RouteReplay replay = replay_route(in, spec, route.cells);
  r.viewpoints = static_cast<int>(route.viewpoints.size());
  if (!route.refused.empty()) {
    r.upper_method = "none: " + route.refused;
  } else if (replay.covers()) {
    r.upper_m = replay.distance_to_final_coverage_m;
    r.route = route.cells;
    r.trips = replay.trips;
    r.upper_method = "covering route";
  }

  const bool small = replay.explorable <= kExactMaxTargets;
  if (small && !(r.upper_m <= r.lower_m * (1.0 + 1e-9))) {
    const ExactResult exact = exact_cover(in, bound, options.exact);
    r.exact_expansions = exact.expansions;
    r.stopped_by_time = exact.stopped_by_time;
    if (exact.lower_m > r.lower_m) {
      r.lower_m = exact.lower_m;
      r.lower_method = exact.solved ? "exact search" : "exact search (open list)";
    }
    if (exact.solved) {
      const RouteReplay exact_replay = replay_route(in, spec, exact.cells);
      if (exact_replay.covers() && exact_replay.distance_to_final_coverage_m < r.upper_m) {
        r.upper_m = exact_replay.distance_to_final_coverage_m;
        r.route = exact.cells;
        r.trips = exact_replay.trips;
        r.upper_method = "exact search";
      }
    }
  }
  if (r.lower_m > r.upper_m) r.lower_m = r.upper_m;  // the margin's rounding the other way
  r.exact = r.upper_m < kInfinity && r.upper_m - r.lower_m <= 1e-9 * std::max(1.0, r.upper_m);
  if (r.exact) r.lower_m = r.upper_m;
  r.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace optimum
}  // namespace fsweep
