/// @file register_all.cpp
/// The one place where planners are registered.

#include <nlohmann/json.hpp>

#include "planners/grid_planner.hpp"
#include "planners/lattice_planner.hpp"
#include "planners/ompl_planner.hpp"
#include "planners/registry.hpp"
#include "planners/shortest_fewest_turns.hpp"

namespace fsweep {
inline namespace planners {
namespace {

using Made = std::unique_ptr<Planner>;

PlannerRegistry make_registry() {
  PlannerRegistry r("planner");
  r.add<GridPlannerParams>("astar",
                           "optimal 8-connected grid A*, octile heuristic (lengths match MovingAI's)",
                           ParamDecl<GridPlannerParams>{}, [](const GridPlannerParams& p) -> Made {
                             return std::make_unique<GridPlanner>(GridSearchKind::AStar, p);
                           });
  r.add<GridPlannerParams>("dijkstra", "optimal 8-connected grid Dijkstra", ParamDecl<GridPlannerParams>{},
                           [](const GridPlannerParams& p) -> Made {
                             return std::make_unique<GridPlanner>(GridSearchKind::Dijkstra, p);
                           });
  r.add<LatticePlannerParams>("lattice",
                              "Mei 2006 minimum-energy planner on the (cell, heading) lattice, Dijkstra",
                              ParamDecl<LatticePlannerParams>{}, [](const LatticePlannerParams& p) -> Made {
                                return std::make_unique<LatticePlanner>(LatticeSearchKind::Dijkstra, p);
                              });
  r.add<LatticePlannerParams>("lattice_astar",
                              "the lattice planner with A* (admissible octile x cheapest travel energy)",
                              ParamDecl<LatticePlannerParams>{}, [](const LatticePlannerParams& p) -> Made {
                                return std::make_unique<LatticePlanner>(LatticeSearchKind::AStar, p);
                              });
  r.add<ShortestFewestTurnsParams>(
      "shortest_fewest_turns", "the least-energy path among all shortest paths (Mei 2006's honest baseline)",
      ParamDecl<ShortestFewestTurnsParams>{}, [](const ShortestFewestTurnsParams& p) -> Made {
        return std::make_unique<ShortestFewestTurnsPlanner>(p);
      });
  for (const OmplPlannerKind kind :
       {OmplPlannerKind::RRTConnect, OmplPlannerKind::RRTstar, OmplPlannerKind::InformedRRTstar,
        OmplPlannerKind::BITstar, OmplPlannerKind::PRMstar, OmplPlannerKind::LazyPRMstar,
        OmplPlannerKind::KPIECE1}) {
    const std::string name(ompl_planner_name(kind));
    r.add<OmplPlannerParams>(
        name, "OMPL's " + name.substr(5) + " geometric planner over the known map (R2, exact motion checks)",
        std::function<ParamDecl<OmplPlannerParams>()>([kind] { return ompl_planner_params(kind); }),
        [kind](const OmplPlannerParams& p) -> Made { return std::make_unique<OmplPlanner>(kind, p); });
  }
  return r;
}

}  // namespace

const PlannerRegistry& planner_registry() {
  static const PlannerRegistry registry = make_registry();
  return registry;
}

}  // namespace planners
}  // namespace fsweep
