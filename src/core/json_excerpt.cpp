#include "core/json_excerpt.hpp"

#include <nlohmann/json.hpp>

namespace fsweep {
inline namespace core {
namespace {

/// Appends the quoted string `s`, cut before quoting: no more than `limit - out.size() + 1`
/// of its characters can show.
void append_string(const std::string& s, std::size_t limit, std::string& out) {
  const std::size_t room = limit - out.size() + 1;
  out += nlohmann::json(s.size() > room ? s.substr(0, room) : s).dump();
  if (s.size() > room) out.pop_back();  // the closing quote of a cut string
}

/// Appends `v` to `out` until `out` holds more than `limit` characters.
void append_excerpt(const nlohmann::json& v, std::size_t limit, int depth, std::string& out) {
  if (out.size() > limit) return;
  if (v.is_string()) {
    append_string(v.get_ref<const std::string&>(), limit, out);
    return;
  }
  if (!v.is_structured()) {
    out += v.dump();
    return;
  }
  const bool object = v.is_object();
  if (depth >= kMaxExcerptDepth) {
    out += object ? "{...}" : "[...]";
    return;
  }
  out += object ? '{' : '[';
  bool first = true;
  for (auto it = v.begin(); it != v.end() && out.size() <= limit; ++it) {
    if (!first) out += ',';
    first = false;
    if (object) {
      append_string(it.key(), limit, out);
      if (out.size() > limit) break;
      out += ':';
    }
    append_excerpt(*it, limit, depth + 1, out);
  }
  out += object ? '}' : ']';
}

}  // namespace

std::string json_excerpt(const nlohmann::json& v, std::size_t max_chars) {
  std::string out;
  append_excerpt(v, max_chars, 0, out);
  if (out.size() > max_chars) out = out.substr(0, max_chars) + "...";
  return out;
}

}  // namespace core
}  // namespace fsweep
