#pragma once
/// @file gbl.hpp
/// González-Baños and Latombe's next-best-view exploration as evaluated by Holz 2010
/// (section IV-B, equation 3): random candidates near the frontier, utility I(p) exp(-lambda L).

#include <cstdint>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "core/params.hpp"
#include "core/random.hpp"
#include "strategies/strategy.hpp"
#include "world/sensor.hpp"

namespace fsweep {
inline namespace strategies {

/// Information-gain scans for strategies (Holz 2010 sections IV-B and IV-C): a Sensor for the
/// observation's sensor model (grid or beams, with its parameters) and map resolution, built
/// on first use and rebuilt only when either changes. Copies share the sensor's immutable ray
/// tables.
class GainScanner {
 public:
  /// Sensor::gain() on obs.known from `p`, facing scan_heading(obs, p).
  [[nodiscard]] ScanCounts at(const Observation& obs, Cell p);

  /// The heading assumed for a simulated scan at `p` (radians, as heading_angle()): the
  /// direction of the straight line from the robot to p (the robot's last leg towards p; the
  /// path's actual last step is not known to strategies), or the robot's current heading when
  /// p is the robot's cell. Matters only with a field of view below 360 degrees or with the
  /// beam model (its beams turn with the heading).
  [[nodiscard]] static double scan_heading(const Observation& obs, Cell p);

 private:
  Sensor sensor_;
  SensorParams params_;
  double resolution_m_ = 0.0;
  bool ready_ = false;
};

/// Parameters (JSON keys as named).
struct GblParams {
  /// Number of random draws of candidate locations per decision, in [1, 100000].
  int samples = 30;
  /// Sampling neighbourhood: candidates are known free cells whose centre lies within this
  /// Euclidean distance (metres, inclusive) of a frontier cell's centre; >= 0 (0: the frontier
  /// cell itself).
  double radius_m = 1.0;
  /// Weight of travel cost in equation 3 (per metre), >= 0; 0.2 as in Holz 2010 and the
  /// original authors.
  double lambda = 0.2;
};

/// Reads and validates the parameters; every problem is reported with its JSON path.
/// The declared parameters (core/params.hpp).
[[nodiscard]] ParamDecl<GblParams> gbl_params();

/// One evaluated candidate of a GBL decision.
struct GblCandidate {
  Cell cell;
  /// Path length from the robot (metres, obs.distances).
  double length_m = 0.0;
  /// Information gain I(p): unknown area a scan from p would see on the known map (m^2).
  double gain_m2 = 0.0;
};

/// The GBL strategy:
/// 1. F = the frontier cells of obs.clusters (open_frontier_cells: so any filter the engine
///    applies to the clusters applies here); with obs.segment_mask set (the `seg` heuristic),
///    only those in the robot's segment, and step 2 draws only cells of that segment (when no
///    frontier cell is in it, the mask is ignored, as restrict_to_segment() does); none: finish.
/// 2. `samples` draws from the strategy's generator (stream "gbl" of the seed given at
///    construction), each: a frontier cell f uniformly from F (ascending index), then a cell
///    uniformly among the known free cells within radius_m of f in row-major order, leaving out
///    the robot's cell (it has just been scanned) and cells where an earlier visit revealed
///    nothing (see below). A draw with no such cell yields nothing; a cell drawn again is kept
///    once, at its first position.
/// 3. Candidates the robot cannot reach over known free space are dropped; L(p) is the path
///    length from obs.distances.
/// 4. I(p) = GainScanner::at(obs, p).unknown x resolution^2 (heading: GainScanner::scan_heading).
/// 5. Among candidates with I(p) > 0, maximise u(p) = I(p) exp(-lambda L(p)) (equation 3),
///    compared as log I(p) - lambda L(p) so that long paths do not underflow; ties: the lowest
///    candidate position.
/// 6. No candidate with I(p) > 0: the nearest cluster representative by path length (ties:
///    lowest cluster); none reachable: finish.
/// State: the generator, and the cells where the robot arrived at its previous goal while the
/// whole trip revealed nothing (known_count unchanged since the previous decision): such a
/// goal's estimated gain cannot be realised, so it is never drawn again. clone() copies both.
class Gbl final : public Strategy {
 public:
  Gbl(const GblParams& params, std::uint64_t seed);

  [[nodiscard]] std::string name() const override { return "gbl"; }
  [[nodiscard]] Decision decide(const Observation& obs) override;
  [[nodiscard]] std::unique_ptr<Strategy> clone() const override { return std::make_unique<Gbl>(*this); }
  [[nodiscard]] const GblParams& params() const { return params_; }

  /// Steps 1-4 of a decision: the reachable candidates in draw order, with L and I. Advances
  /// the generator and updates the memory of fruitless goals exactly as decide() does.
  [[nodiscard]] std::vector<GblCandidate> candidates(const Observation& obs);

  /// Step 5 over `c`: the position of the best candidate with gain > 0, or -1.
  [[nodiscard]] static int best(const std::vector<GblCandidate>& c, double lambda);

  /// Equal parameters, generator state and memory.
  friend bool operator==(const Gbl& a, const Gbl& b) {
    return a.params_.samples == b.params_.samples && a.params_.radius_m == b.params_.radius_m &&
           a.params_.lambda == b.params_.lambda && a.rng_ == b.rng_ && a.fruitless_ == b.fruitless_ &&
           a.last_known_count_ == b.last_known_count_;
  }

 private:
  GblParams params_;
  Rng rng_;
  GainScanner scanner_;
  /// Cell indices of fruitless goals, ascending.
  std::vector<int> fruitless_;
  /// known_count() at the previous decision; -1 before the first.
  int last_known_count_ = -1;
};

}  // namespace strategies
}  // namespace fsweep
