#include "sweep/csv_journal.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <utility>

#include "core/config_error.hpp"
#include "core/files.hpp"

namespace fsweep {
inline namespace sweep {
namespace {

/// A byte range [begin, end) of a file.
struct Span {
  std::uint64_t begin = 0;
  std::uint64_t end = 0;
};

/// Incremental RFC 4180 record parser: feed bytes, get complete records.
class RecordParser {
 public:
  /// Feeds one byte; returns true when it completed a record (then fields() holds it).
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
    if (c == '"') {
      if (closed) field_ += '"';  // "" inside a quoted field
      in_quotes_ = true;
    } else if (c == ',') {
      fields_.push_back(std::move(field_));
      field_.clear();
    } else if (c == '\n') {
      fields_.push_back(std::move(field_));
      field_.clear();
      return true;
    } else {
      field_ += c;
    }
    return false;
  }
  [[nodiscard]] const std::vector<std::string>& fields() const { return fields_; }
  void next_record() { fields_.clear(); }

 private:
  std::vector<std::string> fields_;
  std::string field_;
  bool in_quotes_ = false;
  bool closed_quote_ = false;
};

void write_all(int fd, std::string_view data, const std::string& path) {
  while (!data.empty()) {
    const ssize_t n = ::write(fd, data.data(), data.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      throw ConfigError(path, std::string("write failed: ") + std::strerror(errno));
    }
    data.remove_prefix(static_cast<std::size_t>(n));
  }
}

/// Copies the byte ranges `keep` of `path` into a temp file and renames it over `path`.
void rewrite_ranges(const std::string& path, const std::vector<Span>& keep) {
  std::ifstream in(path, std::ios::binary);
  const std::string tmp = temp_path(path);
  std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
  if (!in || !out) throw ConfigError(path, "cannot rewrite (repairing the file)");
  std::array<char, 1 << 16> buf{};
  for (const Span& s : keep) {
    in.seekg(static_cast<std::streamoff>(s.begin));
    std::uint64_t left = s.end - s.begin;
    while (left > 0) {
      const auto n = static_cast<std::streamsize>(std::min<std::uint64_t>(left, buf.size()));
      in.read(buf.data(), n);
      if (in.gcount() != n) throw ConfigError(path, "short read while repairing the file");
      out.write(buf.data(), n);
      left -= static_cast<std::uint64_t>(n);
    }
  }
  out.close();
  if (!out) throw ConfigError(tmp, "write failed (repairing " + path + ")");
  std::filesystem::rename(tmp, path);
}

}  // namespace

std::vector<std::string> split_csv_line(std::string_view line) {
  RecordParser p;
  for (const char c : line) p.feed(c);
  p.feed('\n');
  return p.fields();
}

CsvJournal::CsvJournal(std::string path, std::string header)
    : path_(std::move(path)), header_(std::move(header)) {
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
  if (fd_ >= 0) ::close(fd_);
}

CsvRepairStats CsvJournal::repair(const RecordFilter& keep) {
  CsvRepairStats stats;
  std::FILE* f = std::fopen(path_.c_str(), "rb");
  if (f == nullptr) throw ConfigError(path_, "cannot open for reading");
  const std::uint64_t body = header_.size() + 1;
  std::fseek(f, static_cast<long>(body), SEEK_SET);

  // 1. Scan the records; remember the kept byte ranges (merged) and where rejected ones lie.
  std::vector<Span> kept{{0, body}};
  bool dropped_before_kept = false;
  bool any_dropped = false;
  RecordParser parser;
  std::uint64_t offset = body;
  std::uint64_t record_begin = body;
  std::array<char, 1 << 16> buf{};
  std::size_t n = 0;
  while ((n = std::fread(buf.data(), 1, buf.size(), f)) > 0) {
    for (std::size_t i = 0; i < n; ++i) {
      ++offset;
      if (!parser.feed(buf[i])) continue;
      if (keep(parser.fields())) {
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
      }
      parser.next_record();
      record_begin = offset;
    }
  }
  std::fclose(f);
  stats.torn = offset > record_begin;

  // 2. Cut: truncate when only a tail goes, else rewrite the kept ranges.
  if (!stats.torn && !any_dropped) return stats;
  if (!dropped_before_kept) {
    std::error_code ec;
    std::filesystem::resize_file(path_, kept.back().end, ec);
    if (ec) throw ConfigError(path_, "cannot truncate a torn record: " + ec.message());
  } else {
    rewrite_ranges(path_, kept);
    stats.rewritten = true;
  }
  return stats;
}

void CsvJournal::append(std::string_view records) { buffer_.append(records); }

void CsvJournal::open_for_append() {
  fd_ = ::open(path_.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
  if (fd_ < 0) throw ConfigError(path_, std::string("cannot open for appending: ") + std::strerror(errno));
}

void CsvJournal::flush() {
  if (buffer_.empty()) return;
  if (fd_ < 0) open_for_append();
  write_all(fd_, buffer_, path_);
  buffer_.clear();
}

}  // namespace sweep
}  // namespace fsweep
