#include "planners/lattice_planner.hpp"

#include <cassert>
#include <chrono>
#include <cmath>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "core/config_error.hpp"
#include "planners/heading_lattice.hpp"
#include "world/motion.hpp"

namespace fsweep {
inline namespace planners {
namespace {

constexpr int kHeadings = kLatticeHeadings;

/// Lattice policy of `lattice` / `lattice_astar`: every step allowed; the heuristic is zero
/// (Dijkstra) or the octile distance to the goal times the cheapest travel energy per cell.
class OctileLatticePolicy {
 public:
  OctileLatticePolicy(const KnownMap& known, const PlanRequest& request, bool use_heuristic)
      : goal_(request.goal),
        width_(known.width()),
        use_heuristic_(use_heuristic),
        travel_per_cell_(request.energy.travel_per_cell(known.resolution_m())) {}

  [[nodiscard]] double heuristic(int cell) const {
    if (!use_heuristic_) return 0.0;
    return octile_distance(Cell{cell % width_, cell / width_}, goal_) * travel_per_cell_;
  }
  [[nodiscard]] static bool allows(int /*from*/, int /*to*/, double /*step_cells*/) { return true; }

 private:
  Cell goal_;
  int width_;
  bool use_heuristic_;
  double travel_per_cell_;
};

}  // namespace

std::string LatticePlanner::name() const {
  return kind_ == LatticeSearchKind::AStar ? "lattice_astar" : "lattice";
}

std::unique_ptr<Planner> LatticePlanner::clone() const {
  return std::make_unique<LatticePlanner>(kind_, params_);
}

PlanResult LatticePlanner::plan(const KnownMap& known, const PlanRequest& request) {
  const auto started = std::chrono::steady_clock::now();
  if (request.start_heading < 0 || request.start_heading >= kHeadings) {
    throw std::invalid_argument("LatticePlanner: start_heading " + std::to_string(request.start_heading) +
                                " is not in 0..7");
  }
  PlanResult result;

  // 1. Endpoints must be known free (outside the grid counts as occupied).
  result.status = check_endpoints(known, request);
  if (result.status == PlanStatus::Success) {
    // 2. Search from (start, start heading); start == goal settles the start as the goal.
    const OctileLatticePolicy policy(known, request, kind_ == LatticeSearchKind::AStar);
    HeadingLattice env(known, request, policy);
    const int start_state = known.index(request.start) * kHeadings + request.start_heading;
    const SearchOutcome outcome = search_.run(env, start_state);
    result.expansions = outcome.expansions;
    if (outcome.goal < 0) {
      result.status = PlanStatus::NoPath;
    } else {
      // 3. Cells of the states along the parents, then the shared motion accounting (its
      //    energy equals the search cost: same per-step rule, no final stop).
      const std::vector<int> states = search_.path_to(outcome.goal);
      std::vector<Cell> path;
      path.reserve(states.size());
      for (const int s : states) path.push_back(known.cell(s / kHeadings));
      set_path(result, std::move(path), request, known.resolution_m());
      assert(std::abs(result.energy - search_.g(outcome.goal)) <= 1e-9 * (1.0 + result.energy));
    }
  }
  result.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return result;
}

}  // namespace planners
}  // namespace fsweep
