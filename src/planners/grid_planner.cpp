#include "planners/grid_planner.hpp"

#include <nlohmann/json.hpp>

#include "core/config_error.hpp"
#include "planners/search_result.hpp"
#include "search/octile_grid.hpp"

namespace fsweep {
inline namespace planners {
namespace {

/// Search environment of one query: cells are states, octile moves in cells (exact costs,
/// OctileCost, so equal lengths tie exactly and the larger-g rule orders them), the goal cell
/// ends the search; the heuristic is the octile distance for A* and 0 for Dijkstra (declared,
/// so BestFirstSearch uses its Dijkstra open list: same order, f == g).
template <bool kAStar>
class GridEnvironment {
 public:
  GridEnvironment(const KnownMap& known, Cell goal, bool allow_corner_cutting)
      : known_(known),
        goal_(goal),
        goal_index_(known.index(goal)),
        width_(known.width()),
        allow_corner_cutting_(allow_corner_cutting) {}

  using Cost = OctileCost;
  static constexpr bool kZeroHeuristic = !kAStar;
  [[nodiscard]] int state_count() const { return known_.size(); }
  [[nodiscard]] Cost heuristic(int state) const {
    return kAStar ? octile_cost(Cell{state % width_, state / width_}, goal_) : Cost{};
  }
  Visit visit(int state, double /*g*/) const { return state == goal_index_ ? Visit::Goal : Visit::Expand; }
  template <typename Sink>
  void for_each_successor(int state, Sink&& sink) const {
    for_each_octile_neighbour<Cost>(known_, state, allow_corner_cutting_, sink);
  }

 private:
  const KnownMap& known_;
  Cell goal_;
  int goal_index_;
  int width_;
  bool allow_corner_cutting_;
};

/// One query's search with `search` over `Env`: the cells from start to goal, or the failure.
template <typename Env>
SearchResult search_grid(OctileSearch& search, const Env& env, const KnownMap& known, Cell start,
                         const StopCondition& stop) {
  SearchLimits limits;
  limits.stop = stop;
  const SearchOutcome outcome = search.run(env, known.index(start), limits);
  return search_result(search, outcome, [&known](int s) { return known.cell(s); });
}

}  // namespace

std::string GridPlanner::name() const { return kind_ == GridSearchKind::AStar ? "astar" : "dijkstra"; }

std::unique_ptr<Planner> GridPlanner::clone() const { return std::make_unique<GridPlanner>(kind_, params_); }

SearchResult GridPlanner::search(const KnownMap& known, const PlanRequest& request,
                                 const StopCondition& stop) {
  // Start == goal settles the start as the goal (a one-cell path).
  if (kind_ == GridSearchKind::AStar) {
    return search_grid(search_, GridEnvironment<true>(known, request.goal, request.allow_corner_cutting),
                       known, request.start, stop);
  }
  return search_grid(search_, GridEnvironment<false>(known, request.goal, request.allow_corner_cutting),
                     known, request.start, stop);
}

}  // namespace planners
}  // namespace fsweep
