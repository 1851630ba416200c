#pragma once
/// @file report_page.hpp
/// report.html of `fsweep report DIR`: one self-contained page (html.hpp: inline styles, PNGs
/// as data: URIs, no script, no other file) about a sweep's result directory:
/// 1. what ran: manifest.json (sweep name and description, sweep file and hash, status, run
///    counts, shards, git revision, compiler, libraries, host, CPU, threads, times, throughput,
///    warnings), the rows of runs.csv by end reason, and the sweep's JSON;
/// 2. the ranking per map class (report_tables.hpp: rounded numbers with units, the columns that
///    name a row first, rows whose runs came out identical marked);
/// 3. the paired comparisons of the strategies against the baseline (report_tables.hpp), when the
///    sweep has two or more strategy labels;
/// 4. exact weight searches: search_best.csv;
/// 5. the figures of `fsweep plot` (tools/plot.py), then the trajectories of the shown runs
///    (result_dir.hpp), re-simulated, with whether the re-simulation reproduced the recorded
///    outcome;
/// 6. the files in full, folded: best.csv and summary.csv with every column, cells as the files
///    write them; columns that are equal in every row shown are listed once above their table;
/// 7. the commands that reproduce the directory and the page.
/// A contents list links every figure by its id (`<a class='figure-link' href='#ID'>`, each
/// figure `<figure id='ID'>`), so a reader (or a test) can tell which pictures the page claims.
/// Every text that comes from a file is escaped.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "report/paired.hpp"
#include "report/result_dir.hpp"

namespace fsweep {
inline namespace report {

/// One picture of the page.
struct PageImage {
  std::string id;       ///< the figure's anchor: letters, digits, '-' and '_' (unique on the page)
  std::string title;    ///< heading above it
  std::string caption;  ///< text under it
  std::string png;      ///< PNG file bytes
};

/// The figure of `fsweep plot`'s file `name` (tools/plot.py: progress.png, metrics.png,
/// heatmap_<wi>_<wj>.png, search<k>_<wa>_<wb>.png) with the PNG bytes `png`: its anchor, a title
/// and a caption saying what it shows.
[[nodiscard]] PageImage plot_image(const std::string& name, std::string png);

/// A shown run re-simulated (sweep/replay.hpp).
struct Replay {
  std::string png;           ///< its trajectory picture (sim/trajectory_image.hpp), PNG bytes
  std::string map;           ///< the map's label in the sweep
  std::size_t compared = 0;  ///< recorded outcome cells compared with the re-simulation
  /// "column: recorded 'X', re-simulated 'Y'" for each that differs.
  std::vector<std::string> differences;
};

/// A shown run and its re-simulation, or why there is none.
struct PageTrajectory {
  ShownRun run;
  std::optional<Replay> replay;
  std::string error;  ///< why it was not re-simulated (replay empty)
};

/// Everything report.html shows.
// NOLINTNEXTLINE(bugprone-exception-escape): false positive inside nlohmann::json's noexcept move
struct ReportPage {
  ResultDir result;
  std::vector<PageImage> plots;  ///< the figures of `fsweep plot`, in its order
  std::vector<PageTrajectory> trajectories;
  /// Why the page has no trajectories when it has none (e.g. `--no-trajectories`).
  std::string trajectories_note;
  /// The paired comparisons of the sweep's strategies, when it has two or more labels.
  std::optional<PairedTable> paired;
  /// Where paired's baseline came from ("the sweep's \"baseline\""), or why there is no comparison.
  std::string paired_note;
};

/// Shell command lines that reproduce `r` into `<dir>-rerun` (the sweep's `fsweep run`, per
/// shard and `fsweep merge` for a merged directory), check it against `dir` (`fsweep compare`)
/// and make this page (`fsweep report`), after a `git checkout` of the recorded revision.
/// Arguments are quoted for a POSIX shell where needed.
[[nodiscard]] std::vector<std::string> reproduce_commands(const ResultDir& r);

/// The generator the page names in its meta tag (html_page_start()).
inline constexpr char kReportGenerator[] = "fsweep report";

/// The page (file comment).
[[nodiscard]] std::string report_html(const ReportPage& page);

}  // namespace report
}  // namespace fsweep
