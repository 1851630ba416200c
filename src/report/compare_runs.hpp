#pragma once
/// @file compare_runs.hpp
/// The tables `fsweep compare` (compare.hpp) reads: runs.csv grouped into configurations
/// (columns and keys as runs_schema.hpp defines them), and the box statistics of summary.csv.

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "report/compare.hpp"

namespace fsweep {
inline namespace report {

/// One directory's runs.csv, every cell kept as text.
struct RunsFile {
  std::string path;
  std::vector<std::string> header;
  std::vector<std::string> config_names;   ///< RunsHeader::config() names
  std::vector<std::string> quality_names;  ///< RunsHeader::quality() names
  std::vector<std::vector<std::string>> rows;
  std::unordered_map<std::string, std::size_t> row_of_key;  ///< run_key -> row
  std::size_t run_key = 0;                                  ///< column of run_key

  /// Index of column `name`, or -1.
  [[nodiscard]] int column(const std::string& name) const;
};

/// Reads `path`. Throws ConfigError at `<file>` when it is missing, at `<file>:<line>` for
/// malformed CSV (csv_reader.hpp), a metric cell that is not a number (metric_value()), or a
/// run_key seen twice; a file without run_key, seed or end_reason columns is an error too.
[[nodiscard]] RunsFile read_runs_file(const std::string& path);

/// Configurations of one side, keyed by runs_schema.hpp's config_key() over chosen columns.
struct Grouping {
  std::vector<std::string> keys;                         ///< in order of first appearance
  std::map<std::string, std::vector<std::size_t>> rows;  ///< key -> row indices, file order
};

/// Indices in `t` of the columns `names` (-1 where missing).
[[nodiscard]] std::vector<int> columns_of(const RunsFile& t, const std::vector<std::string>& names);

/// The rows of `t` grouped by config_key() over `columns`.
[[nodiscard]] Grouping group(const RunsFile& t, const std::vector<int>& columns);

/// The numbers of column `name` over `rows` (empty and NaN cells skipped), sorted ascending;
/// empty when the column is missing.
[[nodiscard]] std::vector<double> sorted_values(const RunsFile& t, const std::vector<std::size_t>& rows,
                                                const std::string& name);

/// One-sided Mann-Whitney (Wilcoxon rank-sum) p-value for "values of `b` tend to be larger
/// than values of `a`": U = #{(x, y) in a x b : y > x} + #{ties} / 2, compared with its null
/// distribution by the normal approximation with tie correction and continuity correction,
/// p = 1 - Phi((U - n_a n_b / 2 - 1/2) / sd). 1 when either sample is empty or every value
/// is tied. Good from about 8 values a side, which is why compare needs min_quantile_runs.
[[nodiscard]] double mann_whitney_greater_p(const std::vector<double>& a, const std::vector<double>& b);

/// Share in [0, 1] of `rows` whose end_reason is a success (runs_schema.hpp's
/// successful_end(); 0 for none).
[[nodiscard]] double success_share(const RunsFile& t, const std::vector<std::size_t>& rows);

/// Two cells are equal: both numbers (parse_number) with equal doubles, NaN equal to NaN, or
/// equal texts.
[[nodiscard]] bool cells_equal(const std::string& a, const std::string& b);

/// summary.csv at `path`: per configuration (config_key() over the columns `key_names`), the
/// q05, q25, median, q75, q95 of each of `metrics` (nullopt where a cell is empty or missing).
/// Empty when the file does not exist; throws ConfigError for malformed CSV.
[[nodiscard]] std::map<std::string, std::vector<std::optional<BoxStats>>> read_boxes(
    const std::string& path, const std::vector<std::string>& key_names,
    const std::vector<std::string>& metrics);

/// Positions in `key_names` of the columns that label configurations (`values`: each
/// configuration's key values): map_class, strategy_label and planner where present, then, in
/// column order, each column that tells apart configurations the columns so far do not.
[[nodiscard]] std::vector<std::size_t> label_positions(const std::vector<std::string>& key_names,
                                                       const std::vector<std::vector<std::string>>& values);

}  // namespace report
}  // namespace fsweep
