#pragma once
/// @file runs_schema.hpp
/// The schema of runs.csv (a sweep's, sweep_runner.hpp) and run.csv (`fsweep sim`): the one
/// place that says which columns a run has and in what order (writer side), what each column
/// of a header is (reader side: aggregate, compare, merge, the runner's resume), how runs group
/// into configurations, and the ranking objectives of best.csv.
///
/// Column order of a sweep's runs.csv (sweep_runs_columns()): run_index, run_key, map_class,
/// strategy_label, the config columns of config_columns() over the sweep with seed last, the
/// metric columns of metric_columns(), then optimal_distance_m and competitive_ratio, then, in a
/// sweep with a competitive map (sweep_plan.hpp, "competitive"), kCompetitiveColumns.
///
/// A header is read by position, so that files of older and newer builds (other metrics, other
/// parameters) read alike (RunsHeader):
/// - identity: run_index, run_key (which run);
/// - instance: map, map.width, map.height, map.start and seed, pooled within a configuration: runs
///   on the maps of one map_class (generator seeds, a dataset's plans of any size) and their seeds
///   are repetitions of one configuration;
/// - config: every other column before seed;
/// - outcome: end_reason and end_detail (text);
/// - metric: every column after end_detail (after end_reason without it) but the note columns,
///   numbers; an empty or
///   `nan` cell has no value. Effort metrics are left out of exact comparisons: timings
///   (`*_time_s`, wall_time_s among them) measure the machine, search counters (`*_expansions`)
///   the engine's algorithms (a faster search settles fewer cells for the same run);
/// - other: a column between seed and end_reason (none today) and the note columns after
///   end_detail (is_note_column(): text saying why a metric is empty, competitive_note), not read.

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/csv_reader.hpp"
#include "sim/run_result.hpp"
#include "sim/run_spec.hpp"

namespace fsweep {
inline namespace report {

// ---- Column names the schema's rules refer to.

inline constexpr char kRunIndexColumn[] = "run_index";
inline constexpr char kRunKeyColumn[] = "run_key";
inline constexpr char kMapClassColumn[] = "map_class";
inline constexpr char kMapColumn[] = "map";
inline constexpr char kMapStartColumn[] = "map.start";
inline constexpr char kMapWidthColumn[] = "map.width";
inline constexpr char kMapHeightColumn[] = "map.height";
inline constexpr char kStrategyLabelColumn[] = "strategy_label";
inline constexpr char kPlannerColumn[] = "planner";
inline constexpr char kSeedColumn[] = "seed";
inline constexpr char kEndReasonColumn[] = "end_reason";
inline constexpr char kEndDetailColumn[] = "end_detail";
/// Metric columns only a sweep writes (sweep_runner.hpp), after metric_columns().
inline constexpr std::array<const char*, 2> kSweepMetricColumns{"optimal_distance_m", "competitive_ratio"};
/// The offline-optimum columns of a sweep with a competitive map (docs/results.md), after
/// kSweepMetricColumns: the certified bounds on the offline optimum of the run's map and robot
/// (optimum/optimum.hpp), whether they are equal, distance_to_final_coverage_m over each bound,
/// and the note saying why the ratios are empty (a note column: text, role Other).
inline constexpr std::array<const char*, 6> kCompetitiveColumns{
    "optimum_lower_m",       "optimum_upper_m",       "optimum_exact",
    "competitive_ratio_min", "competitive_ratio_max", "competitive_note"};
inline constexpr char kCompetitiveNoteColumn[] = "competitive_note";
/// competitive_note of a run whose map is not competitive (every competitive cell empty).
inline constexpr char kNotCompetitiveNote[] = "map not competitive";
/// progress.csv columns of one sample; a sweep's progress.csv starts with run_index, run_key.
inline constexpr std::array<const char*, 4> kProgressColumns{"distance_m", "explored_area_m2", "coverage",
                                                             "energy"};

// ---- Writer side.

/// (column, cell) pairs of one run, in column order.
using Columns = std::vector<std::pair<std::string, std::string>>;

/// Configuration columns: map (source, width, height, resolution_m, start), strategy and each
/// resolved strategy parameter (`strategy.w1`...), planner and its parameters, every robot and
/// sim parameter (`robot.sensor.range_m`...; `robot.dock` is "x;y", or "start" when it is
/// the map's start), seed.
[[nodiscard]] Columns config_columns(const RunSpec& spec);

/// Metric columns: end_reason, end_detail and every RunMetrics field, in declaration order.
[[nodiscard]] Columns metric_columns(const RunResult& result);

/// A sweep's runs.csv columns for `config_names` (the union of the sweep's config_columns()
/// names without seed, sweep_table.hpp), in the order of the file comment; kCompetitiveColumns
/// last when `competitive` (some map of the sweep is competitive).
[[nodiscard]] std::vector<std::string> sweep_runs_columns(const std::vector<std::string>& config_names,
                                                          bool competitive = false);

/// A sweep's progress.csv columns: run_index, run_key, then kProgressColumns.
[[nodiscard]] std::vector<std::string> sweep_progress_columns();

/// The kProgressColumns cells of one sample, joined by commas (no newline).
[[nodiscard]] std::string progress_cells(const ProgressSample& sample);

/// Writes a header line and one row per entry (all rows must have the same column names).
void write_csv(const std::string& path, const std::vector<Columns>& rows);

/// progress.csv of one run (`fsweep sim`): kProgressColumns, one row per sample.
void write_progress_csv(const std::string& path, const RunResult& result);

// ---- Reader side.

/// What a column of runs.csv holds (rules in the file comment).
enum class ColumnRole {
  Identity,  ///< run_index, run_key
  Instance,  ///< map, map.start, seed: pooled within a configuration
  Config,    ///< every other column before seed
  Outcome,   ///< end_reason, end_detail
  Metric,    ///< every column after end_detail but the note columns: numbers
  Other,     ///< between seed and end_reason, and the note columns: not read
};

/// True for the effort columns: timings (`*_time_s`, wall_time_s among them), which measure the
/// machine, and search counters (`*_expansions`), which measure the engine's algorithms.
[[nodiscard]] bool is_effort_column(std::string_view name);

/// True for the text columns among the metrics, which are not read as numbers (role Other):
/// competitive_note.
[[nodiscard]] bool is_note_column(std::string_view name);

/// True for the end reasons that count as a success: `complete` and `target_reached`.
[[nodiscard]] bool successful_end(std::string_view end_reason);

/// The columns of a runs.csv header, classified by the rules of the file comment.
class RunsHeader {
 public:
  /// Classifies `names`, the header of the file `path`. Throws ConfigError at `<path>:1`
  /// ("no column 'seed' in the header") when run_key, seed or end_reason is missing.
  RunsHeader(std::vector<std::string> names, const std::string& path);

  [[nodiscard]] const std::vector<std::string>& names() const { return names_; }
  [[nodiscard]] ColumnRole role(std::size_t column) const { return roles_[column]; }
  /// Index of column `name`, or -1.
  [[nodiscard]] int column(std::string_view name) const;
  [[nodiscard]] std::size_t run_key() const { return run_key_; }
  [[nodiscard]] std::size_t end_reason() const { return end_reason_; }
  /// Config columns, in file order.
  [[nodiscard]] const std::vector<std::size_t>& config() const { return config_; }
  /// Metric columns, in file order.
  [[nodiscard]] const std::vector<std::size_t>& metrics() const { return metrics_; }
  /// Columns two sweeps must agree on exactly: the outcome columns and the metrics that are
  /// not effort columns, in file order.
  [[nodiscard]] const std::vector<std::size_t>& quality() const { return quality_; }
  /// The names of `columns`.
  [[nodiscard]] std::vector<std::string> names_of(const std::vector<std::size_t>& columns) const;
  /// config_key() of a row over the config columns.
  [[nodiscard]] std::string config_key(const std::vector<std::string>& fields) const;

 private:
  std::vector<std::string> names_;
  std::vector<ColumnRole> roles_;
  std::size_t run_key_ = 0;
  std::size_t end_reason_ = 0;
  std::vector<std::size_t> config_;
  std::vector<std::size_t> metrics_;
  std::vector<std::size_t> quality_;
};

/// The value of a metric cell of the record `in` just read: nullopt when empty; NaN for `nan`
/// (no value either). Throws ConfigError at in.where() ("column 'energy': 'x' is not a
/// number") for anything else that is not a number.
[[nodiscard]] std::optional<double> metric_value(const std::string& text, const std::string& column,
                                                 const CsvReader& in);

// ---- Configuration keys.

/// Written after each value of a configuration key: the ASCII unit separator, which no CSV
/// text of these files holds.
inline constexpr char kKeySeparator = '\x1f';

/// The key of a configuration: the values of `columns` in `fields` (-1: an empty value), each
/// followed by kKeySeparator. Equal keys, equal configurations.
[[nodiscard]] std::string config_key(const std::vector<std::string>& fields, const std::vector<int>& columns);

/// The values of a config_key(), in order.
[[nodiscard]] std::vector<std::string> split_config_key(const std::string& key);

// ---- Ranking objectives of best.csv.

/// Which way a metric improves.
enum class Direction { Minimize, Maximize };

/// A ranking objective: its name (sweep file `output.objective`, `--objective`), the way it
/// improves, and the metric column it ranks by.
struct Objective {
  std::string_view name;
  Direction direction;
  std::string_view column;
  /// A run without a value (an empty cell) counts as the worst in rankings (best.csv): it never
  /// reached what the objective measures.
  bool missing_is_worst = false;
};

/// The objectives, the default first.
inline constexpr std::array<Objective, 4> kObjectives{{
    {"distance_to_final_coverage_m", Direction::Minimize, "distance_to_final_coverage_m"},
    {"area_per_metre", Direction::Maximize, "area_per_metre"},
    {"energy", Direction::Minimize, "energy"},
    // Needs sim.stop_at_coverage; a run that never reaches the target has none (ranked after).
    {"distance_to_coverage_target_m", Direction::Minimize, "distance_to_coverage_target_m", true},
}};

/// The objective called `name`, or nullptr.
[[nodiscard]] const Objective* find_objective(std::string_view name);

/// The objective called `name`; throws ConfigError at `where` ("unknown objective 'speed';
/// allowed: distance_to_final_coverage_m, area_per_metre, energy") for another name.
[[nodiscard]] const Objective& require_objective(std::string_view name, const std::string& where);

/// The objectives' names, in kObjectives order.
[[nodiscard]] std::vector<std::string> objective_names();

/// Which way a metric column improves, for comparisons that need a "better": larger is better for
/// the area and coverage metrics (area_per_metre, coverage, completeness, explored_area_m2,
/// known_area_m2), smaller for every other (distances, energy, times, counts of stops, turns,
/// decisions and failures, what is left unexplored, competitive_ratio).
[[nodiscard]] Direction metric_direction(std::string_view column);

/// The unit of a metric column, for headers people read: "m" (`*_m`), "m²" (`*_m2`), "s"
/// (`*_s`), "m²/m" (area_per_metre), "°" (turned_deg); "" for counts, shares and ratios (coverage,
/// completeness, competitive_ratio, stops, ...) and for `energy`, whose unit is the run's energy
/// model's (the robot.energy.unit column: m, units, Wh, ...).
[[nodiscard]] std::string_view metric_unit(std::string_view column);

}  // namespace report
}  // namespace fsweep
