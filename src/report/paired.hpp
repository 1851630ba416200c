#pragma once
/// @file paired.hpp
/// Paired comparisons of a sweep's strategies (`fsweep paired DIR`): every side against a
/// baseline, pair by pair, on the same map instance, robot, planner and run seed.
///
/// Sides and pairs:
/// - runs.csv (runs_schema.hpp): a side is a strategy configuration, told apart by the columns
///   strategy_label, strategy and strategy.*; it is named by its label, or, when one label holds
///   several configurations (a weight grid), by the label and the parameters that differ within
///   it ("EA w1=10 w3=9", the `strategy.` prefix left out). Runs are grouped by map_class and
///   the other config columns (planner, robot, sim: a variant; paired.csv shows those that
///   differ in the file), and within a group paired by the instance columns (map, map.start,
///   map.width, map.height, seed: the map instance and the repetition).
/// - Exact weight searches (behaviours.csv, search_ranks.csv, search_best.csv): per search, a
///   side is a weight vector of its `rank` list (`<label>@w1,w2,...`, its behaviour's runs) or
///   its optimum (`<label>@best`: rank 1 of search_best.csv); pairs are the search's instances.
///   A search's sides are compared with its own baseline: the one asked for when it is one of
///   them, else `<label>@best` (the paper's vector against the optimum, instance by instance).
///
/// Per group, metric and side (paired.csv, one row each):
/// - n_pairs: pairs in the statistics: both runs present, the same end_reason and a value of the
///   metric on both; unpaired: runs of either side without a partner; mixed_end: pairs whose
///   runs ended differently (e.g. complete and range_limited), counted and left out; no_value:
///   pairs with an empty, nan or infinite metric cell, left out; instances: map instances among
///   the pairs.
/// - d = side - baseline per pair: mean_diff, median_diff; rel_diff_pct: the median of
///   100 d / |baseline| (pairs with baseline 0 left out, unless both are 0: 0%).
/// - ci95_lo, ci95_hi: the cluster bootstrap interval of the mean difference
///   (paired_statistics.hpp: map instances resampled with their repetitions together), seeded
///   by the options' seed and the row's identity (independent of row order); empty with fewer
///   than 2 instances.
/// - wilcoxon_p and wilcoxon_method (exact, normal, none): the two-sided signed-rank test of the
///   d, where a pair within kTieRelative of equal counts as a zero difference; wilcoxon_p_holm:
///   Holm-adjusted over the sides of one group and metric.
/// - wins, ties, losses: the side better, equal within kTieRelative (|d| <= kTieRelative x
///   max(|side|, |baseline|)), worse, where better is metric_direction()'s way.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "report/paired_statistics.hpp"

namespace fsweep {
inline namespace report {

/// The metrics compared when none is asked for.
inline constexpr std::array<const char*, 3> kDefaultPairedMetrics{"distance_to_final_coverage_m", "energy",
                                                                  "area_per_metre"};

/// Two values within this relative distance of each other are a tie.
inline constexpr double kTieRelative = 1e-9;

/// What to compare and how.
struct PairedOptions {
  /// The side every other is compared with. Empty: the sweep's `"baseline"` (manifest.json's
  /// copy of the sweep file), else the first strategy entry's label (`<label>@best` for a search).
  std::string baseline;
  /// Metric columns; empty: kDefaultPairedMetrics (those the files have).
  std::vector<std::string> metrics;
  std::uint64_t resamples = 10000;  ///< bootstrap resamples per row
  std::uint64_t seed = 1;           ///< bootstrap seed
};

/// The bootstrap interval's confidence level (paired.csv's ci95_lo, ci95_hi).
inline constexpr double kPairedLevel = 0.95;

/// One comparison: a side against the baseline on one metric in one group.
struct PairedRow {
  std::string source;  ///< "runs" or "search <k>"
  std::string map_class;
  std::vector<std::string> variant;  ///< values of PairedTable::variant_columns ("" for searches)
  std::string side;
  std::string baseline;
  std::string metric;
  std::string unit;  ///< the metric's unit (metric_unit(); energy: the run's energy model's)
  std::size_t n_pairs = 0;
  std::size_t unpaired = 0;
  std::size_t mixed_end = 0;
  std::size_t no_value = 0;
  std::size_t instances = 0;
  double mean_diff = 0.0;     ///< NaN without pairs
  double median_diff = 0.0;   ///< NaN without pairs
  double rel_diff_pct = 0.0;  ///< NaN without a pair with a relative difference
  std::optional<Interval> ci;
  std::optional<SignedRankTest> wilcoxon;  ///< none without pairs
  std::optional<double> p_holm;
  std::size_t wins = 0;
  std::size_t ties = 0;
  std::size_t losses = 0;
};

/// A side of the comparison.
struct PairedSide {
  std::string name;    ///< as paired.csv names it
  std::string source;  ///< "runs" or "search <k>"
  std::string label;   ///< its strategy label
  /// The parameters that tell it apart (strategy.* columns, or a search's weight vector).
  std::vector<std::pair<std::string, std::string>> params;
};

/// Everything `fsweep paired` found and computed.
struct PairedTable {
  std::string dir;
  std::string baseline;                      ///< the runs' baseline side (empty without runs)
  std::vector<std::string> metrics;          ///< the metrics compared
  std::vector<std::string> variant_columns;  ///< runs.csv config columns besides the sides' that differ
  std::vector<PairedSide> sides;
  std::vector<PairedRow> rows;     ///< by source, group, metric, then side (the files' order)
  std::vector<std::string> notes;  ///< what could not be compared, and why
};

/// The comparison of the sweep result directory `dir` (file comment). Throws ConfigError naming
/// the file or option: `dir` without runs.csv; malformed files; an unknown metric (listing the
/// metric columns); a baseline that is no side (listing the sides; a label that holds several
/// configurations names them).
[[nodiscard]] PairedTable paired_comparison(const std::string& dir, const PairedOptions& options);

/// Writes `out_dir`/paired.csv (the rows; numbers at full precision, empty where there is no
/// value) and `out_dir`/paired.json (the options, the sides, the notes and the inputs' sizes),
/// each to a temp file renamed into place.
void write_paired(const std::string& out_dir, const PairedTable& table, const PairedOptions& options);

}  // namespace report
}  // namespace fsweep
