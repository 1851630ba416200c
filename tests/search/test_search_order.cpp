/// Differential test of the open list: BestFirstSearchT (one entry per state in an IndexedHeap,
/// re-keyed on a cheaper path) must settle states in exactly the order of the search it replaced,
/// kept here as the reference: a binary heap (std::push_heap / pop_heap) of (f, g, state)
/// entries with duplicates instead of decrease-key, stale entries skipped when popped. Random
/// maps, endpoints, seeds, corner cutting and cost types (exact OctileCost, and doubles whose
/// f = g + h rounds, so equal f with different g occurs); the whole expansion sequences must be
/// equal, not only the lengths.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

#include "planners/planner_test_utils.hpp"
#include "search/grid_search.hpp"
#include "search/octile_grid.hpp"

namespace fsweep {
namespace test_search_order {

/// Wraps an environment and records the states it is asked to visit that get settled.
template <typename Env>
class Recording {
 public:
  using Cost = typename EnvironmentCost<Env>::type;
  static constexpr bool kZeroHeuristic = ZeroHeuristicEnvironment<Env>;

  explicit Recording(Env env) : env_(std::move(env)) {}

  [[nodiscard]] int state_count() const { return env_.state_count(); }
  [[nodiscard]] Cost heuristic(int s) const { return env_.heuristic(s); }
  Visit visit(int s, double g) {
    const Visit v = env_.visit(s, g);
    if (v != Visit::Stop) settled_.push_back(s);
    return v;
  }
  template <typename Sink>
  void for_each_successor(int s, Sink&& sink) const {
    env_.for_each_successor(s, sink);
  }
  [[nodiscard]] const std::vector<int>& settled() const { return settled_; }

 private:
  Env env_;
  std::vector<int> settled_;
};

/// The search before the IndexedHeap, reduced to its order: returns the settled states.
template <typename Cost, typename Env>
std::vector<int> reference_order(Env env, std::span<const SearchSeedT<Cost>> seeds, double g_limit) {
  struct Item {
    double f;
    double g;
    int state;
  };
  const auto later = [](const Item& a, const Item& b) {
    if (a.f != b.f) return a.f > b.f;
    if (a.g != b.g) return a.g < b.g;
    return a.state > b.state;
  };
  const auto n = static_cast<std::size_t>(env.state_count());
  std::vector<Cost> g(n);
  std::vector<char> reached(n, 0);
  std::vector<char> settled(n, 0);
  std::vector<Item> heap;
  const auto open = [&](int s, Cost cost) {
    const auto i = static_cast<std::size_t>(s);
    if (reached[i] != 0 && cost_value(g[i]) <= cost_value(cost)) return;
    g[i] = cost;
    reached[i] = 1;
    heap.push_back({cost_value(cost + static_cast<Cost>(env.heuristic(s))), cost_value(cost), s});
    std::push_heap(heap.begin(), heap.end(), later);
  };
  for (const SearchSeedT<Cost>& seed : seeds) open(seed.state, seed.g);
  std::vector<int> order;
  while (!heap.empty()) {
    std::pop_heap(heap.begin(), heap.end(), later);
    const Item top = heap.back();
    heap.pop_back();
    const auto t = static_cast<std::size_t>(top.state);
    if (settled[t] != 0 || top.g > cost_value(g[t])) continue;
    const Visit v = env.visit(top.state, top.g);
    if (v == Visit::Stop) break;
    settled[t] = 1;
    order.push_back(top.state);
    if (v == Visit::Goal) break;
    env.for_each_successor(top.state, [&](int next, Cost cost) {
      if (settled[static_cast<std::size_t>(next)] != 0) return;
      const Cost g_next = g[t] + cost;
      if (cost_value(g_next) > g_limit) return;
      open(next, g_next);
    });
  }
  return order;
}

/// Cells of `known` with a weight each (1 to 3 in steps of 1/8, so that sums round): a step
/// costs its length times the mean weight of its ends; the heuristic (octile length times the
/// smallest weight) is consistent. Double costs, A* or, with kZero, Dijkstra.
template <bool kZero>
class WeightedGrid {
 public:
  static constexpr bool kZeroHeuristic = kZero;
  WeightedGrid(const KnownMap& known, std::vector<double> weight, Cell goal, bool cut)
      : known_(&known), weight_(std::move(weight)), goal_(goal), cut_(cut) {}

  [[nodiscard]] int state_count() const { return known_->size(); }
  [[nodiscard]] double heuristic(int s) const {
    return kZero ? 0.0 : octile_distance(known_->cell(s), goal_) * kMinWeight;
  }
  [[nodiscard]] Visit visit(int s, double /*g*/) const {
    return s == known_->index(goal_) ? Visit::Goal : Visit::Expand;
  }
  template <typename Sink>
  void for_each_successor(int s, Sink&& sink) const {
    for_each_octile_neighbour<double>(*known_, s, cut_, [&](int next, double length) {
      sink(next,
           length * 0.5 * (weight_[static_cast<std::size_t>(s)] + weight_[static_cast<std::size_t>(next)]));
    });
  }

 private:
  static constexpr double kMinWeight = 1.0;
  const KnownMap* known_;
  std::vector<double> weight_;
  Cell goal_;
  bool cut_;
};

/// The settled states of BestFirstSearchT over `env` from `seeds`.
template <typename Cost, typename Env>
std::vector<int> indexed_order(BestFirstSearchT<Cost>& search, const Env& env,
                               std::span<const SearchSeedT<Cost>> seeds, double g_limit) {
  Recording<Env> recording(env);
  SearchLimits limits;
  limits.g_limit = g_limit;
  (void)search.run(recording, seeds, limits);
  return recording.settled();
}

/// 1 to 3 random free cells of `known` as seeds (the first at cost 0, others at small costs).
template <typename Cost>
std::vector<SearchSeedT<Cost>> random_seeds(const KnownMap& known, Rng& rng, bool single) {
  std::vector<SearchSeedT<Cost>> seeds;
  const int count = single ? 1 : 1 + static_cast<int>(uniform_below(rng, 3));
  for (int k = 0; k < count; ++k) {
    const int s = known.index(testing::random_free_cell(known, rng));
    if constexpr (std::is_same_v<Cost, double>) {
      seeds.push_back({s, k == 0 ? 0.0 : 0.125 * static_cast<double>(uniform_below(rng, 20))});
    } else {
      seeds.push_back({s, Cost{k == 0 ? 0 : static_cast<int>(uniform_below(rng, 3)), 0}});
    }
  }
  return seeds;
}

constexpr double kNoLimit = std::numeric_limits<double>::infinity();

TEST(SearchOrder, OctileAStarAndDijkstraSettleInTheOrderOfTheDuplicateHeap) {
  OctileSearch search;  // one object for all runs: stamps and positions carry over between them
  long compared = 0;
  for (std::uint64_t seed = 1; seed <= 60; ++seed) {
    Rng rng = make_rng(seed, "search_order_octile");
    const int w = 4 + static_cast<int>(uniform_below(rng, 40));
    const int h = 4 + static_cast<int>(uniform_below(rng, 40));
    const KnownMap known = testing::random_known_map(w, h, 0.45 * uniform01(rng), seed);
    if (known.free_count() == 0) continue;
    for (int q = 0; q < 8; ++q) {
      const bool cut = uniform_below(rng, 2) == 1;
      const Cell goal = testing::random_free_cell(known, rng);
      const auto seeds = random_seeds<OctileCost>(known, rng, q % 2 == 0);
      const double g_limit = q % 4 == 3 ? 0.3 * (w + h) : kNoLimit;
      const OctileGoalEnvironment<true> astar(known, goal, cut);
      const OctileGoalEnvironment<false> dijkstra(known, goal, cut);
      const std::span<const SearchSeedT<OctileCost>> s(seeds);
      EXPECT_EQ(indexed_order(search, astar, s, g_limit), reference_order<OctileCost>(astar, s, g_limit))
          << "seed " << seed << " query " << q;
      EXPECT_EQ(indexed_order(search, dijkstra, s, g_limit),
                reference_order<OctileCost>(dijkstra, s, g_limit))
          << "seed " << seed << " query " << q;
      compared += 2;
    }
  }
  EXPECT_GT(compared, 800);
}

TEST(SearchOrder, RoundedDoubleCostsSettleInTheOrderOfTheDuplicateHeap) {
  BestFirstSearch search;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    Rng rng = make_rng(seed, "search_order_double");
    const int w = 4 + static_cast<int>(uniform_below(rng, 30));
    const int h = 4 + static_cast<int>(uniform_below(rng, 30));
    const KnownMap known = testing::random_known_map(w, h, 0.3 * uniform01(rng), seed);
    if (known.free_count() == 0) continue;
    std::vector<double> weight(static_cast<std::size_t>(known.size()));
    for (double& x : weight) x = 1.0 + 0.125 * static_cast<double>(uniform_below(rng, 17));
    for (int q = 0; q < 6; ++q) {
      const bool cut = uniform_below(rng, 2) == 1;
      const Cell goal = testing::random_free_cell(known, rng);
      const auto seeds = random_seeds<double>(known, rng, q % 2 == 0);
      const WeightedGrid<false> astar(known, weight, goal, cut);
      const WeightedGrid<true> dijkstra(known, weight, goal, cut);
      const std::span<const SearchSeedT<double>> s(seeds);
      EXPECT_EQ(indexed_order(search, astar, s, kNoLimit), reference_order<double>(astar, s, kNoLimit))
          << "seed " << seed << " query " << q;
      EXPECT_EQ(indexed_order(search, dijkstra, s, kNoLimit), reference_order<double>(dijkstra, s, kNoLimit))
          << "seed " << seed << " query " << q;
    }
  }
}

}  // namespace test_search_order
}  // namespace fsweep
