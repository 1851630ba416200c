#include "sweep/csv_journal.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <utility>

#include "core/config_error.hpp"
#include "core/csv_format.hpp"
#include "core/files.hpp"
#include "core/io_error.hpp"
#include "core/replacing_file.hpp"
#include "sweep/done_runs.hpp"

namespace fsweep {
inline namespace sweep {
namespace {

/// A byte range [begin, end) of a file.
struct Span {
  std::uint64_t begin = 0;
  std::uint64_t end = 0;
};

/// Incremental RFC 4180 record parser: feed bytes, get complete records. Strict as CsvReader
/// is: a record it would refuse is malformed (problem() says why) and ends at the next line
/// feed outside quotes, so one garbage line does not swallow the records after it.
class RecordParser {
 public:
  /// Feeds one byte; returns true when it completed a record (then fields() and problem() hold
  /// it).
  bool feed(char c) {
    if (in_quotes_) {
      if (c == '"') {
        in_quotes_ = false;
        closed_quote_ = true;
      } else {
        field_ += c;
      }
      return false;
    }
    const bool closed = std::exchange(closed_quote_, false);
    if (c == '\n') {
      fields_.push_back(std::move(field_));
      field_.clear();
      field_started_ = false;
      return true;
    }
    if (!problem_.empty()) return false;  // malformed: skip to the end of the line
    if (closed && c != '"' && c != ',') {
      fail("field " + std::to_string(fields_.size() + 1) + " has " + shown(c) +
           " after its closing quote, where a comma or the end of the line was expected");
    } else if (c == '"') {
      if (closed || !field_started_) {
        if (closed) field_ += '"';  // "" inside a quoted field
        in_quotes_ = true;
        field_started_ = true;
      } else {
        fail("field " + std::to_string(fields_.size() + 1) +
             " has a quote (\") inside it but does not start with one");
      }
    } else if (c == ',') {
      fields_.push_back(std::move(field_));
      field_.clear();
      field_started_ = false;
    } else if (c == '\r') {
      fail("a carriage return (\\r) inside the line, where only a line feed (\\n) ends a line");
    } else {
      field_ += c;
      field_started_ = true;
    }
    return false;
  }
  [[nodiscard]] const std::vector<std::string>& fields() const { return fields_; }
  /// Why the completed record is malformed; empty when it is well-formed.
  [[nodiscard]] const std::string& problem() const { return problem_; }
  void next_record() {
    fields_.clear();
    problem_.clear();
  }

 private:
  static std::string shown(char c) {
    if (c >= 0x20 && c < 0x7f) return std::string("'") + c + "'";
    std::array<char, 16> hex{};
    std::snprintf(hex.data(), hex.size(), "byte 0x%02x",
                  static_cast<unsigned>(static_cast<unsigned char>(c)));
    return hex.data();
  }
  void fail(std::string why) {
    problem_ = std::move(why);
    field_.clear();
  }

  std::vector<std::string> fields_;
  std::string field_;
  std::string problem_;
  bool in_quotes_ = false;
  bool closed_quote_ = false;
  bool field_started_ = false;
};

/// Adds one dropped record to `out`, merged with the previous entry when it continues it.
void note_dropped(std::vector<CsvDroppedLines>& out, std::uint64_t first, std::uint64_t last,
                  std::string reason) {
  if (!out.empty() && out.back().last_line + 1 == first && out.back().reason == reason) {
    out.back().last_line = last;
    return;
  }
  out.push_back({first, last, std::move(reason)});
}

/// Copies the byte ranges `keep` of `path` into a temp file and renames it over `path`.
void rewrite_ranges(const std::string& path, const std::vector<Span>& keep) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ConfigError(path, "cannot read (repairing the file)");
  ReplacingFile out(path);
  std::array<char, 1 << 16> buf{};
  for (const Span& s : keep) {
    in.seekg(static_cast<std::streamoff>(s.begin));
    std::uint64_t left = s.end - s.begin;
    while (left > 0) {
      const auto n = static_cast<std::streamsize>(std::min<std::uint64_t>(left, buf.size()));
      in.read(buf.data(), n);
      if (in.gcount() != n) throw ConfigError(path, "short read while repairing the file");
      out.write({buf.data(), static_cast<std::size_t>(n)});
      left -= static_cast<std::uint64_t>(n);
    }
  }
  out.commit();
}

}  // namespace

std::vector<std::string> split_csv_line(std::string_view line) {
  RecordParser p;
  for (const char c : line) p.feed(c);
  p.feed('\n');
  return p.fields();
}

CsvJournal::CsvJournal(std::string path, std::string header)
    : path_(std::move(path)), header_(std::move(header)), file_(path_, false) {
  const std::string first = read_first_line(path_);
  if (first.empty()) {
    write_file_atomically(path_, header_ + '\n');
  } else if (first != header_) {
    throw ConfigError(path_,
                      "its columns differ from this sweep's (made by another sweep file or build); "
                      "use --fresh to start over, or another output directory");
  }
}

CsvJournal::~CsvJournal() {
  try {
    flush();
  } catch (...) {  // NOLINT(bugprone-empty-catch): a destructor must not throw
  }
}

std::string CsvDroppedLines::describe(const std::string& path) const {
  std::string lines = std::to_string(first_line);
  if (last_line > first_line) lines += "-" + std::to_string(last_line);
  return path + ":" + lines + ": " + reason;
}

CsvRepairStats CsvJournal::repair(const RecordFilter& keep, const std::function<void()>& before_changes) {
  CsvRepairStats stats;
  std::FILE* f = std::fopen(path_.c_str(), "rb");
  if (f == nullptr) throw ConfigError(path_, "cannot open for reading");
  const std::uint64_t body = header_.size() + 1;
  std::fseek(f, static_cast<long>(body), SEEK_SET);

  // 1. Scan the records; remember the kept byte ranges (merged) and where dropped ones lie. A
  //    dropped record running over several lines (a damaged row's unclosed quote swallows the
  //    rows after it) costs only its first line: the scan restarts on the next one.
  std::vector<Span> kept{{0, body}};
  bool dropped_before_kept = false;
  bool any_dropped = false;
  RecordParser parser;
  std::uint64_t offset = body;
  std::uint64_t record_begin = body;
  std::uint64_t line = 2;         // line of the next byte (the header is line 1)
  std::uint64_t record_line = 2;  // line where the current record starts
  std::uint64_t first_break = 0;  // offset past the current record's first line feed; 0: none yet
  const auto drop_first_line = [&](std::string reason) {
    ++stats.dropped;
    any_dropped = true;
    note_dropped(stats.dropped_lines, record_line, record_line,
                 std::move(reason) + " (read as one record with the lines up to " + std::to_string(line - 1) +
                     ", which are read again on their own)");
    std::fseek(f, static_cast<long>(first_break), SEEK_SET);
    offset = record_begin = first_break;
    line = record_line = record_line + 1;
    first_break = 0;
    parser = RecordParser();
  };
  std::array<char, 1 << 16> buf{};
  for (;;) {
    const std::size_t n = std::fread(buf.data(), 1, buf.size(), f);
    if (n == 0) {
      if (offset > record_begin && first_break != 0) {  // an unfinished record over several lines
        stats.torn = true;
        drop_first_line("a quote opened on this line is not closed before the end of the file");
        continue;
      }
      break;
    }
    for (std::size_t i = 0; i < n; ++i) {
      ++offset;
      if (buf[i] == '\n') {
        ++line;
        if (first_break == 0) first_break = offset;
      }
      if (!parser.feed(buf[i])) continue;
      std::string reason = parser.problem().empty() ? keep(parser.fields()) : parser.problem();
      if (!reason.empty() && first_break != offset) {
        drop_first_line(std::move(reason));
        break;  // read on from the new offset
      }
      if (reason.empty()) {
        ++stats.kept;
        if (any_dropped) dropped_before_kept = true;
        if (kept.back().end == record_begin) {
          kept.back().end = offset;
        } else {
          kept.push_back({record_begin, offset});
        }
      } else {
        ++stats.dropped;
        any_dropped = true;
        note_dropped(stats.dropped_lines, record_line, line - 1, std::move(reason));
      }
      parser.next_record();
      record_begin = offset;
      record_line = line;
      first_break = 0;
    }
  }
  std::fclose(f);
  if (offset > record_begin) {
    stats.torn = true;
    note_dropped(stats.dropped_lines, record_line, line,
                 "the last line is cut short (no final newline: a write torn by a kill)");
  }

  // 2. Cut: truncate when only a tail goes, else rewrite the kept ranges.
  if (before_changes) before_changes();
  if (!stats.torn && !any_dropped) return stats;
  if (!dropped_before_kept) {
    std::error_code ec;
    std::filesystem::resize_file(path_, kept.back().end, ec);
    if (ec) throw IoError(path_, "cannot truncate a torn record", ec.value());
  } else {
    rewrite_ranges(path_, kept);
    stats.rewritten = true;
  }
  return stats;
}

void CsvJournal::rewrite_in_order(std::size_t index_field, const Rewrite& rewrite) {
  flush();
  file_.close();  // the rename replaces the file: append to the new one
  // 1. The records' byte ranges and numbers, stably sorted by number.
  struct Record {
    std::uint64_t index = 0;
    Span span;
  };
  std::vector<Record> records;
  {
    std::ifstream in(path_, std::ios::binary);
    if (!in) throw ConfigError(path_, "cannot open for reading");
    in.seekg(static_cast<std::streamoff>(header_.size() + 1));
    RecordParser parser;
    std::uint64_t offset = header_.size() + 1;
    std::uint64_t record_begin = offset;
    std::array<char, 1 << 16> buf{};
    while (in.read(buf.data(), buf.size()), in.gcount() > 0) {
      const auto n = static_cast<std::size_t>(in.gcount());
      for (std::size_t i = 0; i < n; ++i) {
        ++offset;
        if (!parser.feed(buf[i])) continue;
        const auto& fields = parser.fields();
        const Span span{record_begin, offset};
        record_begin = offset;
        if (rewrite.place) {
          if (const auto index = rewrite.place(fields)) records.push_back({*index, span});
        } else {
          const auto index =
              fields.size() > index_field ? parse_run_index(fields[index_field]) : std::nullopt;
          records.push_back({index.value_or(UINT64_MAX), span});
        }
        parser.next_record();
      }
    }
  }
  std::stable_sort(records.begin(), records.end(),
                   [](const Record& a, const Record& b) { return a.index < b.index; });

  // 2. Header, then the records, into a temp file renamed over the file.
  std::ifstream in(path_, std::ios::binary);
  if (!in) throw ConfigError(path_, "cannot read (putting its rows in run order)");
  ReplacingFile out(path_);
  const std::string header = rewrite.header.empty() ? header_ : rewrite.header;
  out.write(header + '\n');
  std::string bytes;
  for (const Record& r : records) {
    bytes.resize(r.span.end - r.span.begin);
    in.seekg(static_cast<std::streamoff>(r.span.begin));
    in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (in.gcount() != static_cast<std::streamsize>(bytes.size())) {
      throw ConfigError(path_, "short read while putting its rows in run order");
    }
    if (!rewrite.fill) {
      out.write(bytes);
      continue;
    }
    RecordParser parser;
    for (const char c : bytes) (void)parser.feed(c);  // the record ends with its newline
    std::vector<std::string> fields = parser.fields();
    rewrite.fill(r.index, fields);
    out.write(csv_record(fields) + '\n');
  }
  out.commit();
  header_ = header;
}

void CsvJournal::append(std::string_view records) { buffer_.append(records); }

void CsvJournal::flush() {
  if (buffer_.empty()) return;
  file_.write(buffer_);
  buffer_.clear();
}

}  // namespace sweep
}  // namespace fsweep
