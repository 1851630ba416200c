#pragma once
/// @file json_text.hpp
/// Places in the text of a JSON file, for messages about it: nlohmann's exceptions give a byte
/// offset (parse errors) or none at all (a number beyond a double, out_of_range 406).

#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <utility>

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

/// "<path>:<line>:<column>" of byte `offset` of `text` (both counted from 1; an offset past the
/// end is the end).
[[nodiscard]] std::string text_position(const std::string& path, std::string_view text, std::size_t offset);

/// The first number outside strings that a double cannot hold (1e400, -1e999, 400 digits): its
/// byte offset and its text; the offset is text.size() if there is none.
[[nodiscard]] std::pair<std::size_t, std::string> first_overflowing_number(std::string_view text);

/// The byte offset of the first '[' or '{' outside strings that opens nesting level
/// `max_depth + 1` (the top level is 1); text.size() if there is none.
[[nodiscard]] std::size_t first_too_deep_opening(std::string_view text, int max_depth);

}  // namespace core
}  // namespace fsweep
