#include "planners/grid_planner.hpp"

#include <chrono>
#include <nlohmann/json.hpp>

#include "core/config_error.hpp"
#include "search/octile_grid.hpp"
#include "world/motion.hpp"

namespace fsweep {
inline namespace planners {
namespace {

/// Search environment of one query: cells are states, octile moves in cells, the goal cell
/// ends the search; the heuristic is the octile distance for A* and 0 for Dijkstra.
class GridEnvironment {
 public:
  GridEnvironment(const KnownMap& known, Cell goal, bool use_heuristic, bool allow_corner_cutting)
      : known_(known),
        goal_(goal),
        goal_index_(known.index(goal)),
        width_(known.width()),
        use_heuristic_(use_heuristic),
        allow_corner_cutting_(allow_corner_cutting) {}

  [[nodiscard]] int state_count() const { return known_.size(); }
  [[nodiscard]] double heuristic(int state) const {
    return use_heuristic_ ? octile_distance(Cell{state % width_, state / width_}, goal_) : 0.0;
  }
  Visit visit(int state, double /*g*/) const { return state == goal_index_ ? Visit::Goal : Visit::Expand; }
  template <typename Sink>
  void for_each_successor(int state, Sink&& sink) const {
    for_each_octile_neighbour(known_, state, allow_corner_cutting_, sink);
  }

 private:
  const KnownMap& known_;
  Cell goal_;
  int goal_index_;
  int width_;
  bool use_heuristic_;
  bool allow_corner_cutting_;
};

}  // namespace

std::string GridPlanner::name() const { return kind_ == GridSearchKind::AStar ? "astar" : "dijkstra"; }

std::unique_ptr<Planner> GridPlanner::clone() const { return std::make_unique<GridPlanner>(kind_, params_); }

PlanResult GridPlanner::plan(const KnownMap& known, const PlanRequest& request) {
  const auto started = std::chrono::steady_clock::now();
  PlanResult result;

  // 1. Endpoints must be known free (outside the grid counts as occupied).
  result.status = check_endpoints(known, request);
  if (result.status == PlanStatus::Success) {
    // 2. Search; start == goal settles the start as the goal (a one-cell path).
    GridEnvironment env(known, request.goal, kind_ == GridSearchKind::AStar, request.allow_corner_cutting);
    const SearchOutcome outcome = search_.run(env, known.index(request.start));
    result.expansions = outcome.expansions;
    if (outcome.goal < 0) {
      result.status = PlanStatus::NoPath;
    } else {
      // 3. Cells along the parents, then the shared motion accounting.
      const std::vector<int> states = search_.path_to(outcome.goal);
      std::vector<Cell> path;
      path.reserve(states.size());
      for (const int s : states) path.push_back(known.cell(s));
      set_path(result, std::move(path), request, known.resolution_m());
    }
  }
  result.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return result;
}

}  // namespace planners
}  // namespace fsweep
