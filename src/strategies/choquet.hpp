#pragma once
/// @file choquet.hpp
/// The discrete Choquet integral over a fuzzy measure (Holz 2010 section IV-C, equation 6;
/// the MCDM aggregation of Basilico and Amigoni). Generic in the number of criteria: a subset
/// of the n criteria is a bitmask, bit j set when criterion j belongs to it, and a measure is
/// a table of 2^n values indexed by that bitmask.

#include <span>
#include <string>
#include <vector>

namespace fsweep {
inline namespace strategies {

/// Largest number of criteria supported (the measure table has 2^n entries).
inline constexpr int kMaxChoquetCriteria = 16;

/// One violation of the fuzzy-measure axioms, found by fuzzy_measure_violations().
struct MeasureViolation {
  enum class Kind {
    /// mu(subset) is not a number in [0, 1]; `superset` is unused (equal to `subset`).
    OutOfRange,
    /// mu(empty set) != 0 or mu(all criteria) != 1; `superset` is unused.
    Boundary,
    /// subset is a proper subset of superset but mu(subset) > mu(superset).
    NotMonotone,
  };
  Kind kind = Kind::OutOfRange;
  unsigned subset = 0;
  unsigned superset = 0;
};

/// Every violation of the axioms of a fuzzy measure on n criteria, mu.size() == 2^n with
/// 1 <= n <= kMaxChoquetCriteria (else std::invalid_argument): mu(empty) = 0, mu(all) = 1,
/// every value in [0, 1], and mu(A) <= mu(B) for A a subset of B. Monotonicity is checked on
/// the pairs that differ by one criterion (B = A plus criterion j), which implies it for every
/// pair; a violation names such a pair. Order: by subset bitmask, then by the added criterion.
[[nodiscard]] std::vector<MeasureViolation> fuzzy_measure_violations(std::span<const double> mu);

/// The Choquet integral of the utilities `u` (one per criterion, each in [0, 1]) with respect
/// to the fuzzy measure `mu` (mu.size() == 2^u.size(), validated by the caller):
///   sum_{i=1..n} (u_(i) - u_(i-1)) mu(A_(i)),
/// with u_(1) <= ... <= u_(n) the utilities in increasing order, u_(0) = 0, and A_(i) the set
/// of criteria at sorted positions i..n. Criteria with equal utility may be ordered either way:
/// the term between them is zero, so the result does not depend on it (and equals the paper's
/// A_(i) = {j : u_(i) <= u_j}). With an additive mu it is the weighted average sum_j mu({j}) u_j.
/// Throws std::invalid_argument when the sizes do not match or n is out of range. No allocation.
[[nodiscard]] double choquet_integral(std::span<const double> u, std::span<const double> mu);

/// Name of a subset from one-letter criterion names, in criterion order: with names "LIO",
/// bitmask 0b101 is "LO"; the empty set is "{}".
[[nodiscard]] std::string subset_name(unsigned subset, const std::string& letters);

}  // namespace strategies
}  // namespace fsweep
