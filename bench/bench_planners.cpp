/// Micro-benchmarks of the grid planners and the distance field on den312d (MovingAI, 65x81,
/// fully known, 1 m cells). Queries are drawn once from a fixed seed; one benchmark iteration
/// is one query, so the reported time is per query.
///
/// Query time of `astar`, `lattice`, `lattice_astar` and `shortest_fewest_turns` on 512x512 maps
/// (the size asked by issue 4; no 512x512 MovingAI map is in ../shared/data/maps, so generated
/// ones: `random` with 20% obstacles as in Mei 2006 section V-B, and `rooms`). Every benchmark
/// runs the same 32 seeded reachable queries exactly once (random start headings, `mei2006`
/// energy); the reported time is the mean per query and `median_ms` the median query time.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine/world/known_map.hpp"
#include "engine/world/map_loaders.hpp"
#include "engine/world/map_spec.hpp"
#include "engine/world/random.hpp"
#include "engine/world/world_map.hpp"
#include "planners/distance_field.hpp"
#include "planners/grid_planner.hpp"
#include "planners/registry.hpp"

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

/// A fully known 512x512 map and its fixed query set.
struct Map512 {
  KnownMap known;
  std::vector<PlanRequest> queries;
};

constexpr int kQueries512 = 32;

const Map512& map512(int which) {
  static const std::array<std::string, 2> kSpecs{"random:w=512,h=512,p=0.2,seed=1",
                                                 "rooms:w=512,h=512,seed=1"};
  static std::array<std::unique_ptr<Map512>, 2> cache;
  auto& slot = cache[static_cast<std::size_t>(which)];
  if (!slot) {
    slot = std::make_unique<Map512>();
    const WorldMap map = load_map_spec(kSpecs[static_cast<std::size_t>(which)]);
    slot->known = fully_known(map);
    Rng rng = make_rng(2024, "bench_planners_512");
    while (slot->queries.size() < kQueries512) {
      PlanRequest q;
      q.start = random_free(map, rng);
      q.goal = random_free(map, rng);
      q.start_heading = static_cast<int>(uniform_below(rng, 8));
      q.energy = energy_preset("mei2006");
      if (q.start != q.goal && reachable_free(map, q.start).at(q.goal) != 0) slot->queries.push_back(q);
    }
  }
  return *slot;
}

/// One iteration = one query of the fixed set; run with Iterations(kQueries512) so each query
/// runs once. Argument: 0 = random 20% obstacles, 1 = rooms.
void run_planner_512(benchmark::State& state, const char* planner_name) {
  const Map512& m = map512(static_cast<int>(state.range(0)));
  const auto planner = make_planner(planner_name, nlohmann::json::object());
  std::size_t i = 0;
  long expansions = 0;
  std::vector<double> times_ms;
  for (auto _ : state) {
    const PlanResult r = planner->plan(m.known, m.queries[i++ % m.queries.size()]);
    expansions += r.expansions;
    times_ms.push_back(r.time_s * 1e3);
    benchmark::DoNotOptimize(r.energy);
  }
  std::sort(times_ms.begin(), times_ms.end());
  state.counters["median_ms"] = times_ms.empty() ? 0.0 : times_ms[times_ms.size() / 2];
  state.counters["expansions/query"] =
      benchmark::Counter(static_cast<double>(expansions) / static_cast<double>(state.iterations()));
}

void BM_AStar512(benchmark::State& state) { run_planner_512(state, "astar"); }
void BM_Lattice512(benchmark::State& state) { run_planner_512(state, "lattice"); }
void BM_LatticeAStar512(benchmark::State& state) { run_planner_512(state, "lattice_astar"); }
void BM_ShortestFewestTurns512(benchmark::State& state) { run_planner_512(state, "shortest_fewest_turns"); }
BENCHMARK(BM_AStar512)->Arg(0)->Arg(1)->Iterations(kQueries512)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Lattice512)->Arg(0)->Arg(1)->Iterations(kQueries512)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LatticeAStar512)->Arg(0)->Arg(1)->Iterations(kQueries512)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ShortestFewestTurns512)->Arg(0)->Arg(1)->Iterations(kQueries512)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace fsweep
