#include "core/json_text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "core/config_error.hpp"

namespace fsweep {
inline namespace core {
namespace {

/// Calls `visit(offset)` for each character of `text` outside strings, in order, until it
/// returns false. Strings (with their escapes) are skipped.
template <typename Visit>
void scan_outside_strings(std::string_view text, Visit visit) {
  bool in_string = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\') {
        ++i;
      } else if (c == '"') {
        in_string = false;
      }
    } else if (c == '"') {
      in_string = true;
    } else if (!visit(i)) {
      return;
    }
  }
}

}  // namespace

std::string text_position(const std::string& path, std::string_view text, std::size_t offset) {
  offset = std::min(offset, text.size());
  const auto line = 1 + std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(offset), '\n');
  const std::size_t last_newline = offset == 0 ? std::string_view::npos : text.rfind('\n', offset - 1);
  const std::size_t column = last_newline == std::string_view::npos ? offset + 1 : offset - last_newline;
  return path + ":" + std::to_string(line) + ":" + std::to_string(column);
}

std::pair<std::size_t, std::string> first_overflowing_number(std::string_view text) {
  std::pair<std::size_t, std::string> found{text.size(), ""};
  std::size_t skip_to = 0;
  scan_outside_strings(text, [&](std::size_t i) {
    if (i < skip_to) return true;
    const char c = text[i];
    if (c != '-' && (c < '0' || c > '9')) return true;
    std::size_t end = i;
    while (end < text.size() &&
           std::string_view("+-0123456789.eE").find(text[end]) != std::string_view::npos) {
      ++end;
    }
    skip_to = end;
    const std::string number(text.substr(i, end - i));
    if (std::isinf(std::strtod(number.c_str(), nullptr))) {
      found = {i, number};
      return false;
    }
    return true;
  });
  return found;
}

std::size_t first_too_deep_opening(std::string_view text, int max_depth) {
  std::size_t found = text.size();
  int depth = 0;
  scan_outside_strings(text, [&](std::size_t i) {
    if (text[i] == '[' || text[i] == '{') {
      if (++depth > max_depth) {
        found = i;
        return false;
      }
    } else if (text[i] == ']' || text[i] == '}') {
      --depth;
    }
    return true;
  });
  return found;
}

nlohmann::json parse_json_or_discard(std::string_view text) {
  if (first_too_deep_opening(text, kMaxJsonNesting) < text.size()) return nlohmann::json::value_t::discarded;
  return nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
}

nlohmann::json parse_json_bounded(std::string_view text, const std::string& path) {
  if (const std::size_t at = first_too_deep_opening(text, kMaxJsonNesting); at < text.size()) {
    throw ConfigError(text_position(path, text, at), "JSON nested deeper than " +
                                                         std::to_string(kMaxJsonNesting) +
                                                         " levels (arrays and objects); allowed: at most " +
                                                         std::to_string(kMaxJsonNesting));
  }
  return nlohmann::json::parse(text);
}

}  // namespace core
}  // namespace fsweep
