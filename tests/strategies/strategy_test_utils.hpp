#pragma once
/// @file strategy_test_utils.hpp
/// A hand-checkable DistanceOracle shared by the strategy tests.

#include <cstddef>
#include <limits>
#include <set>
#include <span>
#include <vector>

#include "engine/world/grid.hpp"
#include "engine/world/known_map.hpp"
#include "strategies/strategy.hpp"

namespace fsweep::testing {

/// Euclidean distances (metres, resolution 1) from the robot; cells in `unreachable` are
/// +infinity. nearest_from_robot: the smallest finite one, ties to the lowest position.
class EuclideanOracle final : public DistanceOracle {
 public:
  const KnownMap* known = nullptr;
  Cell robot{};
  std::set<int> unreachable;

  std::vector<double> from_robot(std::span<const int> cells, double bound_m) override {
    std::vector<double> out;
    for (const int c : cells) {
      const double d = distance(c);
      out.push_back(d <= bound_m ? d : std::numeric_limits<double>::infinity());
    }
    return out;
  }
  std::vector<double> from_dock(std::span<const int> cells, double bound_m) override {
    return from_robot(cells, bound_m);
  }
  int nearest_from_robot(std::span<const int> cells) override {
    int best = -1;
    double best_d = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < cells.size(); ++i) {
      if (distance(cells[i]) < best_d) {
        best_d = distance(cells[i]);
        best = static_cast<int>(i);
      }
    }
    return best;
  }

 private:
  double distance(int c) const {
    return unreachable.count(c) != 0 ? std::numeric_limits<double>::infinity()
                                     : euclidean_distance(robot, known->cell(c));
  }
};

}  // namespace fsweep::testing
