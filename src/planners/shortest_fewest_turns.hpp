#pragma once
/// @file shortest_fewest_turns.hpp
/// `shortest_fewest_turns`: among all shortest 8-connected paths (octile lengths, the move rule
/// of src/search/octile_grid.hpp, the same lengths as `dijkstra` and `astar`), the one with the
/// least energy under PlanRequest::energy, i.e. the cheapest stops and turns by the rule of
/// src/world/motion.hpp (the start heading counts, no final stop at the goal). It is the
/// honest "best case" shortest-path baseline of a Mei 2006 section V-B comparison: `dijkstra`
/// returns whichever shortest path its tie-breaking gives, often a zig-zag staircase.
///
/// Method (exact, no weighted sum of length and energy):
/// 1. d(c) = shortest length from cell c to the goal (cells), by one Dijkstra from the goal
///    (DistanceField; the move rule is symmetric), stopped once the start is settled;
/// 2. the heading lattice of lattice_planner.hpp from (start, start_heading), restricted to
///    steps u -> v with d(u) == w(u, v) + d(v): every path of that restricted graph is a
///    shortest path and every shortest path is one of its paths, so minimising energy over it
///    gives the cheapest shortest path. The search is A* with h(c) = d(c) x travel energy per
///    cell, the exact remaining travel energy (consistent, since every restricted step lowers d
///    by its own length), so the open list is ordered by the stop and turn energy so far.

#include <limits>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "planners/planner.hpp"
#include "search/distance_field.hpp"
#include "search/grid_search.hpp"

namespace fsweep {
inline namespace planners {

/// Parameters of `shortest_fewest_turns`: only the query budget (declare_budget() in budget_params.hpp); any
/// other key is a ConfigError. The energy model is the request's.
struct ShortestFewestTurnsParams {
  /// Wall time of one query's two searches (seconds, > 0); +infinity (the default, JSON null): none.
  double time_limit_s = std::numeric_limits<double>::infinity();
  /// Cells plus (cell, heading) states one query may settle in its two searches together (>= 0);
  /// 0 (the default): none.
  long max_expansions = 0;
};

/// Cheapest-energy shortest-path planner (see the file comment). Keeps its distance field and
/// lattice search arrays between queries (not thread-safe).
///
/// Statuses (besides Planner::plan()'s endpoint and heading checks): NoPath if the goal is not
/// reachable through known-free cells; Timeout if the time limit or the expansion budget ends
/// either search first; Success otherwise (start == goal gives the one-cell path at energy 0).
/// On Success the length equals the shortest length (as `dijkstra`'s, exactly in cells up to
/// rounding) and the energy is the least over all shortest paths. `expansions` counts the cells
/// settled by the distance field plus the (cell, heading) states settled by the lattice search.
/// Ties between equal-energy shortest paths break as in BestFirstSearch (smaller f, larger g,
/// smaller state id).
class ShortestFewestTurnsPlanner final : public Planner {
 public:
  /// Deterministic (fixed tie-breaking) and length-optimal.
  static constexpr PlannerCapabilities kCapabilities{Determinism::Always, true, false};

  explicit ShortestFewestTurnsPlanner(ShortestFewestTurnsParams params = {})
      : Planner(SearchBudget{params.time_limit_s, params.max_expansions}), params_(params) {}

  [[nodiscard]] std::string name() const override { return "shortest_fewest_turns"; }
  [[nodiscard]] std::unique_ptr<Planner> clone() const override;

  [[nodiscard]] const ShortestFewestTurnsParams& params() const { return params_; }

 protected:
  [[nodiscard]] SearchResult search(const KnownMap& known, const PlanRequest& request,
                                    const StopCondition& stop) override;

 private:
  ShortestFewestTurnsParams params_;
  DistanceField to_goal_;
  BestFirstSearch search_;
};

}  // namespace planners
}  // namespace fsweep
