#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "core/random.hpp"
#include "search/grid_search.hpp"
#include "search/octile_grid.hpp"
#include "world/ascii_world.hpp"
#include "world/grid.hpp"

namespace fsweep {
namespace test_octile_grid {

/// The moves out of free cell `from` by the rule's definition (octile_step_allowed), in heading order.
std::vector<std::pair<int, double>> allowed_moves(const KnownMap& known, int from, bool cut) {
  std::vector<std::pair<int, double>> moves;
  const Cell a = known.cell(from);
  for (const Cell d : kDirections) {
    const Cell b{a.x + d.x, a.y + d.y};
    if (octile_step_allowed(known, a, b, cut))
      moves.emplace_back(known.index(b), d.x != 0 && d.y != 0 ? kSqrt2 : 1.0);
  }
  return moves;
}

/// Every cell of maps from 1x1 to 6x5 (so every cell is on the border, or some are inside) and of
/// larger ones, free, unknown and occupied mixed, with and without corner cutting: the border and
/// interior paths of for_each_octile_neighbour both give exactly the allowed moves, in order.
TEST(OctileNeighbours, AreTheAllowedMovesInHeadingOrderOnEveryCell) {
  Rng rng = make_rng(11, "octile_neighbours");
  for (const auto& [w, h] :
       std::vector<std::pair<int, int>>{{1, 1}, {1, 4}, {4, 1}, {2, 2}, {3, 3}, {6, 5}, {17, 9}}) {
    for (int trial = 0; trial < 20; ++trial) {
      const KnownMap known = test::random_partly_known(w, h, 0.6, 0.2, rng);
      for (const bool cut : {false, true}) {
        for (int from = 0; from < known.size(); ++from) {
          if (!known.is_free(from)) continue;  // the moves out of a cell assume it free
          std::vector<std::pair<int, double>> moves;
          for_each_octile_neighbour<double>(
              known, from, cut, [&moves](int next, double cost) { moves.emplace_back(next, cost); });
          ASSERT_EQ(moves, allowed_moves(known, from, cut))
              << w << "x" << h << " trial " << trial << " cell " << from << " cut " << cut;
        }
      }
    }
  }
}

}  // namespace test_octile_grid
}  // namespace fsweep
