/// @file bench_strategies.cpp
/// `BM_Decision/<strategy>`: the time of one decision (Strategy::decide) of EVERY registered
/// strategy (strategy_names(), so a new strategy is benchmarked without editing this file),
/// with its default parameters and run seed 1, on one half-explored 400 x 400 `office` map
/// (office:w=400,h=400,seed=1; sensor range 10 m at 1 m per cell, clusters split at the sensor
/// range as the simulation does). The map is explored once by closest_frontier until half of
/// its free cells are known; each benchmark then times decide() on that frozen state with its
/// own strategy instance and a distance oracle reset before every decision (its searches are
/// part of the decision, as in a run). One decision is made untimed first, so allocations of
/// the oracle and the strategy happen outside the timed loop. Strategies with random parts
/// (gbl, random_frontier) draw a new sample each decision from their seeded stream, so the
/// sequence of timed decisions is the same in every run.

#include <benchmark/benchmark.h>

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

const HalfExplored& half_explored() {
  static const HalfExplored kState = [] {
    HalfExplored h;
    h.map = std::make_shared<const WorldMap>(load_map_spec("office:w=400,h=400,seed=1"));
    RunSpec spec;
    spec.map = h.map;
    spec.strategy = configure_strategy("closest_frontier", nullptr);
    spec.robot.sensor.range_m = kRangeM;
    spec.seed = 1;
    int free_cells = 0;
    for (int i = 0; i < h.map->occupied.size(); ++i) free_cells += h.map->occupied[i] == 0 ? 1 : 0;
    Simulation sim(spec);
    while (static_cast<double>(sim.known().free_count()) < kExploredFraction * free_cells && sim.step()) {
    }
    h.known = sim.known();
    h.robot = sim.robot();
    h.explored = static_cast<double>(h.known.free_count()) / free_cells;
    h.frontiers = FrontierMap(h.known);
    h.clusters = h.frontiers.clusters(h.known, kRangeM, false);
    return h;
  }();
  return kState;
}

void decision(benchmark::State& state, const std::string& name) {
  const HalfExplored& h = half_explored();
  SensorParams sensor;
  sensor.range_m = kRangeM;
  const std::unique_ptr<Strategy> strategy = make_strategy(name, nullptr, 1);
  GridDistanceOracle oracle;
  const Cell dock = h.map->start;
  const auto decide_once = [&] {
    oracle.reset(h.known, h.robot, dock, false, nullptr, nullptr);
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

/// One BM_Decision/<name> per registered strategy, so a new strategy is benchmarked without
/// editing this file.
const bool kRegistered = [] {
  for (const std::string& name : strategy_names()) {
    benchmark::RegisterBenchmark(("BM_Decision/" + name).c_str(), decision, name)
        ->Unit(benchmark::kMillisecond);
  }
  return true;
}();

}  // namespace
}  // namespace fsweep
