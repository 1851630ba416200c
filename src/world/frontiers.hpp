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

#include "world/grid.hpp"
#include "world/known_map.hpp"

namespace fsweep {
inline namespace world {

/// True when cell `index` of `known` is a frontier cell (the definition above, from scratch).
[[nodiscard]] bool is_frontier_cell(const KnownMap& known, int index);

/// A group of frontier cells: a connected component (see FrontierMap::clusters), or a piece of
/// one after splitting.
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
/// Copyable value type. The frontier cells are kept in a list as well as flagged per cell, so
/// that cells() and clusters() cost O(F log F) in the number F of frontier cells, not O(map).
///
/// Not thread-safe on one object: cells() and clusters() are const but reorganise that list
/// (sorting cells added since the last call, dropping removed ones), so no member may run
/// concurrently with them on the same object. Distinct objects (copies) are independent.
class FrontierMap {
 public:
  FrontierMap() = default;
  explicit FrontierMap(const KnownMap& known);

  /// Updates after `revealed` cells became known: only those cells and their 8-neighbours can
  /// change status. O(|revealed|) (amortised).
  void update(const KnownMap& known, std::span<const int> revealed);

  /// Rebuilds from scratch (used by tests to check update()). O(map).
  void rebuild(const KnownMap& known);

  [[nodiscard]] bool is_frontier(int index) const {
    return (flags_[static_cast<std::size_t>(index)] & kFrontier) != 0;
  }
  [[nodiscard]] int count() const { return count_; }
  /// Frontier cell indices in ascending order. O(F + A log A) for A cells added since the
  /// last call of cells() or clusters().
  [[nodiscard]] std::vector<int> cells() const;

  /// Clusters of the frontier cells not `excluded` (may be empty; else one flag per cell).
  ///
  /// Connectivity follows the robot's motion rule, so that the members of one cluster are
  /// mutually reachable through known free cells (frontier cells are known free): two
  /// frontier cells that are orthogonal neighbours always connect; diagonal neighbours
  /// connect only when both cells beside that diagonal are known free, or when
  /// `allow_corner_cutting` is set (the same flag as the planners' and simulator's).
  ///
  /// Each connected component is split into pieces of at most max_length_m / resolution cells
  /// (rounded down, at least 1; max_length_m <= 0: no splitting), each itself connected: a
  /// piece is grown by a breadth-first walk (neighbours in heading order, see grid.hpp) from
  /// the lowest-index cell of the component not yet in a piece, over such cells only, and
  /// closed when it holds that many cells or the walk runs out; then the next piece starts
  /// from the lowest-index cell left. Pieces can therefore be shorter than the limit.
  ///
  /// Clusters are ordered by their lowest member index. O(F log F) for F frontier cells, plus
  /// O(map) for the scratch marks: a simulation keeps them up to date with FrontierClusters.
  [[nodiscard]] std::vector<FrontierCluster> clusters(const KnownMap& known, double max_length_m,
                                                      bool allow_corner_cutting,
                                                      std::span<const std::uint8_t> excluded = {}) const;

 private:
  // flags_ bits per cell.
  static constexpr std::uint8_t kFrontier = 1;  // the cell is a frontier cell
  static constexpr std::uint8_t kListed = 2;    // the cell is in list_ (frontier or stale)

  /// Marks cell `i` frontier or not, keeping list_ and the counts in step.
  void set(int i, bool frontier);
  /// Drops stale entries from list_ and sorts it (merging the unsorted tail).
  void normalise() const;

  mutable std::vector<std::uint8_t> flags_;
  /// Every frontier cell once, plus `stale_` cells that stopped being frontiers; entries
  /// [0, sorted_) are ascending.
  mutable std::vector<int> list_;
  mutable std::size_t sorted_ = 0;
  mutable std::size_t stale_ = 0;
  int count_ = 0;
  int width_ = 0;
};

/// The clusters of one FrontierMap, kept up to date between calls: exactly what
/// FrontierMap::clusters(known, max_length_m, allow_corner_cutting, excluded) returns, rebuilding
/// only the pieces a change can reach.
///
/// How: FrontierMap::clusters grows its pieces one by one, each from the lowest frontier cell
/// not yet in one. A piece's walk reads only its own cells and their 8-neighbours (the
/// neighbours' frontier and exclusion flags, whether an earlier piece holds them, and the known
/// state of the cells beside a diagonal). clusters() replays that loop in the same order over
/// the pieces of the last call and the cells that changed: a piece is kept as it is unless a
/// changed cell (a revealed cell, or one whose status changed: one of its 8-neighbours, or a
/// cell whose exclusion changed) lies within one cell of it, or it lost a cell to a piece built
/// earlier in this call, or a piece walked again earlier in this call left a cell free within
/// one cell of it; otherwise its walk would read what it read last time, or differ only in
/// cells it never took (frontiers.cpp says why). Every other piece is walked again, and the
/// cells it no longer holds are walked from in turn. The pieces built
/// again are those near the robot's new scans, plus those a different piece pushes along
/// (pieces of a long frontier can shift one after another); the replay starts at the first of
/// them and stops after the last, leaving the pieces before and after in place. Memory: 5
/// bytes per map cell plus the clusters. Copyable value type (a copy forks it).
class FrontierClusters {
 public:
  /// A cell of a piece being grown, with its coordinates (carried along to avoid divisions).
  struct PieceCell {
    int i;
    int x;
    int y;
  };

  FrontierClusters() = default;
  /// Empty, for maps of `known`'s size; the first clusters() call builds every cluster.
  FrontierClusters(const KnownMap& known, double max_length_m, bool allow_corner_cutting);

  /// Takes note of cells that just became known (their neighbours may change too).
  void revealed(std::span<const int> cells);
  /// Takes note that cell `index`'s exclusion flag changed.
  void exclusion_changed(int index);

  /// The clusters of the frontier cells of `frontiers` (kept in step with `known`) not
  /// `excluded` (empty, or one flag per cell), ordered by lowest member as
  /// FrontierMap::clusters orders them. The reference stays valid until the next call.
  const std::vector<FrontierCluster>& clusters(const KnownMap& known, const FrontierMap& frontiers,
                                               std::span<const std::uint8_t> excluded);

 private:
  /// What the walks read: the map, the frontier and exclusion flags, and the owner marks
  /// (frontiers.cpp).
  struct Walk;
  /// A walk with the largest piece in cells and the map's resolution.
  struct Grow {
    const Walk& walk;
    std::size_t cap;
    double resolution_m;
  };
  // clusters()'s steps (frontiers.cpp says what each does).
  void find_starts(const Walk& walk, const FrontierMap& frontiers);
  [[nodiscard]] std::size_t first_replayed() const;
  /// Grows the piece of `start` (not yet placed by this call, open) into next_. True when it
  /// equals `old`, which is then moved into next_ as it is; otherwise piece_ holds the new
  /// piece's cells (ascending, with coordinates).
  bool grow(const Grow& g, int start, FrontierCluster* old);
  /// Replays from the last call's piece `first`; returns the first piece not replayed.
  std::size_t replay(const Grow& g, std::size_t first);
  /// The last call's piece `old`, marked, walked again.
  void walk_again(const Grow& g, FrontierCluster& old);
  void splice(std::size_t first, std::size_t k);
  /// Marks the last call's piece starting at `key` as changed: it must be walked again.
  void mark(int key);
  /// Marks as changed the pieces of the last call that hold a cell within one cell of `cell`
  /// (or of cell (x, y)) and start after `after` (pieces not yet replayed).
  void mark_near(int cell, int after);
  void mark_near(int x, int y, int after);

  double max_length_m_ = 0.0;
  bool allow_corner_cutting_ = false;
  bool everything_dirty_ = true;
  int width_ = 0;
  int height_ = 0;
  /// Per cell: the lowest member of the piece holding it (this call's once replayed, else the
  /// last call's), or -1.
  std::vector<int> owner_;
  /// Per cell, scratch of clusters() (all 0 between calls): kChanged while it is a changed
  /// cell; kWalkAgain when it starts a piece of the last call that must be walked again.
  static constexpr std::uint8_t kChanged = 1;
  static constexpr std::uint8_t kWalkAgain = 2;
  std::vector<std::uint8_t> flags_;
  /// Cells revealed, or whose exclusion changed, since the last clusters() call.
  std::vector<int> revealed_;
  std::vector<int> exclusion_changed_;
  /// The clusters, ordered by lowest member.
  std::vector<FrontierCluster> clusters_;
  /// Scratch of clusters(): changed cells, cells to walk from (a min-heap), the replayed
  /// clusters, the piece being grown (cells with coordinates), cell lists of dropped pieces
  /// (their allocations serve new pieces), and the pieces marked but not yet replayed (how
  /// many, and the lowest start marked before the replay).
  std::vector<int> dirty_cells_;
  std::vector<int> starts_;
  std::vector<FrontierCluster> next_;
  std::vector<PieceCell> piece_;
  std::vector<std::vector<int>> spare_;
  int marked_ = 0;
  int lowest_marked_ = 0;
};

}  // namespace world
}  // namespace fsweep
