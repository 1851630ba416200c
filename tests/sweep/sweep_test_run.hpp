#pragma once
/// @file sweep_test_run.hpp
/// Sweeps as the sweep tests run them: quiet, into one folder, 2 threads unless asked.

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "sweep/sweep_plan.hpp"
#include "sweep/sweep_runner.hpp"

namespace fsweep::testing {

[[nodiscard]] inline RunnerOptions quiet_runner(const std::string& out_dir, int threads = 2) {
  RunnerOptions o;
  o.threads = threads;
  o.out_dir = out_dir;
  o.progress = false;
  return o;
}

/// Shard `index` of `count` of `sweep` (a sweep file's JSON, named test.json) into `dir`, quietly
/// on 2 threads.
inline RunnerReport run_test_shard(const nlohmann::json& sweep, const std::string& dir, std::uint64_t index,
                                   std::uint64_t count) {
  RunnerOptions o = quiet_runner(dir);
  o.shard_index = index;
  o.shard_count = count;
  return run_sweep(SweepPlan::from_json(sweep, "test.json"), o);
}

}  // namespace fsweep::testing
