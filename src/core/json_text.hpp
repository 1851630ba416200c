#pragma once
/// @file json_text.hpp
/// Places in the text of a JSON file, for messages about it: nlohmann's exceptions give a byte
/// offset (parse errors) or none at all (a number beyond a double, out_of_range 406).

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>

namespace fsweep {
inline namespace core {

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
