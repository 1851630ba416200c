#include "planners/register_all.hpp"

#include <array>
#include <nlohmann/json.hpp>

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

template <OmplPlannerKind Kind>
std::unique_ptr<Planner> make_ompl_planner(const nlohmann::json& params, const std::string& where) {
  return std::make_unique<OmplPlanner>(Kind, OmplPlannerParams::from_json(Kind, params, where));
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
      PlannerEntry{"ompl:RRTConnect", &make_ompl_planner<OmplPlannerKind::RRTConnect>},
      PlannerEntry{"ompl:RRTstar", &make_ompl_planner<OmplPlannerKind::RRTstar>},
      PlannerEntry{"ompl:InformedRRTstar", &make_ompl_planner<OmplPlannerKind::InformedRRTstar>},
      PlannerEntry{"ompl:BITstar", &make_ompl_planner<OmplPlannerKind::BITstar>},
      PlannerEntry{"ompl:PRMstar", &make_ompl_planner<OmplPlannerKind::PRMstar>},
      PlannerEntry{"ompl:LazyPRMstar", &make_ompl_planner<OmplPlannerKind::LazyPRMstar>},
      PlannerEntry{"ompl:KPIECE1", &make_ompl_planner<OmplPlannerKind::KPIECE1>},
  };
  return kTable;
}

}  // namespace planners
}  // namespace fsweep
