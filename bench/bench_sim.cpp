/// @file bench_sim.cpp
/// Whole runs, start to end; one benchmark iteration is one run.
///
/// - `BM_FullRun/<map>/<strategy>`: one run of a small in-memory sweep through the same code
///   as `fsweep run` (SweepPlan::from_json, then SweepTable::run: RunSpec from the plan,
///   simulate(), the runs.csv and progress.csv rows), single-threaded. Robot and settings as
///   sweeps/default.json: sensor 8 m missing 5% of visible cells per scan (drawn from the run
///   seed, so every iteration is the same run), `distance` energy, 500 m battery, progress
///   every 10 m, sweep seed 1. Maps: `rooms_100x80` (rooms:w=100,h=80,res=0.5,door=3,seed=1,
///   as in the default sweep) and `room-64-64-8` (MovingAI, tests/data, 1 m cells).
///   Strategies: closest_frontier (`CF`) and energy_aware with the free-space weights
///   10,0,9,20 (`EA`).
/// - `BM_ExploreRooms200_<strategy>`: simulate() of a hand-built RunSpec on a 200x200 `rooms`
///   map (rooms:w=200,h=200,door=3,seed=1, sensor range 10 cells, perfect sensor, run seed 0);
///   closest_frontier, energy_aware (10,0,9,20) with unlimited battery and with a 1200 m
///   battery.
/// - `BM_ExploreRooms800/<strategy>`: the same on rooms:w=800,h=800 (seed 1, door 1 as the
///   generator's default), closest_frontier and energy_aware (10,0,9,20), unlimited battery:
///   the size at which energy-aware decisions used to cost 95x closest frontier's (issue 14).
/// - `BM_ExactWeightSearch/step:<s>` and `BM_BruteWeightSearch/step:<s>`: Rappaport 2016's
///   free-space weight search (sweeps/paper/rappaport2016_weights_free.json's setting on its
///   unclipped 71x71 map: 10 m cells, sensor 30 m, `distance` energy, range 600 m) over the
///   grid {0, s, 2s, ..., 250}^4, on one thread: the exact search (weightsearch/exact_search.hpp) and one
///   simulate() per vector. `behaviours` counts the distinct behaviours, `vectors` the grid.
///   `BM_ExactWeightSearchBox16` and `BM_BruteWeightSearchBox16Slow` (about 3 minutes, left out
///   of the nightly set): the same at step 1 over a 16^4 box (box16_grid()).
/// - `BM_RappaportFree/r:<m>/<strategy>`: Rappaport 2016's free space (10 m cells, sensor 30 m,
///   `distance` energy, battery range r, dock at the centre) on an unclipped square: free
///   half-width r/2 + r_s + 1 cell inside the map's occupied frame, as sweeps/paper/ sizes it, at r = 1800,
///   3600 and the paper's 9000 m; closest_frontier and energy_aware (10,0,9,20).

#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "sim/simulation.hpp"
#include "sweep/sweep_plan.hpp"
#include "sweep/sweep_table.hpp"
#include "weightsearch/exact_search.hpp"
#include "weightsearch/weight_grid.hpp"
#include "world/map_spec.hpp"

namespace fsweep {
namespace {

/// A map or strategy item of the BM_FullRun sweep, with the label that names its benchmarks.
struct Item {
  const char* label;
  nlohmann::json json;
};

std::array<Item, 2> full_run_maps() {
  return {Item{"rooms_100x80",
               {{"generator", "rooms"}, {"w", 100}, {"h", 80}, {"res", 0.5}, {"door", 3}, {"seed", 1}}},
          Item{"room-64-64-8", {{"file", std::string(FSWEEP_TEST_DATA) + "/room-64-64-8.map"}}}};
}

std::array<Item, 2> full_run_strategies() {
  return {Item{"CF", {{"name", "closest_frontier"}}},
          Item{"EA", {{"name", "energy_aware"}, {"params", {{"w1", 10}, {"w2", 0}, {"w3", 9}, {"w4", 20}}}}}};
}

/// The validated BM_FullRun sweep and its runs.csv layout (built on first use).
struct FullRunSweep {
  SweepPlan plan;
  SweepTable table;
};

const FullRunSweep& full_run_sweep() {
  static const FullRunSweep kSweep = [] {
    nlohmann::json maps = nlohmann::json::array();
    for (const Item& m : full_run_maps()) {
      nlohmann::json item = m.json;
      item["label"] = m.label;
      maps.push_back(item);
    }
    nlohmann::json strategies = nlohmann::json::array();
    for (const Item& s : full_run_strategies()) {
      nlohmann::json item = s.json;
      item["label"] = s.label;
      strategies.push_back(item);
    }
    const nlohmann::json j = {{"schema_version", kSweepSchemaVersion},
                              {"name", "bench_full_run"},
                              {"maps", maps},
                              {"strategies", strategies},
                              {"robot",
                               {{"sensor", {{"range_m", 8}, {"miss_probability", 0.05}}},
                                {"energy", "distance"},
                                {"battery", 500}}},
                              {"progress_step_m", 10},
                              {"seed", 1}};
    SweepPlan plan = SweepPlan::from_json(j, "bench_full_run");
    SweepTable table(plan);
    return FullRunSweep{std::move(plan), std::move(table)};
  }();
  return kSweep;
}

/// Field `column` of one CSV record (RFC 4180 quoting; the record may end with a newline).
std::string csv_field(const std::string& record, std::size_t column) {
  std::size_t field = 0;
  std::string out;
  bool quoted = false;
  for (std::size_t i = 0; i < record.size(); ++i) {
    const char c = record[i];
    if (quoted) {
      if (c == '"' && i + 1 < record.size() && record[i + 1] == '"') {
        out += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        out += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',' || c == '\n') {
      if (field == column) return out;
      ++field;
      out.clear();
    } else {
      out += c;
    }
  }
  return field == column ? out : std::string();
}

/// Runs map `map`, strategy `strategy` of the sweep (run index map * strategies + strategy: one
/// planner, one robot variant, one repetition).
void full_run(benchmark::State& state, std::size_t map, std::size_t strategy) {
  const FullRunSweep& s = full_run_sweep();
  const std::uint64_t index = map * full_run_strategies().size() + strategy;
  const RunCoordinates at = s.plan.coordinates(index);
  if (at.map != map || at.strategy_entry != strategy) {
    state.SkipWithError("run order of the bench sweep is not maps x strategies");
    return;
  }
  RunRows rows;
  for (auto _ : state) {
    rows = s.table.run(s.plan, s.plan.run(index));
    benchmark::DoNotOptimize(rows.run_row.data());
  }
  if (rows.failed) {
    state.SkipWithError(("run failed: " + rows.run_row).c_str());
    return;
  }
  for (const char* column : {"distance_m", "decisions", "coverage"}) {
    state.counters[column] = std::stod(csv_field(rows.run_row, s.table.column(column)));
  }
  state.SetLabel(csv_field(rows.run_row, s.table.column("end_reason")));
}

const bool kFullRunsRegistered = [] {
  const auto maps = full_run_maps();
  const auto strategies = full_run_strategies();
  for (std::size_t m = 0; m < maps.size(); ++m) {
    for (std::size_t s = 0; s < strategies.size(); ++s) {
      const std::string name = std::string("BM_FullRun/") + maps[m].label + "/" + strategies[s].label;
      benchmark::RegisterBenchmark(name.c_str(), full_run, m, s)->Unit(benchmark::kMillisecond);
    }
  }
  return true;
}();

RunSpec rooms_spec(const std::string& strategy, nlohmann::json params, double battery) {
  static const auto kMap = std::make_shared<const WorldMap>(load_map_spec("rooms:w=200,h=200,door=3,seed=1"));
  RunSpec s;
  s.map = kMap;
  s.strategy = configure_strategy(strategy, std::move(params));
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

// NOLINTBEGIN(readability-identifier-naming): Google Benchmark's BM_ names
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
// NOLINTEND(readability-identifier-naming)

BENCHMARK(BM_ExploreRooms200_ClosestFrontier)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ExploreRooms200_EnergyAware)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ExploreRooms200_EnergyAwareBattery)->Unit(benchmark::kMillisecond);

/// The strategies of the large-map runs: closest frontier and the paper's free-space weights.
std::array<Item, 2> large_run_strategies() {
  return {Item{"closest_frontier", nullptr},
          Item{"energy_aware", {{"w1", 10}, {"w2", 0}, {"w3", 9}, {"w4", 20}}}};
}

/// Rappaport 2016's free space for battery range `range_m` (metres): 10 m cells, sensor 30 m,
/// travel-only energy, on the smallest odd square whose free half-width is range_m / 2 + 30 m +
/// one cell inside the map's frame of occupied cells, so that the border never cuts the reachable
/// disc or its sensor band (fsweep sim warns when it would: 1800 m needs 191x191 cells).
RunSpec rappaport_free_spec(const Item& strategy, double range_m) {
  constexpr double kCellM = 10.0;
  constexpr double kSensorM = 30.0;
  const int half = static_cast<int>(std::ceil((range_m / 2.0 + kSensorM) / kCellM)) + 2;  // + the frame
  const std::string side = std::to_string(2 * half + 1);
  RunSpec s;
  s.map = std::make_shared<const WorldMap>(load_map_spec("free:w=" + side + ",h=" + side + ",res=10"));
  s.strategy = configure_strategy(strategy.label, strategy.json);
  s.robot.sensor.range_m = kSensorM;
  s.robot.battery_capacity = range_m;
  return s;
}

/// The free-space weight search's run (see the file comment) with energy-aware weights `w`.
RunSpec weight_search_spec(const std::vector<double>& w) {
  static const auto kMap = std::make_shared<const WorldMap>(load_map_spec("free:w=71,h=71,res=10"));
  RunSpec s;
  s.map = kMap;
  s.strategy = configure_strategy("energy_aware", {{"w1", w[0]}, {"w2", w[1]}, {"w3", w[2]}, {"w4", w[3]}});
  s.robot.sensor.range_m = 30.0;
  s.robot.energy = energy_preset("distance");
  s.robot.battery_capacity = 600.0;
  s.sim.progress_step_m = 200.0;
  s.seed = 2016;
  return s;
}

/// {0, step, 2 step, ...} up to 250, four times.
WeightGrid weight_search_grid(int step) {
  std::vector<double> values;
  for (int v = 0; v <= 250; v += step) values.push_back(v);
  return WeightGrid({values, values, values, values});
}

/// The exact search over `grid` on one thread.
void exact_weight_search(benchmark::State& state, const WeightGrid& grid) {
  const RunSpec spec = weight_search_spec({10, 0, 9, 20});
  std::uint64_t behaviours = 0;
  for (auto _ : state) {
    behaviours = exact_search(std::span<const RunSpec>(&spec, 1), grid, 1, [](Behaviour&& b) {
                   benchmark::DoNotOptimize(b.vectors);
                 }).behaviours;
  }
  state.counters["behaviours"] = static_cast<double>(behaviours);
  state.counters["vectors"] = static_cast<double>(grid.size());
}

void BM_ExactWeightSearch(benchmark::State& state) {
  exact_weight_search(state, weight_search_grid(static_cast<int>(state.range(0))));
}

/// Every integer vector of a 16^4 box at step 1 around the step-25 search's best, (100, 25, 75,
/// 0): w1 in 96..111, w2 in 16..31, w3 in 64..79, w4 in 0..15.
WeightGrid box16_grid() {
  const auto from = [](int first) {
    std::vector<double> v;
    for (int i = first; i < first + 16; ++i) v.push_back(i);
    return v;
  };
  return WeightGrid({from(96), from(16), from(64), from(0)});
}

void BM_ExactWeightSearchBox16(benchmark::State& state) { exact_weight_search(state, box16_grid()); }

/// One simulate() per vector of `grid`.
void brute_weight_search(benchmark::State& state, const WeightGrid& grid) {
  for (auto _ : state) {
    grid.for_each_point(grid.everything(), [&](const std::array<int, WeightGrid::kMaxWeights>& at) {
      const RunResult r = simulate(weight_search_spec(grid.weights_at(at)));
      benchmark::DoNotOptimize(r.metrics.distance_m);
    });
  }
  state.counters["vectors"] = static_cast<double>(grid.size());
}
void BM_BruteWeightSearch(benchmark::State& state) {
  brute_weight_search(state, weight_search_grid(static_cast<int>(state.range(0))));
}
/// About 3 minutes: left out of the nightly set by its name.
void BM_BruteWeightSearchBox16Slow(benchmark::State& state) { brute_weight_search(state, box16_grid()); }
// NOLINTBEGIN(readability-identifier-naming): Google Benchmark's BM_ names
BENCHMARK(BM_ExactWeightSearch)
    ->ArgName("step")
    ->Arg(50)
    ->Arg(25)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK(BM_ExactWeightSearchBox16)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_BruteWeightSearchBox16Slow)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_BruteWeightSearch)->ArgName("step")->Arg(50)->Unit(benchmark::kMillisecond)->Iterations(1);
// NOLINTEND(readability-identifier-naming)

const bool kLargeRunsRegistered = [] {
  for (const Item& strategy : large_run_strategies()) {
    const std::string rooms = std::string("BM_ExploreRooms800/") + strategy.label;
    benchmark::RegisterBenchmark(rooms.c_str(),
                                 [strategy](benchmark::State& state) {
                                   static const auto kMap = std::make_shared<const WorldMap>(
                                       load_map_spec("rooms:w=800,h=800,seed=1"));
                                   RunSpec spec;
                                   spec.map = kMap;
                                   spec.strategy = configure_strategy(strategy.label, strategy.json);
                                   spec.robot.sensor.range_m = 10.0;
                                   run(state, spec);
                                 })
        ->Unit(benchmark::kMillisecond)
        ->Iterations(1);
    for (const double range_m : {1800.0, 3600.0, 9000.0}) {
      const std::string name =
          "BM_RappaportFree/r:" + std::to_string(static_cast<int>(range_m)) + "/" + strategy.label;
      benchmark::RegisterBenchmark(name.c_str(),
                                   [strategy, range_m](benchmark::State& state) {
                                     run(state, rappaport_free_spec(strategy, range_m));
                                   })
          ->Unit(benchmark::kMillisecond)
          ->Iterations(1);
    }
  }
  return true;
}();

}  // namespace
}  // namespace fsweep
