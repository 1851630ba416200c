#pragma once
/// @file statistics.hpp
/// Sample statistics shared by the result tables (summary.csv, compare, plan benchmarks).

#include <array>
#include <cstdint>
#include <string_view>
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

/// The nine statistics of a metric in summary.csv (report/aggregate.hpp) and
/// search_summary.csv (report/search_schema.hpp), in their column order.
inline constexpr std::array<std::string_view, 9> kStatisticNames{"mean",   "std", "min", "q05", "q25",
                                                                 "median", "q75", "q95", "max"};
using Statistics = std::array<double, kStatisticNames.size()>;

/// The statistics of `values` (sorted here): mean, standard deviation (n - 1 in the
/// denominator, two passes; 0 for one value), min, the type-7 quantiles of quantile_sorted(),
/// max. NaN for no values.
[[nodiscard]] Statistics describe(std::vector<double>& values);
/// The same over the multiset in which each value occurs `count` times, without expanding it
/// (sorted here by value): the mean and the variance by weighted Welford over the sorted values,
/// the quantiles by counted_quantile_sorted(). NaN for no values.
[[nodiscard]] Statistics describe_counted(std::vector<CountedValue>& values);

}  // namespace core
}  // namespace fsweep
