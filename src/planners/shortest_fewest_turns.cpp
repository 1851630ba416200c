#include "planners/shortest_fewest_turns.hpp"

#include <array>
#include <cmath>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "core/config_error.hpp"
#include "planners/heading_lattice.hpp"

namespace fsweep {
inline namespace planners {
namespace {

/// Tolerance (cells) of the test d(u) == w(u, v) + d(v).
///
/// Why it is exact: octile lengths are a + b sqrt(2) with integers a, b >= 0. Two distinct ones
/// differ by p + q sqrt(2) != 0 (integers p, q), and |p + q sqrt(2)| |p - q sqrt(2)| =
/// |p^2 - 2 q^2| >= 1 (a non-zero integer, sqrt(2) being irrational), so the gap is at least
/// 1 / (|p| + sqrt(2) |q|) >= 1 / (2 L) for lengths up to L cells (at most L orthogonal and
/// L / sqrt(2) diagonal steps). The computed d(c) sums at most L steps of at most sqrt(2), so
/// each side carries at most about L^2 2^-53 of rounding. For L <= 20,000 cells (any path on
/// maps up to a few thousand cells a side, far beyond the 512x512 MovingAI maps): the gap is
/// >= 2.5e-5, 25 times this tolerance, and the rounding <= 1e-7, a tenth of it. So equal
/// lengths always pass and distinct lengths never do.
constexpr double kSameLengthTolCells = 1e-6;

/// Lattice policy: only steps along shortest paths to the goal (d(u) == w + d(v)); the
/// heuristic is the exact remaining travel energy d(c) x travel energy per cell.
class ShortestPathPolicy {
 public:
  ShortestPathPolicy(const DistanceField& to_goal, double resolution_m, double travel_per_cell)
      : to_goal_(to_goal), resolution_m_(resolution_m), travel_per_cell_(travel_per_cell) {}

  /// Shortest length from `cell` to the goal in cells (+infinity if not settled).
  [[nodiscard]] double d_cells(int cell) const { return to_goal_.distance_m(cell) / resolution_m_; }

  [[nodiscard]] double heuristic(int cell) const { return d_cells(cell) * travel_per_cell_; }
  [[nodiscard]] bool allows(int from, int to, double step_cells) const {
    const double d_to = d_cells(to);
    if (std::isinf(d_to)) return false;  // farther from the goal than the start: on no shortest path
    return std::abs(d_cells(from) - (step_cells + d_to)) <= kSameLengthTolCells;
  }

 private:
  const DistanceField& to_goal_;
  double resolution_m_;
  double travel_per_cell_;
};

}  // namespace

std::unique_ptr<Planner> ShortestFewestTurnsPlanner::clone() const {
  return std::make_unique<ShortestFewestTurnsPlanner>(params_);
}

SearchResult ShortestFewestTurnsPlanner::search(const KnownMap& known, const PlanRequest& request,
                                                const StopCondition& stop) {
  SearchResult result;
  // 1. d(c): shortest lengths to the goal, from one Dijkstra at the goal that stops once the
  //    start is settled (every cell closer to the goal than the start is then exact; cells
  //    farther lie on no shortest path from the start and read as infinite).
  const std::array<int, 1> start_cell{known.index(request.start)};
  DistanceQuery query;
  query.allow_corner_cutting = request.allow_corner_cutting;
  query.stop_when_all_settled = start_cell;
  query.stop = stop;
  to_goal_.compute(known, request.goal, query);
  result.expansions = to_goal_.expansions();
  if (!to_goal_.reached(start_cell[0])) {
    result.status = to_goal_.stopped() ? PlanStatus::Timeout : PlanStatus::NoPath;
    return result;
  }

  // 2. Least-energy path on the heading lattice restricted to shortest-path steps, from
  //    (start, start heading), with what is left of the budget; start == goal settles the start
  //    as the goal.
  const double resolution_m = known.resolution_m();
  const ShortestPathPolicy policy(to_goal_, resolution_m, request.energy.travel_per_cell(resolution_m));
  HeadingLattice env(known, request, policy);
  SearchLimits limits;
  limits.stop = stop.after_expansions(result.expansions);
  const int start_state = start_cell[0] * kLatticeHeadings + request.start_heading;
  const SearchOutcome outcome = search_.run(env, start_state, limits);
  result.expansions += outcome.expansions;
  if (outcome.stopped) {
    result.status = PlanStatus::Timeout;
    return result;
  }
  // Every restricted path ends at the goal (d drops by >= 1 per step), so the goal is found.
  if (outcome.goal < 0)
    throw std::logic_error("ShortestFewestTurnsPlanner: restricted lattice missed the goal");

  // 3. Cells of the states along the parents; their length is d(start) (checked by the tests
  //    against `dijkstra`).
  result.status = PlanStatus::Success;
  const std::vector<int> states = search_.path_to(outcome.goal);
  result.path.reserve(states.size());
  for (const int s : states) result.path.push_back(known.cell(s / kLatticeHeadings));
  return result;
}

}  // namespace planners
}  // namespace fsweep
