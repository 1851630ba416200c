#include "planners/register_all.hpp"

#include <nlohmann/json.hpp>
#include <vector>

#include "planners/grid_planner.hpp"
#include "planners/lattice_planner.hpp"
#include "planners/ompl_planner.hpp"
#include "planners/shortest_fewest_turns.hpp"

namespace fsweep {
inline namespace planners {
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
  // Add new planners here (one line each; OMPL planners in ompl_planner.cpp's list); the
  // registry, the CLI and the conformance tests pick them up from this table.
  static const std::vector<PlannerEntry> kTable = [] {
    std::vector<PlannerEntry> table{
        {"astar", GridPlanner::kCapabilities, &make_grid_planner<GridSearchKind::AStar>},
        {"dijkstra", GridPlanner::kCapabilities, &make_grid_planner<GridSearchKind::Dijkstra>},
        {"lattice", LatticePlanner::kCapabilities, &make_lattice_planner<LatticeSearchKind::Dijkstra>},
        {"lattice_astar", LatticePlanner::kCapabilities, &make_lattice_planner<LatticeSearchKind::AStar>},
        {"shortest_fewest_turns", ShortestFewestTurnsPlanner::kCapabilities, &make_shortest_fewest_turns},
    };
    for (const OmplPlannerKind& kind : ompl_planner_kinds()) {
      table.push_back(
          {kind.name, kind.capabilities, [&kind](const nlohmann::json& params, const std::string& where) {
             return std::make_unique<OmplPlanner>(kind, OmplPlannerParams::from_json(kind, params, where));
           }});
    }
    return table;
  }();
  return kTable;
}

}  // namespace planners
}  // namespace fsweep
