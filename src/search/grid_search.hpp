#pragma once
/// @file grid_search.hpp
/// The one best-first search of the planners: A* over an explicit environment contract,
/// Dijkstra when the heuristic is zero. Models: libMultiRobotPlanning's header-only A*
/// (environment concept), nav2 Smac (one search templated on the problem), SBPL (the search
/// sees integer state ids only; the environment owns geometry and costs).
///
/// States are ints in [0, state_count()). A grid environment uses the cell index; a state
/// lattice uses `cell_index * 8 + heading`. Costs and the heuristic are doubles in whatever
/// unit the environment chooses (the grid planners use cells).
///
/// Memory: the per-state arrays and the heap live in a BestFirstSearch object and are reused
/// by every run(). A run starts a new generation instead of clearing the arrays, so a query
/// costs time proportional to the states it touches, and nothing is allocated per expansion
/// once the heap has grown to its working size.

#include <algorithm>
#include <concepts>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "search/stop_condition.hpp"

namespace fsweep {
inline namespace search {

/// What the search does with a state taken from the open list (see SearchEnvironment::visit).
enum class Visit : std::uint8_t {
  /// Settle the state and expand its successors.
  Expand,
  /// Settle the state and stop: it is the goal (SearchOutcome::goal).
  Goal,
  /// Stop without settling the state (e.g. a distance bound or an early-stop rule).
  Stop,
};

/// Receives one successor: its state id and the edge cost (> 0 or >= 0, never negative).
struct SuccessorSink {
  void operator()(int /*state*/, double /*cost*/) const {}
};

/// The environment contract of BestFirstSearch.
/// - `state_count()`: number of state ids; ids are 0..state_count()-1.
/// - `heuristic(s)`: a consistent lower bound on the cost from s to the goal (0 = Dijkstra).
///   Settled states are never reopened, so an inconsistent heuristic loses optimality.
/// - `visit(s, g)`: called once when s is taken from the open list with its final cost g,
///   before it is settled; returns Expand, Goal or Stop. May update the environment.
/// - `for_each_successor(s, sink)`: calls `sink(next_state, edge_cost)` for each successor.
template <typename E>
concept SearchEnvironment = requires(E& env, const E& cenv, int s, double g, SuccessorSink sink) {
  { cenv.state_count() } -> std::convertible_to<int>;
  { cenv.heuristic(s) } -> std::convertible_to<double>;
  { env.visit(s, g) } -> std::same_as<Visit>;
  cenv.for_each_successor(s, sink);
};

/// Bounds of one run.
struct SearchLimits {
  /// States whose cost g would exceed this are never opened (same unit as the costs).
  double g_limit = std::numeric_limits<double>::infinity();
  /// Checked before each visit (StopCondition::should_stop with the expansions so far): a run
  /// settles at most its expansion budget of states and ends soon after its time limit;
  /// SearchOutcome::stopped says so.
  StopCondition stop;
};

/// A start of a run: a state and its initial cost (0 for a single start; a multi-source or
/// incremental search starts states at their known costs).
struct SearchSeed {
  int state = -1;
  double g = 0.0;
};

/// Result of one run. Costs, parents and settled flags stay readable in the BestFirstSearch
/// until the next run().
struct SearchOutcome {
  /// The state for which visit() returned Goal, or -1.
  int goal = -1;
  /// States settled (visit() returned Expand or Goal).
  long expansions = 0;
  /// True when SearchLimits::stop ended the run with states left to visit.
  bool stopped = false;
};

/// Reusable best-first search storage with a generic run().
///
/// Open-list order (deterministic tie-breaking): smaller f = g + h first; on equal f the
/// larger g first (the deeper state, which on grids with a consistent heuristic reaches the
/// goal with fewer expansions); on equal f and g the smaller state id first. The key is a
/// total order on heap entries, so a run is fully determined by the environment.
/// Duplicate heap entries replace decrease-key; stale ones are skipped when popped.
class BestFirstSearch {
 public:
  /// Runs from `start` until visit() returns Goal or Stop, the open list empties, or a limit
  /// is hit. A `start` outside [0, state_count()) gives an empty run.
  template <SearchEnvironment Env>
  SearchOutcome run(Env& env, int start, const SearchLimits& limits = {}) {
    const SearchSeed seed{start, 0.0};
    return run(env, std::span<const SearchSeed>(&seed, 1), limits);
  }
  /// Runs from every seed at once (each opened with its cost g; seeds outside the state range are
  /// ignored, a state seeded twice keeps its cheaper cost and the first seed on a tie). Settled
  /// seeds have parent -1.
  template <SearchEnvironment Env>
  SearchOutcome run(Env& env, std::span<const SearchSeed> seeds, const SearchLimits& limits = {});

  /// Cost of the best path found to `state` in the last run (+infinity if never reached).
  [[nodiscard]] double g(int state) const {
    return in_range(state) && seen_[idx(state)] == generation_ ? g_[idx(state)]
                                                               : std::numeric_limits<double>::infinity();
  }
  /// True if `state` was settled (its g is final) in the last run.
  [[nodiscard]] bool settled(int state) const {
    return in_range(state) && closed_[idx(state)] == generation_;
  }
  /// Predecessor of a reached state on its best path (-1 for the start or unreached states).
  [[nodiscard]] int parent(int state) const {
    return in_range(state) && seen_[idx(state)] == generation_ ? parent_[idx(state)] : -1;
  }
  /// State ids start..state of a reached state, in path order (empty if not reached).
  [[nodiscard]] std::vector<int> path_to(int state) const {
    std::vector<int> path;
    if (!in_range(state) || seen_[idx(state)] != generation_) return path;
    for (int s = state; s >= 0; s = parent_[idx(s)]) path.push_back(s);
    std::reverse(path.begin(), path.end());
    return path;
  }

 private:
  struct HeapItem {
    double f;
    double g;
    int state;
  };
  /// std heap comparator: true when `a` must come out after `b` (max-heap of priority).
  /// A function object (not a function pointer) so that the heap algorithms inline it.
  struct Later {
    bool operator()(const HeapItem& a, const HeapItem& b) const {
      if (a.f != b.f) return a.f > b.f;
      if (a.g != b.g) return a.g < b.g;
      return a.state > b.state;
    }
  };
  static std::size_t idx(int state) { return static_cast<std::size_t>(state); }
  [[nodiscard]] bool in_range(int state) const { return state >= 0 && idx(state) < g_.size(); }

  /// Sizes the arrays for `count` states and starts a new generation.
  void begin_run(int count) {
    const auto n = static_cast<std::size_t>(count);
    if (g_.size() != n) {
      g_.assign(n, 0.0);
      parent_.assign(n, -1);
      seen_.assign(n, 0);
      closed_.assign(n, 0);
      generation_ = 0;
    }
    if (++generation_ == 0) {  // wrapped: stale stamps could alias, so clear once
      std::fill(seen_.begin(), seen_.end(), 0U);
      std::fill(closed_.begin(), closed_.end(), 0U);
      generation_ = 1;
    }
    heap_.clear();
  }

  std::vector<double> g_;
  std::vector<int> parent_;
  std::vector<std::uint32_t> seen_;    // == generation_: g_ and parent_ are valid
  std::vector<std::uint32_t> closed_;  // == generation_: settled
  std::uint32_t generation_ = 0;
  std::vector<HeapItem> heap_;
};

template <SearchEnvironment Env>
SearchOutcome BestFirstSearch::run(Env& env, std::span<const SearchSeed> seeds, const SearchLimits& limits) {
  SearchOutcome outcome;
  begin_run(static_cast<int>(env.state_count()));
  for (const SearchSeed& seed : seeds) {
    if (!in_range(seed.state)) continue;
    const auto s = idx(seed.state);
    if (seen_[s] == generation_ && g_[s] <= seed.g) continue;
    g_[s] = seed.g;
    parent_[s] = -1;
    seen_[s] = generation_;
    heap_.push_back({seed.g + static_cast<double>(env.heuristic(seed.state)), seed.g, seed.state});
    std::push_heap(heap_.begin(), heap_.end(), Later{});
  }

  while (!heap_.empty()) {
    // 1. Take the best entry; skip it if stale (state settled or a cheaper entry exists).
    std::pop_heap(heap_.begin(), heap_.end(), Later{});
    const HeapItem top = heap_.back();
    heap_.pop_back();
    const auto s = idx(top.state);
    if (closed_[s] == generation_ || top.g > g_[s]) continue;

    // 2. The stop condition: budget spent or time up ends the run before the next visit.
    if (limits.stop.should_stop(outcome.expansions)) {
      outcome.stopped = true;
      break;
    }

    // 3. Let the environment decide: expand, goal, or stop before settling.
    const Visit visit = env.visit(top.state, top.g);
    if (visit == Visit::Stop) break;
    closed_[s] = generation_;
    ++outcome.expansions;
    if (visit == Visit::Goal) {
      outcome.goal = top.state;
      break;
    }

    // 4. Relax the successors.
    env.for_each_successor(top.state, [&](int next, double cost) {
      const auto n = idx(next);
      if (closed_[n] == generation_) return;
      const double g_next = top.g + cost;
      if (g_next > limits.g_limit) return;
      if (seen_[n] == generation_ && g_[n] <= g_next) return;
      seen_[n] = generation_;
      g_[n] = g_next;
      parent_[n] = top.state;
      heap_.push_back({g_next + static_cast<double>(env.heuristic(next)), g_next, next});
      std::push_heap(heap_.begin(), heap_.end(), Later{});
    });
  }
  return outcome;
}

}  // namespace search
}  // namespace fsweep
