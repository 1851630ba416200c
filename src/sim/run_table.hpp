#pragma once
/// @file run_table.hpp
/// A run as CSV columns: its resolved configuration, then its metrics. The same columns are
/// used by `fsweep sim` (run.csv) and by the sweep engine (runs.csv).

#include <string>
#include <utility>
#include <vector>

#include "sim/run_result.hpp"
#include "sim/run_spec.hpp"

namespace fsweep {
inline namespace sim {

using Columns = std::vector<std::pair<std::string, std::string>>;

/// Configuration columns: map (source, width, height, resolution_m, start), strategy and each
/// resolved strategy parameter (`strategy.w1`...), planner and its parameters, every robot and
/// sim parameter (`robot.sensor.range_m`...; `robot.dock` is "x;y", or "start" when it is
/// the map's start), seed.
[[nodiscard]] Columns config_columns(const RunSpec& spec);

/// Metric columns: end_reason, end_detail and every RunMetrics field, in declaration order.
[[nodiscard]] Columns metric_columns(const RunResult& result);

/// Writes a header line and one row per entry (all rows must have the same column names).
void write_csv(const std::string& path, const std::vector<Columns>& rows);

/// progress.csv rows of one run: distance_m, explored_area_m2, coverage, energy.
void write_progress_csv(const std::string& path, const RunResult& result);

}  // namespace sim
}  // namespace fsweep
