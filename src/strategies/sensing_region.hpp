#pragma once
/// @file sensing_region.hpp
/// The frontier cells inside and outside the robot's current sensing region, shared by the
/// two target-selection rules of Mei 2006 (orientation, section IV-B; widest frontier,
/// section V-C).

#include <string>
#include <vector>

#include "core/params.hpp"
#include "strategies/strategy.hpp"

namespace fsweep {
inline namespace strategies {

/// Which frontier cells count as "within the current sensing region" (Mei 2006 section IV-B
/// step 1). The paper defines the sensing range as a circle of radius d_s and frontier cells as
/// the known free cells along the border with the unexplored area; it says no more, so the
/// two readings below are options. Defaults: the circle, every border cell.
struct SensingRegionRule {
  /// "disc": every frontier cell within d_s (the circle, whether in view or not); "visible":
  /// only those in view from the robot's cell as well (centre ray clear on the known map,
  /// centre_ray_clear(): known occupied cells block, unknown ones do not).
  std::string region = "disc";
  /// 0: every frontier cell counts. N > 0: a frontier cell whose unknown 8-neighbours all lie
  /// in enclosed pockets of at most N unknown cells (8-connected components of unknown cells
  /// that reach no other unknown cell: holes left in explored space, e.g. by sensor shadows)
  /// does not count; it stays a frontier cell and a goal for step 4.
  int pocket_cells = 0;
};

/// Declares the two options of SensingRegionRule on a params struct P that has members
/// `region` and `pocket_cells`, each recorded only when set (run keys made before them stay).
template <class P>
void declare_sensing_region_params(ParamDecl<P>& d) {
  d.choice("region", &P::region, {"disc", "visible"},
           "which frontier cells are in the sensing region (Mei 2006 section IV-B step 1): all within d_s, "
           "or only those also in view")
      .omitted_at_default();
  d.integer("pocket_cells", &P::pocket_cells,
            "leave out of the sensing region the frontier cells that border only enclosed unknown pockets "
            "of at most this many cells (0: none left out)")
      .range(0, 1000000)
      .unit("cells")
      .omitted_at_default();
}

/// Frontier cells of one decision split by the sensing region (cell indices, ascending).
struct SensingRegion {
  /// Reachable frontier cells whose centre lies within d_s of the robot's centre (Euclidean,
  /// inclusive), d_s = sensor.range_m / resolution_m in cells. The robot's own cell included.
  std::vector<int> inside;
  /// Frontier cells beyond d_s (reachability not checked: see closest_outside()).
  std::vector<int> outside;
};

/// The frontier cells a strategy may choose: the members of obs.clusters, i.e. every frontier
/// cell of obs.frontiers except those the engine has dropped as unobservable or unreachable
/// goals (clusters are a partition of exactly those cells). Ascending cell indices.
[[nodiscard]] std::vector<int> open_frontier_cells(const Observation& obs);

/// Splits open_frontier_cells(obs) by the sensing region (Mei 2006 section IV-B step 1) under
/// `rule`. Cells within d_s that the rule leaves out (out of view, or bordering only small
/// pockets) go to `outside`. In-region cells that the robot cannot reach over known free space
/// (obs.distances, no bound) are treated as absent: they are in neither list.
[[nodiscard]] SensingRegion split_by_sensing_region(const Observation& obs,
                                                    const SensingRegionRule& rule = {});

/// Mei 2006 section IV-B steps 4 and 5 (and the same rule in section V-C): the frontier cell of
/// `outside` nearest to the robot by path length (obs.distances.nearest_from_robot; ties: the
/// lowest index), or Decision::finish() when none is reachable.
[[nodiscard]] Decision closest_outside(const Observation& obs, const std::vector<int>& outside);

/// For the sensing-region rules of orientation and widest_frontier (which read frontier cells
/// rather than obs.clusters): when obs.segment_mask is set (the `seg` heuristic restricts this
/// decision, src/sim/heuristics.hpp), keeps in `region.inside` and `region.outside` only the
/// cells of the robot's segment, unless none of either list is in it; then, and when the mask
/// is null, leaves `region` unchanged. Order is kept.
void restrict_to_segment(const Observation& obs, SensingRegion& region);

}  // namespace strategies
}  // namespace fsweep
