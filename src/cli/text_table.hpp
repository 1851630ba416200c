#pragma once
/// @file text_table.hpp
/// Numbers for the terminal tables of the CLI commands.

#include <array>
#include <cmath>
#include <cstdio>
#include <string>

namespace fsweep::cli {

/// `v` with `decimals` digits after the point ("12.50"); "-" for NaN (no value).
[[nodiscard]] inline std::string fixed_decimals(double v, int decimals) {
  if (std::isnan(v)) return "-";
  std::array<char, 64> buf{};
  std::snprintf(buf.data(), buf.size(), "%.*f", decimals, v);
  return buf.data();
}

}  // namespace fsweep::cli
