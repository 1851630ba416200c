#pragma once
/// @file lattice_planner.hpp
/// `lattice` and `lattice_astar`: energy-optimal paths on the (cell, heading) state lattice of
/// Mei et al. 2006, section IV-C and Figure 6. Each known-free cell has 8 states, one per
/// 45-degree heading; the search minimises the energy of PlanRequest::energy (the run's
/// model, e.g. the `mei2006` preset: 1 per cell length, stop 0.5, turns 0.4/0.6/0.8/1.0), not
/// the length, so it may return a longer path with fewer stops and turns (paper Figure 2).
///
/// Lattice (state ids `cell_index * 8 + heading`; headings as in grid.hpp):
/// - the state (c, h) means "the robot is on cell c facing h"; the start state is
///   (start, PlanRequest::start_heading) with cost 0, so the start heading counts;
/// - from (c, h) the robot may step to the neighbour c + dir(h') in any heading h' whose step
///   src/search/octile_grid.hpp allows (corner rule from PlanRequest::allow_corner_cutting),
///   reaching (c + dir(h'), h') at cost energy.turn(heading_difference(h, h')) +
///   energy.travel(step_length(h'), resolution): keeping the heading costs only travel, a
///   change of k eighth-turns adds one stop plus the k-step turn (energy_model.hpp);
/// - the goal is reached at any heading on the goal cell: NO final stop is charged, the same
///   rule measure_path() applies to every planner (energy_model.hpp).
/// This is Mei's graph with the turn charged on the edge that leaves in the new heading rather
/// than the edge that arrives; the path costs are the same.

#include <limits>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "planners/planner.hpp"
#include "search/grid_search.hpp"

namespace fsweep {
inline namespace planners {

/// Which search a LatticePlanner runs (both return minimum-energy paths).
enum class LatticeSearchKind {
  /// Uniform-cost search (zero heuristic), as in the paper: registry name `lattice`.
  Dijkstra,
  /// A* with the octile distance to the goal times the cheapest travel energy per cell
  /// (admissible and consistent, since turns cost >= 0): `lattice_astar`.
  AStar,
};

/// Parameters of the lattice planners: only the query budget (declare_budget() in budget_params.hpp); any
/// other key is a ConfigError. The energy model is not a parameter: it is the request's.
struct LatticePlannerParams {
  /// Wall time of one query's search (seconds, > 0); +infinity (the default, JSON null): none.
  double time_limit_s = std::numeric_limits<double>::infinity();
  /// (cell, heading) states one query may settle (>= 0); 0 (the default): none.
  long max_expansions = 0;
};

/// Minimum-energy planner on the heading lattice. Keeps its search arrays (8 states per cell)
/// between queries (not thread-safe).
///
/// Statuses (besides Planner::plan()'s endpoint and heading checks): NoPath if the goal is not
/// reachable through known-free cells; Timeout if the time limit or the expansion budget ends the
/// search first; Success otherwise (start == goal gives the one-cell path at energy 0).
/// The energy Planner::plan() measures equals the search cost. `expansions` counts settled
/// (cell, heading) states. Ties between equal-energy paths break as in BestFirstSearch (smaller
/// f, larger g, smaller state id).
class LatticePlanner final : public Planner {
 public:
  /// Deterministic (fixed tie-breaking); energy-optimal, which is not length-optimal.
  static constexpr PlannerCapabilities kCapabilities{Determinism::Always, false, false};

  explicit LatticePlanner(LatticeSearchKind kind, LatticePlannerParams params = {})
      : Planner(SearchBudget{params.time_limit_s, params.max_expansions}), kind_(kind), params_(params) {}

  [[nodiscard]] std::string name() const override;
  [[nodiscard]] std::unique_ptr<Planner> clone() const override;

  [[nodiscard]] LatticeSearchKind kind() const { return kind_; }
  [[nodiscard]] const LatticePlannerParams& params() const { return params_; }

 protected:
  [[nodiscard]] SearchResult search(const KnownMap& known, const PlanRequest& request,
                                    const StopCondition& stop) override;

 private:
  LatticeSearchKind kind_;
  LatticePlannerParams params_;
  BestFirstSearch search_;
};

}  // namespace planners
}  // namespace fsweep
