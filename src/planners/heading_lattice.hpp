#pragma once
/// @file heading_lattice.hpp
/// The (cell, heading) state lattice of Mei et al. 2006 (section IV-C, Figure 6) as a
/// BestFirstSearch environment, shared by `lattice`, `lattice_astar` (lattice_planner.cpp) and
/// `shortest_fewest_turns` (shortest_fewest_turns.cpp). The rules are documented in
/// lattice_planner.hpp; what differs between the planners is a small policy object:
/// - `policy.heuristic(cell)`: a consistent lower bound on the energy from `cell` to the goal;
/// - `policy.allows(from_cell, to_cell, step_cells)`: whether the lattice may use that step
///   (the octile move rule has already been checked);
/// - optionally `Policy::kZeroHeuristic` (true when the heuristic is 0 everywhere).

#include <array>
#include <concepts>
#include <cstddef>

#include "planners/planner.hpp"
#include "search/grid_search.hpp"
#include "search/octile_grid.hpp"
#include "world/grid.hpp"
#include "world/known_map.hpp"

namespace fsweep {
inline namespace planners {

/// Headings per cell in the lattice; state id = cell_index * kLatticeHeadings + heading.
inline constexpr int kLatticeHeadings = 8;

/// What a HeadingLattice asks of its policy (see the file comment).
template <typename P>
concept LatticePolicy = requires(const P& p, int cell, double step) {
  { p.heuristic(cell) } -> std::convertible_to<double>;
  { p.allows(cell, cell, step) } -> std::convertible_to<bool>;
};

/// Search environment of one lattice query: states are `cell_index * 8 + heading`, edge costs
/// are energies under the request's model, any state on the goal cell ends the search.
/// Holds references to `known` and `policy`, which must outlive it.
template <LatticePolicy Policy>
class HeadingLattice {
 public:
  HeadingLattice(const KnownMap& known, const PlanRequest& request, const Policy& policy)
      : known_(known),
        policy_(policy),
        goal_index_(known.index(request.goal)),
        width_(known.width()),
        allow_corner_cutting_(request.allow_corner_cutting) {
    const double resolution_m = known.resolution_m();
    for (int k = 0; k <= 4; ++k) turn_[static_cast<std::size_t>(k)] = request.energy.turn(k);
    travel_[0] = request.energy.travel(1.0, resolution_m);
    travel_[1] = request.energy.travel(kSqrt2, resolution_m);
  }

  /// A policy with a zero heuristic may declare `kZeroHeuristic` (see grid_search.hpp).
  static constexpr bool kZeroHeuristic = ZeroHeuristicEnvironment<Policy>;
  [[nodiscard]] int state_count() const { return known_.size() * kLatticeHeadings; }
  [[nodiscard]] double heuristic(int state) const { return policy_.heuristic(state / kLatticeHeadings); }
  Visit visit(int state, double /*g*/) const {
    return state / kLatticeHeadings == goal_index_ ? Visit::Goal : Visit::Expand;
  }
  template <typename Sink>
  void for_each_successor(int state, Sink&& sink) const {
    const int cell = state / kLatticeHeadings;
    const int heading = state % kLatticeHeadings;
    const Cell c{cell % width_, cell / width_};
    for (int next_heading = 0; next_heading < kLatticeHeadings; ++next_heading) {
      const Cell d = kDirections[static_cast<std::size_t>(next_heading)];
      const Cell n{c.x + d.x, c.y + d.y};
      if (!octile_step_allowed(known_, c, n, allow_corner_cutting_)) continue;
      const int next_cell = known_.index(n);
      if (!policy_.allows(cell, next_cell, step_length(next_heading))) continue;
      const double cost = turn_[static_cast<std::size_t>(heading_difference(heading, next_heading))] +
                          travel_[static_cast<std::size_t>(next_heading & 1)];
      sink(next_cell * kLatticeHeadings + next_heading, cost);
    }
  }

 private:
  const KnownMap& known_;
  const Policy& policy_;
  int goal_index_;
  int width_;
  bool allow_corner_cutting_;
  /// Stop + turn energy for 0..4 eighth-turns (0 for none).
  std::array<double, 5> turn_{};
  /// Travel energy of an orthogonal [0] and a diagonal [1] step.
  std::array<double, 2> travel_{};
};

}  // namespace planners
}  // namespace fsweep
