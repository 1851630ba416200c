#pragma once
/// @file csv_format.hpp
/// Writing CSV text: numbers as cells, quoting, records (RFC 4180). The reading side is
/// csv_reader.hpp; every result file (runs.csv, summaries, compare.csv, plan benchmarks)
/// formats its cells here, so a number reads back the same everywhere.

#include <string>
#include <vector>

namespace fsweep {
inline namespace core {

/// Shortest text that reads back to the same double (std::to_chars); "inf", "-inf" and "nan"
/// for the non-finite values.
[[nodiscard]] std::string format_number(double v);

/// A numeric cell in which NaN means "no value": empty for NaN, else format_number(v).
[[nodiscard]] std::string number_cell(double v);

/// Quotes a CSV field when it holds a comma, quote, CR or LF (a quote doubled inside).
[[nodiscard]] std::string csv_field(const std::string& s);

/// One CSV record: every field through csv_field(), joined by commas; no newline.
[[nodiscard]] std::string csv_record(const std::vector<std::string>& fields);

}  // namespace core
}  // namespace fsweep
