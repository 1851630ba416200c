#pragma once
/// @file exact_cover.hpp
/// The exact offline optimum of small instances: A* over the states (robot node, set of revealed
/// targets), one state per reachable combination, the moves of the planners (8-connected, octile
/// lengths, the run's corner rule) as edges, a move into a node adding what that node's scan
/// reveals. A goal state has every explorable target revealed; its cost is the distance at
/// which the last one was revealed. The heuristic is the larger of CoverageLowerBound::from_node
/// and the distance to the farthest unrevealed target's nearest viewpoint, both lower bounds on
/// the rest of any route (lower_bound.hpp), so it is admissible; it need not be consistent, so
/// a state reached again more cheaply is reopened. With an admissible heuristic the first goal
/// taken from the open list is optimal (Hart, Nilsson and Raphael 1968; with reopening, Pearl
/// 1984), which is the proof of exactness. The battery is not modelled here: the result is the
/// optimum without one, a lower bound with one, and exact with one when its route, replayed with
/// the battery, stays within each charge.
///
/// Work is bounded by a deterministic budget of expansions; when it runs out, the smallest
/// f = g + h on the open list is still a lower bound on the optimum (some state of an optimal
/// route is open with its optimal g).

#include <chrono>
#include <optional>
#include <vector>

#include "optimum/coverage_instance.hpp"
#include "optimum/lower_bound.hpp"

namespace fsweep {
inline namespace optimum {

/// Most explorable targets the exact search takes (one bit each in a 64-bit set).
inline constexpr int kExactMaxTargets = 64;

struct ExactOptions {
  /// Most states expanded (deterministic budget).
  long max_expansions = 1'000'000;
  /// Wall-clock limit for interactive use (fsweep optimum --time-limit); none in sweeps.
  std::optional<std::chrono::steady_clock::time_point> deadline;
};

struct ExactResult {
  /// True when the search reached a goal: `optimum_m` is the optimum and `cells` its route.
  bool solved = false;
  double optimum_m = 0.0;
  std::vector<int> cells;
  /// When not solved: a lower bound on the optimum (the smallest f on the open list).
  double lower_m = 0.0;
  long expansions = 0;
  bool stopped_by_time = false;
};

/// A* as above. Requires instance's explorable targets <= kExactMaxTargets (else returns an
/// unsolved result with lower_m 0).
[[nodiscard]] ExactResult exact_cover(const CoverageInstance& instance, const CoverageLowerBound& bound,
                                      const ExactOptions& options = {});

}  // namespace optimum
}  // namespace fsweep
