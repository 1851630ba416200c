#pragma once
/// @file csv_reader.hpp
/// A streaming RFC 4180 reader for the sweep's CSV files (runs.csv, progress.csv, summaries).
///
/// Fields are separated by commas; a field in double quotes may hold commas, newlines and
/// doubled quotes (`""` reads as `"`); records end with LF or CRLF. The first record is the
/// header, and every record must have as many fields as the header. Problems throw ConfigError
/// at `<file>:<line>` (the line where the offending record starts, 1-based).

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fsweep {
inline namespace core {

class CsvReader {
 public:
  /// Opens `path` and reads the header (empty for an empty file). With `require_final_newline`,
  /// a last record without a newline is an error (the runner's mark of a torn write).
  explicit CsvReader(const std::string& path, bool require_final_newline = true);

  /// Reads the next record into fields(); false at the end of the file.
  [[nodiscard]] bool next();

  [[nodiscard]] const std::vector<std::string>& header() const { return header_; }
  /// Fields of the record read by the last successful next().
  [[nodiscard]] const std::vector<std::string>& fields() const { return fields_; }
  /// 1-based line where the current record starts.
  [[nodiscard]] std::size_t line() const { return record_line_; }
  [[nodiscard]] const std::string& path() const { return path_; }
  /// "<file>:<line>" of the current record, for error messages.
  [[nodiscard]] std::string where() const;

  /// Index of header column `name`, or -1.
  [[nodiscard]] int column(const std::string& name) const;
  /// Index of header column `name`; throws ConfigError naming the file if it is missing.
  [[nodiscard]] std::size_t require_column(const std::string& name) const;

 private:
  /// Reads one record into `out`; false at the end of the file (no characters left).
  bool read_record(std::vector<std::string>& out);
  /// Next character, or -1 at the end of the file.
  int get();
  /// Next character without consuming it, or -1.
  int peek();

  std::string path_;
  bool require_final_newline_;
  std::ifstream in_;
  std::vector<char> buffer_;
  std::size_t pos_ = 0;
  std::size_t end_ = 0;
  std::size_t next_line_ = 1;  // line of the next character
  std::size_t record_line_ = 0;
  std::vector<std::string> header_;
  std::vector<std::string> fields_;
};

/// Parses a whole CSV cell as a number ("inf", "nan" and exponents allowed); nullopt if it is not
/// one (empty, trailing characters, ...).
[[nodiscard]] std::optional<double> parse_number(std::string_view text);

/// Parses a whole text as an unsigned 64-bit number in `base` (digits only: no sign, no space);
/// nullopt if it is not one (empty, trailing characters, out of range).
[[nodiscard]] std::optional<std::uint64_t> parse_unsigned(std::string_view text, int base = 10);

}  // namespace core
}  // namespace fsweep
