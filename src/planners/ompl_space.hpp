#pragma once
/// @file ompl_space.hpp
/// The OMPL side of the grid (used by src/planners/ompl_planner.cpp only; includes OMPL headers,
/// which only the planners library sees): R2 in cell units over a KnownMap, a state validity
/// checker (the cell under the state is known free) and an exact motion validator
/// (check_segment() of src/planners/ompl_segment_walk.hpp).

#include <ompl/base/SpaceInformation.h>
#include <ompl/base/State.h>

#include "planners/ompl_segment_walk.hpp"
#include "world/known_map.hpp"

namespace fsweep {
inline namespace planners {

/// The (x, y) of an R2 state of make_grid_space_information(), in cell units.
[[nodiscard]] PlanePoint point_of(const ompl::base::State* state);

/// Set-up SpaceInformation of R2 over `known` in cell units, bounds [0, width] x [0, height]:
/// a state is valid if the cell under it is known free; a motion is valid if check_segment()
/// says so under `allow_corner_cutting`; the default projection (KPIECE1) is the identity onto
/// the plane with cells of max(1, max(width, height) / 20) map cells. `known` must outlive the
/// returned object and everything built on it.
[[nodiscard]] ompl::base::SpaceInformationPtr make_grid_space_information(const KnownMap& known,
                                                                          bool allow_corner_cutting);

/// State validity checks plus motion checks made so far on `si` (from
/// make_grid_space_information()).
[[nodiscard]] long grid_validity_checks(const ompl::base::SpaceInformation& si);

}  // namespace planners
}  // namespace fsweep
