/// @file readable_number.cpp
/// readable_number() (readable_number.hpp).

#include "core/readable_number.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace fsweep {
inline namespace core {
namespace {

/// "1234567" -> "1,234,567" (digits only).
std::string group_thousands(const std::string& digits) {
  std::string out;
  const std::size_t n = digits.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (i > 0 && (n - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

}  // namespace

std::string readable_number(double v, int significant, Sign sign) {
  if (significant < 1 || significant > 17)
    throw std::invalid_argument("readable_number: significant not in [1, 17]");
  if (std::isnan(v)) return "";
  const std::string plus = sign == Sign::Always && v > 0 ? "+" : "";
  if (std::isinf(v)) return v > 0 ? plus + "inf" : "-inf";
  if (v == 0.0) return "0";
  const double magnitude = std::abs(v);
  char buf[64];
  if (magnitude < 1e-4) {
    std::snprintf(buf, sizeof buf, "%.*e", significant - 1, v);
    return plus + buf;
  }
  const int exponent = static_cast<int>(std::floor(std::log10(magnitude)));
  const int decimals = std::max(0, significant - 1 - exponent);
  std::snprintf(buf, sizeof buf, "%.*f", decimals, magnitude);
  std::string text = buf;
  if (text.find('.') != std::string::npos) {
    while (text.back() == '0') text.pop_back();
    if (text.back() == '.') text.pop_back();
  }
  const std::size_t point = std::min(text.find('.'), text.size());
  text = group_thousands(text.substr(0, point)) + text.substr(point);
  if (text == "0") return "0";  // a value that rounds to zero has no sign
  return (v < 0 ? "-" : plus) + text;
}

}  // namespace core
}  // namespace fsweep
