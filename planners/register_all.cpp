#include "planners/register_all.hpp"

#include <array>
#include <nlohmann/json.hpp>

#include "planners/grid_planner.hpp"
#include "planners/lattice_planner.hpp"
#include "planners/shortest_fewest_turns.hpp"

namespace fsweep {
namespace {

template <GridSearchKind Kind>
std::unique_ptr<Planner> make_grid_planner(const nlohmann::json& params, const std::string& where) {
  return std::make_unique<GridPlanner>(Kind, GridPlannerParams::from_json(params, where));
}

template <LatticeSearchKind Kind>
std::unique_ptr<Planner> make_lattice_planner(const nlohmann::json& params, const std::string& where) {
  return std::make_unique<LatticePlanner>(Kind, LatticePlannerParams::from_json(params, where));
}

std::unique_ptr<Planner> make_shortest_fewest_turns(const nlohmann::json& params, const std::string& where) {
  return std::make_unique<ShortestFewestTurnsPlanner>(ShortestFewestTurnsParams::from_json(params, where));
}

}  // namespace

std::span<const PlannerEntry> planner_table() {
  // Add new planners here (one line each); the registry, the CLI and the conformance tests
  // pick them up from this table.
  static constexpr std::array kTable{
      PlannerEntry{"astar", &make_grid_planner<GridSearchKind::AStar>},
      PlannerEntry{"dijkstra", &make_grid_planner<GridSearchKind::Dijkstra>},
      PlannerEntry{"lattice", &make_lattice_planner<LatticeSearchKind::Dijkstra>},
      PlannerEntry{"lattice_astar", &make_lattice_planner<LatticeSearchKind::AStar>},
      PlannerEntry{"shortest_fewest_turns", &make_shortest_fewest_turns},
  };
  return kTable;
}

}  // namespace fsweep
