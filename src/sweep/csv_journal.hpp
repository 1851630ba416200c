#pragma once
/// @file csv_journal.hpp
/// An append-only CSV file that survives being killed at any moment (sweep_runner.hpp).
///
/// Writes go through an in-memory buffer that reaches the file only on flush(), as whole
/// write(2) calls (core/append_file.hpp), so the caller decides the order in which rows of several files
/// become visible (progress rows before the runs row that completes them). A process killed in the middle of
/// a write leaves at most one torn record at the end; repair() cuts it off.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/append_file.hpp"
#include "core/files.hpp"

namespace fsweep {
inline namespace sweep {

/// Lines repair() dropped for one reason: a record, or consecutive records with the same reason.
struct CsvDroppedLines {
  std::uint64_t first_line = 0;  ///< 1-based, the header is line 1
  std::uint64_t last_line = 0;   ///< last line of the last record (a quoted field may hold newlines)
  std::string reason;            ///< plain words: what was found and what was expected

  /// "<path>:<first>[-<last>]: <reason>", the line of a report on stderr.
  [[nodiscard]] std::string describe(const std::string& path) const;
};

/// What repair() found.
struct CsvRepairStats {
  std::uint64_t kept = 0;     ///< complete records kept (the header excluded)
  std::uint64_t dropped = 0;  ///< complete records dropped: malformed or rejected by the filter
  bool torn = false;          ///< a last record without its final newline was cut off
  bool rewritten = false;     ///< the file was rewritten (temp file and rename), not truncated
  /// Every dropped line with its reason, in file order (the torn last record included).
  std::vector<CsvDroppedLines> dropped_lines;
};

/// One CSV file with a fixed header line, appended to record by record.
class CsvJournal {
 public:
  /// Decides whether a complete, well-formed record (its fields, unquoted) stays: returns an
  /// empty string to keep it, else the reason it is dropped (plain words). Called once per
  /// record, in file order, so it may collect state.
  using RecordFilter = std::function<std::string(const std::vector<std::string>& fields)>;

  /// Opens `path` for a header `header` (one line, no newline). A missing file, or one without
  /// a complete first line, is (re)created holding just the header (temp file and rename).
  /// An existing file with a different header is refused with a ConfigError that names the
  /// file and says to start over with --fresh.
  CsvJournal(std::string path, std::string header);
  CsvJournal(const CsvJournal&) = delete;
  CsvJournal& operator=(const CsvJournal&) = delete;
  /// Flushes (errors ignored) and closes.
  ~CsvJournal();

  /// Reads every record after the header (RFC 4180: quoted fields may hold commas, quotes and
  /// newlines), keeps the complete, well-formed ones `keep` accepts, and cuts off a torn last
  /// record. Malformed records (what CsvReader refuses: a carriage return inside a line, a
  /// quote inside an unquoted field, text after a closing quote) are dropped without asking
  /// `keep`. A dropped record over several lines (a damaged row's unclosed quote swallows the
  /// rows after it) drops only its first line: the scan restarts on the next. When only a tail goes, the file
  /// is truncated; when a dropped record is followed by a kept one, the file is rewritten through a temp file
  /// and rename. `before_changes`, when given, runs after the scan and before the file is
  /// touched: if it throws, the file is left as it was. Call before the first append().
  CsvRepairStats repair(const RecordFilter& keep, const std::function<void()>& before_changes = {});

  /// How rewrite_in_order() changes the records it copies. Each part may be empty.
  struct Rewrite {
    /// A record's place in the new file (its fields, unquoted): its number, or nullopt to leave
    /// it out. Empty: the decimal number in the record's field `index_field`.
    std::function<std::optional<std::uint64_t>(const std::vector<std::string>& fields)> place;
    /// Sets a kept record's fields as the new file has them, given its number; the record is
    /// then written as csv_record() of them. Empty: the record is copied as it is.
    std::function<void(std::uint64_t index, std::vector<std::string>& fields)> fill;
    /// The new file's header line, and the journal's from then on. Empty: the same.
    std::string header;
  };

  /// Rewrites the file (temp file and rename, so a kill leaves the old or the new file) with
  /// its records in ascending order of their number (stable: equal numbers keep their order),
  /// by default the decimal number in field `index_field`; records without one go last.
  /// `rewrite` may renumber, leave out and change records, and change the header. Call before the
  /// first append() (or after a flush(): the file is reopened).
  void rewrite_in_order(std::size_t index_field, const Rewrite& rewrite = {});

  /// Queues whole records (each ending in '\n'); nothing reaches the file before flush().
  void append(std::string_view records);
  /// Bytes queued and not yet written.
  [[nodiscard]] std::size_t pending() const { return buffer_.size(); }
  /// Writes the queued bytes, all or none (core/append_file.hpp): IoError naming the file and
  /// the OS error when the machine refuses them (a full disk, a file size limit), and then
  /// they stay queued.
  void flush();

  [[nodiscard]] const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::string header_;
  std::string buffer_;
  AppendFile file_;
};

/// Splits one CSV line (no newline) into unquoted fields (RFC 4180).
[[nodiscard]] std::vector<std::string> split_csv_line(std::string_view line);

}  // namespace sweep
}  // namespace fsweep
