/// @file register_all.cpp
/// The one place where planners are registered, each with its declared capabilities (the OMPL
/// planners come from their own one list, ompl_planner_kinds()).

#include <map>
#include <nlohmann/json.hpp>

#include "planners/budget_params.hpp"
#include "planners/grid_planner.hpp"
#include "planners/jps_planner.hpp"
#include "planners/jps_plus_planner.hpp"
#include "planners/lattice_planner.hpp"
#include "planners/ompl_planner.hpp"
#include "planners/registry.hpp"
#include "planners/shortest_fewest_turns.hpp"

namespace fsweep {
inline namespace planners {
namespace {

using Made = std::unique_ptr<Planner>;

/// The registry and, by the same names, the capabilities.
struct PlannerCatalog {
  PlannerRegistry registry{"planner"};
  std::map<std::string, PlannerCapabilities, std::less<>> capabilities;

  template <class P, class Declare, class Make>
  void add(const std::string& name, const PlannerCapabilities& caps, std::string doc, Declare declare,
           Make make) {
    registry.add<P>(name, std::move(doc), std::function<ParamDecl<P>()>(std::move(declare)),
                    std::function<Made(const P&)>(std::move(make)));
    capabilities.emplace(name, caps);
  }
};

ParamDecl<GridPlannerParams> grid_params() {
  ParamDecl<GridPlannerParams> d;
  declare_budget(d, "cells one query may settle");
  return d;
}

ParamDecl<JpsPlannerParams> jps_params() {
  ParamDecl<JpsPlannerParams> d;
  declare_budget(d, "jump points one query may settle");
  return d;
}

ParamDecl<JpsPlusPlannerParams> jps_plus_params() {
  ParamDecl<JpsPlusPlannerParams> d;
  declare_budget(d, "jump points one query may settle");
  return d;
}

ParamDecl<LatticePlannerParams> lattice_params() {
  ParamDecl<LatticePlannerParams> d;
  declare_budget(d, "(cell, heading) states one query may settle");
  return d;
}

ParamDecl<ShortestFewestTurnsParams> shortest_fewest_turns_params() {
  ParamDecl<ShortestFewestTurnsParams> d;
  declare_budget(d, "cells plus (cell, heading) states one query may settle in its two searches together");
  return d;
}

PlannerCatalog make_catalog() {
  PlannerCatalog c;
  c.add<GridPlannerParams>("astar", GridPlanner::kCapabilities,
                           "optimal 8-connected grid A*, octile heuristic (lengths match MovingAI's)",
                           grid_params, [](const GridPlannerParams& p) -> Made {
                             return std::make_unique<GridPlanner>(GridSearchKind::AStar, p);
                           });
  c.add<GridPlannerParams>("dijkstra", GridPlanner::kCapabilities, "optimal 8-connected grid Dijkstra",
                           grid_params, [](const GridPlannerParams& p) -> Made {
                             return std::make_unique<GridPlanner>(GridSearchKind::Dijkstra, p);
                           });
  c.add<JpsPlannerParams>("jps", JpsPlanner::kCapabilities,
                          "jump point search (Harabor 2011), deterministic and optimal: astar's lengths, "
                          "settling only jump points",
                          jps_params,
                          [](const JpsPlannerParams& p) -> Made { return std::make_unique<JpsPlanner>(p); });
  c.add<JpsPlusPlannerParams>(
      "jps+", JpsPlusPlanner::kCapabilities,
      "JPS+ (Harabor 2012, Rabin 2015): jps over jump distances precomputed per cell and heading, "
      "astar's lengths; the table is rebuilt whenever the map changed, so it pays off on static maps only",
      jps_plus_params,
      [](const JpsPlusPlannerParams& p) -> Made { return std::make_unique<JpsPlusPlanner>(p); });
  c.add<LatticePlannerParams>("lattice", LatticePlanner::kCapabilities,
                              "Mei 2006 minimum-energy planner on the (cell, heading) lattice, Dijkstra",
                              lattice_params, [](const LatticePlannerParams& p) -> Made {
                                return std::make_unique<LatticePlanner>(LatticeSearchKind::Dijkstra, p);
                              });
  c.add<LatticePlannerParams>("lattice_astar", LatticePlanner::kCapabilities,
                              "the lattice planner with A* (admissible octile x cheapest travel energy)",
                              lattice_params, [](const LatticePlannerParams& p) -> Made {
                                return std::make_unique<LatticePlanner>(LatticeSearchKind::AStar, p);
                              });
  c.add<ShortestFewestTurnsParams>(
      "shortest_fewest_turns", ShortestFewestTurnsPlanner::kCapabilities,
      "the least-energy path among all shortest paths (Mei 2006's honest baseline)",
      shortest_fewest_turns_params, [](const ShortestFewestTurnsParams& p) -> Made {
        return std::make_unique<ShortestFewestTurnsPlanner>(p);
      });
  for (const OmplPlannerKind& kind : ompl_planner_kinds()) {
    const std::string name(kind.name);
    c.add<OmplPlannerParams>(
        name, kind.capabilities,
        "OMPL's " + name.substr(5) + " geometric planner over the known map (R2, exact motion checks)",
        [&kind] { return ompl_planner_params(kind); },
        [&kind](const OmplPlannerParams& p) -> Made { return std::make_unique<OmplPlanner>(kind, p); });
  }
  return c;
}

const PlannerCatalog& catalog() {
  static const PlannerCatalog kCatalog = make_catalog();
  return kCatalog;
}

}  // namespace

const PlannerRegistry& planner_registry() { return catalog().registry; }

std::optional<PlannerCapabilities> planner_capabilities(std::string_view name) {
  const auto& caps = catalog().capabilities;
  const auto it = caps.find(name);
  if (it == caps.end()) return std::nullopt;
  return it->second;
}

}  // namespace planners
}  // namespace fsweep
