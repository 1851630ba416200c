/// @file sweep_values.cpp
/// Sweep values (a value, a list, a range) and a strategy entry's parameter combinations.

#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <set>

#include "core/json_excerpt.hpp"
#include "sweep/sweep_axes.hpp"

namespace fsweep {
inline namespace sweep {
namespace {

using nlohmann::json;

const char* const kAllowedForms =
    "allowed: a value, a non-empty list of values, or {\"range\": [lo, hi], \"step\": s} with lo <= hi, s > "
    "0";

/// Digits after the decimal point in the shortest text that reads back to `x` (0.1 -> 1,
/// 2.5e-3 -> 4, 250 -> 0).
int decimals(double x) {
  char buf[64];
  const auto res = std::to_chars(buf, buf + sizeof(buf), x, std::chars_format::scientific);
  const std::string s(buf, res.ptr);
  const std::size_t e = s.find('e');
  const std::size_t dot = s.find('.');
  const int mantissa_decimals = dot == std::string::npos ? 0 : static_cast<int>(e - dot - 1);
  const int exponent = std::stoi(s.substr(e + 1));
  return std::max(0, mantissa_decimals - exponent);
}

/// `x` rounded to `digits` decimals, as the double nearest to that decimal number.
double round_decimals(double x, int digits) {
  char buf[512];
  const auto res = std::to_chars(buf, buf + sizeof(buf), x, std::chars_format::fixed, digits);
  if (res.ec != std::errc()) return x;
  double out = x;
  std::from_chars(buf, res.ptr, out);
  return out == 0.0 ? 0.0 : out;  // no negative zero
}

bool fits_int64(const json& v) {
  return v.is_number_integer() &&
         (!v.is_number_unsigned() || v.get<std::uint64_t>() <= static_cast<std::uint64_t>(INT64_MAX));
}

std::vector<json> expand_range(const json& v, const std::string& where, std::vector<std::string>& problems) {
  const std::size_t before = problems.size();
  for (const auto& [key, value] : v.items()) {
    if (key != "range" && key != "step") {
      problems.push_back(sweep_detail::concat(
          {where, "/", key, ": unknown key '", key, "' in a range; allowed: range, step"}));
    }
  }
  const json& r = v.at("range");
  const bool range_ok = r.is_array() && r.size() == 2 && r[0].is_number() && r[1].is_number();
  if (!range_ok) {
    problems.push_back(where + "/range: expected [lo, hi] with two numbers, got " +
                       sweep_detail::value_text(r));
  }
  if (!v.contains("step")) {
    problems.push_back(where + ": a range needs \"step\", a number > 0 (" + kAllowedForms + ")");
  } else if (!v.at("step").is_number() || !(v.at("step").get<double>() > 0.0)) {
    problems.push_back(where + "/step: value " + sweep_detail::value_text(v.at("step")) +
                       " not allowed; allowed: a number > 0");
  }
  if (range_ok && r[0].get<double>() > r[1].get<double>()) {
    problems.push_back(where + "/range: lo " + sweep_detail::value_text(r[0]) + " > hi " +
                       sweep_detail::value_text(r[1]) + "; allowed: lo <= hi");
  }
  if (problems.size() != before) return {};

  const json& step = v.at("step");
  std::vector<json> out;
  if (fits_int64(r[0]) && fits_int64(r[1]) && step.is_number_integer()) {
    // Integers stay integers; unsigned arithmetic is exact here because lo <= hi.
    const auto lo = r[0].get<std::int64_t>();
    const auto hi = r[1].get<std::int64_t>();
    const auto s = step.get<std::uint64_t>();
    const std::uint64_t n = (static_cast<std::uint64_t>(hi) - static_cast<std::uint64_t>(lo)) / s + 1;
    if (n > kMaxAxisValues) {
      problems.push_back(where + ": the range has " + sweep_detail::with_thousands(n) +
                         " values; allowed: at most " + sweep_detail::with_thousands(kMaxAxisValues) +
                         " per axis");
      return {};
    }
    out.reserve(n);
    for (std::uint64_t i = 0; i < n; ++i) {
      const auto value = static_cast<std::int64_t>(static_cast<std::uint64_t>(lo) + i * s);
      out.push_back(value >= 0 ? json(static_cast<std::uint64_t>(value)) : json(value));
    }
    return out;
  }
  const double lo = r[0].get<double>();
  const double hi = r[1].get<double>();
  const double s = step.get<double>();
  const double q = (hi - lo) / s;
  if (!std::isfinite(q) || q + 1.0 > static_cast<double>(kMaxAxisValues)) {
    problems.push_back(where + ": the range has more than " + sweep_detail::with_thousands(kMaxAxisValues) +
                       " values; allowed: at most " + sweep_detail::with_thousands(kMaxAxisValues) +
                       " per axis");
    return {};
  }
  const auto n = static_cast<std::uint64_t>(std::floor(q + 1e-9)) + 1;
  const int digits = std::max({decimals(lo), decimals(hi), decimals(s)});
  out.reserve(n);
  for (std::uint64_t i = 0; i < n; ++i) {
    double value = lo + static_cast<double>(i) * s;
    if (i + 1 == n && std::abs(value - hi) <= 1e-9 * s) value = hi;
    // Beyond 30 decimals the inputs are not decimal literals worth matching: keep lo + i*s.
    if (digits <= 30) value = round_decimals(value, digits);
    out.emplace_back(value);
  }
  return out;
}

}  // namespace

namespace sweep_detail {

std::string value_text(const json& v) { return json_excerpt(v, kMaxExcerptChars - 3); }

std::string strip_path(const std::string& message, const std::string& path) {
  const std::string prefix = path + ": ";
  return message.rfind(prefix, 0) == 0 ? message.substr(prefix.size()) : message;
}

std::string value_path(const json& written, const std::string& where, std::size_t k) {
  if (written.is_array()) return where + "/" + std::to_string(k);
  if (written.is_object() && written.contains("range")) return where + "/range";
  return where;
}

std::string concat(std::initializer_list<std::string_view> parts) {
  std::size_t size = 0;
  for (const auto part : parts) size += part.size();
  std::string out;
  out.reserve(size);
  for (const auto part : parts) out += part;
  return out;
}

std::string with_thousands(std::uint64_t n) {
  std::string digits = std::to_string(n);
  std::string out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

}  // namespace sweep_detail

std::vector<json> expand_values(const json& v, const std::string& where, std::vector<std::string>& problems,
                                bool repeats_allowed) {
  if (v.is_object() && v.contains("range")) return expand_range(v, where, problems);
  if (!v.is_array()) return {v};
  if (v.empty()) {
    problems.push_back(where + ": empty list; " + kAllowedForms);
    return {};
  }
  if (v.size() > kMaxAxisValues) {
    problems.push_back(where + ": the list has " + sweep_detail::with_thousands(v.size()) +
                       " values; allowed: at most " + sweep_detail::with_thousands(kMaxAxisValues) +
                       " per axis");
    return {};
  }
  if (repeats_allowed) return std::vector<json>(v.begin(), v.end());
  // Equal values would give runs with equal run keys (json compares 1 and 1.0 as equal).
  std::set<json> seen;
  bool duplicate = false;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (!seen.insert(v[i]).second) {
      problems.push_back(
          where + "/" + std::to_string(i) + ": value " + sweep_detail::value_text(v[i]) +
          " repeats an earlier element; allowed: distinct values (repeated ones would be the same runs)");
      duplicate = true;
    }
  }
  if (duplicate) return {};
  return std::vector<json>(v.begin(), v.end());
}

std::uint64_t WeightSearch::vectors() const {
  std::uint64_t n = 1;
  for (const auto& v : values) n *= v.size();
  return n;
}

std::uint64_t StrategyEntry::count() const {
  if (search) return 0;
  std::uint64_t n = 1;
  for (const auto& g : groups) n *= g.combos.size();
  return n;
}

json StrategyEntry::params_at(std::uint64_t k) const {
  if (groups.empty()) return nullptr;
  json params = json::object();
  // Mixed radix, last group fastest.
  for (auto g = groups.rbegin(); g != groups.rend(); ++g) {
    const std::uint64_t size = g->combos.size();
    const auto& combo = g->combos[static_cast<std::size_t>(k % size)];
    k /= size;
    for (std::size_t i = 0; i < g->names.size(); ++i) params[g->names[i]] = combo[i];
  }
  return params;
}

}  // namespace sweep
}  // namespace fsweep
