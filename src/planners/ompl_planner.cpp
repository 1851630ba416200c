#include "planners/ompl_planner.hpp"

#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/config.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/PathSimplifier.h>
#include <ompl/geometric/planners/informedtrees/BITstar.h>
#include <ompl/geometric/planners/kpiece/KPIECE1.h>
#include <ompl/geometric/planners/prm/LazyPRMstar.h>
#include <ompl/geometric/planners/prm/PRMstar.h>
#include <ompl/geometric/planners/rrt/InformedRRTstar.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <mutex>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <thread>
#include <utility>

#include "core/config_error.hpp"
#include "core/json_excerpt.hpp"
#include "core/random.hpp"
#include "planners/ompl_segment_walk.hpp"
#include "planners/ompl_space.hpp"
#include "search/octile_grid.hpp"

namespace fsweep {
inline namespace planners {
namespace {

namespace ob = ompl::base;
namespace og = ompl::geometric;

/// Our own keys of the params object (the rest are OMPL parameter names).
constexpr std::string_view kTimeLimitKey = "time_limit_s";
constexpr std::string_view kMaxIterationsKey = "max_iterations";
constexpr std::string_view kSimplifyKey = "simplify";

/// The lock every OMPL call of this module holds (see the file comment of the header).
std::mutex& ompl_mutex() {
  static std::mutex mutex;
  return mutex;
}

/// Holds the OMPL lock for its lifetime and reseeds OMPL's process-wide seed sequence, so the
/// OMPL generators created while it lives get seeds that depend on `seed` only.
class OmplSession {
 public:
  explicit OmplSession(std::uint64_t seed) : lock_(ompl_mutex()) {
    // OMPL logs every query at info level and reports each reseeding as an error.
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    auto ompl_seed = static_cast<std::uint32_t>(derive_seed(seed, "ompl"));
    if (ompl_seed == 0) ompl_seed = 1;  // OMPL rejects seed 0
    ompl::RNG::setSeed(ompl_seed);
  }

 private:
  std::lock_guard<std::mutex> lock_;
};

/// Samples an OMPL planner's progress properties during one solve (PlanProgress): at its first
/// termination check, then at the first check at least `interval_s` after the previous sample,
/// and once more when the solve returns. The properties are only read (none of OMPL's progress
/// functions changes the planner), in the solving thread, so a query's result is the same with
/// or without sampling unless a time limit ends it. A planner that solves in several threads
/// (`during_solve` false: PRMstar, whose solution thread writes the best cost while the roadmap
/// grows) is sampled only when its solve has returned: its properties are not safe to read before.
class ProgressSampler {
 public:
  using Clock = StopCondition::Clock;

  ProgressSampler(const ob::Planner& planner, double interval_s, bool during_solve, Clock::time_point started)
      : properties_(interval_s > 0.0 ? &planner.getPlannerProgressProperties() : nullptr),
        interval_(std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(interval_s))),
        during_solve_(during_solve && properties_ != nullptr && !properties_->empty()),
        started_(started),
        solver_(std::this_thread::get_id()) {
    if (properties_ == nullptr) return;
    for (const auto& [name, read] : *properties_) progress_.properties.push_back(name);
  }

  /// Called at every termination check.
  void on_check() {
    if (!during_solve_ || std::this_thread::get_id() != solver_) return;
    const Clock::time_point now = Clock::now();
    if (!progress_.samples.empty() && now < last_ + interval_) return;
    sample(now);
  }

  /// Called once the solve has returned; gives the samples.
  [[nodiscard]] PlanProgress finish() {
    if (properties_ != nullptr && !properties_->empty()) {
      const Clock::time_point now = Clock::now();
      if (progress_.samples.empty() || now > last_) sample(now);
    }
    return std::move(progress_);
  }

 private:
  void sample(Clock::time_point now) {
    PlanProgress::Sample s;
    s.time_s = std::chrono::duration<double>(now - started_).count();
    for (const auto& [name, read] : *properties_) s.values.push_back(read());
    progress_.samples.push_back(std::move(s));
    last_ = now;
  }

  const ob::Planner::PlannerProgressProperties* properties_;
  Clock::duration interval_;
  bool during_solve_;
  Clock::time_point started_;
  Clock::time_point last_;
  std::thread::id solver_;
  PlanProgress progress_;
};

/// The OMPL planner factory of a table row.
template <typename OmplPlannerClass>
ob::PlannerPtr make_planner_of(const ob::SpaceInformationPtr& si) {
  return std::make_shared<OmplPlannerClass>(si);
}

/// Capabilities of the single-threaded OMPL planners that stop at their first path (RRTConnect,
/// KPIECE1) and of the anytime ones (asymptotically optimal, not optimal in finite time); PRMstar
/// checks for a solution in a second thread, so it is never deterministic.
constexpr PlannerCapabilities kFirstPath{Determinism::WithMaxIterations, false, false, true};
constexpr PlannerCapabilities kAnytime{Determinism::WithMaxIterations, false, true, true};
constexpr PlannerCapabilities kAnytimeThreaded{Determinism::Never, false, true, true};

/// THE list of OMPL planners (add one here, one line; registry order).
constexpr std::array kOmplPlanners{
    OmplPlannerKind{"ompl:RRTConnect", kFirstPath, &make_planner_of<og::RRTConnect>},
    OmplPlannerKind{"ompl:RRTstar", kAnytime, &make_planner_of<og::RRTstar>},
    OmplPlannerKind{"ompl:InformedRRTstar", kAnytime, &make_planner_of<og::InformedRRTstar>},
    OmplPlannerKind{"ompl:BITstar", kAnytime, &make_planner_of<og::BITstar>},
    OmplPlannerKind{"ompl:PRMstar", kAnytimeThreaded, &make_planner_of<og::PRMstar>},
    OmplPlannerKind{"ompl:LazyPRMstar", kAnytime, &make_planner_of<og::LazyPRMstar>},
    OmplPlannerKind{"ompl:KPIECE1", kFirstPath, &make_planner_of<og::KPIECE1>},
};

/// The string OMPL's ParamSet gets for a JSON value.
std::string ompl_value_string(const nlohmann::json& value, const std::string& where) {
  if (value.is_string()) return value.get<std::string>();
  if (value.is_boolean()) return value.get<bool>() ? "1" : "0";
  if (value.is_number()) return value.dump();
  throw ConfigError(where, "expected a string, number or boolean, got " + json_excerpt(value));
}

/// What one OMPL query gives back.
struct OmplOutcome {
  PlanStatus status = PlanStatus::NoPath;
  /// The solution's states (cell units), start first.
  std::vector<PlanePoint> points;
  /// State and motion validity checks OMPL made while solving.
  long checks = 0;
  /// The planner's progress properties, when the request asks for them.
  PlanProgress progress;
};

OmplOutcome solve_with_ompl(const OmplPlannerKind& kind, const OmplPlannerParams& params,
                            const KnownMap& known, const PlanRequest& request, const StopCondition& stop) {
  const OmplSession session(request.seed);
  // 1. Problem: centres of the start and goal cells, shortest path length.
  const ob::SpaceInformationPtr si = make_grid_space_information(known, request.allow_corner_cutting);
  auto pdef = std::make_shared<ob::ProblemDefinition>(si);
  ob::ScopedState<ob::RealVectorStateSpace> start(si->getStateSpace());
  ob::ScopedState<ob::RealVectorStateSpace> goal(si->getStateSpace());
  const PlanePoint s = centre_of(request.start);
  const PlanePoint g = centre_of(request.goal);
  start->values[0] = s.x;
  start->values[1] = s.y;
  goal->values[0] = g.x;
  goal->values[1] = g.y;
  pdef->setStartAndGoalStates(start, goal);
  pdef->setOptimizationObjective(std::make_shared<ob::PathLengthOptimizationObjective>(si));

  // 2. Planner with its OMPL parameters (validated by ompl_planner_params()).
  const ob::PlannerPtr planner = kind.make(si);
  if (!planner->params().setParams(params.ompl)) {
    throw std::logic_error("OmplPlanner: OMPL rejected parameters that ompl_planner_params() accepted");
  }
  planner->setProblemDefinition(pdef);
  planner->setup();

  // 3. Budget: the stop condition with its clock restarted now (the time limit is solve time,
  //    not the wait for the lock nor the set-up), the expansion budget counting termination checks;
  //    the progress properties sampled at the checks when asked for.
  const StopCondition::Clock::time_point solve_started = StopCondition::Clock::now();
  const StopCondition solve_stop = stop.restarted(solve_started);
  const bool one_thread =
      kind.capabilities.determinism != Determinism::Never;  // Never: PRMstar's two threads
  ProgressSampler progress(*planner, request.progress_interval_s, one_thread, solve_started);
  std::atomic<long> checks{0};
  const ob::PlannerTerminationCondition ptc([&solve_stop, &checks, &progress] {
    progress.on_check();
    return solve_stop.time_up() || solve_stop.budget_spent(checks.fetch_add(1, std::memory_order_relaxed));
  });
  const ob::PlannerStatus solved = planner->solve(ptc);

  OmplOutcome outcome;
  outcome.progress = progress.finish();
  outcome.checks = grid_validity_checks(*si);
  const bool exact = pdef->hasExactSolution();
  og::PathGeometric path(si);
  if (exact) path = *pdef->getSolutionPath()->as<og::PathGeometric>();  // a deep copy
  // Debian's OMPL 1.5.2 LazyPRM leaks its roadmap states unless cleared before destruction
  // (OMPL issue #833); clearing is harmless for every planner.
  planner->clear();
  if (!exact) {
    const bool budget =
        solved == ob::PlannerStatus::TIMEOUT || solved == ob::PlannerStatus::APPROXIMATE_SOLUTION;
    outcome.status = budget ? PlanStatus::Timeout : PlanStatus::NoPath;
    return outcome;
  }
  // 4. The solution, simplified (every change OMPL makes is checked by our motion validator).
  if (params.simplify) {
    og::PathSimplifier simplifier(si);
    simplifier.simplifyMax(path);
  }
  outcome.status = PlanStatus::Success;
  for (const ob::State* state : path.getStates()) outcome.points.push_back(point_of(state));
  return outcome;
}

}  // namespace

std::span<const OmplPlannerKind> ompl_planner_kinds() { return kOmplPlanners; }

std::string ompl_version() {
  // Debian's OMPL 1.5.2 headers define OMPL_VERSION as "" (the numeric macros are right).
  std::string version = OMPL_VERSION;
  if (!version.empty()) return version;
  return std::to_string(OMPL_MAJOR_VERSION) + "." + std::to_string(OMPL_MINOR_VERSION) + "." +
         std::to_string(OMPL_PATCH_VERSION);
}

const OmplPlannerKind& ompl_planner_kind(std::string_view name) {
  for (const OmplPlannerKind& kind : kOmplPlanners) {
    if (kind.name == name) return kind;
  }
  throw std::invalid_argument("no OMPL planner is registered as '" + std::string(name) + "'");
}

ParamDecl<OmplPlannerParams> ompl_planner_params(const OmplPlannerKind& kind) {
  using P = OmplPlannerParams;
  ParamDecl<P> d;
  d.number(std::string(kTimeLimitKey), &P::time_limit_s,
           "planning time budget per query (simplification comes on top)")
      .above(0)
      .unit("s");
  d.integer(std::string(kMaxIterationsKey), &P::max_iterations,
            "iteration budget per query: times the planner may test its termination condition; 0: none "
            "(with it, single-threaded planners are reproducible)")
      .at_least(0);
  d.boolean(std::string(kSimplifyKey), &P::simplify,
            "run OMPL's PathSimplifier (simplifyMax) on the solution");
  // OMPL's own parameters of this planner, as its ParamSet declares them (value and range
  // suggestion read from a probe planner; a value is checked by setting it on a probe).
  const OmplSession session(0);
  const KnownMap probe_map(1, 1, 1.0);
  const ob::SpaceInformationPtr si = make_grid_space_information(probe_map, false);
  const ob::PlannerPtr probe = kind.make(si);
  std::map<std::string, std::string> defaults;
  probe->params().getParams(defaults);
  const std::string planner = std::string(kind.name).substr(5);
  for (const auto& [name, value] : defaults) {
    ParamSpec spec;
    spec.name = name;
    spec.type = ParamType::Custom;
    spec.doc = "OMPL parameter of " + planner + " (set through its ParamSet)";
    const std::string range = probe->params()[name].getRangeSuggestion();
    spec.allowed_text = "a value OMPL accepts (string, number or boolean)" +
                        (range.empty() ? "" : "; OMPL suggests " + range);
    spec.custom_check = [make = kind.make, name = name](const nlohmann::json& v) -> std::vector<std::string> {
      std::string text;
      try {
        text = ompl_value_string(v, name);
      } catch (const ConfigError&) {
        return {"expected a string, number or boolean, got " + json_excerpt(v)};
      }
      const OmplSession check_session(0);
      const KnownMap map(1, 1, 1.0);
      const ob::PlannerPtr p = make(make_grid_space_information(map, false));
      try {
        if (p->params().setParam(name, text)) return {};
      } catch (const std::exception& e) {
        return {"OMPL rejects '" + text + "': " + e.what()};
      }
      // NOLINTNEXTLINE(performance-inefficient-string-concatenation): once, for a refused value
      return {"OMPL rejects '" + text + "' for parameter '" + name + "'"};
    };
    d.custom(
        std::move(spec),
        [name = name](P& p, const nlohmann::json& v) { p.ompl[name] = ompl_value_string(v, name); },
        [name = name, value = value](const P& p) {
          const auto it = p.ompl.find(name);
          return nlohmann::json(it == p.ompl.end() ? value : it->second);
        });
  }
  return d;
}

SearchResult OmplPlanner::search(const KnownMap& known, const PlanRequest& request,
                                 const StopCondition& stop) {
  SearchResult result;
  // 1. start == goal needs no planner.
  if (request.start == request.goal) {
    result.status = PlanStatus::Success;
    result.path = {request.start};
    return result;
  }
  // 2. OMPL, then the cell chain of its polyline.
  OmplOutcome outcome = solve_with_ompl(kind_, params_, known, request, stop);
  result.expansions = outcome.checks;
  result.status = outcome.status;
  result.progress = std::move(outcome.progress);
  if (outcome.status != PlanStatus::Success) return result;
  result.path = polyline_cell_chain(known, outcome.points, request.allow_corner_cutting);
  // 3. The chain must be a valid plan by construction; anything else is a bug here.
  bool valid =
      !result.path.empty() && result.path.front() == request.start && result.path.back() == request.goal;
  for (std::size_t i = 1; valid && i < result.path.size(); ++i) {
    valid = octile_step_allowed(known, result.path[i - 1], result.path[i], request.allow_corner_cutting);
  }
  if (!valid) throw std::logic_error(name() + ": OMPL solution does not map to a valid cell chain");
  return result;
}

}  // namespace planners
}  // namespace fsweep
