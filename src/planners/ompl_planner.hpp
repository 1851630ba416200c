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
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/params.hpp"
#include "planners/planner.hpp"

namespace ompl::base {
class Planner;
class SpaceInformation;
}  // namespace ompl::base

namespace fsweep {
inline namespace planners {

/// One OMPL geometric planner on offer. ompl_planner_kinds() is the one list of them: the
/// registry, the reproducibility rule and the tests read it.
struct OmplPlannerKind {
  /// Registry name, `ompl:` + the OMPL class name, e.g. "ompl:RRTConnect".
  std::string_view name;
  /// Declared capabilities: none is optimal in finite time; single-threaded ones are
  /// deterministic with `max_iterations` (see the file comment), PRMstar never.
  PlannerCapabilities capabilities;
  /// Makes the OMPL planner over `si`.
  std::shared_ptr<ompl::base::Planner> (*make)(const std::shared_ptr<ompl::base::SpaceInformation>& si);
};

/// Every OMPL planner on offer, in registry order.
[[nodiscard]] std::span<const OmplPlannerKind> ompl_planner_kinds();

/// The version of the OMPL headers of this build, e.g. "1.5.2": OMPL_VERSION, or
/// OMPL_MAJOR_VERSION.OMPL_MINOR_VERSION.OMPL_PATCH_VERSION where OMPL_VERSION is empty.
[[nodiscard]] std::string ompl_version();

/// The kind registered as `name` (e.g. "ompl:RRTstar"); throws std::invalid_argument if none is.
[[nodiscard]] const OmplPlannerKind& ompl_planner_kind(std::string_view name);

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
[[nodiscard]] ParamDecl<OmplPlannerParams> ompl_planner_params(const OmplPlannerKind& kind);

/// An OMPL planner (see the file comment). Builds the OMPL objects per query; the instance
/// holds only its parameters.
///
/// Statuses (besides Planner::plan()'s endpoint checks): start == goal gives the one-cell path
/// without calling OMPL; Timeout if OMPL has no exact solution when the time or iteration budget
/// ends (a sampling planner cannot prove that no path exists, so NoPath is only returned if
/// OMPL gives up before the budget). The budget is Planner::budget(): `time_limit_s` counted
/// from the start of OMPL's solve (after the process-wide lock and the set-up), and
/// `max_iterations` as the expansion budget over OMPL's termination checks. On Success the
/// OMPL path (simplified if `simplify`) is turned into the cell chain of polyline_cell_chain(),
/// every move of which is allowed by octile_step_allowed(). `expansions` is the number of state
/// and motion validity checks OMPL made while solving (its sampling effort; simplification not
/// included).
///
/// Progress: with PlanRequest::progress_interval_s > 0, PlanResult::progress holds the OMPL
/// planner's progress properties (as OMPL's Benchmark records them: RRTstar and InformedRRTstar
/// "best cost REAL", "iterations INTEGER"; BITstar "best cost DOUBLE" and its counters; PRMstar
/// and LazyPRMstar "best cost REAL", "iterations INTEGER", "milestone count INTEGER", "edge count
/// INTEGER"; none for RRTConnect and KPIECE1), sampled at OMPL's termination checks in the solving
/// thread: at the first, then every interval, and once when the solve returns (PRMstar, which
/// solves in two threads, only then). Sampling only reads the planner, so a query that ends by
/// itself or by `max_iterations` gives the same result with or without it.
class OmplPlanner final : public Planner {
 public:
  /// `params` must come from ompl_planner_params(kind) (or be defaults).
  explicit OmplPlanner(const OmplPlannerKind& kind, OmplPlannerParams params = {})
      : Planner(SearchBudget{params.time_limit_s, params.max_iterations}),
        kind_(kind),
        params_(std::move(params)) {}

  [[nodiscard]] std::string name() const override { return std::string(kind_.name); }
  [[nodiscard]] std::unique_ptr<Planner> clone() const override {
    return std::make_unique<OmplPlanner>(kind_, params_);
  }

  [[nodiscard]] const OmplPlannerKind& kind() const { return kind_; }
  [[nodiscard]] const OmplPlannerParams& params() const { return params_; }

 protected:
  [[nodiscard]] SearchResult search(const KnownMap& known, const PlanRequest& request,
                                    const StopCondition& stop) override;

 private:
  OmplPlannerKind kind_;
  OmplPlannerParams params_;
};

}  // namespace planners
}  // namespace fsweep
