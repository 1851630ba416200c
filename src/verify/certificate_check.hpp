#pragma once
/// @file certificate_check.hpp
/// Checks the certificate of an exact weight search of mode best
/// (docs/dev/weight-search-design.md, "The certificate"; `fsweep verify`) without the search's
/// code: this layer does not link `weightsearch`. It reads the file's regions as plain boxes of
/// grid indices, and re-simulates regions through the simulation layer:
///
/// 1. Every line parses, its numbers of the JSON type they are (indices and counts integers,
///    not 6.0 or true), and every box lies in the box of the header. A region's `choices` (its
///    path in the search's tree) are read for their form only: step 4 proves every decision.
/// 2. The regions cover the box exactly: their counts sum to its size, and no vector is in two
///    of them (a bitmap of the box, up to 2^33 vectors; above that the count alone).
/// 3. Every finished region's objective is at least the optimum (minimised objectives; at most,
///    maximised), some finished region's is the optimum, and every pruned region's bound
///    exceeds it. An optimum of none (null: no vector's runs have a value) holds when every
///    region is a finished one without a value.
/// 4. For each region checked (all of them when the box has at most `full_limit` vectors, else
///    the optimal ones and a seeded sample of the others): its representative, the
///    lexicographically smallest vector of the region, is simulated twice per instance,
///    - once by the ordinary single-run path (Simulation::step()), and
///    - once taking at each decision the candidates Simulation::choice() gives for the region's
///      bounding box of weights and the representative's choice among them, after checking
///      that every vector of the region makes that choice (below);
///    both runs must make the same decisions (Simulation::decision_trace()). A finished
///    region's runs must end with its trace and objective; a pruned region's must reach, after
///    its recorded steps, a state whose bound (report/search_objective.hpp) is at least its
///    value (equal when the search that wrote it bounded as this build does; a build with a
///    weaker bound wrote less).
///
/// Every vector of a box makes the representative's choice c when, for each other candidate
/// j, d_j(w) = w . (f_j - f_c) beats the rounding of the two costs: the costs are sums of n
/// products of non-negative weights, each within gamma = (n + 2) 2^-53 of sum_k w_k |f_k|, so
/// d_j(w) - gamma w . (|f_j| + |f_c|) > 0 (j before c, which wins a tie) or >= 0 (j after c)
/// over the box proves it. That bound is linear in w, so its corners decide it; it is computed
/// with a further error allowance of (n + 1) 2^-53 times its terms' magnitudes. A box the
/// corners do not decide (a tie on its face, a non-finite feature) is checked point by point with
/// argmin_linear() itself, the function the runs choose by, up to 2^20 points; a larger one is
/// a problem.

#include <cstdint>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <vector>

#include "sim/run_spec.hpp"

namespace fsweep {
inline namespace verify {

/// A certificate's first line.
// NOLINTNEXTLINE(bugprone-exception-escape): false positive inside nlohmann::json's noexcept move
struct CertificateHeader {
  std::size_t search_id = 0;
  std::string strategy_label;
  std::string map_class;
  std::vector<std::string> weights;
  std::vector<std::vector<double>> values;
  std::string objective;
  std::string objective_column;
  bool minimize = true;
  /// NaN: no behaviour had a value.
  double optimum = 0.0;
  std::uint64_t vectors = 0;
  /// Per instance, its resolved parameters (SweepPlan::search_instance_json()).
  nlohmann::json instances;
};

/// Reads the first line of the certificate at `path`. Throws ConfigError naming the file and
/// field for a line that is not a certificate's header of a known format.
[[nodiscard]] CertificateHeader read_certificate_header(const std::string& path);

struct VerifyOptions {
  /// Boxes of at most this many vectors have every region re-simulated.
  std::uint64_t full_limit = 1'000'000;
  /// Larger boxes: regions re-simulated besides the optimal ones, drawn with `seed`.
  std::size_t sample = 1000;
  std::uint64_t seed = 1;
  /// Worker threads for the re-simulations (the result does not depend on them).
  int threads = 1;
};

struct CertificateCheck {
  std::uint64_t regions = 0;
  std::uint64_t finished = 0;
  std::uint64_t pruned = 0;
  /// Finished regions whose objective is the optimum, and their vectors.
  std::uint64_t optimal_regions = 0;
  std::uint64_t optimal_vectors = 0;
  /// The regions' vector counts sum to the box's size.
  bool counts_match = false;
  /// Whether no vector is in two regions was checked (a bitmap of the box), and what it found.
  bool overlap_checked = false;
  bool overlap_found = false;
  /// Regions re-simulated; true when they are a sample.
  std::uint64_t resimulated = 0;
  bool sampled = false;
  /// Decisions with several candidates whose choice was checked over a region, and the boxes
  /// decided by their corners and point by point.
  std::uint64_t decisions_checked = 0;
  std::uint64_t boxes_by_corners = 0;
  std::uint64_t boxes_by_points = 0;
  /// What does not hold, each naming the file's line and the region; empty: it verified.
  std::vector<std::string> problems;
};

/// Checks the certificate at `path` with header `header`; `specs` are its instances in the
/// header's order (the caller builds them from the sweep and checks that they are the header's
/// `instances`). Throws ConfigError naming the file and line for a line that does not parse;
/// every other failure is a problem of the result.
[[nodiscard]] CertificateCheck check_certificate(const std::string& path, const CertificateHeader& header,
                                                 std::span<const RunSpec> specs,
                                                 const VerifyOptions& options);

}  // namespace verify
}  // namespace fsweep
