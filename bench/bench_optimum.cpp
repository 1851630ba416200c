/// @file bench_optimum.cpp
/// The offline coverage optimum's bounds (optimum/optimum.hpp): one iteration is one
/// solve_optimum() of a map and robot, from the instance's set-up (one scan per reachable free
/// cell) to the replayed route, on one thread.
///
/// - `BM_Optimum/<map>`: the default sweep's ten maps (`rooms_<seed>`:
///   rooms:w=100,h=80,res=0.5,door=3,seed=<seed> and `office_<seed>`:
///   office:w=100,h=80,res=0.5,seed=<seed>, seeds 1-5) with its robot (sensor 8 m, `distance`
///   energy, 500 m battery); the Manhattan and old-town classes (`manhattan:w=48,h=48,seed=1`,
///   `oldtown:w=48,h=48,seed=1`, sensor 4 m), the MovingAI map `room-64-64-8` (tests/data,
///   sensor 4 m) and the HouseExpo plan 1451 at 0.1 m (tests/data/houseexpo, sensor 4 m), no
///   battery; and two small maps the bounds solve exactly (`free:w=8,h=6` and
///   `rooms:w=9,h=7,door=1,min_room=3,seed=2`, sensor 2 m).
///
/// Counters: `lower_m`, `upper_m`, `gap` ((upper - lower) / lower, 0 when exact), `exact` (1 when
/// the bounds meet), `explorable` (cells the route must reveal), and `upper_one_cover_m`: the
/// covering route from the plain greedy cover alone (RouteOptions::restarts 1; computed after the
/// timing), 0 when its replay misses a cell.

#include <benchmark/benchmark.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "optimum/cover_route.hpp"
#include "optimum/coverage_instance.hpp"
#include "optimum/optimum.hpp"
#include "world/map_spec.hpp"

namespace fsweep {
namespace {

struct OptimumCase {
  std::string label;
  std::string map;
  double sensor_m;
  double battery;  // 0: unlimited
};

std::vector<OptimumCase> optimum_cases() {
  std::vector<OptimumCase> cases;
  for (int seed = 1; seed <= 5; ++seed) {
    const std::string s = std::to_string(seed);
    cases.push_back({"rooms_" + s, "rooms:w=100,h=80,res=0.5,door=3,seed=" + s, 8.0, 500.0});
  }
  for (int seed = 1; seed <= 5; ++seed) {
    const std::string s = std::to_string(seed);
    cases.push_back({"office_" + s, "office:w=100,h=80,res=0.5,seed=" + s, 8.0, 500.0});
  }
  const std::string data = FSWEEP_TEST_DATA;
  cases.push_back({"manhattan_48", "manhattan:w=48,h=48,seed=1", 4.0, 0.0});
  cases.push_back({"oldtown_48", "oldtown:w=48,h=48,seed=1", 4.0, 0.0});
  cases.push_back({"room-64-64-8", data + "/room-64-64-8.map", 4.0, 0.0});
  cases.push_back({"houseexpo_1451", data + "/houseexpo/house_expo_room_1451.json:res=0.1", 4.0, 0.0});
  cases.push_back({"free_8x6", "free:w=8,h=6", 2.0, 0.0});
  cases.push_back({"rooms_9x7", "rooms:w=9,h=7,door=1,min_room=3,seed=2", 2.0, 0.0});
  return cases;
}

void optimum(benchmark::State& state, const OptimumCase& c) {
  RunSpec spec;
  spec.map = std::make_shared<const WorldMap>(load_map_spec(c.map));
  spec.robot.sensor.range_m = c.sensor_m;
  if (c.battery > 0.0) spec.robot.battery_capacity = c.battery;
  OptimumResult r;
  for (auto _ : state) {
    r = solve_optimum(spec, OptimumOptions{});
    benchmark::DoNotOptimize(r);
  }
  state.counters["lower_m"] = r.lower_m;
  state.counters["upper_m"] = r.upper_m;
  state.counters["gap"] = r.gap();
  state.counters["exact"] = r.exact ? 1.0 : 0.0;
  state.counters["explorable"] = r.targets - r.out_of_reach;
  // Outside the timing: the upper bound of the plain greedy cover alone (RouteOptions::restarts
  // 1), what the other covers add.
  const CoverageInstance in = build_coverage_instance(spec);
  RouteOptions plain;
  plain.restarts = 1;
  const RouteReplay one = replay_route(in, spec, cover_route(in, spec, plain).cells);
  state.counters["upper_one_cover_m"] = one.covers() ? one.distance_to_final_coverage_m : 0.0;
}

const bool kOptimumRegistered = [] {
  for (const OptimumCase& c : optimum_cases()) {
    benchmark::RegisterBenchmark(("BM_Optimum/" + c.label).c_str(), optimum, c)
        ->Unit(benchmark::kMillisecond)
        ->Iterations(1);
  }
  return true;
}();

}  // namespace
}  // namespace fsweep
