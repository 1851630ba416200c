#pragma once
/// @file planner.hpp
/// The planner plugin edge: one small virtual interface, failures as status values.

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "world/energy_model.hpp"
#include "world/grid.hpp"
#include "world/known_map.hpp"

namespace fsweep {
inline namespace planners {

enum class PlanStatus { Success, StartInvalid, GoalInvalid, NoPath, Timeout };

[[nodiscard]] std::string_view to_string(PlanStatus s);

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
};

/// StartInvalid or GoalInvalid when that endpoint is not a known-free cell (outside the grid
/// counts as occupied; the start is checked first), else Success. Every planner starts so.
[[nodiscard]] PlanStatus check_endpoints(const KnownMap& known, const PlanRequest& request);

/// Marks `result` successful with `path` and fills length, energy, stops and turns by the one
/// accounting rule shared by all planners (measure_path in src/world/motion.hpp).
void set_path(PlanResult& result, std::vector<Cell> path, const PlanRequest& request, double resolution_m);

/// A path planner. Instances keep preallocated search arrays between queries, so they are not
/// thread-safe: use one per simulation.
class Planner {
 public:
  virtual ~Planner() = default;
  /// Registry name, e.g. "astar".
  [[nodiscard]] virtual std::string name() const = 0;
  /// Plans one query on `known`.
  [[nodiscard]] virtual PlanResult plan(const KnownMap& known, const PlanRequest& request) = 0;
  /// A fresh planner with the same parameters.
  [[nodiscard]] virtual std::unique_ptr<Planner> clone() const = 0;
};

}  // namespace planners
}  // namespace fsweep
