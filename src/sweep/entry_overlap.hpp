#pragma once
/// @file entry_overlap.hpp
/// Strategy entries of one sweep that reach the same configuration (the same strategy with
/// equal parameters, the label aside: it is not part of a run's key), found when the sweep is
/// read, without expanding its runs.

#include <string>
#include <vector>

#include "sweep/sweep_plan.hpp"

namespace fsweep {
inline namespace sweep {
namespace sweep_detail {

/// Adds a problem for each strategy entry (search entries aside: they have no runs) that shares
/// a configuration with an earlier entry, naming both and one shared configuration.
///
/// Two entries of one strategy overlap when some configuration is in both: every parameter
/// either entry sets takes, in the other, a value of its axis (the declared default where the
/// other does not set it). Parameters that vary independently are compared value set by value
/// set, so entries of billions of configurations cost no more than their axes. Parameters tied
/// by a zip group (in either entry) are compared as tuples: the tuples of the side with fewer
/// are looked up in the other's groups, at most kMaxOverlapTuples of them; a linked set of
/// parameters with more on both sides is not checked. Entries of a single configuration each,
/// the common case of long generated sweeps, are compared by a hash of their parameters:
/// linear in their number.
void check_entry_overlaps(const std::vector<StrategyEntry>& entries, std::vector<std::string>& problems);

/// Most tuples of linked zipped parameters enumerated for one pair of entries.
inline constexpr std::uint64_t kMaxOverlapTuples = 10'000'000;

}  // namespace sweep_detail
}  // namespace sweep
}  // namespace fsweep
