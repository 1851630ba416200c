#pragma once
/// @file distance_field.hpp
/// One-to-many shortest path lengths over known free space (8-connected, octile costs),
/// bounded by a maximum distance, with early stop at targets, and single lengths by A* in the same
/// storage. Search arrays are reused between queries (reset by generation stamp, not by
/// clearing). Moves and corner cutting follow
/// src/search/octile_grid.hpp; the search is the generic core of src/search/grid_search.hpp with a
/// zero heuristic.

#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "search/grid_search.hpp"
#include "search/stop_condition.hpp"
#include "world/grid.hpp"
#include "world/known_map.hpp"

namespace fsweep {
inline namespace search {

/// A caller's stop rule for a search that settles cells in order of path length (see
/// DistanceQuery::watcher): the search reports each target as it is settled and, before it
/// settles a cell beyond the radius the watcher last named, asks whether to go on. A caller that
/// chooses among the targets by a score that grows with the distance can so stop as soon as no
/// target not yet settled can win (the energy-aware choice, strategies/energy_aware.cpp).
class SettleWatcher {
 public:
  virtual ~SettleWatcher() = default;
  /// The target at `position` of the query's target list is settled at `distance_m`. Targets are
  /// reported in order of distance; a cell listed twice is reported once per position.
  virtual void settled(std::size_t position, double distance_m) = 0;
  /// Every cell not yet settled is at least `radius_m` away (an exact bound: the search settles in
  /// order of its double costs). Returns how far the search may go on before it asks again; a
  /// value below `radius_m` stops the search now. Asked again after every settled target.
  virtual double go_on_until(double radius_m) = 0;
};

struct DistanceQuery {
  /// Stop expanding beyond this path length (metres); cells farther away read as infinite.
  double max_distance_m = std::numeric_limits<double>::infinity();
  bool allow_corner_cutting = false;
  /// When not empty: stop as soon as every cell strictly closer than the nearest target is
  /// settled and all targets at that same distance are settled, i.e. the nearest target(s)
  /// are exact. Other cells read as infinite unless settled. "Same distance" allows 1e-9 cells
  /// of rounding. Indices outside the grid are ignored. The span must outlive compute() only.
  std::span<const int> stop_at_first_of{};
  /// When not empty (and stop_at_first_of is empty): stop as soon as every listed cell that is
  /// reachable within the bound is settled. Listed cells read exactly; other cells read as
  /// infinite unless settled. Indices outside the grid are ignored.
  std::span<const int> stop_when_all_settled{};
  /// With stop_when_all_settled: told about every listed cell as it is settled, and may stop the
  /// search earlier (SettleWatcher). Null: none. Must outlive compute() only.
  SettleWatcher* watcher = nullptr;
  /// Time limit and expansion budget (default: none); DistanceField::stopped() tells whether it
  /// ended the search (cells not settled by then read as infinite).
  StopCondition stop{};
};

/// A field of path lengths from one source, kept in reusable search storage (12 bytes a cell:
/// exact costs and stamps, no parents; each compute() replaces the last one's field).
class DistanceField {
 public:
  DistanceField() = default;

  /// Dijkstra from `source` over known-free cells (a non-free source gives an empty field).
  void compute(const KnownMap& known, Cell source, const DistanceQuery& query);

  /// One path length by A* (octile heuristic, OctileGoalEnvironment of octile_grid.hpp) in this
  /// field's storage, for a caller that needs the distance to a few cells rather than a field.
  /// Costs are exact, so the length equals compute()'s for the same cell bit for bit. Under
  /// `query`'s bound and corner rule (its target lists and watcher are not used): +infinity when
  /// `goal` is unreachable or beyond max_distance_m as distance_m() reads it; nullopt when
  /// query.stop ended the search first. Afterwards the field holds the cells the A* settled
  /// (exact lengths, as a consistent heuristic settles each cell at its final cost).
  [[nodiscard]] std::optional<double> compute_to(const KnownMap& known, Cell source, Cell goal,
                                                 const DistanceQuery& query);

  /// Path length (metres) from the source to cell `index`, or +infinity if not settled.
  [[nodiscard]] double distance_m(int index) const;
  [[nodiscard]] bool reached(int index) const {
    return distance_m(index) < std::numeric_limits<double>::infinity();
  }
  /// Cells settled by the last compute() or compute_to().
  [[nodiscard]] long expansions() const { return expansions_; }
  /// True if DistanceQuery::stop ended the last compute() early.
  [[nodiscard]] bool stopped() const { return stopped_; }
  [[nodiscard]] Cell source() const { return source_; }

 private:
  OctileDistanceSearch search_;  // exact costs in cells; scaled to metres on read
  /// Per cell: a stop target of the running compute() (all false between calls).
  std::vector<bool> is_target_;
  /// With a watcher: (cell, position in the target list) of every listed cell, sorted.
  std::vector<std::pair<int, int>> target_positions_;
  double resolution_m_ = 1.0;
  long expansions_ = 0;
  bool stopped_ = false;
  Cell source_{};
};

/// DistanceField::compute_to() with the parents kept (16 bytes a cell): the same A*
/// (OctileGoalEnvironment, BestFirstSearchT's tie rule), so when it reaches the goal its path and
/// its count of settled cells are those of the `astar` planner (planners/grid_planner.hpp) for the
/// same start, goal and corner rule on the same map, whatever bound and stop it ran under: a cell
/// beyond the bound costs more than the goal, so A* settles none before the goal, and none of
/// the cells it does settle is reached through one. A caller that measured a path length this way
/// hands the path on to the planner (PlanRequest::searched) rather than searching again.
class PathProbe {
 public:
  /// DistanceField::compute_to() (the same values, bit for bit).
  [[nodiscard]] std::optional<double> compute_to(const KnownMap& known, Cell source, Cell goal,
                                                 const DistanceQuery& query);
  /// True when the last compute_to() reached its goal.
  [[nodiscard]] bool reached_goal() const { return goal_ >= 0; }
  /// Cell indices from the source to the goal of the last compute_to(), both included; empty
  /// unless it reached the goal.
  [[nodiscard]] std::vector<int> path() const {
    return goal_ >= 0 ? search_.path_to(goal_) : std::vector<int>{};
  }
  /// Cells settled by the last compute_to().
  [[nodiscard]] long expansions() const { return expansions_; }

 private:
  OctileSearch search_;
  int goal_ = -1;
  long expansions_ = 0;
};

}  // namespace search
}  // namespace fsweep
