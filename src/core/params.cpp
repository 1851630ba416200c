#include "core/params.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/config_error.hpp"
#include "core/json_excerpt.hpp"

namespace fsweep {
inline namespace core {
namespace {

/// A bound for messages: integral values without decimals ("250", "0.5", "1e+300").
std::string bound_text(double v) {
  if (std::abs(v) < 1e15 && v == std::floor(v)) return std::to_string(static_cast<long long>(v));
  std::ostringstream out;
  out << v;
  return out.str();
}

std::string quoted_list(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + nlohmann::json(n).dump();
  return out;
}

/// 2^53: the largest integer magnitude a double holds exactly.
constexpr double kMaxExactInteger = 9007199254740992.0;

/// A value in messages, cut (a bad value may be a huge array).
std::string value_text(const nlohmann::json& v) { return json_excerpt(v); }

}  // namespace

std::string param_path(const std::string& where, const std::string& key) {
  if (where.empty()) return key;
  const bool named = where.rfind("--", 0) == 0 || where.find_first_of(" '") != std::string::npos;
  if (!named) return where + "/" + key;
  // A key inside a named parameter ("--robot: sensor") joins it with a dot, as the option spells it.
  return where.rfind("--", 0) == 0 && where.find(": ") != std::string::npos ? where + "." + key
                                                                            : where + ": " + key;
}

std::string_view to_string(ParamType type) {
  switch (type) {
    case ParamType::Boolean:
      return "boolean";
    case ParamType::Integer:
      return "integer";
    case ParamType::Number:
      return "number";
    case ParamType::Text:
      return "string";
    case ParamType::Choice:
      return "choice";
    case ParamType::Custom:
      return "custom";
    case ParamType::Object:
      return "object";
  }
  return "unknown";
}

std::string ParamSpec::allowed() const {
  std::string text;
  switch (type) {
    case ParamType::Boolean:
      text = "true or false";
      break;
    case ParamType::Integer:
    case ParamType::Number: {
      text = type == ParamType::Integer ? "an integer" : "a number";
      if (min && max) {
        text += std::string(" in ") + (min_open ? "(" : "[") + bound_text(*min) + ", " + bound_text(*max) +
                (max_open ? ")" : "]");
      } else if (min) {
        text += std::string(min_open ? " > " : " >= ") + bound_text(*min);
      } else if (max) {
        text += std::string(max_open ? " < " : " <= ") + bound_text(*max);
      }
      break;
    }
    case ParamType::Text:
      text = "a string";
      break;
    case ParamType::Choice:
      text = "one of " + quoted_list(choices);
      break;
    case ParamType::Custom:
      text = allowed_text;
      break;
    case ParamType::Object: {
      std::vector<std::string> keys;
      if (fields) {
        keys.reserve(fields->size());
        for (const auto& f : *fields) keys.push_back(f.name);
      }
      text = "an object with keys " + join_names(keys);
      break;
    }
  }
  if (nullable) text += ", or null";
  return text;
}

std::optional<std::string> ParamSpec::check(const nlohmann::json& value) const {
  if (value.is_null() && nullable) return std::nullopt;
  const auto bad = [&] { return "value " + value_text(value) + " not allowed; allowed: " + allowed(); };
  switch (type) {
    case ParamType::Boolean:
      if (!value.is_boolean()) return bad();
      break;
    case ParamType::Integer:
    case ParamType::Number: {
      if (!value.is_number() || (type == ParamType::Integer && !value.is_number_integer())) return bad();
      const double x = value.get<double>();
      const auto out_of_range = [&] {
        return "value " + value_text(value) + " out of range; allowed: " + allowed();
      };
      if (!std::isfinite(x)) return out_of_range();
      // Integers a double (and so every JSON reader) holds exactly; also what a `long` holds.
      if (type == ParamType::Integer && std::abs(x) > kMaxExactInteger) return out_of_range();
      if (min && (min_open ? !(x > *min) : !(x >= *min))) return out_of_range();
      if (max && (max_open ? !(x < *max) : !(x <= *max))) return out_of_range();
      break;
    }
    case ParamType::Text:
      if (!value.is_string()) return bad();
      break;
    case ParamType::Choice:
      if (!value.is_string() ||
          std::find(choices.begin(), choices.end(), value.get<std::string>()) == choices.end()) {
        return bad();
      }
      break;
    case ParamType::Custom: {
      const std::vector<std::string> problems =
          custom_check ? custom_check(value) : std::vector<std::string>{};
      if (!problems.empty()) {
        std::string text;
        for (const auto& p : problems) text += (text.empty() ? "" : "; ") + p;
        return text;
      }
      break;
    }
    case ParamType::Object:
      if (!value.is_object()) return bad();
      break;
  }
  return std::nullopt;
}

std::vector<std::string> param_problems(const ParamSpecs& specs, const nlohmann::json& given,
                                        const std::string& where) {
  std::vector<std::string> problems;
  if (given.is_null()) return problems;
  if (!given.is_object()) {
    problems.push_back(where + ": expected an object of parameters, got " + value_text(given));
    return problems;
  }
  for (const auto& [key, value] : given.items()) {
    const auto spec =
        std::find_if(specs.begin(), specs.end(), [&key = key](const ParamSpec& s) { return s.name == key; });
    if (spec == specs.end()) {
      std::vector<std::string> known;
      known.reserve(specs.size());
      for (const auto& s : specs) known.push_back(s.name);
      problems.push_back(param_path(where, key) + ": unknown key '" + key +
                         "'; allowed: " + (known.empty() ? std::string("none") : join_names(known)));
      continue;
    }
    if (const auto problem = spec->check(value)) {
      problems.push_back(param_path(where, key) + ": " + *problem);
    } else if (spec->nested_problems && !value.is_null()) {
      for (auto& p : spec->nested_problems(value, param_path(where, key))) problems.push_back(std::move(p));
    }
  }
  return problems;
}

void throw_problems(const std::vector<std::string>& problems) {
  if (problems.empty()) return;
  if (problems.size() == 1) {  // where() names the parameter's path
    const std::size_t cut = problems.front().find(": ");
    if (cut != std::string::npos)
      throw ConfigError(problems.front().substr(0, cut), problems.front().substr(cut + 2));
  }
  std::string text;
  for (const auto& p : problems) text += (text.empty() ? "" : "\n") + p;
  throw ConfigError("", text);  // every line carries its own JSON path
}

}  // namespace core
}  // namespace fsweep
