#pragma once
/// @file compare.hpp
/// `fsweep compare NEW_DIR BASELINE_DIR`: does a sweep's output (sweep_runner.hpp layout, plus
/// optionally Google Benchmark's `bench.json` and `plots/*.png`) regress against a baseline?
///
/// Configurations are those of aggregate.hpp: runs with equal config columns (runs_schema.hpp;
/// the instance columns `map`, `map.start` and `seed` are pooled). A configuration is matched
/// across the two directories by the config key (runs_schema.hpp) over the config columns both
/// runs.csv files have (a column only one side has is named in a warning). Quality columns:
/// RunsHeader::quality() (end_reason, end_detail and the metrics except the timing columns
/// `*_time_s`, which include wall_time_s), of those both files have.
///
/// Checks:
/// 1. Reproducible configurations (src/planners/reproducibility.hpp, from `planner` and its
///    `planner.<param>` columns): every baseline run (by run_key) must be in NEW with every
///    quality cell equal: both cells numbers and the doubles equal (NaN equals NaN), or the
///    texts equal. Else the configuration is `changed` (one `run` check per differing cell).
/// 2. Other configurations: q25, median, q75 (core/statistics.hpp's quantile_sorted) of distance_m,
///    energy (lower is better) and coverage (higher is better) over the runs' non-empty cells.
///    A quantile is `regressed` when it is worse than the baseline's by more than
///    tolerance x max(|baseline|, scale), scale = 1 m, 1 energy unit, 0.01 coverage (so a zero
///    baseline still has a band), and the one-sided Mann-Whitney test of the metric's runs
///    (compare_runs.hpp) gives p < significance for "NEW is worse"; `improved` likewise in the
///    other direction; else `within tolerance`. The configuration is also regressed when its
///    share of successful runs (end_reason `complete` or `target_reached`) drops with the same
///    test on the 0/1 outcomes significant. With fewer than min_quantile_runs runs on either side the
///    configuration is `not judged` (one `runs` check): quantiles of a few runs are noise.
/// 3. Baseline runs (by run_key) missing in NEW make their configuration `incomplete`, a
///    configuration of the baseline not in NEW is `missing`; both are failures. A configuration
///    only in NEW is `new` (not a failure). Different manifest sweep hashes are a warning.
/// 4. Speed, as time ratios new / baseline (> 1 = slower): the sweep's seconds per run (manifest
///    `wall_s / runs.ran`; not judged for a manifest merged from shards, or when the baseline's
///    wall_s is below CompareOptions::min_judged_sweep_wall_s), each configuration's
///    median wall_time_s (informational, never a failure: a run's wall time depends on what
///    runs beside it; `not judged` when the baseline median is below
///    CompareOptions::min_judged_wall_time_s), and each
///    micro-benchmark of bench.json (median aggregate's real_time, else the mean of the
///    iteration rows' real_time; by run_name) when both directories have one. Ratio
///    > 1 + speed_tolerance is `slower`, < 1 / (1 + speed_tolerance) `faster`. Slower is a
///    failure only on the same machine (manifest host and cpu_model, bench.json host_name,
///    num_cpus and mhz_per_cpu equal where both sides have them; the sweep throughput also
///    needs equal `threads`) or with `strict_speed`; otherwise it is informational.
///
/// Errors (ConfigError naming the file, and the line for CSV files): a missing directory,
/// runs.csv or manifest.json; malformed CSV (csv_reader.hpp), a non-numeric metric cell, a
/// run_key twice; malformed JSON; a bench.json entry without name or real_time, or with an
/// unknown time_unit; negative tolerances.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace fsweep {
inline namespace report {

/// Tolerances and rules of a comparison.
struct CompareOptions {
  /// Relative quality tolerance for non-reproducible configurations (>= 0).
  double quality_tolerance = 0.10;
  /// Speed tolerance: slower means a time ratio above 1 + this (>= 0). 0.5 because shared CI
  /// machines are noisy: 1.5x is far beyond their run-to-run spread, a real slowdown is not.
  double speed_tolerance = 0.5;
  /// Slower is a failure even on a different machine.
  bool strict_speed = false;
  /// Non-reproducible configurations with fewer runs than this on either side are not judged
  /// by quantiles (their quantiles are noise); >= 1.
  std::size_t min_quantile_runs = 8;
  /// A shift beyond the tolerance counts (regressed or improved) only when a one-sided
  /// Mann-Whitney test over the runs rejects "no shift" at this level, in (0, 1): noise of
  /// a varying planner is not flagged.
  double significance = 0.01;
  /// Configurations whose baseline median wall_time_s is below this (seconds) are not judged
  /// on speed: timings of tiny runs are mostly noise.
  double min_judged_wall_time_s = 0.05;
  /// The sweep's throughput is not judged when the baseline sweep's wall time is below this
  /// (seconds): a sweep of a few seconds times mostly the process start and the machine's load.
  double min_judged_sweep_wall_s = 10.0;
  /// At most this many differing runs are listed (as `run` checks) per configuration; the
  /// rest are counted.
  std::size_t listed_runs_per_config = 5;
};

/// Outcome of one check.
enum class CheckStatus {
  Match,            ///< reproducible configuration, every run equal
  Changed,          ///< reproducible run or configuration differs (failure)
  WithinTolerance,  ///< difference within the tolerance
  Regressed,        ///< worse beyond the tolerance (failure)
  Improved,         ///< better beyond the tolerance
  Missing,          ///< in the baseline, not in NEW (failure)
  Incomplete,       ///< configuration with baseline runs missing in NEW (failure)
  New,              ///< only in NEW
  Slower,           ///< time ratio above 1 + speed tolerance (failure on the same machine)
  Faster,           ///< time ratio below 1 / (1 + speed tolerance)
  NotJudged,        ///< too short to time reliably, or a value missing on a side
};

/// "match", "changed", "within tolerance", "regressed", "improved", "missing", "incomplete",
/// "new", "slower", "faster", "not judged".
[[nodiscard]] std::string to_string(CheckStatus status);

/// One row of compare.csv.
struct CompareCheck {
  std::string kind;             ///< "run", "config", "speed" or "bench"
  std::string name;             ///< configuration label (run checks: label and run_key), benchmark, "sweep"
  std::string metric;           ///< e.g. "distance_m", "distance_m.q25", "wall_time_s.median", "real_time_ns"
  std::string baseline;         ///< baseline value as text (empty when absent)
  std::string current;          ///< NEW value as text (empty when absent)
  std::optional<double> delta;  ///< current - baseline (quality checks)
  std::optional<double> ratio;  ///< current / baseline time (speed and bench checks)
  std::optional<double> tolerance;  ///< absolute band (quality) or relative tolerance (speed)
  /// Quantile and success checks: one-sided Mann-Whitney p-value that NEW is worse.
  std::optional<double> p_value;
  CheckStatus status = CheckStatus::Match;
  bool failure = false;  ///< counts as a regression
};

/// Five quantiles of one metric of one configuration, from summary.csv.
struct BoxStats {
  double q05 = 0.0, q25 = 0.0, median = 0.0, q75 = 0.0, q95 = 0.0;
};

/// One configuration of either directory.
struct ConfigComparison {
  std::vector<std::string> label;  ///< values of CompareReport::label_columns
  std::string name;                ///< label joined with " | "
  bool reproducible = false;
  std::size_t baseline_runs = 0;
  std::size_t new_runs = 0;
  std::size_t changed_runs = 0;  ///< reproducible: runs with a differing quality cell
  CheckStatus status = CheckStatus::Match;
  bool failure = false;
  std::string worst;  ///< the worst difference, e.g. "distance_m.median +12.5%" (may be empty)
  /// Box statistics of CompareReport::box_metrics, baseline and NEW (nullopt when absent).
  std::vector<std::optional<BoxStats>> baseline_box, new_box;
};

/// Everything a comparison found.
struct CompareReport {
  std::string new_dir, baseline_dir;
  /// Config columns that tell the configurations apart (map_class, strategy_label, planner
  /// where present, then every other config column whose value varies).
  std::vector<std::string> label_columns;
  std::vector<ConfigComparison> configs;  ///< baseline order, then configurations only in NEW
  std::vector<CompareCheck> checks;       ///< every check, configurations first
  std::vector<std::string> box_metrics;   ///< "distance_m", "energy", "coverage"
  std::vector<std::string> warnings;      ///< sweep hash, machine, header differences
  std::vector<std::string> notes;         ///< e.g. "aggregated DIR first"
  bool sweep_hash_differs = false;
  bool same_machine = true;
  double speed_tolerance = 0.5;
  std::size_t regressions = 0;  ///< failing configurations plus failing speed and bench checks
};

/// Compares `new_dir` with `baseline_dir`. A directory whose summary.csv is missing or older than
/// its runs.csv is aggregated first (aggregate.hpp; writes its summary files), so the box plots
/// show the runs that were compared; without a progress.csv to aggregate, a warning instead (the
/// box plots of that side are left out or may be stale). Throws ConfigError on bad input (file
/// comment).
[[nodiscard]] CompareReport compare_dirs(const std::string& new_dir, const std::string& baseline_dir,
                                         const CompareOptions& options);

/// The readable report: warnings, one line per configuration (label columns, status, worst
/// difference), the differing runs, speed lines, and "compare: N regressions" or
/// "compare: no regressions".
[[nodiscard]] std::string format_compare_table(const CompareReport& report);

/// compare.csv: header `kind,name,metric,baseline,new,delta,ratio,tolerance,p_value,status,failure`,
/// one row per check.
[[nodiscard]] std::string compare_csv(const CompareReport& report);

/// compare.html: a self-contained page (inline SVG, no scripts): box plots of each box metric
/// per configuration (baseline and NEW side by side), a bar chart of the speed ratios with the
/// tolerance band, the status table, and the PNGs of `<dir>/plots/` of both sides embedded as
/// base64 data URIs (so the page survives being copied alone, e.g. as a CI artifact).
[[nodiscard]] std::string compare_html(const CompareReport& report);

/// Writes compare.csv and compare.html into `out_dir` (created if missing), each through a temp
/// file and rename. Throws IoError naming the file when it cannot be written.
void write_compare_outputs(const CompareReport& report, const std::string& out_dir);

}  // namespace report
}  // namespace fsweep
