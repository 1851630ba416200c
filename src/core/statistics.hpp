#pragma once
/// @file statistics.hpp
/// Sample statistics shared by the result tables (summary.csv, compare, plan benchmarks).

#include <cstdint>
#include <vector>

namespace fsweep {
inline namespace core {

/// Quantile of sorted (ascending) values, Hyndman and Fan (1996) type 7 (numpy's default):
/// h = (n - 1) q, x[floor h] + (h - floor h) (x[floor h + 1] - x[floor h]). At an order
/// statistic, or between equal neighbours, that value itself (so infinite values stay
/// infinite rather than becoming NaN). q in [0, 1] and values not empty, else
/// std::invalid_argument.
[[nodiscard]] double quantile_sorted(const std::vector<double>& sorted, double q);

/// A value that occurs `count` times.
struct CountedValue {
  double value = 0.0;
  std::uint64_t count = 0;
};

/// quantile_sorted() of the multiset in which each value occurs `count` times, without
/// expanding it (the exact weight search weighs each behaviour by its number of weight
/// vectors): `sorted` ascending by value, counts > 0, total count below 2^53. q in [0, 1] and
/// values not empty, else std::invalid_argument.
[[nodiscard]] double counted_quantile_sorted(const std::vector<CountedValue>& sorted, double q);

}  // namespace core
}  // namespace fsweep
