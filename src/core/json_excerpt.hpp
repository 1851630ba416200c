#pragma once
/// @file json_excerpt.hpp
/// A JSON value shortened for messages, bounded in size and depth whatever the value is (a bad
/// value may be a 200 KB string or an array nested 100,000 deep; `dump()` would copy all of it,
/// and recursively).

#include <cstddef>
#include <nlohmann/json_fwd.hpp>
#include <string>

namespace fsweep {
inline namespace core {

/// Characters of a value's text in messages (json_excerpt's default), before "...".
inline constexpr std::size_t kMaxExcerptChars = 80;

/// Nesting levels shown in messages; deeper arrays and objects are written "[...]" / "{...}".
inline constexpr int kMaxExcerptDepth = 8;

/// `v` as compact JSON text (as `dump()` writes it), cut after `max_chars` characters with
/// "..." appended. Long strings and containers are cut before they are formatted, so the work
/// and the stack used are bounded by `max_chars` and kMaxExcerptDepth, not by the value.
[[nodiscard]] std::string json_excerpt(const nlohmann::json& v, std::size_t max_chars = kMaxExcerptChars);

}  // namespace core
}  // namespace fsweep
