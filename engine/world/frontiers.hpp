#pragma once
/// @file frontiers.hpp
/// Frontier cells, maintained incrementally, and their clusters.
///
/// Definition: a frontier cell is a known-free cell with an unknown 8-neighbour that is not
/// sealed off from it. A diagonal neighbour is sealed when both cells beside the diagonal are
/// occupied: then neither the sensor (see sensor.hpp) nor the robot can get through, and such
/// a neighbour alone does not make a frontier. Every frontier cell therefore has an unknown
/// neighbour that a scan from the cell itself can see.

#include <cstdint>
#include <span>
#include <vector>

#include "engine/world/grid.hpp"
#include "engine/world/known_map.hpp"

namespace fsweep {

/// True when cell `index` of `known` is a frontier cell (the definition above, from scratch).
[[nodiscard]] bool is_frontier_cell(const KnownMap& known, int index);

/// A group of frontier cells: an 8-connected component, or a piece of one after splitting.
struct FrontierCluster {
  /// Member cell indices, ascending.
  std::vector<int> cells;
  /// The member nearest to the members' centroid (ties: lowest index).
  int representative = -1;
  /// Centroid of the member cell centres (cells).
  double centroid_x = 0.0;
  double centroid_y = 0.0;
  /// Length (metres): member count times resolution.
  double length_m = 0.0;
};

/// The set of frontier cells of a KnownMap, kept up to date from the cells each scan reveals.
/// Copyable value type.
class FrontierMap {
 public:
  FrontierMap() = default;
  explicit FrontierMap(const KnownMap& known);

  /// Updates after `revealed` cells became known: only those cells and their 8-neighbours can
  /// change status. O(|revealed|).
  void update(const KnownMap& known, std::span<const int> revealed);

  /// Rebuilds from scratch (used by tests to check update()).
  void rebuild(const KnownMap& known);

  [[nodiscard]] bool is_frontier(int index) const { return flags_[static_cast<std::size_t>(index)] != 0; }
  [[nodiscard]] int count() const { return count_; }
  /// Frontier cell indices in ascending order (computed on demand).
  [[nodiscard]] std::vector<int> cells() const;

  /// Clusters: 8-connected components of frontier cells, each split into pieces of at most
  /// `max_length_m` (<= 0: no splitting). Pieces are made by a breadth-first walk from the
  /// component's lowest-index cell: a piece is closed once it holds max_length_m / resolution
  /// cells. Clusters are ordered by their lowest member index. `excluded` cells (may be empty;
  /// else one flag per cell) are left out.
  [[nodiscard]] std::vector<FrontierCluster> clusters(const KnownMap& known, double max_length_m,
                                                      std::span<const std::uint8_t> excluded = {}) const;

 private:
  std::vector<std::uint8_t> flags_;
  int count_ = 0;
  int width_ = 0;
};

}  // namespace fsweep
