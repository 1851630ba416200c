/// Micro-benchmarks of the grid planners and the distance field on den312d (MovingAI, 65x81,
/// fully known, 1 m cells). Queries are drawn once from a fixed seed; one benchmark iteration
/// is one query, so the reported time is per query.

#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "engine/world/known_map.hpp"
#include "engine/world/map_loaders.hpp"
#include "engine/world/random.hpp"
#include "engine/world/world_map.hpp"
#include "planners/distance_field.hpp"
#include "planners/grid_planner.hpp"

namespace fsweep {
namespace {

struct Den312d {
  WorldMap map;
  KnownMap known;
  /// Reachable (start, goal) pairs, no corner cutting.
  std::vector<PlanRequest> queries;
  std::vector<Cell> sources;
};

Cell random_free(const WorldMap& map, Rng& rng) {
  for (;;) {
    const int i = static_cast<int>(uniform_below(rng, static_cast<std::uint64_t>(map.occupied.size())));
    if (map.is_free(i)) return map.occupied.cell(i);
  }
}

const Den312d& den312d() {
  static const Den312d data = [] {
    Den312d d;
    d.map = load_movingai_map(std::string(FSWEEP_TEST_DATA) + "/den312d.map");
    d.known = fully_known(d.map);
    Rng rng = make_rng(2024, "bench_planners");
    while (d.queries.size() < 512) {
      PlanRequest q;
      q.start = random_free(d.map, rng);
      q.goal = random_free(d.map, rng);
      if (reachable_free(d.map, q.start).at(q.goal) != 0) d.queries.push_back(q);
    }
    for (int i = 0; i < 512; ++i) d.sources.push_back(random_free(d.map, rng));
    return d;
  }();
  return data;
}

void run_grid_planner(benchmark::State& state, GridSearchKind kind) {
  const Den312d& d = den312d();
  GridPlanner planner(kind);
  std::size_t i = 0;
  long expansions = 0;
  for (auto _ : state) {
    const PlanResult r = planner.plan(d.known, d.queries[i++ % d.queries.size()]);
    expansions += r.expansions;
    benchmark::DoNotOptimize(r.length_m);
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["expansions/query"] =
      benchmark::Counter(static_cast<double>(expansions) / static_cast<double>(state.iterations()));
}

void BM_AStarDen312d(benchmark::State& state) { run_grid_planner(state, GridSearchKind::AStar); }
BENCHMARK(BM_AStarDen312d);

void BM_DijkstraDen312d(benchmark::State& state) { run_grid_planner(state, GridSearchKind::Dijkstra); }
BENCHMARK(BM_DijkstraDen312d);

/// Bounded one-to-many Dijkstra from random free cells; the argument is the bound in metres.
void BM_DistanceFieldBounded(benchmark::State& state) {
  const Den312d& d = den312d();
  DistanceField field;
  DistanceQuery query;
  query.max_distance_m = static_cast<double>(state.range(0));
  std::size_t i = 0;
  long expansions = 0;
  for (auto _ : state) {
    field.compute(d.known, d.sources[i++ % d.sources.size()], query);
    expansions += field.expansions();
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["cells/query"] =
      benchmark::Counter(static_cast<double>(expansions) / static_cast<double>(state.iterations()));
}
BENCHMARK(BM_DistanceFieldBounded)->Arg(10)->Arg(30)->Arg(1000);

}  // namespace
}  // namespace fsweep
