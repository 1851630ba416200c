#pragma once
/// @file repetition_check.hpp
/// Repetitions that cannot differ. A sweep's repetitions of a configuration on one map instance
/// differ only in their run seed, so they are distinct runs only when something in the run draws
/// from it: a sensor that misses cells (miss_probability > 0), a random start (`start=random`), a
/// seeded strategy (StrategyTraits::seeded, or `"target": "random"`), a seeded planner
/// (PlannerCapabilities::seeded: OMPL's) or a random stop cell (`sim.stop_at_cell: "random"`).
/// Without any, every repetition repeats the first run and summary.csv's n overstates the
/// evidence (its n_distinct says so after the runs; this says so before).

#include <string>
#include <vector>

#include "sweep/sweep_plan.hpp"

namespace fsweep {
inline namespace sweep {

/// The configurations of `plan` (map class x strategy configuration x planner x robot, search
/// entries aside) that have nothing random, counted and named, with what to do instead, as
/// warning lines for sweep_warnings(); none when the sweep has one repetition or every
/// configuration draws from its seed.
[[nodiscard]] std::vector<std::string> identical_repetition_warnings(const SweepPlan& plan);

}  // namespace sweep
}  // namespace fsweep
