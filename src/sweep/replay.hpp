#pragma once
/// @file replay.hpp
/// Re-simulates a run a result directory recorded (result_dir.hpp's ShownRun) from the sweep's
/// plan, for its trajectory picture: runs are pure functions of their configuration and seed,
/// so the run of the same index (or, for an exact weight search's behaviour, the search's
/// instance with the behaviour's weights) is the recorded one, which the recorded outcome
/// confirms cell by cell.

#include "report/report_page.hpp"
#include "sweep/sweep_plan.hpp"

namespace fsweep {
inline namespace sweep {

/// Re-simulates `run` of `plan`: its trajectory picture, and its outcome compared with the
/// recorded one by column name. Throws ConfigError when the plan has no such run: the run index
/// is past the sweep's runs, its run key differs from the recorded one (the sweep is not the one
/// that ran), or the search id or weights do not fit the plan's searches.
[[nodiscard]] Replay replay(const SweepPlan& plan, const ShownRun& run);

}  // namespace sweep
}  // namespace fsweep
