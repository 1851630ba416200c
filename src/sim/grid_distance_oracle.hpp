#pragma once
/// @file grid_distance_oracle.hpp
/// The engine's answer to strategies' distance queries: bounded one-to-many Dijkstra over
/// known free space from the robot and from the dock, cached for one decision.

#include "search/distance_field.hpp"
#include "search/incremental_distance_field.hpp"
#include "strategies/strategy.hpp"

namespace fsweep {
inline namespace sim {

class GridDistanceOracle final : public DistanceOracle {
 public:
  GridDistanceOracle() = default;

  /// Starts a new decision: the map, the robot and the dock may have changed. `dock_field`
  /// (may be null) is the simulation's up-to-date field from the dock; without it, dock
  /// distances are searched like robot distances.
  /// `pending` (with dock_field) are the cells revealed since the field was last brought up to
  /// date: they are applied on the first dock query, so runs whose strategy never asks for
  /// dock distances never pay for the field.
  void reset(const KnownMap& known, Cell robot, Cell dock, bool allow_corner_cutting,
             IncrementalDistanceField* dock_field, std::vector<int>* pending);

  [[nodiscard]] std::vector<double> from_robot(std::span<const int> cells, double bound_m) override;
  [[nodiscard]] std::vector<double> from_dock(std::span<const int> cells, double bound_m) override;
  [[nodiscard]] int nearest_from_robot(std::span<const int> cells) override;

  /// Expansions of all searches since the last reset().
  [[nodiscard]] long expansions() const { return expansions_; }

 private:
  struct Cached {
    DistanceField field;
    double bound_m = -1.0;   // < 0: not computed for this decision
    std::vector<int> cells;  // the cells the field is exact for
  };
  std::vector<double> lookup(Cached& c, Cell source, std::span<const int> cells, double bound_m);

  const KnownMap* known_ = nullptr;
  Cell robot_{};
  Cell dock_{};
  bool corner_cutting_ = false;
  IncrementalDistanceField* dock_field_ = nullptr;
  std::vector<int>* pending_ = nullptr;
  Cached robot_field_;
  Cached dock_search_;
  DistanceField scratch_;
  long expansions_ = 0;
};

}  // namespace sim
}  // namespace fsweep
