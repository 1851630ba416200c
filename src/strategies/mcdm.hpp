#pragma once
/// @file mcdm.hpp
/// Multi-criteria decision making exploration (Basilico and Amigoni) on an occupancy grid, as
/// evaluated by Holz 2010 section IV-C: travel cost, information gain and overlap, normalised
/// over the candidates (equation 5) and aggregated by the Choquet integral (equation 6).

#include <array>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "core/params.hpp"
#include "strategies/gbl.hpp"
#include "strategies/strategy.hpp"

namespace fsweep {
inline namespace strategies {

/// Criterion bits of a subset of {L, I, O} (the fuzzy measure's index, choquet.hpp).
inline constexpr unsigned kMcdmL = 1U;  ///< travel cost L
inline constexpr unsigned kMcdmI = 2U;  ///< information gain I
inline constexpr unsigned kMcdmO = 4U;  ///< overlap O

/// Parameters. JSON: {"measure": {"L": .., "I": .., "O": .., "LI": .., "LO": .., "IO": ..}},
/// the values of the six proper non-empty subsets of {L, I, O} (all six required when
/// "measure" is given; mu(empty) = 0 and mu(LIO) = 1 are fixed).
struct McdmParams {
  /// mu indexed by subset bitmask (kMcdmL | kMcdmI | kMcdmO). Default: Holz 2010 Table I.
  std::array<double, 8> measure{0.0, 0.2, 0.4, 0.9, 0.4, 0.6, 0.8, 1.0};
};

/// The declared parameters (core/params.hpp): "measure", an object of the six proper
/// non-empty subsets of {L, I, O} (all six required), each a number in [0, 1], monotone
/// (mu(A) <= mu(B) for A a subset of B; a violation names the pair of subsets).
[[nodiscard]] ParamDecl<McdmParams> mcdm_params();

/// One evaluated candidate of an MCDM decision.
struct McdmCandidate {
  Cell cell;
  double length_m = 0.0;            ///< L: path length from the robot (metres)
  double gain_m2 = 0.0;             ///< I: unknown area a scan from the cell would see (m^2)
  double overlap_m2 = 0.0;          ///< O: known area a scan from the cell would see (m^2)
  std::array<double, 3> utility{};  ///< u_L, u_I, u_O in [0, 1]
  double global = 0.0;              ///< Choquet integral of the utilities (equation 6)
};

/// The MCDM strategy:
/// 1. candidates: the representatives of obs.clusters that the robot can reach (L from
///    obs.distances); none: finish;
/// 2. I(p) and O(p) from one simulated scan at p (GainScanner, heading as
///    GainScanner::scan_heading): I the unknown area, O the known area it would see.
///    The paper splits the cells V_p in view into "new" (uncertain) and "old" (nearly certain)
///    by a probability threshold k; I maximises the entropy over new cells and O is meant to
///    favour much well-known map in view (good localisation). On this deterministic grid every
///    cell is either unknown (p = 0.5, entropy 1 bit: "new") or known (p = 0 or 1, entropy 0:
///    "old"), so the entropy over new cells is their count, and the entropy over old cells is
///    always 0 and cannot rank candidates; its intent, the amount of certain map in view, is
///    their count. Both are in m^2 (count x resolution^2);
/// 3. equation 5 and its analogues: u_L = 1 - (L - min L) / (max L - min L),
///    u_I = (I - min I) / (max I - min I), u_O likewise, over the candidates of this decision;
///    when max == min the criterion does not tell the candidates apart and every candidate gets
///    utility 1 on it (a single candidate gets 1 on every criterion);
/// 4. global utility: choquet_integral((u_L, u_I, u_O), measure); maximise; ties: the lowest
///    cluster index.
/// Stateless apart from its parameters and the scanner cache; works with any planner.
class Mcdm final : public Strategy {
 public:
  explicit Mcdm(const McdmParams& params) : params_(params) {}

  [[nodiscard]] std::string name() const override { return "mcdm"; }
  [[nodiscard]] Decision decide(const Observation& obs) override;
  [[nodiscard]] std::unique_ptr<Strategy> clone() const override { return std::make_unique<Mcdm>(*this); }
  [[nodiscard]] const McdmParams& params() const { return params_; }

  /// Steps 1-4: every reachable candidate in cluster order, evaluated.
  [[nodiscard]] std::vector<McdmCandidate> evaluate(const Observation& obs);

 private:
  McdmParams params_;
  GainScanner scanner_;
};

}  // namespace strategies
}  // namespace fsweep
