#pragma once
/// @file report_tables.hpp
/// The tables of report.html a person reads (report_page.hpp), numbers rounded for reading
/// (core/readable_number.hpp: 4 significant digits) with units in the headers; the files keep
/// full precision, and the page shows them too, folded.
/// - The ranking per map class: the configurations of each class in best.csv's order, named by the
///   columns that tell them apart (the strategy: its label, and the parameters that differ within
///   the label; then planner, robot and sim columns that differ, config_names.hpp), the config
///   columns equal in every row stated once above; per row its runs n (marked when fewer of them
///   differ: n_distinct), the objective's median with q05 and q95, the medians of the main
///   metrics, and how the runs ended when not every one completed.
/// - The paired comparisons (paired.hpp): per map class and variant, each strategy against the
///   baseline, metric by metric.

#include <string>

#include "report/paired.hpp"
#include "report/result_dir.hpp"

namespace fsweep {
inline namespace report {

/// The heading of a metric column for people: its name with words for underscores and without
/// its unit suffix, and its unit: "distance to final coverage (m)", "area per metre (m²/m)",
/// "energy (units)". `energy_unit` is the energy model's unit, for `energy`.
[[nodiscard]] std::string metric_title(const std::string& column, const std::string& energy_unit = {});

/// The ranking per map class (file comment): HTML, a table per class.
[[nodiscard]] std::string ranking_html(const ResultDir& r);

/// The offline optimum of a competitive sweep: per map instance and robot of `runs_csv`, the
/// bounds, their gap, the star optimum on free maps and how many runs have a ratio (with the
/// notes of those that do not). Empty when runs.csv has no optimum columns.
[[nodiscard]] std::string optimum_html(const std::string& runs_csv);

/// The paired comparisons of `table` (file comment): HTML, a table per map class and variant;
/// `baseline_from` says where the baseline came from ("the sweep's baseline").
[[nodiscard]] std::string paired_html(const PairedTable& table, const std::string& baseline_from);

}  // namespace report
}  // namespace fsweep
