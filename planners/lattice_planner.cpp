#include "planners/lattice_planner.hpp"

#include <array>
#include <cassert>
#include <chrono>
#include <cmath>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "engine/world/config_error.hpp"
#include "engine/world/motion.hpp"
#include "planners/octile_grid.hpp"

namespace fsweep {
namespace {

constexpr int kHeadings = 8;

/// Search environment of one query: states are `cell_index * 8 + heading`, edge costs are
/// energies under the request's model (see lattice_planner.hpp), any state on the goal cell
/// ends the search.
class LatticeEnvironment {
 public:
  LatticeEnvironment(const KnownMap& known, const PlanRequest& request, bool use_heuristic)
      : known_(known),
        goal_(request.goal),
        goal_index_(known.index(request.goal)),
        width_(known.width()),
        allow_corner_cutting_(request.allow_corner_cutting),
        use_heuristic_(use_heuristic) {
    const double resolution_m = known.resolution_m();
    travel_per_cell_ = request.energy.travel_per_cell(resolution_m);
    for (int k = 0; k <= 4; ++k) turn_[static_cast<std::size_t>(k)] = request.energy.turn(k);
    travel_[0] = request.energy.travel(1.0, resolution_m);
    travel_[1] = request.energy.travel(kSqrt2, resolution_m);
  }

  [[nodiscard]] int state_count() const { return known_.size() * kHeadings; }
  [[nodiscard]] double heuristic(int state) const {
    if (!use_heuristic_) return 0.0;
    const int cell = state / kHeadings;
    return octile_distance(Cell{cell % width_, cell / width_}, goal_) * travel_per_cell_;
  }
  Visit visit(int state, double /*g*/) const {
    return state / kHeadings == goal_index_ ? Visit::Goal : Visit::Expand;
  }
  template <typename Sink>
  void for_each_successor(int state, Sink&& sink) const {
    const int cell = state / kHeadings;
    const int heading = state % kHeadings;
    const Cell c{cell % width_, cell / width_};
    for (int next_heading = 0; next_heading < kHeadings; ++next_heading) {
      const Cell d = kDirections[static_cast<std::size_t>(next_heading)];
      const Cell n{c.x + d.x, c.y + d.y};
      if (!octile_step_allowed(known_, c, n, allow_corner_cutting_)) continue;
      const double cost = turn_[static_cast<std::size_t>(heading_difference(heading, next_heading))] +
                          travel_[static_cast<std::size_t>(next_heading & 1)];
      sink(known_.index(n) * kHeadings + next_heading, cost);
    }
  }

 private:
  const KnownMap& known_;
  Cell goal_;
  int goal_index_;
  int width_;
  bool allow_corner_cutting_;
  bool use_heuristic_;
  double travel_per_cell_ = 0.0;
  /// Stop + turn energy for 0..4 eighth-turns (0 for none).
  std::array<double, 5> turn_{};
  /// Travel energy of an orthogonal [0] and a diagonal [1] step.
  std::array<double, 2> travel_{};
};

}  // namespace

LatticePlannerParams LatticePlannerParams::from_json(const nlohmann::json& j, const std::string& where) {
  if (j.is_null()) return {};
  require_known_keys(j, {}, where);
  return {};
}

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
    LatticeEnvironment env(known, request, kind_ == LatticeSearchKind::AStar);
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

}  // namespace fsweep
