#pragma once
/// @file sqlite_export.hpp
/// A result directory's runs.csv and progress.csv (layout in sweep/sweep_runner.hpp) as one
/// SQLite database, for queries in SQL (`fsweep export-sqlite DIR`, `fsweep run --sqlite`). The
/// CSVs stay the primary output: the database is made from them and can be made again.
///
/// Schema (PRAGMA application_id kSqliteApplicationId, PRAGMA user_version kSqliteSchemaVersion):
/// - `runs`: one row per runs.csv row, in file order: `config_id` (the row's configuration),
///   then every runs.csv column under its own name, in file order (names with a dot are quoted
///   in SQL: "strategy.w1").
/// - `configurations`: `config_id INTEGER PRIMARY KEY`, then runs.csv's config columns
///   (RunsHeader::config(): map_class, strategy_label, map.width, strategy.*, planner.*, robot.*,
///   sim.*, ...): one row per configuration, numbered from 0 by first appearance, as summary.csv's
///   config_id (runs of one configuration differ only in map, map.start and seed).
/// - `progress`: progress.csv's columns (run_index, run_key, distance_m, explored_area_m2,
///   coverage, energy), one row per sample in file order; joined to runs by run_key. Rows of
///   runs without a runs.csv row (a torn write) are left out, as aggregate.hpp does.
/// - `columns`: `name TEXT, position INTEGER, role TEXT, type TEXT`: every runs.csv column, its
///   position (from 0), its role in runs_schema.hpp (identity, instance, config, outcome, metric,
///   other) and its SQL type.
/// - `manifest`: `json TEXT`, manifest.json's text (one row; none without a manifest).
///
/// Types: run_index INTEGER; metric columns REAL (runs_schema.hpp: numbers; counts such as
/// turns too, so that a ratio of two columns never divides integers); config columns REAL when
/// every non-empty cell is a number (and one is not empty), else TEXT; every other column TEXT:
/// run_key, map, map.start, end_reason, end_detail and seed (an unsigned 64-bit number, beyond
/// SQLite's signed INTEGER). progress: run_index INTEGER, run_key TEXT, the samples REAL. An empty
/// cell is NULL, and so is `nan` in a REAL column; a number reads back as the same double.
///
/// Writing: the database is built in a temp file beside the output and renamed over it, so a
/// reader never sees half a database. An existing output is replaced only when it is a database
/// of this export (its application_id); anything else there is left alone (ConfigError).
///
/// Errors (ConfigError, one line naming the file): `dir` missing or not a directory; no runs.csv
/// (not a result directory; a sharded run's results are in its shard-i-of-n/ directories until
/// `fsweep merge`); no progress.csv; a damaged CSV (wrong field count, unclosed quote, torn last
/// line, a metric that is not a number, a header without run_key, seed or end_reason, a run_key
/// twice), at `<file>:<line>`; an output that is not this export's database; SQLite's errors.

#include <cstdint>
#include <string>

namespace fsweep {
inline namespace report {

/// PRAGMA application_id of an export: "FSWQ".
inline constexpr std::int32_t kSqliteApplicationId = 0x46535751;
/// PRAGMA user_version: the schema of the file comment.
inline constexpr int kSqliteSchemaVersion = 1;
/// The default output, in the result directory.
inline constexpr char kSqliteFileName[] = "results.sqlite";

/// What an export wrote.
struct SqliteExport {
  std::string path;
  std::uint64_t runs = 0;
  std::uint64_t configurations = 0;
  std::uint64_t progress_rows = 0;
};

/// "PATH (N runs, C configurations, P progress rows)".
[[nodiscard]] std::string describe_export(const SqliteExport& e);

/// Writes the database of result directory `dir` to `out` (empty: `dir`/results.sqlite).
[[nodiscard]] SqliteExport export_sqlite(const std::string& dir, const std::string& out = {});

}  // namespace report
}  // namespace fsweep
