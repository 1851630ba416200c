/// @file sweep_json_reader.cpp
/// parse_sweep_json: a SAX pass (JsonKeyFinder) that finds duplicate keys and stops at kMaxSweepNesting, then
/// nlohmann's parser, and its exceptions turned into messages naming the file, line and column;
/// apply_sweep_overrides: the command line's PATH=VALUE overrides.

#include "sweep/sweep_json_reader.hpp"

#include <algorithm>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>

#include "core/config_error.hpp"
#include "core/json_excerpt.hpp"
#include "core/json_text.hpp"

namespace fsweep {
inline namespace sweep {
namespace {

using nlohmann::json;

/// `s` cut to `n` characters for messages.
std::string cut(const std::string& s, std::size_t n) { return s.size() > n ? s.substr(0, n) + "..." : s; }

}  // namespace

SweepJson parse_sweep_json(const std::string& text, const std::string& path) {
  auto finder = std::make_shared<JsonKeyFinder>(kMaxSweepNesting);
  SweepJson out;
  try {
    // The pass stops at a syntax error, which the parse then throws with its message.
    (void)json::sax_parse(text, finder.get());
    out.value = json::parse(text);
  } catch (const JsonNestingTooDeep& e) {
    throw ConfigError(text_position(path, text, first_too_deep_opening(text, kMaxSweepNesting)),
                      e.path + ": arrays and objects are nested more than " +
                          std::to_string(kMaxSweepNesting) + " levels deep; allowed: at most " +
                          std::to_string(kMaxSweepNesting) + " levels");
  } catch (const json::parse_error& e) {
    // e.byte: 1-based position of the offending character.
    std::string detail = e.what();
    if (const std::size_t colon = detail.find(": ", detail.find("column")); colon != std::string::npos) {
      detail = detail.substr(colon + 2);
    }
    throw ConfigError(text_position(path, text, e.byte == 0 ? 0 : e.byte - 1),
                      "invalid JSON: " + cut(detail, 200));
  } catch (const json::out_of_range&) {
    // 406: a number beyond the range of a double; nlohmann names neither the place nor the path.
    const auto [offset, number] = first_overflowing_number(text);
    throw ConfigError(text_position(path, text, offset),
                      finder->path() + ": number " + cut(number, 40) +
                          " is out of range; allowed: numbers of magnitude below 1.8e308 (a double)");
  }
  out.problems = finder->problems();
  return out;
}

namespace {

/// One step of an override's path: an object key, or a list position when `index` is set.
struct PathStep {
  std::string key;
  std::optional<std::size_t> index;
  std::string written;  ///< the path up to and including this step, as written ("maps[2]")
};

/// An override's path parsed, or why it cannot be.
struct OverridePath {
  std::vector<PathStep> steps;
  std::string problem;
};

bool key_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
}

/// A character for messages: 'c', or \xNN for a byte that does not print.
std::string char_text(char c) {
  const auto byte = static_cast<unsigned char>(c);
  if (byte >= 0x20 && byte < 0x7f) return std::string("'") + c + "'";
  char buf[8];
  std::snprintf(buf, sizeof(buf), "\\x%02x", byte);
  return buf;
}

/// Why `path` has no key at character `i` (0-based; nothing of a key there).
std::string missing_key(const std::string& path, std::size_t i) {
  const std::string allowed =
      "; allowed: keys of letters, digits, '_' and '-', joined by '.', and [i] for list entries";
  const std::string at = "character " + std::to_string(i + 1) + " of the path";
  if (i == path.size()) return "empty key at the end of the path" + allowed;
  if (path[i] != '.' && path[i] != '[')
    return char_text(path[i]) + " at " + at + " is not allowed in a key" + allowed;
  return i == 0 ? "the path starts with " + char_text(path[i]) + allowed : "empty key at " + at + allowed;
}

/// "a.b[2].c" as steps (a key first, then ".key" and "[i]" steps).
OverridePath parse_override_path(const std::string& path) {
  OverridePath out;
  const auto fail = [&out](std::string problem) {
    out.steps.clear();
    out.problem = std::move(problem);
    return out;
  };
  if (path.empty()) return fail("the path before '=' is empty; allowed: PATH=VALUE, e.g. robot.battery=800");
  std::size_t i = 0;
  bool key_next = true;
  while (i < path.size()) {
    if (key_next) {
      const std::size_t start = i;
      while (i < path.size() && key_char(path[i])) ++i;
      if (i == start) return fail(missing_key(path, i));
      out.steps.push_back(PathStep{path.substr(start, i - start), std::nullopt, path.substr(0, i)});
      key_next = false;
    } else if (path[i] == '.') {
      ++i;
      key_next = true;
    } else if (path[i] == '[') {
      const std::size_t close = path.find(']', i);
      const std::string digits =
          close == std::string::npos ? path.substr(i + 1) : path.substr(i + 1, close - i - 1);
      const bool number =
          !digits.empty() && digits.size() <= 18 &&
          std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
      if (close == std::string::npos || !number) {
        return fail("'[' at character " + std::to_string(i + 1) +
                    " of the path must be followed by a list position and ']' (" + path.substr(0, i) +
                    "[0], " + path.substr(0, i) + "[1], ...), got " +
                    (digits.empty()
                         ? std::string("nothing")
                         : "'" + (digits.size() > 20 ? digits.substr(0, 20) + "..." : digits) + "'"));
      }
      out.steps.push_back(PathStep{{}, std::stoull(digits), path.substr(0, close + 1)});
      i = close + 1;
    } else {
      return fail(char_text(path[i]) + " at character " + std::to_string(i + 1) +
                  " of the path is not allowed; allowed after " + path.substr(0, i) +
                  ": '.KEY', '[i]' or '='");
    }
  }
  if (key_next) return fail(missing_key(path, path.size()));
  return out;
}

/// What a JSON value is, for messages: the string "t", a list of 2 entries, an object.
std::string what_is(const json& v) {
  if (v.is_object()) return v.empty() ? "an empty object" : "an object";
  if (v.is_array()) return "a list of " + std::to_string(v.size()) + (v.size() == 1 ? " entry" : " entries");
  if (v.is_string()) return "the string " + json_excerpt(v, 40);
  if (v.is_number()) return "the number " + json_excerpt(v, 40);
  return json_excerpt(v, 40);  // true, false, null
}

/// Nesting levels of arrays and objects in `v` (0 for a scalar); `v` is at most kMaxSweepNesting deep.
int nesting(const json& v) {
  if (!v.is_structured()) return 0;
  int deepest = 0;
  for (const json& e : v) deepest = std::max(deepest, nesting(e));
  return deepest + 1;
}

/// The value of an override: JSON when it parses, else the text; problems in `problems` (the
/// value's own duplicate keys, at `pointer`) or, when it cannot be a value, in `problem`.
struct OverrideValue {  // NOLINT(bugprone-exception-escape): as SweepJson's
  json value;
  std::vector<std::string> problems;
  std::string problem;
};

OverrideValue parse_override_value(const std::string& text, const std::string& pointer) {
  OverrideValue out;
  const bool structured =
      !text.empty() && (text.front() == '[' || text.front() == '{' || text.front() == '"');
  // A number a double cannot hold (1e400) is JSON text that does not parse: an error, not a string.
  const auto [offset, number] = first_overflowing_number(text);
  const bool overflowing_number = !text.empty() && offset == 0 && number.size() == text.size();
  if (structured || overflowing_number || json::accept(text)) {
    try {
      SweepJson parsed = parse_sweep_json(text, "value");
      out.value = std::move(parsed.value);
      for (const std::string& p : parsed.problems) out.problems.push_back(pointer + p);
    } catch (const ConfigError& e) {
      out.problem = std::string(e.what()) +
                    (structured ? "; a value starting with [, { or \" must be JSON (a string with them: "
                                  "'KEY=\"[text\"')"
                                : "");
    }
    return out;
  }
  try {
    (void)json(text).dump();  // nlohmann refuses to write a string that is not UTF-8
  } catch (const json::type_error&) {
    out.problem = "the value is not UTF-8 text";
    return out;
  }
  out.value = text;
  return out;
}

/// Why list `here` of `size` entries has no entry `missing`.
std::string missing_entry(const std::string& here, std::size_t size, const std::string& missing) {
  std::string out = here + " has " + std::to_string(size) + (size == 1 ? " entry" : " entries");
  if (size > 0) {
    const std::string last = here + "[" + std::to_string(size - 1) + "]";
    out += size == 1 ? " (" + last + ")" : " (" + here + "[0] to " + last + ")";
  }
  return out + ", so there is no " + missing +
         "; allowed: an entry that is there (a list with other entries is given whole: " + here + "=[...])";
}

/// Sets `value` at `steps` in `sweep`; a problem (what is in the way) when it cannot.
std::string set_at(json& sweep, const std::vector<PathStep>& steps, json value) {
  json* node = &sweep;
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const PathStep& s = steps[k];
    const bool last = k + 1 == steps.size();
    const std::string here = k == 0 ? std::string("the sweep") : steps[k - 1].written;
    if (s.index) {
      if (!node->is_array()) {
        return here + " is " + what_is(*node) + ", not a list, so there is no " + s.written +
               (node->is_object() ? "; allowed: " + here + ".KEY" : std::string());
      }
      if (*s.index >= node->size()) return missing_entry(here, node->size(), s.written);
      node = &(*node)[*s.index];
    } else {
      if (!node->is_object()) {
        return here + " is " + what_is(*node) + ", not an object, so it has no key '" + s.key + "'";
      }
      if (!last && !node->contains(s.key)) {
        if (steps[k + 1].index) {
          return s.written + " is not in the sweep, so there is no " + steps[k + 1].written +
                 "; allowed: the whole list, " + s.written + "=[...]";
        }
        (*node)[s.key] = json::object();
      }
      node = &(*node)[s.key];
    }
  }
  *node = std::move(value);
  return {};
}

/// `steps` as a JSON pointer: "/strategies/1/params/w1" (keys need no escapes: key_char()).
std::string pointer_of(const std::vector<PathStep>& steps) {
  std::string p;
  for (const PathStep& s : steps) p += "/" + (s.index ? std::to_string(*s.index) : s.key);
  return p;
}

}  // namespace

std::string override_label(const std::string& text) {
  constexpr std::size_t kShown = 80;
  if (text.size() <= kShown) return "override '" + text + "'";
  std::size_t cut = kShown;
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0U) == 0x80U)
    --cut;  // not inside a UTF-8 character
  return "override '" + text.substr(0, cut) + "...' (" + std::to_string(text.size()) + " characters)";
}

SweepJson apply_sweep_overrides(SweepJson parsed, const std::vector<std::string>& overrides,
                                const std::string& path) {
  std::vector<std::string> problems;
  std::map<std::string, std::string> seen;  // pointer -> the override that set it
  for (const std::string& text : overrides) {
    const auto problem = [&](const std::string& what) {
      problems.push_back(override_label(text) + ": " + what);
    };
    if (text.size() > kMaxOverrideChars) {
      problem("it is " + std::to_string(text.size()) + " characters long; allowed: at most " +
              std::to_string(kMaxOverrideChars) + " (a longer value belongs in the sweep file)");
      continue;
    }
    const std::size_t eq = text.find('=');
    if (eq == std::string::npos) {
      problem("expected PATH=VALUE, e.g. robot.battery=800 or 'strategies[0].params.w1=[0,10]'");
      continue;
    }
    const OverridePath p = parse_override_path(text.substr(0, eq));
    if (!p.problem.empty()) {
      problem(p.problem);
      continue;
    }
    const std::string pointer = pointer_of(p.steps);
    if (const auto [it, added] = seen.emplace(pointer, text); !added) {
      problem("sets the same path as " + override_label(it->second) + "; allowed: each path once");
      continue;
    }
    OverrideValue v = parse_override_value(text.substr(eq + 1), pointer);
    if (!v.problem.empty()) {
      problem(v.problem);
      continue;
    }
    if (static_cast<int>(p.steps.size()) + nesting(v.value) > kMaxSweepNesting) {
      problem("the value at " + p.steps.back().written + " makes the sweep nested more than " +
              std::to_string(kMaxSweepNesting) + " levels deep; allowed: at most " +
              std::to_string(kMaxSweepNesting) + " levels");
      continue;
    }
    if (const std::string in_the_way = set_at(parsed.value, p.steps, std::move(v.value));
        !in_the_way.empty()) {
      problem(in_the_way);
      continue;
    }
    parsed.problems.insert(parsed.problems.end(), v.problems.begin(), v.problems.end());
    parsed.overrides.push_back(SweepOverride{text, pointer});
  }
  if (!problems.empty()) {
    std::string message = std::to_string(problems.size()) +
                          (problems.size() == 1 ? " override" : " overrides") +
                          " of the sweep cannot be applied:";
    for (const std::string& p : problems) message.append("\n").append(path).append(": ").append(p);
    throw ConfigError(path, message);
  }
  return parsed;
}

}  // namespace sweep
}  // namespace fsweep
