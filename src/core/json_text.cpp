#include "core/json_text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "core/config_error.hpp"

namespace fsweep {
inline namespace core {
namespace {

/// JSON paths in messages are cut here (keys may be long).
constexpr std::size_t kMaxPathText = 160;

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

std::string null_non_finite_words(std::string_view text) {
  std::string out;
  std::size_t copied = 0;
  std::size_t skip_to = 0;
  scan_outside_strings(text, [&](std::size_t i) {
    if (i < skip_to) return true;
    const std::size_t word = text[i] == '-' ? i + 1 : i;
    for (const std::string_view name : {std::string_view("NaN"), std::string_view("Infinity")}) {
      if (text.substr(word, name.size()) == name) {
        out.append(text.substr(copied, i - copied)).append("null");
        copied = skip_to = word + name.size();
        break;
      }
    }
    return true;
  });
  return out.append(text.substr(copied));
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

namespace {

/// Throws ConfigError at the first array or object of `text` nested deeper than kMaxJsonNesting.
void refuse_too_deep(std::string_view text, const std::string& path) {
  if (const std::size_t at = first_too_deep_opening(text, kMaxJsonNesting); at < text.size()) {
    throw ConfigError(text_position(path, text, at), "JSON nested deeper than " +
                                                         std::to_string(kMaxJsonNesting) +
                                                         " levels (arrays and objects); allowed: at most " +
                                                         std::to_string(kMaxJsonNesting));
  }
}

}  // namespace

nlohmann::json parse_json_bounded(std::string_view text, const std::string& path) {
  refuse_too_deep(text, path);
  return nlohmann::json::parse(text);
}

namespace {

/// A SAX handler that builds the value as json::parse does (nlohmann's own DOM builder) and
/// finds repeated keys on the way (JsonKeyFinder): one pass over the text.
class UniqueKeyDom {
 public:
  explicit UniqueKeyDom(nlohmann::json& out) : dom_(out) {}
  bool null() { return keys.null() && dom_.null(); }
  bool boolean(bool v) { return keys.boolean(v) && dom_.boolean(v); }
  bool number_integer(nlohmann::json::number_integer_t v) {
    return keys.number_integer(v) && dom_.number_integer(v);
  }
  bool number_unsigned(nlohmann::json::number_unsigned_t v) {
    return keys.number_unsigned(v) && dom_.number_unsigned(v);
  }
  bool number_float(nlohmann::json::number_float_t v, const std::string& text) {
    return keys.number_float(v, text) && dom_.number_float(v, text);
  }
  bool string(std::string& v) { return keys.string(v) && dom_.string(v); }
  bool binary(nlohmann::json::binary_t& v) { return keys.binary(v) && dom_.binary(v); }
  bool start_object(std::size_t n) { return keys.start_object(n) && dom_.start_object(n); }
  bool start_array(std::size_t n) { return keys.start_array(n) && dom_.start_array(n); }
  bool end_object() { return keys.end_object() && dom_.end_object(); }
  bool end_array() { return keys.end_array() && dom_.end_array(); }
  bool key(std::string& k) { return keys.key(k) && dom_.key(k); }
  /// Throws `error` (nlohmann's parse_error, out_of_range, ...) as json::parse does: a template,
  /// so that the exception keeps its own type.
  template <typename Exception>
  bool parse_error(std::size_t position, const std::string& token, const Exception& error) {
    return dom_.parse_error(position, token, error);
  }

  JsonKeyFinder keys{kMaxJsonNesting};

 private:
  nlohmann::detail::json_sax_dom_parser<nlohmann::json> dom_;
};

}  // namespace

nlohmann::json parse_json_unique_keys(std::string_view text, const std::string& path) {
  refuse_too_deep(text, path);
  nlohmann::json j;
  UniqueKeyDom handler(j);
  (void)nlohmann::json::sax_parse(text, &handler);
  if (!handler.keys.problems().empty()) throw ConfigError(path, handler.keys.problems().front());
  return j;
}

bool JsonKeyFinder::key(std::string& k) {
  Frame& top = stack_.back();
  top.key = k;
  if (!top.keys.insert(top.key).second)
    problems_.push_back(path() + ": duplicate key '" + top.key +
                        "'; allowed: each key once (JSON keeps only the last)");
  return true;
}

std::string JsonKeyFinder::path() const {
  std::string p;
  for (const auto& f : stack_) {
    p += "/" + (f.object ? f.key : std::to_string(f.index));
    if (p.size() > kMaxPathText) return p.substr(0, kMaxPathText) + "...";
  }
  return p.empty() ? "/" : p;
}

bool JsonKeyFinder::open(bool object) {
  if (stack_.size() + 1 > static_cast<std::size_t>(max_nesting_)) throw JsonNestingTooDeep{path()};
  stack_.push_back(Frame{object, {}, {}, 0});
  return true;
}

}  // namespace core
}  // namespace fsweep
