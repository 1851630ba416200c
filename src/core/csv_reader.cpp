#include "core/csv_reader.hpp"

#include <charconv>

#include "core/config_error.hpp"

namespace fsweep {
inline namespace core {
namespace {

constexpr std::size_t kBufferSize = std::size_t{1} << 16;
constexpr int kEnd = -1;

/// What a damaged sweep file's reader can do about it.
constexpr const char* kDamaged =
    " (the file is damaged; for a sweep's runs.csv or progress.csv, running the sweep again drops the "
    "damaged lines, saying which, and redoes their runs)";

/// A character for a message: 'x', or its byte value when it is not printable.
std::string shown(int c) {
  if (c >= 0x20 && c < 0x7f) return std::string("'") + static_cast<char>(c) + "'";
  constexpr const char* kHex = "0123456789abcdef";
  const auto b = static_cast<unsigned>(c) & 0xffU;
  return std::string("the byte 0x") + kHex[b >> 4U] + kHex[b & 0xfU];
}

}  // namespace

CsvReader::CsvReader(const std::string& path, bool require_final_newline)
    : path_(path),
      require_final_newline_(require_final_newline),
      in_(path, std::ios::binary),
      buffer_(kBufferSize) {
  if (!in_) throw ConfigError(path, "cannot open for reading");
  if (read_record(header_)) fields_.reserve(header_.size());
}

std::string CsvReader::where() const { return path_ + ":" + std::to_string(record_line_); }

int CsvReader::peek() {
  if (pos_ == end_) {
    if (!in_) return kEnd;
    in_.read(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
    end_ = static_cast<std::size_t>(in_.gcount());
    pos_ = 0;
    if (end_ == 0) return kEnd;
  }
  return static_cast<unsigned char>(buffer_[pos_]);
}

int CsvReader::get() {
  const int c = peek();
  if (c == kEnd) return kEnd;
  ++pos_;
  if (c == '\n') ++next_line_;
  return c;
}

bool CsvReader::read_record(std::vector<std::string>& out) {
  if (peek() == kEnd) return false;
  record_line_ = next_line_;
  std::size_t count = 0;
  for (;;) {
    // 1. One field, quoted or not, reusing the string of the previous record.
    if (count == out.size()) out.emplace_back();
    std::string& field = out[count++];
    field.clear();
    int c = get();
    if (c == '"') {
      for (;;) {
        c = get();
        if (c == kEnd) {
          throw ConfigError(where(), "field " + std::to_string(count) +
                                         " opens a quote (\") that is never closed: expected a closing quote "
                                         "before the end of the file" +
                                         kDamaged);
        }
        if (c == '"') {
          if (peek() != '"') break;
          get();
        }
        field += static_cast<char>(c);
      }
      c = get();
      if (c != ',' && c != '\n' && c != '\r' && c != kEnd) {
        throw ConfigError(where(), "field " + std::to_string(count) + " has " + shown(c) +
                                       " after its closing quote: expected a comma or the end of the line" +
                                       kDamaged);
      }
    } else {
      while (c != ',' && c != '\n' && c != '\r' && c != kEnd) {
        if (c == '"') {
          throw ConfigError(where(), "field " + std::to_string(count) +
                                         " has a quote (\") inside it: expected a field with a quote to be "
                                         "quoted whole, its quotes doubled (\"a \"\"b\"\"\")" +
                                         kDamaged);
        }
        field += static_cast<char>(c);
        c = get();
      }
    }
    // 2. What ended the field: a comma (next field), a line break or the end of the file.
    if (c == ',') continue;
    if (c == '\r') {
      if (peek() != '\n') {
        throw ConfigError(where(),
                          "a carriage return (\\r) inside the line, not followed by a line feed: "
                          "expected each line to end with a line feed (\\n) or \\r\\n" +
                              std::string(kDamaged));
      }
      get();
    } else if (c == kEnd && require_final_newline_) {
      throw ConfigError(where(),
                        "last line has no final newline (a torn write; rerunning the sweep repairs it)");
    }
    out.resize(count);
    return true;
  }
}

bool CsvReader::next() {
  if (!read_record(fields_)) return false;
  if (fields_.size() != header_.size()) {
    throw ConfigError(where(), "the line has " + std::to_string(fields_.size()) +
                                   (fields_.size() == 1 ? " field" : " fields") + ": expected " +
                                   std::to_string(header_.size()) + ", as many as the header" + kDamaged);
  }
  return true;
}

int CsvReader::column(const std::string& name) const {
  for (std::size_t i = 0; i < header_.size(); ++i) {
    if (header_[i] == name) return static_cast<int>(i);
  }
  return -1;
}

std::size_t CsvReader::require_column(const std::string& name) const {
  const int i = column(name);
  if (i < 0) throw ConfigError(path_ + ":1", "no column '" + name + "' in the header");
  return static_cast<std::size_t>(i);
}

std::optional<double> parse_number(std::string_view text) {
  if (text.empty()) return std::nullopt;
  const char* first = text.data();
  const char* last = text.data() + text.size();
  if (*first == '+') {  // from_chars rejects a leading plus
    ++first;
    if (first == last || *first == '-') return std::nullopt;
  }
  double value = 0.0;
  const auto res = std::from_chars(first, last, value);
  if (res.ec != std::errc() || res.ptr != last) return std::nullopt;
  return value;
}

std::optional<std::uint64_t> parse_unsigned(std::string_view text, int base) {
  std::uint64_t value = 0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value, base);
  if (text.empty() || ec != std::errc() || ptr != text.data() + text.size()) return std::nullopt;
  return value;
}

}  // namespace core
}  // namespace fsweep
