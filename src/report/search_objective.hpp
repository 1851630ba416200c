#pragma once
/// @file search_objective.hpp
/// The exact weight search's objective over a class of instances and branch and bound's lower
/// bound of it, shared by the search (sweep/weight_search_runner.cpp) and the check of its
/// certificate (verify/certificate_check.hpp), so that both compute them alike, bit for bit.

#include <span>
#include <string_view>
#include <vector>

#include "report/runs_schema.hpp"
#include "sim/run_result.hpp"
#include "sim/simulation.hpp"

namespace fsweep {
inline namespace report {

/// A metric cell's number (NaN: empty, or not a number).
[[nodiscard]] double metric_number(std::string_view cell);

/// The value of metric column `column` of a run (NaN: none), as runs.csv's cell holds it.
[[nodiscard]] double metric_value(const RunResult& result, std::string_view column);

/// A behaviour's objective: the mean over its instances' runs, summed in instance order.
[[nodiscard]] double class_objective(std::span<const RunResult> results, const Objective& objective);

/// Branch and bound's admissible lower bound of class_objective() (signed: for a maximised
/// objective, of its negation) over the behaviours that continue `sims`. Both minimised
/// objectives only grow as a run goes on, so their values so far bound them, summed in the same
/// order (rounding is monotone):
/// - distance_to_final_coverage_m: the distance at the last reveal so far (the final coverage
///   is reached at a reveal no earlier than it);
/// - energy: the energy used so far (every step costs energy >= 0);
/// - distance_to_coverage_target_m: the distance so far plus the travel that can reveal the
///   cells still needed to reach the target (Simulation::coverage_target_bound_m()).
/// Nothing is known of area_per_metre: -infinity (no pruning).
[[nodiscard]] double class_lower_bound(std::span<const Simulation> sims, const Objective& objective);

}  // namespace report
}  // namespace fsweep
