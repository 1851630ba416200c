/// @file bench_planners.cpp
/// Query time of the path planners, all on fully known maps (1 m cells):
///
/// - `BM_PlannerQuery/<planner>`: EVERY planner of the registry (planner_names(), so a new
///   planner is benchmarked without editing this file) on the same fixed query set: every
///   10th query of the MovingAI scenario den312d.map.scen (32 queries over all length buckets,
///   optimal lengths 3.4 to 124 cells), start heading 0, `mei2006` energy, no corner cutting,
///   seed derive_seed(1, "bench_planner_query") + query. One benchmark iteration plans the
///   whole set once, so the reported time is per 32 queries; the counter `s_per_query` is the
///   time per query. OMPL planners run with max_iterations = 1000 (LazyPRMstar 250: its cost
///   grows about quadratically with the iterations, 1000 took 0.11 s per query) and a time
///   limit (60 s) they never reach, so each query ends by a solution or by its iteration
///   budget and does the same work every time (PRMstar is bounded the same way but checks for
///   a solution in a second thread, so its work varies a little; see ompl_planner.hpp).
///   `solved` is the fraction of queries solved.
/// - `BM_ScenarioQuery/<planner>/<map>`: `astar`, `jps` and `jps+` on every reachable query (optimal
///   length > 0) of each MovingAI scenario in tests/data (arena 160 queries, den312d 320,
///   room-64-64-8 1000), start heading 0, no corner cutting. One iteration plans the whole set;
///   `s_per_query` is the mean time per query, `expansions/query` the settled states (cells for
///   `astar`, jump points for `jps` and `jps+`; `jps+` builds its table in the untimed warm-up)
///   and `cells/query` the mean path length in cells (equal for all: the check that they answer
///   alike). Compare them with interleaved repetitions:
///   `--benchmark_filter=ScenarioQuery --benchmark_repetitions=9
///   --benchmark_enable_random_interleaving=true`.
/// - `BM_TextbookAstar/<map>`: the yardstick of `astar` (bench/textbook_astar.hpp: a compact
///   standalone octile A*, Warthog's open list) on the same maps and queries as
///   `BM_ScenarioQuery`; it must find MovingAI's optimal length, and `astar`'s length and
///   expansions, on every query (checked before timing). Compare
///   `--benchmark_filter='ScenarioQuery/astar|TextbookAstar'` with interleaved repetitions.
/// - `BM_ScenarioSearch/astar/<map>`: `astar`'s search alone on the same queries (no
///   Planner::plan() around it): the same work as `BM_TextbookAstar`, so the two compare the
///   search loops, and `BM_ScenarioQuery/astar` minus this is the planner interface per query.
/// - `BM_AStarDen312d`, `BM_DijkstraDen312d`, `BM_DistanceFieldBounded/max_m:<m>`: the grid
///   searches on 512 seeded random reachable pairs of den312d; one iteration is one query.
/// - `BM_<planner>512/<map>`: issue 4's query times on 512x512 maps (no 512x512 MovingAI map
///   is in ../shared/data/maps, so generated ones: 0 = `random` with 20% obstacles as in Mei
///   2006 section V-B, 1 = `rooms`). Every benchmark runs the same 32 seeded reachable queries
///   exactly once (random start headings, `mei2006` energy); the reported time is the mean per
///   query and `median_ms` the median query time. These take about 25 s per repetition and
///   are left out of the nightly set (`--benchmark_filter='-512|Slow'`).
///
/// Every benchmark plans one query (`BM_PlannerQuery`: its whole set) before timing, so the
/// planners' search arrays are allocated outside the timed loop.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/random.hpp"
#include "evaluation/scenario_check.hpp"
#include "planners/grid_planner.hpp"
#include "planners/planner.hpp"
#include "planners/registry.hpp"
#include "search/distance_field.hpp"
#include "search/grid_search.hpp"
#include "search/octile_grid.hpp"
#include "textbook_astar.hpp"
#include "world/energy_model.hpp"
#include "world/known_map.hpp"
#include "world/map_loaders.hpp"
#include "world/map_spec.hpp"
#include "world/world_map.hpp"

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
  static const Den312d kData = [] {
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
  return kData;
}

void run_grid_planner(benchmark::State& state, GridSearchKind kind) {
  const Den312d& d = den312d();
  GridPlanner planner(kind);
  benchmark::DoNotOptimize(planner.plan(d.known, d.queries.front()).length_m);  // warm-up, untimed
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

// NOLINTBEGIN(readability-identifier-naming): Google Benchmark's BM_ names
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
  field.compute(d.known, d.sources.front(), query);  // warm-up, untimed
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
BENCHMARK(BM_DistanceFieldBounded)->ArgName("max_m")->Arg(10)->Arg(30)->Arg(1000);
// NOLINTEND(readability-identifier-naming)

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
  benchmark::DoNotOptimize(planner->plan(m.known, m.queries.front()).energy);  // warm-up, untimed
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

// NOLINTBEGIN(readability-identifier-naming): Google Benchmark's BM_ names
void BM_AStar512(benchmark::State& state) { run_planner_512(state, "astar"); }
void BM_Jps512(benchmark::State& state) { run_planner_512(state, "jps"); }
void BM_Lattice512(benchmark::State& state) { run_planner_512(state, "lattice"); }
void BM_LatticeAStar512(benchmark::State& state) { run_planner_512(state, "lattice_astar"); }
void BM_ShortestFewestTurns512(benchmark::State& state) { run_planner_512(state, "shortest_fewest_turns"); }
// NOLINTEND(readability-identifier-naming)
BENCHMARK(BM_AStar512)->Arg(0)->Arg(1)->Iterations(kQueries512)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Jps512)->Arg(0)->Arg(1)->Iterations(kQueries512)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Lattice512)->Arg(0)->Arg(1)->Iterations(kQueries512)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LatticeAStar512)->Arg(0)->Arg(1)->Iterations(kQueries512)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ShortestFewestTurns512)->Arg(0)->Arg(1)->Iterations(kQueries512)->Unit(benchmark::kMillisecond);

/// den312d, fully known, and BM_PlannerQuery's fixed query set (see the file comment).
struct ScenarioSet {
  KnownMap known;
  std::vector<PlanRequest> queries;
  /// MovingAI's optimal length of each query (cells; load_scenario_set() only).
  std::vector<double> optimal_lengths;
};

constexpr std::size_t kScenarioStride = 10;
constexpr long kOmplIterations = 1000;
constexpr long kLazyPrmIterations = 250;

const ScenarioSet& den312d_scenario() {
  static const ScenarioSet kData = [] {
    ScenarioSet s;
    s.known = fully_known(load_movingai_map(std::string(FSWEEP_TEST_DATA) + "/den312d.map"));
    const std::vector<ScenarioQuery> scen =
        load_scenario(std::string(FSWEEP_TEST_DATA) + "/den312d.map.scen");
    const std::uint64_t base_seed = derive_seed(1, "bench_planner_query");
    for (std::size_t i = 0; i < scen.size(); i += kScenarioStride) {
      if (scen[i].optimal_length <= 0.0) continue;  // 0 marks an unreachable pair
      PlanRequest q;
      q.start = scen[i].start;
      q.goal = scen[i].goal;
      q.energy = energy_preset("mei2006");
      q.seed = base_seed + s.queries.size();
      s.queries.push_back(q);
    }
    return s;
  }();
  return kData;
}

/// Parameters for `name` in BM_PlannerQuery: defaults, except that OMPL planners end by an
/// iteration budget instead of the (wall-clock, so irreproducible) time limit.
nlohmann::json planner_query_params(const std::string& name) {
  if (name.rfind("ompl:", 0) != 0) return nlohmann::json::object();
  const long iterations = name == "ompl:LazyPRMstar" ? kLazyPrmIterations : kOmplIterations;
  return {{"max_iterations", iterations}, {"time_limit_s", 60.0}};
}

/// The timed part of the query benchmarks: every query of `s` in order per iteration, answered
/// by `answer(query)`, which returns its expansions; sets the counters `queries`, `s_per_query`
/// and `expansions/query`.
template <typename Answer>
void time_answers(benchmark::State& state, const ScenarioSet& s, Answer&& answer) {
  long expansions = 0;
  for (auto _ : state) {
    for (const PlanRequest& q : s.queries) expansions += answer(q);
  }
  const auto queries = static_cast<double>(s.queries.size());
  state.counters["queries"] = queries;
  state.counters["s_per_query"] = benchmark::Counter(
      queries, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["expansions/query"] = benchmark::Counter(
      static_cast<double>(expansions) / (queries * static_cast<double>(state.iterations())));
}

/// time_answers() with `planner`.
void time_queries(benchmark::State& state, Planner& planner, const ScenarioSet& s) {
  time_answers(state, s, [&](const PlanRequest& q) {
    const PlanResult r = planner.plan(s.known, q);
    benchmark::DoNotOptimize(r.length_m);
    return r.expansions;
  });
}

/// One iteration = the whole fixed query set, planned in order.
void planner_query(benchmark::State& state, const std::string& name) {
  const ScenarioSet& s = den312d_scenario();
  const auto planner = make_planner(name, planner_query_params(name));
  long solved = 0;
  for (const PlanRequest& q : s.queries)
    solved += planner->plan(s.known, q).status == PlanStatus::Success ? 1 : 0;
  time_queries(state, *planner, s);
  state.counters["solved"] = static_cast<double>(solved) / static_cast<double>(s.queries.size());
}

/// One BM_PlannerQuery/<name> per registered planner.
const bool kPlannerQueriesRegistered = [] {
  for (const std::string& name : planner_names()) {
    benchmark::RegisterBenchmark(("BM_PlannerQuery/" + name).c_str(), planner_query, name)
        ->Unit(benchmark::kMillisecond);
  }
  return true;
}();

/// A MovingAI map of tests/data, fully known, and the reachable queries of its scenario.
struct ScenarioMap {
  const char* label;
  const char* map_file;
  const char* scen_file;
};

constexpr std::array<ScenarioMap, 3> kScenarioMaps{
    ScenarioMap{"arena", "arena.map", "arena.map.scen"},
    ScenarioMap{"den312d", "den312d.map", "den312d.map.scen"},
    ScenarioMap{"room-64-64-8", "room-64-64-8.map", "room-64-64-8-random-1.scen"}};

ScenarioSet load_scenario_set(const ScenarioMap& files) {
  ScenarioSet s;
  s.known = fully_known(load_movingai_map(std::string(FSWEEP_TEST_DATA) + "/" + files.map_file));
  for (const ScenarioQuery& row : load_scenario(std::string(FSWEEP_TEST_DATA) + "/" + files.scen_file)) {
    if (row.optimal_length <= 0.0) continue;  // 0 marks an unreachable pair
    PlanRequest q;
    q.start = row.start;
    q.goal = row.goal;
    s.queries.push_back(q);
    s.optimal_lengths.push_back(row.optimal_length);
  }
  return s;
}

/// The query set of map `which` of kScenarioMaps (loaded once).
const ScenarioSet& scenario_set(std::size_t which) {
  static const std::array<ScenarioSet, kScenarioMaps.size()> kSets{load_scenario_set(kScenarioMaps[0]),
                                                                   load_scenario_set(kScenarioMaps[1]),
                                                                   load_scenario_set(kScenarioMaps[2])};
  return kSets[which];
}

/// One iteration = every query of map `which` of kScenarioMaps, planned in order.
void scenario_query(benchmark::State& state, const std::string& name, std::size_t which) {
  const ScenarioSet& s = scenario_set(which);
  const auto planner = make_planner(name, nlohmann::json::object());
  double cells = 0.0;
  for (const PlanRequest& q : s.queries) cells += planner->plan(s.known, q).length_m;  // warm-up, untimed
  time_queries(state, *planner, s);
  state.counters["cells/query"] = cells / static_cast<double>(s.queries.size());  // 1 m cells
}

/// BM_ScenarioQuery/<planner>/<map> for astar, jps and jps+ on every map of kScenarioMaps.
const bool kScenarioQueriesRegistered = [] {
  for (const char* name : {"astar", "jps", "jps+"}) {
    for (std::size_t m = 0; m < kScenarioMaps.size(); ++m) {
      const std::string label = std::string("BM_ScenarioQuery/") + name + "/" + kScenarioMaps[m].label;
      benchmark::RegisterBenchmark(label.c_str(), scenario_query, std::string(name), m)
          ->Unit(benchmark::kMicrosecond);
    }
  }
  return true;
}();

/// One iteration = every query of map `which` of kScenarioMaps by the textbook A*
/// (textbook_astar.hpp), in order. Before timing, every query is checked against MovingAI's
/// optimal length (kScenarioToleranceRel: the older files print 6 digits) and against `astar`: the same
/// length (1e-9: `astar` sums its steps) and the same expansions (both expand in the order of
/// BestFirstSearchT); any difference fails the benchmark.
void textbook_query(benchmark::State& state, std::size_t which) {
  const ScenarioSet& s = scenario_set(which);
  textbook::TextbookAStar astar(s.known);
  const auto planner = make_planner("astar", nlohmann::json::object());
  for (std::size_t i = 0; i < s.queries.size(); ++i) {
    const textbook::TextbookResult r = astar.search(s.queries[i].start, s.queries[i].goal);
    const PlanResult p = planner->plan(s.known, s.queries[i]);
    if (std::abs(r.length - s.optimal_lengths[i]) > kScenarioToleranceRel * s.optimal_lengths[i] ||
        std::abs(r.length - p.length_m) > 1e-9 || r.expansions != p.expansions ||
        r.path_cells != p.path.size()) {
      state.SkipWithError(("query " + std::to_string(i) + " differs from MovingAI or astar").c_str());
      return;
    }
  }
  time_answers(state, s, [&](const PlanRequest& q) {
    const textbook::TextbookResult r = astar.search(q.start, q.goal);
    benchmark::DoNotOptimize(r.length);
    return r.expansions;
  });
}

/// One iteration = every query of map `which` by `astar`'s search alone (OctileSearch over
/// OctileGoalEnvironment, the path's cells counted): the work BM_TextbookAstar does, without
/// Planner::plan()'s interface (endpoint checks, the clock reads of `time_s`, the path vector and
/// its motion accounting). The gap between this and BM_ScenarioQuery/astar is that interface.
void search_only_query(benchmark::State& state, std::size_t which) {
  const ScenarioSet& s = scenario_set(which);
  OctileSearch search;
  const auto answer = [&](const PlanRequest& q) {
    const OctileGoalEnvironment<true> env(s.known, q.goal, false);
    const SearchOutcome outcome = search.run(env, s.known.index(q.start));
    benchmark::DoNotOptimize(search.trace_back(outcome.goal, [](int /*state*/) {}));
    return outcome.expansions;
  };
  for (const PlanRequest& q : s.queries) (void)answer(q);  // warm-up, untimed
  time_answers(state, s, answer);
}

/// BM_ScenarioSearch/astar/<map> on every map of kScenarioMaps.
const bool kSearchOnlyQueriesRegistered = [] {
  for (std::size_t m = 0; m < kScenarioMaps.size(); ++m) {
    const std::string label = std::string("BM_ScenarioSearch/astar/") + kScenarioMaps[m].label;
    benchmark::RegisterBenchmark(label.c_str(), search_only_query, m)->Unit(benchmark::kMicrosecond);
  }
  return true;
}();

/// BM_TextbookAstar/<map> on every map of kScenarioMaps.
const bool kTextbookQueriesRegistered = [] {
  for (std::size_t m = 0; m < kScenarioMaps.size(); ++m) {
    const std::string label = std::string("BM_TextbookAstar/") + kScenarioMaps[m].label;
    benchmark::RegisterBenchmark(label.c_str(), textbook_query, m)->Unit(benchmark::kMicrosecond);
  }
  return true;
}();
}  // namespace
}  // namespace fsweep
