#pragma once
/// @file result_dir.hpp
/// A sweep's result directory (sweep_runner.hpp's layout), read for `fsweep report`: the
/// manifest, the run count, the first rows of best.csv, summary.csv and search_best.csv, and
/// the runs whose trajectories the page shows.
///
/// Shown runs (ShownRun), each re-simulated later from its recorded configuration (runs are
/// pure functions of their configuration and seed):
/// - sweep runs: the first run (lowest run_index) of the best configuration of best.csv (rank
///   1) and of the worst (its last row), the one configuration's first run when they are the
///   same. A configuration's runs are found as aggregate.hpp numbers configurations: config_id
///   k is the k-th distinct config key of runs.csv in file order; the run's config cells must
///   equal best.csv's row (else ConfigError: best.csv does not belong to runs.csv).
/// - exact weight searches (behaviours.csv): per search (at most kShownSearches), its best
///   behaviour (rank 1 of search_best.csv) and its worst (last row, when another behaviour),
///   as instance 0 of the search with the behaviour's representative weight vector.

#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "report/runs_schema.hpp"

namespace fsweep {
inline namespace report {

/// Searches whose behaviours the page shows at most.
inline constexpr std::size_t kShownSearches = 4;

/// The header and first rows of a CSV file, cells as written.
struct CsvExcerpt {
  std::string path;
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;  ///< the first rows, at most the limit asked for
  std::vector<std::string> last_row;           ///< the file's last row (empty without rows)
  std::size_t total_rows = 0;                  ///< every row of the file
};

/// The header and the first `max_rows` rows of `path`, counting the others. Throws ConfigError
/// at `<file>:<line>` for malformed CSV (csv_reader.hpp), naming the file when it is missing.
[[nodiscard]] CsvExcerpt read_csv_excerpt(const std::string& path, std::size_t max_rows);

/// A run the page shows as a trajectory: a sweep run, or instance 0 of a behaviour of an exact
/// weight search.
struct ShownRun {
  std::string role;  ///< why it is shown, e.g. "best configuration (rank 1 of 4): its first run"
  /// A sweep run: its run_index and run_key in runs.csv.
  std::optional<std::uint64_t> run_index;
  std::string run_key;
  /// A behaviour: its search (the search_id: the index into SweepPlan::search_units()), its id
  /// and representative weight vector (in the search's weight order).
  std::optional<std::size_t> search_id;
  std::string behaviour_id;
  std::vector<double> weights;
  /// The recorded outcome: end_reason, end_detail and the metrics but the effort metrics, as
  /// runs.csv (or behaviours.csv) holds them.
  Columns recorded;
};

/// One map class's configurations in best.csv's order (its objective's ranking): their summary.csv
/// rows, the first `max_rows` of them, with each one's rank within the class.
struct ClassRanking {
  std::string map_class;
  std::vector<std::size_t> ranks;              ///< from 1, within the class
  std::vector<std::vector<std::string>> rows;  ///< summary.csv rows (ResultDir::summary.header)
  std::size_t total = 0;                       ///< configurations of the class
};

/// What `fsweep report` shows of a result directory.
// NOLINTNEXTLINE(bugprone-exception-escape): false positive inside nlohmann::json's noexcept move
struct ResultDir {
  std::string dir;
  nlohmann::json manifest;  ///< manifest.json
  std::uint64_t runs = 0;   ///< rows of runs.csv
  /// Rows of runs.csv by end_reason, in the order of first appearance.
  std::vector<std::pair<std::string, std::uint64_t>> end_reasons;
  CsvExcerpt best;                        ///< best.csv
  CsvExcerpt summary;                     ///< summary.csv
  std::vector<ClassRanking> rankings;     ///< per map class, by first appearance in best.csv
  std::optional<CsvExcerpt> search_best;  ///< search_best.csv of exact weight searches
  std::vector<ShownRun> shown;            ///< sweep runs first, then behaviours
  std::vector<std::string> notes;         ///< e.g. "summary.csv was older than runs.csv: aggregated it"
};

/// Reads `dir`. A directory whose summary.csv, progress_summary.csv or best.csv is missing, or
/// whose summary.csv is older than runs.csv, is aggregated first (aggregate.hpp, with the
/// manifest's objective; a note says so). Tables keep their first `max_rows` rows. Throws
/// ConfigError naming the file: `dir` is not a directory; manifest.json or runs.csv missing
/// ("not a sweep result directory", with a hint when `dir` holds shard directories to merge);
/// manifest.json not a JSON object with the sweep; malformed CSV.
[[nodiscard]] ResultDir read_result_dir(const std::string& dir, std::size_t max_rows);

}  // namespace report
}  // namespace fsweep
