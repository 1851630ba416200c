#pragma once
/// @file aggregate.hpp
/// summary.csv, progress_summary.csv and best.csv from runs.csv and progress.csv
/// (sweep_runner.hpp gives the layout). Reads each input once, streaming; holds every metric
/// value of every configuration (n values per configuration and metric) and every progress
/// sample, as exact quantiles need them.
///
/// - Columns of runs.csv: config, instance and metric columns as runs_schema.hpp classifies
///   them (RunsHeader); metric cells are numbers (an empty or `nan` cell is skipped, anything
///   else that is not a number is an error; `inf` is a number).
/// - summary.csv: one row per configuration (runs with equal config columns, runs_schema.hpp's
///   config key; the instance columns `map`, `map.start` and `seed` are not part of it, so runs
///   on the maps of one `map_class` — e.g. the seeds of one generated map — are pooled like
///   repetitions), in order of first appearance in runs.csv, numbered by `config_id` from 0:
///   `config_id`, the config columns, `n` (runs), `n_distinct` (distinct runs: those that differ in
///   their map instance (map, map.start, map.width, map.height) or in their outcome (end_reason,
///   end_detail and every metric but the effort columns), so repetitions that came out identical,
///   having nothing random in them, count once; compared by a 64-bit hash), one count column per end reason
///   (`end.complete`, ... for every EndReason in declaration order, then any reason this build
///   does not know, by first appearance), then for every metric column M:
///   `M.mean, M.std, M.min, M.q05, M.q25, M.median, M.q75, M.q95, M.max`. Quantiles are
///   Hyndman-Fan type 7 (core/statistics.hpp's quantile_sorted, as numpy's default);
///   std is the sample standard deviation (n - 1; 0 for n = 1). Empty cells are skipped, so a
///   metric's statistics are over its non-empty cells (empty statistics where there are none,
///   e.g. competitive_ratio off free space; such columns are empty for a whole configuration
///   since map and robot are config columns, so `n` is also their count). Every run counts,
///   whatever its end reason (the end.* columns tell how many ended how).
/// - progress_summary.csv: per configuration and distance bin, `config_id, distance_m, n,
///   explored_area_m2.mean, explored_area_m2.q05, explored_area_m2.q50, explored_area_m2.q95`.
///   A run's progress samples are a grid (0, step, 2 step, ..., the same values for every run of
///   a configuration) and a last sample with its final state at its exact end distance. The
///   bins are the union of the grid samples (every sample but each run's last) and one closing
///   bin at the longest run's end distance (unless within 1e-9 m of the last grid bin). At a
///   bin, a run contributes its sample there, or, if it ended before the bin, its final explored
///   area (it explores no more), so every bin has all n runs (Rappaport 2016, Figure 4 bands),
///   and the closing bin is the distribution of final explored areas. n counts the runs with
///   progress rows and a runs.csv row (progress rows of runs without one, a torn write, are
///   ignored).
/// - best.csv: `rank` (from 1), `config_id`, `n`, `<objective>.median`, `<objective>.q05`,
///   `<objective>.q95`, the config columns; configurations ranked by the median of the
///   objective's column (runs_schema.hpp's kObjectives: ascending for distance and energy,
///   descending for area per metre; configurations without a value last; ties by config_id).
/// - Outputs are written to `<file>.tmp` and renamed, so a reader never sees half a file.
/// - Errors: a missing file, a row with a different number of fields than the header, an
///   unclosed quote, a last line without a newline (torn write), a non-numeric metric, a
///   run_key twice in runs.csv, a run's progress rows split or with decreasing distance: each
///   throws ConfigError at `<file>:<line>`; runs of one configuration sampled on different
///   distance grids throw ConfigError naming progress.csv.

#include <string>

namespace fsweep {
inline namespace report {

struct AggregateOptions {
  /// Objective for best.csv, a name of runs_schema.hpp's kObjectives
  /// ("distance_to_final_coverage_m", the default, "area_per_metre", "energy"). Empty = the
  /// manifest's `/sweep/output/objective` (the sweep file's), else its `/objective` (the
  /// runner's resolved one), else the default. Another name is a ConfigError listing these.
  std::string objective;
};

/// Reads `dir`/runs.csv and `dir`/progress.csv, writes summary.csv, progress_summary.csv and
/// best.csv. Throws ConfigError naming the file and line on malformed input.
void aggregate(const std::string& dir, const AggregateOptions& options);

}  // namespace report
}  // namespace fsweep
