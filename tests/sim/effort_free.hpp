#pragma once
/// @file effort_free.hpp
/// Run results with the fields that may differ between two computations of the same run
/// cleared, for tests that compare runs field by field.

#include <utility>

#include "sim/run_result.hpp"

namespace fsweep::test {

/// `r` with its wall-clock timings (the only fields a repeated run may change) zeroed.
inline RunResult without_timing(RunResult r) {
  r.metrics.planner_time_s = 0.0;
  r.metrics.decision_time_s = 0.0;
  r.metrics.wall_time_s = 0.0;
  r.metrics.segmentation_time_s = 0.0;
  return r;
}

/// `r` without its effort metrics (timings and search counters: the `*_time_s` and
/// `*_expansions` columns), which depend on how the decisions were computed, not on what they
/// were.
inline RunResult without_effort(RunResult r) {
  r = without_timing(std::move(r));
  r.metrics.planner_expansions = 0;
  return r;
}

}  // namespace fsweep::test
