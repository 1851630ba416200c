#pragma once
/// @file grid_search.hpp
/// The one best-first search of the planners: A* over an explicit environment contract,
/// Dijkstra when the heuristic is zero. Models: libMultiRobotPlanning's header-only A*
/// (environment concept), nav2 Smac (one search templated on the problem), SBPL (the search
/// sees integer state ids only; the environment owns geometry and costs).
///
/// States are ints in [0, state_count()). A grid environment uses the cell index; a state
/// lattice uses `cell_index * 8 + heading`. Costs and the heuristic are of the environment's
/// cost type (`Env::Cost`, double when not declared) in whatever unit it chooses (the grid
/// searches use cells): double sums round, so two paths of equal length can differ in the last
/// bits; OctileCost counts straight and diagonal steps, so a path's cost is exact and equal
/// lengths are equal costs, whichever path and whichever order the search sums them in.
///
/// It is also the one Dijkstra of the code base: the distance fields (distance_field.hpp,
/// incremental_distance_field.hpp, the latter by continuing a run after costs dropped) and the
/// geodesic distances of the strategies run it with a zero heuristic.
///
/// Memory: the per-state data (16 bytes: cost, parent, run and pass stamps; 12 bytes for exact
/// octile costs without parents, Parents::Dropped, the distance searches that read lengths only),
/// the open lists and the A* list's positions (4 bytes a state, indexed_heap.hpp) live in a
/// BestFirstSearch object and are reused by every run(). A run takes fresh stamps instead of clearing the
/// data, so a query costs time proportional to the states it touches, and nothing is allocated per expansion
/// once the open list has grown to its working size.

#include <algorithm>
#include <concepts>
#include <cstdint>
#include <limits>
#include <span>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "core/always_inline.hpp"
#include "search/dijkstra_list.hpp"
#include "search/indexed_heap.hpp"
#include "search/stop_condition.hpp"
#include "world/grid.hpp"

namespace fsweep {
inline namespace search {

/// An exact 8-connected path cost: `straight` steps of 1 and `diagonal` steps of sqrt(2) cells.
/// value() = straight + diagonal * sqrt(2), one rounding from the counts: equal counts give the
/// same double, and distinct counts (below 2^20 steps each) give doubles in the order of their
/// real values (two such lengths differ by more than 1e-7, their roundings by less than 1e-9),
/// so comparing values compares lengths exactly. The value of an empty-grid path is
/// octile_distance() bit for bit.
struct OctileCost {
  std::int32_t straight = 0;
  std::int32_t diagonal = 0;
  [[nodiscard]] constexpr double value() const { return straight + diagonal * kSqrt2; }
  friend constexpr OctileCost operator+(OctileCost a, OctileCost b) {
    return {a.straight + b.straight, a.diagonal + b.diagonal};
  }
  friend constexpr bool operator==(OctileCost, OctileCost) = default;
};

/// An entry of A*'s open list over exact octile costs: the open-list order of BestFirstSearchT
/// (smaller f, then larger g, then smaller state) as one 128-bit integer key, so that a
/// comparison is one integer compare instead of four of doubles, in 16 bytes instead of 24.
/// f and g enter as floor(value() * 2^24): below 2^20 straight and 2^20 diagonal steps,
/// OctileCost's values are exact to 1e-9 and distinct ones differ by more than 1e-7 (see there),
/// more than the quantum 2^-24 (6e-8), so equal costs give equal keys and distinct ones keys in
/// their order: the same order as comparing the doubles. (Beyond that, where the doubles'
/// order is no longer exact either, costs within 6e-8 of each other may key as equal and be
/// ordered by g and the state.) The key is f (48 bits: f < 2^24 cells), 2^49 - 1 - g (49
/// bits), the state (31 bits). make() throws std::overflow_error for a cost of 2^24 cells or
/// more: a path longer than any map of fewer than ten million cells can hold.
struct PackedOctileItem {
  __extension__ typedef unsigned __int128 Key;  // a typedef: __extension__ (for -Wpedantic) takes no alias
  Key key;

  [[nodiscard]] static PackedOctileItem make(OctileCost f, OctileCost g, int state) {
    const double fv = f.value() * kScale;
    const double gv = g.value() * kScale;
    if (!(fv < kFLimit) || !(gv < kFLimit)) {
      throw std::overflow_error("A*: a path cost of 2^24 cells or more (PackedOctileItem)");
    }
    const auto qf = static_cast<std::uint64_t>(fv);
    const auto qg = static_cast<std::uint64_t>(gv);
    return {static_cast<Key>(qf) << (kGBits + kStateBits) | static_cast<Key>(kGMax - qg) << kStateBits |
            static_cast<Key>(state)};
  }
  [[nodiscard]] int id() const { return static_cast<int>(static_cast<std::uint64_t>(key) & kStateMask); }
  static bool before(const PackedOctileItem& a, const PackedOctileItem& b) { return a.key < b.key; }

 private:
  static constexpr double kScale = 16777216.0;  // 2^24
  static constexpr int kStateBits = 31;
  static constexpr int kGBits = 49;
  static constexpr std::uint64_t kStateMask = (std::uint64_t{1} << kStateBits) - 1;
  static constexpr std::uint64_t kGMax = (std::uint64_t{1} << kGBits) - 1;
  static constexpr double kFLimit = 281474976710656.0;  // 2^48 = 2^24 cells * kScale
};

/// The octile length between two cells as an exact cost: its value is octile_distance(a, b).
[[nodiscard]] inline OctileCost octile_cost(Cell a, Cell b) {
  const int dx = a.x > b.x ? a.x - b.x : b.x - a.x;
  const int dy = a.y > b.y ? a.y - b.y : b.y - a.y;
  return dx < dy ? OctileCost{dy - dx, dx} : OctileCost{dx - dy, dy};
}

/// The double a cost compares by (see OctileCost).
[[nodiscard]] constexpr double cost_value(double c) { return c; }
[[nodiscard]] constexpr double cost_value(OctileCost c) { return c.value(); }

/// The cost type of environment E: E::Cost when declared, else double.
template <typename E>
struct EnvironmentCost {
  using type = double;
};
template <typename E>
requires requires { typename E::Cost; }
struct EnvironmentCost<E> {
  using type = typename E::Cost;
};

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
template <typename Cost>
struct SuccessorSink {
  void operator()(int /*state*/, Cost /*cost*/) const {}
};

/// The environment contract of BestFirstSearchT<Cost>.
/// - `Cost` (optional, default double): the cost type, as the search's.
/// - `state_count()`: number of state ids; ids are 0..state_count()-1.
/// - `heuristic(s)`: a consistent lower bound on the cost from s to the goal (0 = Dijkstra).
///   Settled states are never reopened, so an inconsistent heuristic loses optimality.
/// - `visit(s, g)`: called once when s is taken from the open list with its final cost g
///   (cost_value()), before it is settled; returns Expand, Goal or Stop. May update the
///   environment.
/// - `for_each_successor(s, sink)`: calls `sink(next_state, edge_cost)` for each successor.
template <typename E, typename Cost>
concept SearchEnvironment = std::same_as<typename EnvironmentCost<E>::type, Cost> &&
    requires(E& env, const E& cenv, int s, double g, SuccessorSink<Cost> sink) {
  { cenv.state_count() } -> std::convertible_to<int>;
  { cenv.heuristic(s) } -> std::convertible_to<Cost>;
  { env.visit(s, g) } -> std::same_as<Visit>;
  cenv.for_each_successor(s, sink);
};

/// An environment whose heuristic is 0 everywhere (a Dijkstra search) may say so with
/// `static constexpr bool kZeroHeuristic = true;`: its open list then holds (g, state) entries of
/// 16 bytes instead of (f, g, state) of 24, in the same order (f == g), which is faster.
template <typename E>
concept ZeroHeuristicEnvironment = requires {
  requires E::kZeroHeuristic;
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
template <typename Cost = double>
struct SearchSeedT {
  int state = -1;
  Cost g{};
};
using SearchSeed = SearchSeedT<double>;

/// Result of one run. Costs, parents and settled flags stay readable in the BestFirstSearch
/// until the next run() or reopen().
struct SearchOutcome {
  /// The state for which visit() returned Goal, or -1.
  int goal = -1;
  /// States settled (visit() returned Expand or Goal).
  long expansions = 0;
  /// True when SearchLimits::stop ended the run with states left to visit.
  bool stopped = false;
};

/// Whether a BestFirstSearchT keeps each state's parent (for paths) or only its cost (for
/// lengths: 4 bytes a state less).
enum class Parents : std::uint8_t { Kept, Dropped };

/// Reusable best-first search storage with a generic run(), over costs of type `Cost` (double
/// or OctileCost; the environments' cost type), keeping parents or not (`P`).
///
/// Open-list order (deterministic tie-breaking): smaller f = g + h first; on equal f the
/// larger g first (the deeper state, which on grids with a consistent heuristic reaches the
/// goal with fewer expansions); on equal f and g the smaller state id first. The key is a
/// total order on open-list entries, so a run is fully determined by the environment, and any
/// open list that pops in this order gives the same run. A*'s list (IndexedHeap) holds one entry
/// per open state and re-keys it when a cheaper path is found. The Dijkstra lists
/// (dijkstra_list.hpp: buckets for exact octile costs, else a binary heap, of 16-byte entries)
/// take a duplicate instead and the search skips stale entries when popped: measured faster
/// there (fields over many states, which the indexed heap's positions add a cache line to).
template <typename Cost, Parents P = Parents::Kept>
class BestFirstSearchT {
 public:
  static constexpr bool kKeepsParents = P == Parents::Kept;

  /// Runs from `start` until visit() returns Goal or Stop, the open list empties, or a limit
  /// is hit. A `start` outside [0, state_count()) gives an empty run.
  template <SearchEnvironment<Cost> Env>
  SearchOutcome run(Env& env, int start, const SearchLimits& limits = {}) {
    begin_run<Env>(static_cast<int>(env.state_count()));
    (void)lower_cost(env, start, Cost{}, -1);
    return expand(env, limits);
  }
  /// Runs from every seed at once (each opened with its cost g; seeds outside the state range are
  /// ignored, a state seeded twice keeps its cheaper cost and the first seed on a tie). Settled
  /// seeds have parent -1.
  template <SearchEnvironment<Cost> Env>
  SearchOutcome run(Env& env, std::span<const SearchSeedT<Cost>> seeds, const SearchLimits& limits = {}) {
    begin_run<Env>(static_cast<int>(env.state_count()));
    for (const SearchSeedT<Cost>& seed : seeds) (void)lower_cost(env, seed.state, seed.g, -1);
    return resume(env, limits);
  }

  /// Continuing a finished run after some costs dropped (an incremental search, e.g. a distance
  /// field on a growing map, where revealed cells only add moves): reopen() keeps every cost and
  /// parent of the last run and unsettles every state, lower_cost() opens states at lower costs,
  /// resume() searches from them. The last run must have ended with an empty open list (never by
  /// Goal, Stop or a limit), so that every state it reached was settled at its final cost.
  void reopen() {
    if (pass_ == kLastStamp) {  // the pass stamps would wrap: unsettle every state once
      for (Node& node : nodes_) node.pass = 0;
      pass_ = 0;
    }
    ++pass_;
    reopened_ = true;
    heap_.clear();
    dijkstra_list_.clear();
  }
  /// Opens `state` at cost `g`, reached from `parent` (-1: none; not kept with Parents::Dropped),
  /// if that is below its cost so far (between reopen() and resume()). Returns whether it did; a
  /// state outside the state range is ignored.
  template <SearchEnvironment<Cost> Env>
  bool lower_cost(const Env& env, int state, Cost g, int parent) {
    if (!in_range(state)) return false;
    Node& node = nodes_[idx(state)];
    if (node.run == run_ && cost_value(node.g) <= cost_value(g)) return false;
    node = make_node(g, parent, run_);
    if constexpr (ZeroHeuristicEnvironment<Env>) {
      dijkstra_list_.add(open_item(env, state, g));  // ordered by resume(), all at once
    } else {
      heap_.push_or_update(open_item(env, state, g));
    }
    return true;
  }
  /// Searches from the states opened by lower_cost() since reopen() (or from run()'s seeds).
  template <SearchEnvironment<Cost> Env>
  SearchOutcome resume(Env& env, const SearchLimits& limits = {}) {
    if constexpr (ZeroHeuristicEnvironment<Env>) dijkstra_list_.start();
    return expand(env, limits);
  }

  /// Cost of the best path found to `state` in the last run, as cost_value() (+infinity if
  /// never reached).
  [[nodiscard]] double g(int state) const {
    return reached(state) ? cost_value(nodes_[idx(state)].g) : std::numeric_limits<double>::infinity();
  }
  /// The same as a Cost; reached states only.
  [[nodiscard]] Cost cost(int state) const { return nodes_[idx(state)].g; }
  /// True if `state` was reached (opened or settled) in the last run.
  [[nodiscard]] bool reached(int state) const { return in_range(state) && nodes_[idx(state)].run == run_; }
  /// True if `state` was settled (its g is final) in the last run.
  [[nodiscard]] bool settled(int state) const { return in_range(state) && nodes_[idx(state)].pass == pass_; }
  /// Starts loading the search data of `state` (in range) into the cache, for an environment
  /// that finds a successor some time before it hands it to the sink (`jps`'s jumps).
  void prefetch(int state) const { __builtin_prefetch(&nodes_[idx(state)]); }
  /// Predecessor of a reached state on its best path (-1 for the start or unreached states).
  [[nodiscard]] int parent(int state) const requires(kKeepsParents) {
    return reached(state) ? nodes_[idx(state)].parent : -1;
  }
  /// Calls `visit(s)` for every state of the best path to `state`, from `state` back to the
  /// start, and returns their number (0, calling nothing, if `state` was not reached). The
  /// states of a reached state's chain are all reached, so the walk checks none of them.
  template <typename F>
  std::size_t trace_back(int state, F&& visit) const requires(kKeepsParents) {
    if (!reached(state)) return 0;
    std::size_t count = 0;
    for (int s = state; s >= 0; s = nodes_[idx(s)].parent, ++count) visit(s);
    return count;
  }
  /// State ids start..state of a reached state, in path order (empty if not reached).
  [[nodiscard]] std::vector<int> path_to(int state) const requires(kKeepsParents) {
    std::vector<int> path;
    (void)trace_back(state, [&path](int s) { path.push_back(s); });
    std::reverse(path.begin(), path.end());
    return path;
  }

 private:
  /// The open-list entry: costs as cost_value().
  struct HeapItem {
    double f;
    double g;
    int state;
    [[nodiscard]] int id() const { return state; }
    /// The open-list order: smaller f, then larger g, then smaller state.
    static bool before(const HeapItem& a, const HeapItem& b) {
      // Bitwise, not short-circuit: no branches, so the heap's child selection needs none.
      return static_cast<bool>(
          static_cast<unsigned>(a.f < b.f) |
          (static_cast<unsigned>(a.f == b.f) &
           (static_cast<unsigned>(a.g > b.g) |
            (static_cast<unsigned>(a.g == b.g) & static_cast<unsigned>(a.state < b.state)))));
    }
  };
  /// A*'s open-list entry: the packed one for exact octile costs.
  using AStarItem = std::conditional_t<std::is_same_v<Cost, OctileCost>, PackedOctileItem, HeapItem>;
  /// Removes and returns the first entry of a non-empty open list.
  static AStarItem pop_open(IndexedHeap<AStarItem>& heap) { return heap.pop(); }
  template <typename List>
  static DijkstraItem pop_open(List& list) {
    return list.pop();
  }
  /// The open list `Env`'s searches use.
  template <typename Env>
  auto& open_list() {
    if constexpr (ZeroHeuristicEnvironment<Env>) {
      return dijkstra_list_;
    } else {
      return heap_;
    }
  }
  /// The entry of `state` at cost `g` on `Env`'s open list.
  template <typename Env>
  static auto open_item(const Env& env, int state, Cost g) {
    if constexpr (ZeroHeuristicEnvironment<Env>) {
      return DijkstraItem{cost_value(g), state};
    } else {
      if constexpr (std::is_same_v<Cost, OctileCost>) {
        return PackedOctileItem::make(g + static_cast<Cost>(env.heuristic(state)), g, state);
      } else {
        return HeapItem{cost_value(g + static_cast<Cost>(env.heuristic(state))), cost_value(g), state};
      }
    }
  }
  /// Opens `state` at cost `g` on `Env`'s open list; `reached`: it may have an entry already
  /// (reached in this run; begin_run() emptied the lists, so a state first reached has none).
  template <typename Env>
  void open(const Env& env, int state, Cost g, bool reached) {
    if constexpr (ZeroHeuristicEnvironment<Env>) {
      dijkstra_list_.push(open_item(env, state, g));
    } else if (reached) {
      if constexpr (std::is_same_v<Cost, OctileCost>) {
        // A state reached in this pass and not settled has its entry on the list, and a cheaper
        // exact cost is a smaller f (h is fixed): the entry only moves up. After reopen() a
        // reached state may have none (it was settled in an earlier pass).
        if (!reopened_) return heap_.decrease(open_item(env, state, g));
      }
      heap_.push_or_update(open_item(env, state, g));
    } else {
      heap_.push(open_item(env, state, g));
    }
  }
  /// Per-state search data, together so that a relaxation touches one cache line (16 bytes; 12
  /// without the parent).
  struct NodeWithParent {
    Cost g;
    int parent;
    /// == run_: reached in this run (g and parent are valid); else stale.
    std::uint16_t run;
    /// == pass_: settled in this pass (a run, or its continuation after reopen()); pass stamps
    /// grow with every pass, so a stale one never matches.
    std::uint16_t pass;
  };
  /// The same without the parent (Parents::Dropped).
  struct NodeWithoutParent {
    Cost g;
    std::uint16_t run;
    std::uint16_t pass;
  };
  using Node = std::conditional_t<kKeepsParents, NodeWithParent, NodeWithoutParent>;
  static_assert(kKeepsParents || !std::is_same_v<Cost, OctileCost> || sizeof(Node) == 12);
  /// A node reached at `g` from `parent` in run `run`, not settled.
  static Node make_node(Cost g, [[maybe_unused]] int parent, std::uint16_t run) {
    if constexpr (kKeepsParents) {
      return Node{g, parent, run, 0};
    } else {
      return Node{g, run, 0};
    }
  }
  /// The relaxation's update: `node` (of `state`) reached in run `run` at the cheaper `g` from
  /// `parent`, and opened. A function of its own, not lines of the relaxation: with it GCC 12
  /// inlines the whole opening (heuristic, entry, sift-up) at the successor calls of
  /// grid_planner.cpp, which it did not for the same lines in the lambda (`astar` 4-7% faster a
  /// query than before; that variant kept its old time). Forcing every step of the opening inline
  /// measured slower than this (0.98-1.00x the old time). GCC may still choose otherwise in
  /// another translation unit (bench_planners.cpp keeps one out-of-line copy of open_item()).
  template <typename Env>
  void improve(const Env& env, Node& node, int state, Cost g, int parent, std::uint16_t run, bool reached) {
    node = make_node(g, parent, run);
    open(env, state, g, reached);
  }
  static std::size_t idx(int state) { return static_cast<std::size_t>(state); }
  [[nodiscard]] bool in_range(int state) const { return state >= 0 && idx(state) < nodes_.size(); }

  /// The search loop of run() from the opened seeds.
  template <SearchEnvironment<Cost> Env>
  SearchOutcome expand(Env& env, const SearchLimits& limits);

  /// Sizes the arrays for `count` states (the open list `Env` uses included) and starts a new run
  /// with fresh run and pass stamps, so nothing is cleared between runs (but once every 65535
  /// runs, when the stamps would wrap).
  template <typename Env>
  void begin_run(int count) {
    const auto n = static_cast<std::size_t>(count);
    if (nodes_.size() != n || run_ == kLastStamp || pass_ == kLastStamp) {
      nodes_.assign(n, make_node(Cost{}, -1, 0));
      run_ = 0;
      pass_ = 0;
    }
    ++run_;
    ++pass_;
    reopened_ = false;
    dijkstra_list_.clear();
    if constexpr (ZeroHeuristicEnvironment<Env>) {
      heap_.clear();
    } else {
      heap_.reset(n);
    }
  }

  static constexpr std::uint16_t kLastStamp = std::numeric_limits<std::uint16_t>::max();
  std::vector<Node> nodes_;
  std::uint16_t run_ = 0;  // >= 1 once sized, so fresh nodes (stamps 0) are neither reached nor settled
  std::uint16_t pass_ = 0;
  /// True from reopen() to the next run: reached states need not be on the open list.
  bool reopened_ = false;
  IndexedHeap<AStarItem> heap_;
  /// The Dijkstra list: buckets for exact octile costs (every step at least one cell long).
  std::conditional_t<std::is_same_v<Cost, OctileCost>, DijkstraBuckets, DijkstraHeap> dijkstra_list_;
};

/// The search over double costs (planners, geodesic regions).
using BestFirstSearch = BestFirstSearchT<double>;
/// The search over exact octile costs with paths (grid planners).
using OctileSearch = BestFirstSearchT<OctileCost>;
/// The search over exact octile costs for lengths only (distance fields).
using OctileDistanceSearch = BestFirstSearchT<OctileCost, Parents::Dropped>;

template <typename Cost, Parents P>
template <SearchEnvironment<Cost> Env>
SearchOutcome BestFirstSearchT<Cost, P>::expand(Env& env, const SearchLimits& limits) {
  SearchOutcome outcome;
  // Locals, not reads through `limits`, in the hot loop.
  const StopCondition stop = limits.stop;
  const double g_limit = limits.g_limit;
  const std::uint16_t run = run_;
  const std::uint16_t pass = pass_;
  // With a zero heuristic (costs >= 0) a settled state is never improved and its stale entries
  // cost more than it, so the cost comparisons alone skip settled states.
  constexpr bool kDijkstra = ZeroHeuristicEnvironment<Env>;
  auto& heap = open_list<Env>();
  while (!heap.empty()) {
    // 1. Take the best entry; Dijkstra: skip it if stale (a cheaper entry of its state came
    //    first). A*'s list holds one entry per open state, at its current cost.
    const auto top = pop_open(heap);
    const int state = top.id();
    Node& node = nodes_[idx(state)];
    double g_top_value;
    if constexpr (kDijkstra) {
      if (top.g > cost_value(node.g)) continue;
      g_top_value = top.g;
    } else {
      g_top_value = cost_value(node.g);  // its one entry's cost
    }

    // 2. The stop condition: budget spent or time up ends the run before the next visit.
    if (stop.should_stop(outcome.expansions)) {
      outcome.stopped = true;
      break;
    }

    // 3. Let the environment decide: expand, goal, or stop before settling.
    const Visit visit = env.visit(state, g_top_value);
    if (visit == Visit::Stop) break;
    node.pass = pass;
    ++outcome.expansions;
    if (visit == Visit::Goal) {
      outcome.goal = state;
      break;
    }

    // 4. Relax the successors.
    // The scalars by value: captured by reference they are reloaded after every store the
    // relaxation makes (the compiler cannot tell that the stores leave them alone).
    const Cost g_top = node.g;
    const int from = state;
    Node* const nodes = nodes_.data();
    // The relaxation is inlined into each of the environment's successor calls: GCC otherwise
    // calls it there, and the call's register saves cost more than the usual early return.
    env.for_each_successor(
        from, [this, &env, nodes, g_top, from, g_limit, run, pass](int next, Cost cost) FSWEEP_ALWAYS_INLINE {
          Node& n = nodes[idx(next)];
          if constexpr (!kDijkstra) {
            if (n.pass == pass) return;
          } else {
            (void)pass;  // captured for the A* branch only
          }
          const Cost g_next = g_top + cost;
          const double g_next_value = cost_value(g_next);
          if (g_next_value > g_limit) return;
          const bool reached = n.run == run;
          if (reached && cost_value(n.g) <= g_next_value) return;
          improve(env, n, next, g_next, from, run, reached);
        });
  }
  return outcome;
}

}  // namespace search
}  // namespace fsweep
