#pragma once
/// @file search_order.hpp
/// The order of branch and bound's exploration (exact_search.hpp), a setting of a sweep's search
/// entry ("order", "max_open": sweep/sweep_plan.hpp).

#include <cstddef>

namespace fsweep {
inline namespace weightsearch {

/// The order branch and bound explores the region tree in (docs/weight-search.md, "Boxes out of
/// reach"). The behaviours it reports and its optimum are the same in both; the partition in
/// its certificate, its counts and its time are not.
enum class SearchOrder {
  /// Depth first: each branch goes on with one share of a split, the others wait as tasks
  /// (oneTBB's own order). Few branches wait, and finished behaviours (incumbents) come early;
  /// but branches forked near the root wait with their small bounds until the end, so the bound
  /// of AnytimeState rises only at the end.
  Depth,
  /// Smallest bound first: at a split every share waits, and a free thread takes the waiting
  /// branch of the smallest bound (the largest when more than max_open wait, to drain them),
  /// so AnytimeState's bound rises as the search goes on, at the cost of more waiting branches
  /// (each holds its runs' state) and later incumbents.
  Bound,
};

/// Default and largest number of branches SearchOrder::Bound keeps waiting.
inline constexpr std::size_t kDefaultMaxOpenBranches = 64;
inline constexpr std::size_t kMaxOpenBranchesLimit = 1'000'000;

/// Default and largest number of weight vectors a search of mode best runs alone first for its
/// first incumbent (BranchAndBound::probes).
inline constexpr std::size_t kDefaultProbes = 0;
inline constexpr std::size_t kMaxProbes = 10'000;

}  // namespace weightsearch
}  // namespace fsweep
