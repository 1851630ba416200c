/// @file bench_jps.cpp
/// `jps` (src/planners/jps_planner.cpp) against its yardstick, bench/textbook_jps.hpp: a compact
/// standalone jump point search with the block-based jumps of Harabor and Grastien, "Improving Jump
/// Point Search" (ICAPS 2014), the way bench/textbook_astar.hpp stands for `astar`. All on fully
/// known maps (1 m cells), no corner cutting, start heading 0; one benchmark iteration answers the
/// whole query set of a map in order, `s_per_query` is the mean time per query and
/// `expansions/query` the jump points settled (the goal included):
///
/// - `BM_TextbookJps/<map>`: the yardstick's search alone (length, expansions and the path's cell
///   count, no path cells written) on every reachable query of each MovingAI scenario of
///   BM_ScenarioQuery (arena 160 queries, den312d 320, room-64-64-8 1000). The project's side is
///   `BM_ScenarioQuery/jps/<map>` of bench_planners.cpp, directly comparable (the same queries in
///   the same order, the same default PlanRequest, the same Planner::plan() call per query), so it
///   is not repeated here: run both in one interleaved set,
///   `--benchmark_filter='Jps|ScenarioQuery/jps' --benchmark_repetitions=5
///   --benchmark_enable_random_interleaving=true`.
/// - `BM_TextbookJpsPlanned/<map>`: the yardstick behind the Planner interface
///   (TextbookJpsPlanner below): Planner::plan()'s endpoint checks, clock reads and motion accounting
///   (measure_path over every cell), and the path's every cell written, as `jps` returns it. Against
///   `BM_ScenarioQuery/jps/<map>` it compares the searches and the paths they return, the interface
///   being the same code but for the motion totals, which `jps` works out from its jump points
///   (SearchResult::motion); `BM_TextbookJpsPlanned` minus `BM_TextbookJps` is the interface's cost
///   per query set.
/// - `BM_OpenJps/jps`, `BM_OpenJps/textbook`, `BM_OpenJps/textbook_planned`: `jps` through
///   make_planner("jps") and plan() (as BM_ScenarioQuery calls it), the yardstick's search alone, and
///   the yardstick through plan(), on an open 1,024 x 1,024 map generated from a fixed seed
///   (open_map(): 0.5% scattered single obstacles and eight long walls with three gaps each) with
///   100 seeded random reachable queries (bench_queries_from_pairs(), seed 2024, optimal lengths by
///   `astar`). Long jumps: where scanning a word at a time pays most.
///
/// Before timing, every query of a map (once per process, when a benchmark of it first runs) is
/// answered by the yardstick, by `jps` and by the planned yardstick: the lengths must agree with each
/// other (within 1e-6) and with the optimal length (within 1e-6, or kScenarioToleranceRel relative:
/// the older .scen files print 6 significant digits), and the yardstick must expand as many jump
/// points as `jps` and count as many path cells; otherwise every benchmark of the map fails with
/// SkipWithError naming the first query that differs.
///
/// How the yardstick differs from `jps` (both expand the same jump points, in the same order by
/// design; the check compares their numbers per query):
/// - `jps` runs inside Planner::plan() (endpoint checks, a clock read before and after, the
///   StopCondition checked before every expansion, the motion accounting, which `jps` works out
///   from its jump points with measure_jump_points()) and returns every path cell (search_result()
///   writes the jump points, fill_segments() the cells between them into a second vector);
///   BM_TextbookJps does none of it, BM_TextbookJpsPlanned all of it but the stop condition, its
///   motion accounting by measure_path() over every cell;
/// - `jps` scans KnownMap's bit rows and columns, which follow every revealed cell (a guard word
///   at each end of a line and a guard line beyond each edge, so no read is bounds-checked); the
///   yardstick owns a padded static copy of its own;
/// - `jps` runs the project's A* (BestFirstSearchT over an environment: a 4-ary indexed heap of
///   packed 128-bit keys, 16-byte nodes, the direction of arrival from the parent's cell) and serves
///   both corner rules; the yardstick has its own binary heap and MovingAI's rule only;
/// - its diagonal steps and pruning tests read those bit rows too; the yardstick reads a padded
///   byte grid.

#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/random.hpp"
#include "evaluation/plan_bench.hpp"
#include "evaluation/scenario_check.hpp"
#include "planners/planner.hpp"
#include "planners/registry.hpp"
#include "textbook_jps.hpp"
#include "world/known_map.hpp"
#include "world/map_loaders.hpp"
#include "world/world_map.hpp"

namespace fsweep {
namespace {

/// The yardstick as a Planner: plan() around its search, the path's every cell written.
class TextbookJpsPlanner final : public Planner {
 public:
  explicit TextbookJpsPlanner(const KnownMap& known) : Planner(SearchBudget{}), jps_(known) {}
  [[nodiscard]] std::string name() const override { return "textbook_jps"; }
  [[nodiscard]] std::unique_ptr<Planner> clone() const override {
    return std::make_unique<TextbookJpsPlanner>(*this);
  }

 protected:
  /// Searches the map the planner was made with (not `known`: they must be the same); no budget.
  [[nodiscard]] SearchResult search(const KnownMap& /*known*/, const PlanRequest& request,
                                    const StopCondition& /*stop*/) override {
    SearchResult result;
    const textbook::TextbookResult r = jps_.search(request.start, request.goal, &result.path);
    result.expansions = r.expansions;
    result.status = r.length < 0.0 ? PlanStatus::NoPath : PlanStatus::Success;
    return result;
  }

 private:
  textbook::TextbookJps jps_;
};

/// A fully known map, its queries and the outcome of their check.
struct JpsMap {
  KnownMap known;
  std::vector<BenchQuery> queries;
  /// Empty when every query passed check_queries(); else the first that did not.
  std::string mismatch;
};

/// The MovingAI scenarios of BM_ScenarioQuery (bench_planners.cpp), in tests/data: the label, which
/// is also the map's file name without ".map", and the scenario file.
constexpr std::array<std::array<const char*, 2>, 3> kScenarios{
    {{"arena", "arena.map.scen"},
     {"den312d", "den312d.map.scen"},
     {"room-64-64-8", "room-64-64-8-random-1.scen"}}};
/// Index of the open map among the maps of jps_map(), after the scenarios.
constexpr std::size_t kOpen = kScenarios.size();
constexpr int kOpenSize = 1024;
constexpr int kOpenQueries = 100;
constexpr std::uint64_t kOpenSeed = 2024;

/// The open 1,024 x 1,024 map: each cell an obstacle with probability 0.005, then eight walls
/// one cell thick, alternately across and down, each crossing most of the map (32 to 95 cells
/// short of either edge) with three gaps of 4 to 11 cells.
WorldMap open_map() {
  WorldMap map;
  map.occupied = Grid<std::uint8_t>(kOpenSize, kOpenSize, 0);
  map.source = "bench_jps open map";
  Rng rng = make_rng(kOpenSeed, "bench_jps_open_map");
  const auto below = [&rng](int n) {
    return static_cast<int>(uniform_below(rng, static_cast<std::uint64_t>(n)));
  };
  for (std::uint8_t& cell : map.occupied.data()) cell = uniform01(rng) < 0.005 ? 1 : 0;
  for (int k = 0; k < 8; ++k) {
    const int line = 100 + 110 * k + below(40);
    const int from = 32 + below(64);
    const int to = kOpenSize - 32 - below(64);
    std::array<int, 6> gaps{};  // [begin, end) pairs
    for (std::size_t g = 0; g < gaps.size(); g += 2) {
      gaps[g] = from + below(to - from - 12);
      gaps[g + 1] = gaps[g] + 4 + below(8);
    }
    for (int p = from; p < to; ++p) {
      bool gap = false;
      for (std::size_t g = 0; g < gaps.size(); g += 2) gap = gap || (p >= gaps[g] && p < gaps[g + 1]);
      if (!gap) map.occupied.at(k % 2 == 0 ? Cell{p, line} : Cell{line, p}) = 1;
    }
  }
  map.start = nearest_free_cell(map, Cell{0, 0});
  return map;
}

/// The request of query `q`: the defaults of PlanRequest (start heading 0, no corner cutting).
PlanRequest request_of(const BenchQuery& q) {
  PlanRequest request;
  request.start = q.start;
  request.goal = q.goal;
  return request;
}

/// Every query of `m` by the yardstick, by `jps` and by the planned yardstick (see the file
/// comment): "" when all agree with each other and with the optimal lengths, else the first
/// query that does not.
std::string check_queries(const JpsMap& m) {
  textbook::TextbookJps yardstick(m.known);
  TextbookJpsPlanner planned(m.known);
  const auto jps = make_planner("jps", nlohmann::json::object());
  for (std::size_t i = 0; i < m.queries.size(); ++i) {
    const BenchQuery& q = m.queries[i];
    const textbook::TextbookResult r = yardstick.search(q.start, q.goal);
    const PlanResult p = jps->plan(m.known, request_of(q));
    const PlanResult t = planned.plan(m.known, request_of(q));
    const double off = std::abs(r.length - q.optimal_cells);
    const bool optimal = off < 1e-6 || off <= kScenarioToleranceRel * q.optimal_cells;
    if (!optimal || p.status != PlanStatus::Success || std::abs(r.length - p.length_m) >= 1e-6 ||
        std::abs(r.length - t.length_m) >= 1e-6 || r.expansions != p.expansions ||
        r.path_cells != p.path.size() || r.path_cells != t.path.size()) {
      return "query " + std::to_string(i) + " ((" + std::to_string(q.start.x) + ", " +
             std::to_string(q.start.y) + ") to (" + std::to_string(q.goal.x) + ", " +
             std::to_string(q.goal.y) + ")): optimal " + std::to_string(q.optimal_cells) + ", textbook " +
             std::to_string(r.length) + " (" + std::to_string(r.expansions) + " expansions, " +
             std::to_string(r.path_cells) + " cells), jps " + std::to_string(p.length_m) + " (" +
             std::to_string(p.expansions) + ", " + std::to_string(p.path.size()) + "), planned textbook " +
             std::to_string(t.length_m) + " (" + std::to_string(t.path.size()) + " cells)";
    }
  }
  return "";
}

/// Map `which` (kScenarios, then kOpen) with its queries, checked; loaded on first use.
const JpsMap& jps_map(std::size_t which) {
  static std::array<std::unique_ptr<JpsMap>, kScenarios.size() + 1> cache;
  std::unique_ptr<JpsMap>& slot = cache[which];
  if (slot) return *slot;
  slot = std::make_unique<JpsMap>();
  if (which == kOpen) {
    slot->known = fully_known(open_map());
    PairDrawOptions pairs;
    pairs.count = kOpenQueries;
    pairs.seed = kOpenSeed;
    pairs.start_heading = 0;
    slot->queries = bench_queries_from_pairs(slot->known, pairs);
  } else {
    const std::string dir = std::string(FSWEEP_TEST_DATA) + "/";
    slot->known = fully_known(load_movingai_map(dir + kScenarios[which][0] + ".map"));
    slot->queries = bench_queries_from_scenario(load_scenario(dir + kScenarios[which][1]));
  }
  slot->mismatch = check_queries(*slot);
  return *slot;
}

/// The timed loop: every query of `m` answered in order per iteration by `answer(query)`, which
/// returns its expansions, after one untimed round; fails instead if `m`'s check did.
template <typename Answer>
void answer_all(benchmark::State& state, const JpsMap& m, Answer answer) {
  if (!m.mismatch.empty()) {
    state.SkipWithError(m.mismatch.c_str());
    return;
  }
  for (const BenchQuery& q : m.queries) (void)answer(q);
  long expansions = 0;
  for (auto _ : state) {
    for (const BenchQuery& q : m.queries) expansions += answer(q);
  }
  const auto n = static_cast<double>(m.queries.size());
  state.counters["queries"] = n;
  state.counters["s_per_query"] =
      benchmark::Counter(n, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["expansions/query"] =
      static_cast<double>(expansions) / (n * static_cast<double>(state.iterations()));
}

/// The yardstick's search alone on map `which`.
void textbook_search(benchmark::State& state, std::size_t which) {
  const JpsMap& m = jps_map(which);
  textbook::TextbookJps jps(m.known);
  answer_all(state, m, [&jps](const BenchQuery& q) {
    const textbook::TextbookResult r = jps.search(q.start, q.goal);
    benchmark::DoNotOptimize(r.length);
    return r.expansions;
  });
}

/// `planner` through Planner::plan() on map `which`.
void planned(benchmark::State& state, std::size_t which, Planner& planner) {
  const JpsMap& m = jps_map(which);
  answer_all(state, m, [&](const BenchQuery& q) {
    const PlanResult r = planner.plan(m.known, request_of(q));
    benchmark::DoNotOptimize(r.length_m);
    return r.expansions;
  });
}

/// The planned yardstick on map `which`.
void textbook_planned(benchmark::State& state, std::size_t which) {
  TextbookJpsPlanner planner(jps_map(which).known);
  planned(state, which, planner);
}

/// The project's planner `name` (`jps` or `jps+`) on map `which`; one query first, untimed, so
/// that `jps+` has built its jump table (the map does not change between queries).
void project_planner(benchmark::State& state, std::size_t which, const std::string& name) {
  const auto planner = make_planner(name, nlohmann::json::object());
  const JpsMap& m = jps_map(which);
  if (!m.queries.empty())
    benchmark::DoNotOptimize(planner->plan(m.known, request_of(m.queries.front())).length_m);
  planned(state, which, *planner);
}

/// `jps+`'s table built for map `which` and its first query answered: a new planner each
/// iteration (a planner keeps its table while the map does not change).
void jps_plus_build(benchmark::State& state, std::size_t which) {
  const JpsMap& m = jps_map(which);
  if (m.queries.empty()) return;
  for (auto _ : state) {
    const auto planner = make_planner("jps+", nlohmann::json::object());
    benchmark::DoNotOptimize(planner->plan(m.known, request_of(m.queries.front())).length_m);
  }
}

/// BM_TextbookJps/<map>, BM_TextbookJpsPlanned/<map>, BM_JpsPlusBuild/<map> and
/// BM_OpenJps/{jps,jps+,textbook,textbook_planned}.
const bool kJpsRegistered = [] {
  for (std::size_t m = 0; m < kScenarios.size(); ++m) {
    const std::string label = kScenarios[m][0];
    benchmark::RegisterBenchmark(("BM_TextbookJps/" + label).c_str(), textbook_search, m)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("BM_TextbookJpsPlanned/" + label).c_str(), textbook_planned, m)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("BM_JpsPlusBuild/" + label).c_str(), jps_plus_build, m)
        ->Unit(benchmark::kMicrosecond);
  }
  benchmark::RegisterBenchmark("BM_JpsPlusBuild/open", jps_plus_build, kOpen)->Unit(benchmark::kMillisecond);
  for (const char* name : {"jps", "jps+"}) {
    benchmark::RegisterBenchmark((std::string("BM_OpenJps/") + name).c_str(), project_planner, kOpen,
                                 std::string(name))
        ->Unit(benchmark::kMillisecond);
  }
  benchmark::RegisterBenchmark("BM_OpenJps/textbook", textbook_search, kOpen)->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("BM_OpenJps/textbook_planned", textbook_planned, kOpen)
      ->Unit(benchmark::kMillisecond);
  return true;
}();

}  // namespace
}  // namespace fsweep
