#pragma once
/// @file widest_frontier.hpp
/// The "widest frontier" baseline of Mei 2006 section V-C (a utility-based rule after their
/// reference [4]): go to the middle of the largest frontier inside the sensing region.

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

/// Section V-C "clusters the frontier cells ... into groups ... connected as neighbors":
/// the 8-connected components of `cells` (indices of `known`, ascending), plain 8-neighbour
/// adjacency as in the paper's grid (section IV-A), without FrontierMap's corner rule. Each
/// group ascending; groups ordered by their lowest index.
[[nodiscard]] std::vector<std::vector<int>> frontier_groups(const KnownMap& known,
                                                            std::span<const int> cells);

/// "Picks one in the middle": the paper does not define the middle; this is the member
/// nearest to the group's centroid (Euclidean between cell centres; ties: the lowest index),
/// the same rule as FrontierCluster::representative. For a straight opening it is the middle
/// cell along it; for a bent one it can sit nearer the bend than the middle along the border.
[[nodiscard]] int middle_cell(const KnownMap& known, std::span<const int> group);

/// Parameters: the sensing-region rule of step 1 (`region`, `pocket_cells`), as orientation's.
struct WidestFrontierParams : SensingRegionRule {};

/// The declared parameters (core/params.hpp).
[[nodiscard]] ParamDecl<WidestFrontierParams> widest_frontier_params();

/// The widest-frontier strategy of Mei 2006 section V-C:
/// 1. the frontier cells within the sensing region (split_by_sensing_region under the params'
///    SensingRegionRule: Euclidean <= d_s, d_s = sensor.range_m / resolution in cells, by
///    default every such cell; unreachable ones ignored);
/// 2. grouped by frontier_groups(); the widest frontier is the group with the most cells
///    (ties: the group with the lowest cell index);
/// 3. target: its middle_cell();
/// 4. no frontier cell in the region: the closest frontier cell outside, by path length;
///    none reachable: finish.
/// Stateless; works with any planner.
class WidestFrontier final : public Strategy {
 public:
  explicit WidestFrontier(const WidestFrontierParams& params = {}) : params_(params) {}
  [[nodiscard]] std::string name() const override { return "widest_frontier"; }
  [[nodiscard]] Decision decide(const Observation& obs) override;
  [[nodiscard]] std::unique_ptr<Strategy> clone() const override {
    return std::make_unique<WidestFrontier>(*this);
  }

 private:
  WidestFrontierParams params_;
};

}  // namespace strategies
}  // namespace fsweep
