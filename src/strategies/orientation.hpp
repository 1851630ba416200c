#pragma once
/// @file orientation.hpp
/// Orientation-based target selection, Mei 2006 section IV-B (steps 1-5, Figures 3 and 4).

#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <span>
#include <string>
#include <vector>

#include "core/params.hpp"
#include "strategies/sensing_region.hpp"
#include "strategies/strategy.hpp"

namespace fsweep {
inline namespace strategies {

/// Parameters (JSON keys as named): the sensing-region rule of step 1 (`region`,
/// `pocket_cells`: SensingRegionRule) and the walk of step 3.
struct OrientationParams : SensingRegionRule {
  /// The walk along the list stops before the first cell whose distance from the list head is
  /// not below head_distance_ratio * d_s (section IV-B step 3(b): 0.7, so that the robot at
  /// the target still senses at least 0.3 d_s beyond the head). In (0, 1].
  double head_distance_ratio = 0.7;
};

/// Reads and validates the parameters; every problem is reported with its JSON path.
/// The declared parameters (core/params.hpp).
[[nodiscard]] ParamDecl<OrientationParams> orientation_params();

/// Section IV-B step 2: `cells` (indices of `known`) ordered clockwise on screen starting from
/// the robot's left. The left is heading_angle(heading) - 90 degrees (heading 0 = east: the
/// left is north, -y); a cell's key is its clockwise angle from that direction, atan2(dy, dx)
/// minus the left's angle wrapped into [0, 2 pi), so the list sweeps left, front, right, back
/// (section III-A). Ties: Euclidean distance from the robot, then cell index. The robot's own
/// cell has no direction and is left out.
[[nodiscard]] std::vector<int> clockwise_from_left(const KnownMap& known, Cell robot, int heading,
                                                   std::span<const int> cells);

/// Section IV-B step 3: the position in `ordered` (non-empty) of the target. Starting at the
/// head (position 0), the walk moves to the next cell while (a) it is an 8-neighbour of the
/// current one (no jump) and (b) its Euclidean distance from the head is below `limit_cells`
/// (0.7 d_s). It stops at the first cell that fails either; the target is the last cell
/// reached, the farthest cell along the border that satisfies both conditions (the paper's
/// reason for (b): the target should be as far along as keeps the head in sensing range with
/// 0.3 d_s to spare; picking the head itself is the behaviour of Figure 5 it avoids).
[[nodiscard]] std::size_t walk_from_head(const KnownMap& known, std::span<const int> ordered,
                                         double limit_cells);

/// The orientation strategy of Mei 2006 section IV-B:
/// 1. the frontier cells within the sensing region (split_by_sensing_region under the params'
///    SensingRegionRule: Euclidean <= d_s, d_s = sensor.range_m / resolution in cells, by
///    default every such cell; unreachable ones ignored);
/// 2. listed clockwise from the robot's left (clockwise_from_left);
/// 3. target: the end of the walk from the head (walk_from_head, limit head_distance_ratio d_s);
/// 4. none in the region: the closest frontier cell outside, by path length (closest_outside);
/// 5. no reachable frontier cell at all: finish.
/// If the only frontier cell in the region is the robot's own cell (possible with a limited
/// field of view or a noisy sensor), the target is that cell: the engine looks again from
/// there and drops it if nothing new is seen. The paper is silent on this case.
/// Stateless apart from its parameters; works with any planner.
class Orientation final : public Strategy {
 public:
  explicit Orientation(const OrientationParams& params) : params_(params) {}

  [[nodiscard]] std::string name() const override { return "orientation"; }
  [[nodiscard]] Decision decide(const Observation& obs) override;
  [[nodiscard]] std::unique_ptr<Strategy> clone() const override {
    return std::make_unique<Orientation>(*this);
  }
  [[nodiscard]] const OrientationParams& params() const { return params_; }

 private:
  OrientationParams params_;
};

}  // namespace strategies
}  // namespace fsweep
