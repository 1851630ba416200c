#pragma once
/// @file ompl_planner.hpp
/// `ompl:<name>`: OMPL's geometric sampling planners behind the Planner interface.
///
/// State space: R2 (OMPL's RealVectorStateSpace) in cell units over the known map, bounds
/// [0, width] x [0, height]. R2, not SE2, for every planner: the simulated robot is a point
/// that follows an 8-connected cell chain and turns in place, so heading is not a planning
/// dimension; turns and energy are counted on the resulting chain like for every planner.
/// Start and goal are the centres of their cells. A state is valid if the cell under it is
/// known free. Motions are checked exactly, not at a resolution: a segment is valid if every
/// cell it crosses is known free and, without corner cutting, it passes a grid vertex only
/// between two free cells (src/planners/ompl_space.hpp, src/planners/ompl_segment_walk.hpp,
/// src/search/octile_grid.hpp).
///
/// Reproducibility: OMPL seeds every generator from one process-wide seed sequence. Every
/// OMPL call of this module (planner construction, solve, simplification) runs under one
/// process-wide lock and starts by reseeding that sequence from PlanRequest::seed, so every
/// OMPL generator of a query gets the same seed whatever other threads do; OMPL queries of
/// parallel simulations run one at a time (the rest of those simulations runs in parallel).
/// A query is then reproducible if its planner is single-threaded (all but PRMstar, which
/// checks for a solution in a second thread) and it ends by itself or by `max_iterations`,
/// not by `time_limit_s` (an anytime planner without `max_iterations` always runs to the time
/// limit and is not reproducible). OMPL's console output is switched off process-wide.

#include <map>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "core/params.hpp"
#include "planners/planner.hpp"

namespace fsweep {
inline namespace planners {

/// The OMPL geometric planners on offer (registry names `ompl:<OMPL class name>`).
enum class OmplPlannerKind { RRTConnect, RRTstar, InformedRRTstar, BITstar, PRMstar, LazyPRMstar, KPIECE1 };

/// Registry name of `kind`, e.g. "ompl:RRTConnect".
[[nodiscard]] std::string_view ompl_planner_name(OmplPlannerKind kind);

/// True if queries of `kind` are reproducible from PlanRequest::seed when they end by a
/// solution or by `max_iterations` (see the file comment); false for PRMstar.
[[nodiscard]] bool ompl_planner_single_threaded(OmplPlannerKind kind);

/// Parameters of an OMPL planner: ours, plus the planner's own OMPL parameters by their OMPL
/// names (ParamSet, e.g. `range`, `goal_bias`, `rewire_factor`) in the same JSON object.
struct OmplPlannerParams {
  /// Planning time budget per query (seconds, > 0). Simplification comes on top.
  double time_limit_s = 0.5;
  /// Iteration budget per query: the number of times the planner may test its termination
  /// condition (about one per planner iteration; > 0), or 0 for none.
  long max_iterations = 0;
  /// Run OMPL's PathSimplifier (simplifyMax) on the solution.
  bool simplify = true;
  /// OMPL parameter values as strings, by OMPL parameter name: only those given (the others
  /// keep OMPL's defaults).
  std::map<std::string, std::string> ompl;
};

/// The declared parameters (core/params.hpp) of planner `kind`: ours (time_limit_s,
/// max_iterations, simplify) and every OMPL parameter its ParamSet declares, with OMPL's
/// default value and range suggestion; a value is checked by setting it on a probe planner.
[[nodiscard]] ParamDecl<OmplPlannerParams> ompl_planner_params(OmplPlannerKind kind);

/// Sorted names of our own keys and of every OMPL parameter `kind` declares.
[[nodiscard]] std::vector<std::string> ompl_planner_param_names(OmplPlannerKind kind);

/// An OMPL planner (see the file comment). Builds the OMPL objects per query; the instance
/// holds only its parameters.
///
/// Statuses: StartInvalid / GoalInvalid by check_endpoints(); start == goal gives the one-cell
/// path without calling OMPL; Timeout if OMPL has no exact solution when the time or
/// iteration budget ends (a sampling planner cannot prove that no path exists, so NoPath is
/// only returned if OMPL gives up before the budget). On Success the OMPL path (simplified if
/// `simplify`) is turned into the cell chain of polyline_cell_chain(), every move of which is
/// allowed by octile_step_allowed(); length, energy, stops and turns come from set_path().
/// `expansions` is the number of state and motion validity checks OMPL made while solving
/// (its sampling effort; simplification not included).
class OmplPlanner final : public Planner {
 public:
  /// `params` must come from ompl_planner_params(kind) (or be defaults).
  explicit OmplPlanner(OmplPlannerKind kind, OmplPlannerParams params = {})
      : kind_(kind), params_(std::move(params)) {}

  [[nodiscard]] std::string name() const override { return std::string(ompl_planner_name(kind_)); }
  [[nodiscard]] PlanResult plan(const KnownMap& known, const PlanRequest& request) override;
  [[nodiscard]] std::unique_ptr<Planner> clone() const override {
    return std::make_unique<OmplPlanner>(kind_, params_);
  }

  [[nodiscard]] OmplPlannerKind kind() const { return kind_; }
  [[nodiscard]] const OmplPlannerParams& params() const { return params_; }

 private:
  OmplPlannerKind kind_;
  OmplPlannerParams params_;
};

}  // namespace planners
}  // namespace fsweep
