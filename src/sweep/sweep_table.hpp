#pragma once
/// @file sweep_table.hpp
/// The columns of a sweep's runs.csv and progress.csv (layout in sweep_runner.hpp), and one
/// run turned into its rows.

#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "report/runs_schema.hpp"
#include "sweep/optimum_table.hpp"
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
/// `run_index, run_key, map_class, strategy_label`, the union of config_columns(), in a sweep
/// with a free-space map `optimum_check` (kOptimumCheckColumn), seed, the metric columns,
/// `optimal_distance_m, competitive_ratio`, and in a sweep with a competitive map (SweepPlan::
/// competitive()) the offline optimum's kCompetitiveColumns (optimum_table.hpp).
///
/// The union is taken over one representative run per (strategy entry, planner, robot variant),
/// in that order: the config columns depend on those and not on the map, the parameter values or
/// the repetition, so the header costs a few decodes even for 10^9 runs. Order: the first
/// representative's columns; a column first seen later goes right after the column preceding it
/// in that representative's list (so one strategy's parameters stay together). Every parameter a
/// strategy entry gives has its column too, after the strategy's others (one recorded only away
/// from its default, ParamSpec::omitted_at_default, may be missing from the representative). A
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

  /// The offline optima run() reads for runs on competitive maps (prepared before the runs,
  /// OptimumTable::prepare()). A key it lacks (or without a table) is solved by run() itself, to
  /// the same value. Not thread-safe: set it before the runs.
  void use_optima(std::shared_ptr<const OptimumTable> optima) { optima_ = std::move(optima); }

  /// Simulates `run` (resolved by plan.run()) and formats its rows. Never throws for a failing
  /// run: an exception from the plugins or the simulation becomes an `error` row with the
  /// message as end_detail and the metric cells empty (the optimum's bounds stay, for a
  /// competitive map). Thread-safe (const).
  [[nodiscard]] RunRows run(const SweepPlan& plan, const SweepRun& run) const;

  /// The cells of `run`'s runs.csv row that do not depend on its simulation: run_index, run_key,
  /// map_class, strategy_label, its config columns and (in a sweep with a free-space map)
  /// optimum_check; the outcome and metric cells are empty. Throws std::runtime_error when the
  /// run has a config column outside the header (run() records that as an `error` row).
  [[nodiscard]] std::vector<std::string> describe(const SweepPlan& plan, const SweepRun& run) const;

 private:
  /// describe() into `fields` (the row's size), so that a throw leaves what was set before it.
  void fill_description(const SweepPlan& plan, const SweepRun& run, std::vector<std::string>& fields) const;

  /// kCompetitiveColumns of `run` into `fields` (a sweep with a competitive map only).
  void fill_competitive(const SweepPlan& plan, const SweepRun& run, const RunResult* result,
                        std::vector<std::string>& fields) const;

  std::vector<std::string> columns_;
  std::unordered_map<std::string, std::size_t> position_;
  bool competitive_ = false;
  std::shared_ptr<const OptimumTable> optima_;
};

/// Whether the star-pattern optimum d* (sim/competitive.hpp) applies to a run, and its value.
struct StarOptimum {
  enum class Status : std::uint8_t {
    /// Not a free-space competitive setting: another map, no battery limit, an energy model with
    /// stop or turn costs, or no travel cost or sensor range.
    NotApplicable,
    /// d* applies: the free map holds the disc the robot can reach and its sensor band.
    Ok,
    /// A free-space competitive setting on a map too small for it: the border cuts the disc of
    /// radius r/2 around the dock or its sensor band, so the robot explores less than d* assumes.
    Clipped,
  };
  Status status = Status::NotApplicable;
  /// d* in metres (Ok only; NaN otherwise).
  double optimum_m = std::numeric_limits<double>::quiet_NaN();
  /// Free cells beyond the dock along the map's axes before a blocked cell or the edge, the
  /// smallest of the four directions (free-space settings only).
  int half_width_cells = 0;
  /// The half-width d* needs: ceil((r/2 + r_s) / resolution) + 1 cells.
  int needed_cells = 0;

  /// The `optimum_check` cell: "" (not applicable), "ok", or "clipped: ..." with both widths.
  [[nodiscard]] std::string check_text() const;
};

/// The star-pattern optimum of a run of `spec` on `map`: it applies in free space (the `free`
/// generator), with a finite battery and an energy model that charges travel only (no stop or
/// turn costs); r = capacity / energy per metre of straight travel, r_s = sensor range. The map
/// must hold the disc of radius r/2 around the dock plus the sensor band and one cell:
/// half-width >= r/2 + r_s + 1 cell, else the run explores less than d* assumes (Clipped).
[[nodiscard]] StarOptimum star_optimum(const SweepMap& map, const RobotParams& robot);

/// The same for `world`, where `free_space` says whether it comes from the `free` generator
/// (`fsweep sim`, which has no SweepMap).
[[nodiscard]] StarOptimum star_optimum(const WorldMap& world, bool free_space, const RobotParams& robot);

/// The warning for a Clipped `check` of `world` (named `map_label`; `robot_label` empty when the
/// sweep has one robot variant): the map, the dock, both widths and what it costs.
[[nodiscard]] std::string clipped_free_space_warning(const std::string& map_label, const WorldMap& world,
                                                     const RobotParams& robot, const std::string& robot_label,
                                                     const StarOptimum& check);

/// star_optimum(map, spec.robot).optimum_m: d*, or NaN where it does not apply or the map clips it.
[[nodiscard]] double optimal_distance_m(const SweepMap& map, const RunSpec& spec);

/// The runs.csv config column that says whether each run's free-space optimum applies
/// (StarOptimum::check_text()); present only in sweeps with a free-space map.
inline constexpr char kOptimumCheckColumn[] = "optimum_check";

/// One line per (free-space map, robot variant) of `plan` whose map clips the disc the robot can
/// reach (StarOptimum::Clipped): the map, the robot, both widths and what it costs (no
/// optimal_distance_m or competitive_ratio). Empty when there is none.
[[nodiscard]] std::vector<std::string> clipped_free_space_warnings(const SweepPlan& plan);

/// Repetitions that cannot differ (identical_repetition_warnings()). A sweep's repetitions of a configuration
/// on one map instance differ only in their run seed, so they are distinct runs only when something in the
/// run draws from it: a sensor that misses cells (miss_probability > 0), a random start (`start=random`), a
/// seeded strategy (StrategyTraits::seeded, or `"target": "random"`), a seeded planner
/// (PlannerCapabilities::seeded: OMPL's) or a random stop cell (`sim.stop_at_cell: "random"`).
/// Without any, every repetition repeats the first run and summary.csv's n overstates the
/// evidence (its n_distinct says so after the runs; this says so before).

/// The configurations of `plan` (map class x strategy configuration x planner x robot, search
/// entries aside) that have nothing random, counted and named, with what to do instead, as
/// warning lines for sweep_warnings(); none when the sweep has one repetition or every
/// configuration draws from its seed.
[[nodiscard]] std::vector<std::string> identical_repetition_warnings(const SweepPlan& plan);

/// Every warning about `plan` that `expand`, `run` and `slurm` print and manifest.json keeps: one
/// line per relative path read from the working directory (SweepPlan::path_warnings()), one per
/// skipped dataset plan (SweepPlan::skipped_maps()), then clipped_free_space_warnings(), then
/// identical_repetition_warnings().
[[nodiscard]] std::vector<std::string> sweep_warnings(const SweepPlan& plan);

/// Index of the run at the given axis positions (repetition 0): the inverse of
/// SweepPlan::coordinates() for the header's representatives. Throws std::logic_error when the
/// plan's run order is not the documented one.
[[nodiscard]] std::uint64_t representative_run(const SweepPlan& plan, std::size_t strategy_entry,
                                               std::size_t planner, std::size_t robot);

}  // namespace sweep
}  // namespace fsweep
