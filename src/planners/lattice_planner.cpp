#include "planners/lattice_planner.hpp"

#include <nlohmann/json.hpp>

#include "core/config_error.hpp"
#include "planners/heading_lattice.hpp"
#include "planners/search_result.hpp"

namespace fsweep {
inline namespace planners {
namespace {

constexpr int kHeadings = kLatticeHeadings;

/// Lattice policy of `lattice` / `lattice_astar`: every step allowed; the heuristic is the
/// octile distance to the goal times the cheapest travel energy per cell (A*), or zero
/// (Dijkstra, declared so that BestFirstSearch uses its Dijkstra open list: same order).
template <bool kAStar>
class OctileLatticePolicy {
 public:
  OctileLatticePolicy(const KnownMap& known, const PlanRequest& request)
      : goal_(request.goal),
        width_(known.width()),
        travel_per_cell_(request.energy.travel_per_cell(known.resolution_m())) {}

  static constexpr bool kZeroHeuristic = !kAStar;
  [[nodiscard]] double heuristic(int cell) const {
    if (!kAStar) return 0.0;
    return octile_distance(Cell{cell % width_, cell / width_}, goal_) * travel_per_cell_;
  }
  [[nodiscard]] static bool allows(int /*from*/, int /*to*/, double /*step_cells*/) { return true; }

 private:
  Cell goal_;
  int width_;
  double travel_per_cell_;
};

/// One query's search with `search` on the lattice of `policy`: the cells from start to goal,
/// or the failure.
template <typename Policy>
SearchResult search_lattice(BestFirstSearch& search, const Policy& policy, const KnownMap& known,
                            const PlanRequest& request, const StopCondition& stop) {
  // 1. Search from (start, start heading); start == goal settles the start as the goal.
  HeadingLattice env(known, request, policy);
  SearchLimits limits;
  limits.stop = stop;
  const int start_state = known.index(request.start) * kHeadings + request.start_heading;
  const SearchOutcome outcome = search.run(env, start_state, limits);
  // 2. Cells of the states along the parents (Planner::plan() measures them by the same
  //    per-step rule as the search cost, no final stop).
  return search_result(search, outcome, [&known](int s) { return known.cell(s / kHeadings); });
}

}  // namespace

std::string LatticePlanner::name() const {
  return kind_ == LatticeSearchKind::AStar ? "lattice_astar" : "lattice";
}

std::unique_ptr<Planner> LatticePlanner::clone() const {
  return std::make_unique<LatticePlanner>(kind_, params_);
}

SearchResult LatticePlanner::search(const KnownMap& known, const PlanRequest& request,
                                    const StopCondition& stop) {
  if (kind_ == LatticeSearchKind::AStar) {
    return search_lattice(search_, OctileLatticePolicy<true>(known, request), known, request, stop);
  }
  return search_lattice(search_, OctileLatticePolicy<false>(known, request), known, request, stop);
}

}  // namespace planners
}  // namespace fsweep
