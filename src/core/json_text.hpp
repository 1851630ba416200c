#pragma once
/// @file json_text.hpp
/// Places in the text of a JSON file, for messages about it: nlohmann's exceptions give a byte
/// offset (parse errors) or none at all (a number beyond a double, out_of_range 406).

#include <cstddef>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace fsweep {
inline namespace core {

/// The deepest nesting of arrays and objects in JSON the engine reads besides sweep files
/// (sweep_json_reader.hpp) and HouseExpo plans: manifests (a sweep of up to 64 levels inside),
/// searches.json, bench.json, journal lines, key=value option values. nlohmann's parser does
/// not recurse, but copying, comparing or dumping a value does, once per level (100,000 levels
/// overflow the stack), so deeper text is refused before it is parsed.
inline constexpr int kMaxJsonNesting = 128;

/// json::parse(text, nullptr, false), and a discarded value too for text nested deeper than
/// kMaxJsonNesting.
[[nodiscard]] nlohmann::json parse_json_or_discard(std::string_view text);

/// json::parse(text) (nlohmann's parse_error for text that is not JSON), after a ConfigError
/// "<path>:<line>:<column>: JSON nested deeper than 128 levels" for too deep text.
[[nodiscard]] nlohmann::json parse_json_bounded(std::string_view text, const std::string& path);

/// parse_json_bounded(text, path), and a ConfigError "<path>: <JSON path>: duplicate key ..." for
/// the first key an object holds twice (nlohmann keeps only its last value, another reader may
/// keep the first), found in the same pass over the text: for files whose every value must mean
/// one thing, such as a certificate.
[[nodiscard]] nlohmann::json parse_json_unique_keys(std::string_view text, const std::string& path);

/// Thrown by JsonKeyFinder when an array or object opens deeper than its limit; `path` is the
/// JSON path of the value being read.
struct JsonNestingTooDeep {
  std::string path;
};

/// A SAX handler for json::sax_parse that lists the keys an object holds twice, with their JSON
/// paths, and knows the path of the value being read. A SAX pass, not the DOM parser's callback:
/// nlohmann's callback parser looks through the enclosing container at every value's end,
/// quadratic in a list of 100,000 entries. Throws JsonNestingTooDeep at an array or object
/// opening deeper than `max_nesting` levels; ends the pass at a syntax error (which the DOM
/// parser then reports with its message).
class JsonKeyFinder {
 public:
  explicit JsonKeyFinder(int max_nesting) : max_nesting_(max_nesting) {}

  bool null() { return value(); }
  bool boolean(bool /*v*/) { return value(); }
  bool number_integer(nlohmann::json::number_integer_t /*v*/) { return value(); }
  bool number_unsigned(nlohmann::json::number_unsigned_t /*v*/) { return value(); }
  bool number_float(nlohmann::json::number_float_t /*v*/, const std::string& /*text*/) { return value(); }
  bool string(std::string& /*v*/) { return value(); }
  bool binary(nlohmann::json::binary_t& /*v*/) { return value(); }
  bool start_object(std::size_t /*elements*/) { return open(true); }
  bool start_array(std::size_t /*elements*/) { return open(false); }
  bool end_object() { return close(); }
  bool end_array() { return close(); }
  bool key(std::string& k);
  bool parse_error(std::size_t /*position*/, const std::string& /*token*/,
                   const nlohmann::detail::exception& /*error*/) {
    return false;
  }

  /// "<JSON path>: duplicate key '<key>'; allowed: ..." for each repeated key, in text order.
  [[nodiscard]] const std::vector<std::string>& problems() const { return problems_; }
  /// The JSON path of the value being parsed ("/" at the top), cut after 160 characters.
  [[nodiscard]] std::string path() const;

 private:
  struct Frame {
    bool object;
    std::set<std::string> keys;
    std::string key;
    std::size_t index;
  };
  bool open(bool object);
  bool close() {
    stack_.pop_back();
    return value();
  }
  /// A value of the enclosing container is done.
  bool value() {
    if (!stack_.empty() && !stack_.back().object) ++stack_.back().index;
    return true;
  }
  int max_nesting_;
  std::vector<Frame> stack_;
  std::vector<std::string> problems_;
};

/// "<path>:<line>:<column>" of byte `offset` of `text` (both counted from 1; an offset past the
/// end is the end).
[[nodiscard]] std::string text_position(const std::string& path, std::string_view text, std::size_t offset);

/// The first number outside strings that a double cannot hold (1e400, -1e999, 400 digits): its
/// byte offset and its text; the offset is text.size() if there is none.
[[nodiscard]] std::pair<std::size_t, std::string> first_overflowing_number(std::string_view text);

/// `text` with the words NaN, Infinity, -NaN and -Infinity outside strings replaced by null:
/// Google Benchmark's JSON writes non-finite numbers so (the coefficient of variation of a counter
/// whose mean is 0), which JSON does not allow and no JSON parser reads.
[[nodiscard]] std::string null_non_finite_words(std::string_view text);

/// The byte offset of the first '[' or '{' outside strings that opens nesting level
/// `max_depth + 1` (the top level is 1); text.size() if there is none.
[[nodiscard]] std::size_t first_too_deep_opening(std::string_view text, int max_depth);

}  // namespace core
}  // namespace fsweep
