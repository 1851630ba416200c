// Full explorations of a 200x200 `rooms` map (sensor range 10 cells), one per strategy.
#include <benchmark/benchmark.h>

#include <memory>
#include <nlohmann/json.hpp>

#include "engine/sim/simulation.hpp"
#include "engine/world/map_spec.hpp"

namespace fsweep {
namespace {

RunSpec rooms_spec(const std::string& strategy, nlohmann::json params, double battery) {
  static const auto map = std::make_shared<const WorldMap>(load_map_spec("rooms:w=200,h=200,door=3,seed=1"));
  RunSpec s;
  s.map = map;
  s.strategy = strategy;
  s.strategy_params = std::move(params);
  s.robot.sensor.range_m = 10.0;
  s.robot.battery_capacity = battery;
  return s;
}

void run(benchmark::State& state, const RunSpec& spec) {
  RunResult r;
  for (auto _ : state) {
    r = simulate(spec);
    benchmark::DoNotOptimize(r);  // the whole object: 1.7.1's "+r" form garbles a double
  }
  state.counters["distance_m"] = r.metrics.distance_m;
  state.counters["decisions"] = r.metrics.decisions;
  state.counters["coverage"] = r.metrics.coverage;
}

void BM_ExploreRooms200_ClosestFrontier(benchmark::State& state) {
  run(state, rooms_spec("closest_frontier", nullptr, std::numeric_limits<double>::infinity()));
}
void BM_ExploreRooms200_EnergyAware(benchmark::State& state) {
  run(state, rooms_spec("energy_aware", {{"w1", 10}, {"w2", 0}, {"w3", 9}, {"w4", 20}},
                        std::numeric_limits<double>::infinity()));
}
void BM_ExploreRooms200_EnergyAwareBattery(benchmark::State& state) {
  run(state, rooms_spec("energy_aware", {{"w1", 10}, {"w2", 0}, {"w3", 9}, {"w4", 20}}, 1200.0));
}

BENCHMARK(BM_ExploreRooms200_ClosestFrontier)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ExploreRooms200_EnergyAware)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ExploreRooms200_EnergyAwareBattery)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace fsweep
