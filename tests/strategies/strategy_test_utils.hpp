#pragma once
/// @file strategy_test_utils.hpp
/// What the strategy tests share: a hand-checkable DistanceOracle and a decision situation
/// drawn in ASCII.

#include <cstddef>
#include <limits>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "strategies/strategy.hpp"
#include "world/ascii_world.hpp"
#include "world/grid.hpp"
#include "world/known_map.hpp"

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

/// One decision's inputs drawn in ASCII: '?' unknown, '.' free, '#' occupied, 'R' the robot
/// (free); 1 m cells, Euclidean distances from the robot. Set `sensor`, `heading` or
/// `previous_goal` before observe() where a test needs them.
struct AsciiSituation {
  KnownMap known;
  FrontierMap frontiers;
  std::vector<FrontierCluster> clusters;
  EuclideanOracle oracle;
  SensorParams sensor;
  Cell robot{};
  int heading = 0;
  std::optional<Cell> previous_goal;

  /// `cluster_max_length_m` as FrontierMap::clusters (<= 0: whole components).
  explicit AsciiSituation(std::vector<std::string> rows, double cluster_max_length_m = 0.0) {
    for (int y = 0; y < static_cast<int>(rows.size()); ++y) {
      auto& row = rows[static_cast<std::size_t>(y)];
      const auto x = row.find('R');
      if (x != std::string::npos) {
        robot = Cell{static_cast<int>(x), y};
        row[x] = '.';
      }
    }
    known = test::ascii_known(rows);
    frontiers = FrontierMap(known);
    clusters = frontiers.clusters(known, cluster_max_length_m, false);
    oracle.known = &known;
    oracle.robot = robot;
  }
  AsciiSituation(const AsciiSituation&) = delete;  // oracle points into known
  AsciiSituation& operator=(const AsciiSituation&) = delete;

  void move_robot(Cell c) {
    robot = c;
    oracle.robot = c;
  }
  [[nodiscard]] Observation observe() {
    return Observation{known,   frontiers, clusters,      oracle, sensor, robot,
                       heading, robot,     previous_goal, robot,  {},     1};
  }
  [[nodiscard]] int at(int x, int y) const { return known.index(Cell{x, y}); }
  [[nodiscard]] std::vector<Cell> as_cells(const std::vector<int>& indices) const {
    std::vector<Cell> out;
    for (const int i : indices) out.push_back(known.cell(i));
    return out;
  }
};

}  // namespace fsweep::testing
