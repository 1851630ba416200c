/// @file bench_strategies.cpp
/// `BM_Decision/<strategy>`: the time of one decision (Strategy::decide) of EVERY registered
/// strategy (strategy_names(), so a new strategy is benchmarked without editing this file),
/// with its default parameters and run seed 1, on one half-explored 400 x 400 `office` map
/// (office:w=400,h=400,seed=1; sensor range 10 m at 1 m per cell, clusters split at the sensor
/// range as the simulation does). The map is explored once by closest_frontier until half of
/// its free cells are known; each benchmark then times decide() on that frozen state with its
/// own strategy instance and a new distance oracle for every decision over the same search
/// arrays (its searches are part of the decision, as in a run). One decision is made untimed
/// first, so allocations of the search arrays and the strategy happen outside the timed loop. Strategies with
/// random parts (gbl, random_frontier) draw a new sample each decision from their seeded stream, so the
/// sequence of timed decisions is the same in every run.
///
/// Forking a run (copying a Simulation, as a search over weight vectors does at every
/// decision), against what one decision costs on the same state, for closest_frontier and
/// energy_aware (default parameters): a run on rooms:w=200,h=200,door=3,seed=1 (as
/// BM_ExploreRooms200 in bench_sim.cpp: sensor range 10 m at 1 m per cell, perfect sensor,
/// unlimited battery, run seed 0) stepped until half of the map's free cells are known.
/// - `BM_Fork/rooms200/<strategy>`: one copy of that Simulation (and its destruction).
/// - `BM_Decision/rooms200/<strategy>`: decide() on that state, timed as BM_Decision.
/// - `BM_Step/rooms200/<strategy>`: one step() (decide, plan, travel) of a fresh fork of that
///   state; the copy is made outside the timed part.

#include <benchmark/benchmark.h>

#include <array>
#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sim/grid_distance_oracle.hpp"
#include "sim/simulation.hpp"
#include "strategies/registry.hpp"
#include "world/frontiers.hpp"
#include "world/map_spec.hpp"

namespace fsweep {
namespace {

constexpr double kRangeM = 10.0;
constexpr double kExploredFraction = 0.5;

/// The frozen half-explored state: the robot's map, frontiers and clusters at one decision.
struct HalfExplored {
  std::shared_ptr<const WorldMap> map;
  KnownMap known;
  FrontierMap frontiers;
  std::vector<FrontierCluster> clusters;
  Cell robot{};
  double explored = 0.0;  // known free cells / free cells of the map
};

/// A run of `spec` stepped until half of its map's free cells are known (or it ended).
Simulation run_to_half(const RunSpec& spec) {
  int free_cells = 0;
  for (int i = 0; i < spec.map->occupied.size(); ++i) free_cells += spec.map->occupied[i] == 0 ? 1 : 0;
  Simulation sim(spec);
  while (static_cast<double>(sim.known().free_count()) < kExploredFraction * free_cells && sim.step()) {
  }
  return sim;
}

/// The frozen decision state of `sim`.
HalfExplored freeze(const Simulation& sim, std::shared_ptr<const WorldMap> map) {
  int free_cells = 0;
  for (int i = 0; i < map->occupied.size(); ++i) free_cells += map->occupied[i] == 0 ? 1 : 0;
  HalfExplored h;
  h.map = std::move(map);
  h.known = sim.known();
  h.robot = sim.robot();
  h.explored = static_cast<double>(h.known.free_count()) / free_cells;
  h.frontiers = FrontierMap(h.known);
  h.clusters = h.frontiers.clusters(h.known, kRangeM, false);
  return h;
}

const HalfExplored& half_explored() {
  static const HalfExplored kState = [] {
    RunSpec spec;
    spec.map = std::make_shared<const WorldMap>(load_map_spec("office:w=400,h=400,seed=1"));
    spec.strategy = configure_strategy("closest_frontier", nullptr);
    spec.robot.sensor.range_m = kRangeM;
    spec.seed = 1;
    return freeze(run_to_half(spec), spec.map);
  }();
  return kState;
}

/// The strategies of the fork benchmarks.
constexpr std::array<const char*, 2> kForkStrategies{"closest_frontier", "energy_aware"};

/// A run of `strategy` on the 200 x 200 rooms map, half explored, and its frozen state.
struct MidRun {
  Simulation sim;
  HalfExplored frozen;
};

const MidRun& mid_run(std::size_t strategy) {
  static const std::array<MidRun, kForkStrategies.size()> kRuns = [] {
    const auto map = std::make_shared<const WorldMap>(load_map_spec("rooms:w=200,h=200,door=3,seed=1"));
    const auto make = [&](const char* name) {
      RunSpec spec;
      spec.map = map;
      spec.strategy = configure_strategy(name, nullptr);
      spec.robot.sensor.range_m = kRangeM;
      Simulation sim = run_to_half(spec);
      HalfExplored frozen = freeze(sim, map);
      return MidRun{std::move(sim), std::move(frozen)};
    };
    return std::array<MidRun, kForkStrategies.size()>{make(kForkStrategies[0]), make(kForkStrategies[1])};
  }();
  return kRuns[strategy];
}

void decision(benchmark::State& state, const HalfExplored& h, const std::string& name) {
  SensorParams sensor;
  sensor.range_m = kRangeM;
  const std::unique_ptr<Strategy> strategy = make_strategy(name, nullptr, 1);
  const Cell dock = h.map->start;
  DistanceScratch scratch;
  const auto decide_once = [&] {
    GridDistanceOracle oracle(h.known, h.robot, dock, false, nullptr, scratch);
    const Observation obs{h.known, h.frontiers, h.clusters,   oracle, sensor, h.robot,
                          0,       h.robot,     std::nullopt, dock,   {},     1};
    return strategy->decide(obs);
  };
  benchmark::DoNotOptimize(decide_once());  // warm-up, untimed
  long goals = 0;
  for (auto _ : state) {
    const Decision d = decide_once();
    goals += d.kind == Decision::Kind::GoTo ? 1 : 0;
    benchmark::DoNotOptimize(d);
  }
  state.counters["clusters"] = static_cast<double>(h.clusters.size());
  state.counters["explored"] = h.explored;
  state.counters["goto_fraction"] = static_cast<double>(goals) / static_cast<double>(state.iterations());
}

void fork(benchmark::State& state, std::size_t strategy) {
  const MidRun& run = mid_run(strategy);
  for (auto _ : state) {
    Simulation copy = run.sim;
    benchmark::DoNotOptimize(copy);
  }
  state.counters["explored"] = run.frozen.explored;
}

void step(benchmark::State& state, std::size_t strategy) {
  const MidRun& run = mid_run(strategy);
  for (auto _ : state) {
    Simulation copy = run.sim;
    const auto t0 = std::chrono::steady_clock::now();
    benchmark::DoNotOptimize(copy.step());
    state.SetIterationTime(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  state.counters["explored"] = run.frozen.explored;
}

/// One BM_Decision/<name> per registered strategy, so a new strategy is benchmarked without
/// editing this file; then the fork benchmarks.
const bool kRegistered = [] {
  for (const std::string& name : strategy_names()) {
    benchmark::RegisterBenchmark(("BM_Decision/" + name).c_str(), [name](benchmark::State& state) {
      decision(state, half_explored(), name);
    })->Unit(benchmark::kMillisecond);
  }
  for (std::size_t i = 0; i < kForkStrategies.size(); ++i) {
    const std::string name = kForkStrategies[i];
    benchmark::RegisterBenchmark(("BM_Fork/rooms200/" + name).c_str(), fork, i)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("BM_Decision/rooms200/" + name).c_str(), [i,
                                                                            name](benchmark::State& state) {
      decision(state, mid_run(i).frozen, name);
    })->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("BM_Step/rooms200/" + name).c_str(), step, i)
        ->UseManualTime()
        ->Unit(benchmark::kMicrosecond);
  }
  return true;
}();

}  // namespace
}  // namespace fsweep
