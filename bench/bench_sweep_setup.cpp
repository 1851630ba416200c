/// @file bench_sweep_setup.cpp
/// Setting up a sweep of many strategy entries, before its first run.
///
/// - `BM_SweepSetup/entries:<n>`: a sweep file's text of n energy_aware entries of one weight
///   vector each (distinct vectors, a label each, one 6x6 free map) read by
///   parse_sweep_json(), SweepPlan::from_json() (every entry validated, the entries checked
///   for shared configurations) and SweepTable's construction (the runs.csv columns). Goal:
///   100,000 entries in under 2 s (linear in n: the list's parse, the overlap check by hashes
///   and each entry's first run found by its offset). `BM_SweepSetupParse/with_plan:<0|1>`:
///   the 100,000 entries' parse alone, and with the plan.

#include <benchmark/benchmark.h>

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "sweep/sweep_json_reader.hpp"
#include "sweep/sweep_plan.hpp"
#include "sweep/sweep_table.hpp"

namespace fsweep {
namespace {

/// The text of a sweep of `n` single-vector energy_aware entries.
std::string many_entries(std::int64_t n) {
  nlohmann::json entries = nlohmann::json::array();
  for (std::int64_t i = 0; i < n; ++i) {
    entries.push_back(
        {{"name", "energy_aware"},
         {"label", "e" + std::to_string(i)},
         {"params", {{"w1", i % 251}, {"w2", (i / 251) % 251}, {"w3", (i / 63001) % 251}, {"w4", 7}}}});
  }
  const nlohmann::json sweep = {{"schema_version", 1},
                                {"name", "many"},
                                {"maps", {"free:w=6,h=6"}},
                                {"strategies", entries},
                                {"robot", {{"sensor", {{"range_m", 3}}}}}};
  return sweep.dump();
}

void BM_SweepSetup(benchmark::State& state) {
  const std::string text = many_entries(state.range(0));
  for (auto _ : state) {
    const SweepJson parsed = parse_sweep_json(text, "many.json");
    const SweepPlan plan = SweepPlan::from_json(parsed.value, "many.json");
    const SweepTable table(plan);
    benchmark::DoNotOptimize(&table);
  }
  state.counters["entries"] = static_cast<double>(state.range(0));
}
BENCHMARK(BM_SweepSetup)
    ->ArgName("entries")
    ->Arg(1000)
    ->Arg(10000)
    ->Arg(100000)
    ->Unit(benchmark::kMillisecond);

/// The parse alone, and the parse with the plan (no SweepTable), of 100,000 entries.
void BM_SweepSetupParse(benchmark::State& state) {
  const std::string text = many_entries(100000);
  for (auto _ : state) {
    const SweepJson parsed = parse_sweep_json(text, "many.json");
    if (state.range(0) == 0) {
      benchmark::DoNotOptimize(&parsed);
      continue;
    }
    const SweepPlan plan = SweepPlan::from_json(parsed.value, "many.json");
    benchmark::DoNotOptimize(&plan);
  }
}
BENCHMARK(BM_SweepSetupParse)->ArgName("with_plan")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace fsweep
