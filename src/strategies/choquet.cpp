#include "strategies/choquet.hpp"

#include <array>
#include <cstddef>
#include <stdexcept>

namespace fsweep {
inline namespace strategies {
namespace {

/// The number of criteria n of a measure table of size 2^n; throws when it is not one.
int criteria_of_measure(std::size_t size) {
  for (int n = 1; n <= kMaxChoquetCriteria; ++n) {
    if (size == (std::size_t{1} << static_cast<unsigned>(n))) return n;
  }
  throw std::invalid_argument("fuzzy measure: table size " + std::to_string(size) +
                              " is not 2^n for 1 <= n <= " + std::to_string(kMaxChoquetCriteria));
}

}  // namespace

std::vector<MeasureViolation> fuzzy_measure_violations(std::span<const double> mu) {
  const int n = criteria_of_measure(mu.size());
  const unsigned all = (1U << static_cast<unsigned>(n)) - 1U;
  std::vector<MeasureViolation> out;
  for (unsigned a = 0; a <= all; ++a) {
    const double v = mu[a];
    if (!(v >= 0.0 && v <= 1.0)) out.push_back({MeasureViolation::Kind::OutOfRange, a, a});
  }
  if (mu[0] != 0.0) out.push_back({MeasureViolation::Kind::Boundary, 0U, 0U});
  if (mu[all] != 1.0) out.push_back({MeasureViolation::Kind::Boundary, all, all});
  for (unsigned a = 0; a <= all; ++a) {
    for (int j = 0; j < n; ++j) {
      const unsigned bit = 1U << static_cast<unsigned>(j);
      if ((a & bit) != 0) continue;
      if (mu[a] > mu[a | bit]) out.push_back({MeasureViolation::Kind::NotMonotone, a, a | bit});
    }
  }
  return out;
}

double choquet_integral(std::span<const double> u, std::span<const double> mu) {
  const int n = criteria_of_measure(mu.size());
  if (u.size() != static_cast<std::size_t>(n)) {
    throw std::invalid_argument("choquet_integral: " + std::to_string(u.size()) +
                                " utilities for a measure on " + std::to_string(n) + " criteria");
  }
  // 1. Criteria in increasing order of utility (insertion sort: n is small; ties keep the
  //    criterion order, which does not change the result).
  std::array<int, kMaxChoquetCriteria> order{};
  for (int i = 0; i < n; ++i) {
    int k = i;
    while (k > 0 && u[static_cast<std::size_t>(order[static_cast<std::size_t>(k - 1)])] >
                        u[static_cast<std::size_t>(i)]) {
      order[static_cast<std::size_t>(k)] = order[static_cast<std::size_t>(k - 1)];
      --k;
    }
    order[static_cast<std::size_t>(k)] = i;
  }
  // 2. Equation 6: A_(1) is every criterion; each step drops the criterion just passed.
  unsigned remaining = (1U << static_cast<unsigned>(n)) - 1U;
  double previous = 0.0;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const int j = order[static_cast<std::size_t>(i)];
    const double value = u[static_cast<std::size_t>(j)];
    sum += (value - previous) * mu[remaining];
    previous = value;
    remaining &= ~(1U << static_cast<unsigned>(j));
  }
  return sum;
}

std::string subset_name(unsigned subset, const std::string& letters) {
  if (subset == 0) return "{}";
  std::string out;
  for (std::size_t j = 0; j < letters.size(); ++j) {
    if ((subset >> j) & 1U) out += letters[j];
  }
  return out;
}

}  // namespace strategies
}  // namespace fsweep
