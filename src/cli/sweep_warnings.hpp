#pragma once
/// @file sweep_warnings.hpp
/// Warnings about a valid sweep that will not measure what it seems to ask for, printed by the
/// commands that load one (expand, run, slurm) before anything runs.

#include <string>

#include "sweep/sweep_plan.hpp"

namespace fsweep::cli {

/// Prints "fsweep: warning: <file>: <line>" on stderr for every warning of `plan` (dataset plans
/// skipped by "on_bad_map": "skip", free maps that clip the free-space optimum:
/// sweep_table.hpp's sweep_warnings()).
void print_sweep_warnings(const SweepPlan& plan, const std::string& file);

}  // namespace fsweep::cli
