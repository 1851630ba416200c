#pragma once
/// @file planner.hpp
/// The planner plugin edge (OMPL's shape): a non-virtual plan() does what every planner shares
/// and calls the plugin's search() with a stop condition; failures are status values;
/// capabilities are declared data.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "search/stop_condition.hpp"
#include "world/energy_model.hpp"
#include "world/grid.hpp"
#include "world/known_map.hpp"
#include "world/motion.hpp"

namespace fsweep {
inline namespace planners {

enum class PlanStatus { Success, StartInvalid, GoalInvalid, NoPath, Timeout };

[[nodiscard]] std::string_view to_string(PlanStatus s);

struct SearchResult;

/// One query. Planning is over known-free cells of the KnownMap.
struct PlanRequest {
  Cell start;
  Cell goal;
  /// Robot heading at the start (0..7, see grid.hpp), for turn accounting.
  int start_heading = 0;
  /// Energy model used to report (and, for energy planners, to minimise) path energy.
  EnergyModel energy;
  /// Allow diagonal moves past an occupied orthogonal neighbour (default: no, MovingAI rule).
  bool allow_corner_cutting = false;
  /// Seed for sampling planners (derived from the run seed).
  std::uint64_t seed = 0;
  /// Seconds between samples of the planner's own progress properties (PlanResult::progress);
  /// 0, the default: none. Only planners that report progress properties take samples.
  double progress_interval_s = 0.0;
  /// What planner `astar`'s own search finds for this very query (start, goal, corner rule) on
  /// this map, found already by someone else with the same A* (search::PathProbe: the distance
  /// probe of the decision that chose the goal); `astar` without a time limit or expansion budget
  /// returns it instead of searching again (its expansions count as the planner's: the cells
  /// `astar` would settle), every other planner ignores it. Null: none. Must outlive plan().
  const SearchResult* searched = nullptr;
};

/// A planner's own progress properties sampled during one query: OMPL's planner progress
/// properties (e.g. RRTstar's "best cost REAL" and "iterations INTEGER"). Empty unless asked for
/// (PlanRequest::progress_interval_s) and the planner reports any.
struct PlanProgress {
  /// One sample: when, and the value of every property, in the order of `properties`.
  struct Sample {
    /// Seconds since the search started.
    double time_s = 0.0;
    /// The values as the planner writes them (text).
    std::vector<std::string> values;
  };
  /// Property names, each ending in its type as OMPL names it (REAL, DOUBLE, INTEGER, ...).
  std::vector<std::string> properties;
  /// Samples in time order (strictly increasing time_s).
  std::vector<Sample> samples;
};

/// Outcome of one query. On failure `path` is empty and the metrics are 0.
struct PlanResult {
  PlanStatus status = PlanStatus::NoPath;
  /// 8-connected cell chain from start to goal, both included.
  std::vector<Cell> path;
  double length_m = 0.0;
  double energy = 0.0;
  int stops = 0;
  int turns = 0;
  /// Nodes expanded (grid and lattice planners) or states sampled.
  long expansions = 0;
  /// Wall time of the query (seconds).
  double time_s = 0.0;
  /// The planner's progress properties during the search, when asked for.
  PlanProgress progress;
};

/// StartInvalid or GoalInvalid when that endpoint is not a known-free cell (outside the grid
/// counts as occupied; the start is checked first), else Success. Planner::plan() starts so.
[[nodiscard]] PlanStatus check_endpoints(const KnownMap& known, const PlanRequest& request);

/// When a planner's results repeat exactly for the same request and seed, whatever the timing.
/// Every answer assumes no query ends by its wall-time limit (`time_limit_s`): one that does
/// depends on the machine whatever the planner.
enum class Determinism {
  /// Always: fixed tie-breaking, and every query ends by itself (a path, or proof there is none).
  Always,
  /// Only with `max_iterations` > 0: otherwise some queries run until the time limit (an
  /// anytime planner every query, the others the queries they cannot solve).
  WithMaxIterations,
  /// Never: the result depends on thread timing.
  Never,
};

/// What a planner promises, declared as data with it (the planner tables of register_all.cpp and
/// ompl_planner.cpp) and exposed per name by the registry.
struct PlannerCapabilities {
  Determinism determinism = Determinism::Never;
  /// Every Success is a shortest path (octile length under the move rule of octile_grid.hpp).
  bool optimal = false;
  /// Keeps improving a found path until its budget ends (instead of returning the first).
  bool anytime = false;
  /// Draws random samples from the request's seed (sampling planners): runs that differ only in
  /// their seed (the repetitions of a sweep) take different paths.
  bool seeded = false;
};

/// What a planner's search gives back to Planner::plan(), which measures the path.
struct SearchResult {
  /// Success, NoPath or Timeout.
  PlanStatus status = PlanStatus::NoPath;
  /// On Success the 8-connected cell chain from start to goal, both included; else empty.
  std::vector<Cell> path;
  /// Nodes expanded (grid and lattice planners) or validity checks made (sampling planners).
  long expansions = 0;
  /// On Success, optionally: measure_path() of `path` from PlanRequest::start_heading under
  /// PlanRequest::energy, which a planner that knows its path's runs (the jump points of `jps`
  /// and `jps+`) works out without walking the cells; plan() measures the cells when unset.
  std::optional<MotionCost> motion;
  /// The planner's progress properties, when PlanRequest::progress_interval_s asks for them.
  PlanProgress progress;
};

/// A path planner: the plugin edge. plan() is the one entry point and does what every planner
/// shares; a plugin implements search(). Instances keep preallocated search arrays between
/// queries, so they are not thread-safe: use one per simulation.
class Planner {
 public:
  virtual ~Planner() = default;
  /// Registry name, e.g. "astar".
  [[nodiscard]] virtual std::string name() const = 0;
  /// A fresh planner with the same parameters.
  [[nodiscard]] virtual std::unique_ptr<Planner> clone() const = 0;

  /// Plans one query on `known`: checks the endpoints (check_endpoints()), runs search() under
  /// a StopCondition of budget() started now, and measures a found path by the one accounting
  /// rule of every planner (measure_path() in src/world/motion.hpp, from
  /// PlanRequest::start_heading under PlanRequest::energy). Timeout when the budget ended the
  /// search. `time_s` is the wall time of the whole call. Throws std::invalid_argument if
  /// PlanRequest::start_heading is not in 0..7.
  [[nodiscard]] PlanResult plan(const KnownMap& known, const PlanRequest& request);
  /// The time limit and expansion budget of one query, from the planner's parameters.
  [[nodiscard]] const SearchBudget& budget() const { return budget_; }

 protected:
  explicit Planner(const SearchBudget& budget) : budget_(budget) {}
  Planner(const Planner&) = default;
  Planner& operator=(const Planner&) = default;

  /// Searches a query whose endpoints are known free, honouring `stop` (Timeout once it says
  /// so). On Success the path starts at PlanRequest::start and ends at PlanRequest::goal.
  [[nodiscard]] virtual SearchResult search(const KnownMap& known, const PlanRequest& request,
                                            const StopCondition& stop) = 0;

 private:
  SearchBudget budget_;
};

}  // namespace planners
}  // namespace fsweep
