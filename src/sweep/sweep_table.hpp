#pragma once
/// @file sweep_table.hpp
/// The columns of a sweep's runs.csv and progress.csv (layout in sweep_runner.hpp), and one
/// run turned into its rows.

#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "report/runs_schema.hpp"
#include "sweep/sweep_plan.hpp"

namespace fsweep {
inline namespace sweep {

/// One run's output, formatted.
struct RunRows {
  /// The runs.csv record, with its newline.
  std::string run_row;
  /// The run's progress.csv records (zero or more), each with its newline.
  std::string progress_rows;
  /// The run ended with EndReason::Error (or threw).
  bool failed = false;
};

/// runs.csv columns of one sweep, in runs_schema.hpp's order (sweep_runs_columns()):
/// `run_index, run_key, map_class, strategy_label`, the union of config_columns() (seed last),
/// the metric columns, `optimal_distance_m, competitive_ratio`.
///
/// The union is taken over one representative run per (strategy entry, planner, robot variant),
/// in that order: the config columns depend on those and not on the map, the parameter values or
/// the repetition, so the header costs a few decodes even for 10^9 runs. Order: the first
/// representative's columns; a column first seen later goes right after the column preceding it
/// in that representative's list (so one strategy's parameters stay together). A
/// run whose configuration has a column outside the union (a strategy parameter whose nested
/// keys change with its value) is recorded as an `error` row saying so.
class SweepTable {
 public:
  explicit SweepTable(const SweepPlan& plan);

  [[nodiscard]] const std::vector<std::string>& columns() const { return columns_; }
  /// The runs.csv header line (no newline).
  [[nodiscard]] std::string header() const;
  /// The progress.csv header line (no newline).
  [[nodiscard]] static std::string progress_header();
  /// Number of progress.csv fields (sweep_progress_columns()).
  static constexpr std::size_t kProgressFields = 2 + kProgressColumns.size();
  /// Position of a progress.csv column; throws std::out_of_range for an unknown name.
  [[nodiscard]] static std::size_t progress_column(std::string_view name);
  /// Position of a runs.csv column; throws std::out_of_range for an unknown name.
  [[nodiscard]] std::size_t column(std::string_view name) const;

  /// Simulates `run` (resolved by plan.run()) and formats its rows. Never throws for a failing
  /// run: an exception from the plugins or the simulation becomes an `error` row with the
  /// message as end_detail and the metric cells empty. Thread-safe (const).
  [[nodiscard]] RunRows run(const SweepPlan& plan, const SweepRun& run) const;

 private:
  std::vector<std::string> columns_;
  std::unordered_map<std::string, std::size_t> position_;
};

/// The star-pattern optimum d* (sim/competitive.hpp) of a run of `spec` on `map`, or NaN where
/// it does not apply: free space, a finite battery, an energy model that charges travel only
/// (no stop or turn costs), and the whole disc of radius r/2 around the dock inside the free
/// part of the map; r = capacity / energy per metre of straight travel, r_s = sensor range.
[[nodiscard]] double optimal_distance_m(const SweepMap& map, const RunSpec& spec);

/// Index of the run at the given axis positions (repetition 0): the inverse of
/// SweepPlan::coordinates() for the header's representatives. Throws std::logic_error when the
/// plan's run order is not the documented one.
[[nodiscard]] std::uint64_t representative_run(const SweepPlan& plan, std::size_t strategy_entry,
                                               std::size_t planner, std::size_t robot);

}  // namespace sweep
}  // namespace fsweep
