#pragma once
/// @file readable_number.hpp
/// Numbers for people (terminal tables, report pages, captions): rounded to a few significant
/// digits, thousands separated. The CSV files keep full precision (csv_format.hpp).

#include <string>

namespace fsweep {
inline namespace core {

/// How readable_number() writes a number's sign.
enum class Sign {
  Negative,  ///< "-" before negative numbers only
  Always,    ///< "+" before positive numbers too (differences)
};

/// `v` rounded for reading: at least `significant` significant digits (1 to 17), trailing zeros
/// after the point dropped; the integer part in groups of three digits separated by commas. A
/// number of `significant` or more digits before the point is rounded to an integer (48,495.65 with
/// 4 digits reads "48,496"); below 0.0001 in magnitude it is written in scientific notation
/// ("1.235e-05"). "" for NaN (no value); "inf" and "-inf" (or "+inf") as they are; "0" for zero.
[[nodiscard]] std::string readable_number(double v, int significant = 4, Sign sign = Sign::Negative);

}  // namespace core
}  // namespace fsweep
