#pragma once
/// @file dock_field.hpp
/// Path lengths from the dock over the known free space, for the strategies' dock distances:
/// built on the first decision that asks (so a run whose strategy never does holds no field),
/// then brought up to date lazily, and shared copy-on-write between a run and its forks.

#include <memory>
#include <span>
#include <vector>

#include "search/incremental_distance_field.hpp"
#include "world/known_map.hpp"

namespace fsweep {
inline namespace sim {

/// The dock's IncrementalDistanceField and the cells revealed since it was last brought up to
/// date. A value: copies share the (map-sized) field until one of them brings it up to date,
/// which then works on its own copy, so forking a run never copies the field and a fork whose
/// strategy never asks for dock distances never does. As any value, one object must not be
/// used from two threads at once; distinct copies may.
///
/// The field is built from scratch on the first bring_up_to_date(), and again when more cells
/// were revealed since the last one than an update is worth (rebuild_after()): then the list of
/// revealed cells is dropped, so it never holds more than that many. Both give the same lengths
/// as an update (exact costs; tests/search/test_incremental_distance_field.cpp).
class DockField {
 public:
  /// Takes in the cells one scan revealed on `known`: the field is ready() once the dock is
  /// known free (the run's corner rule); once built, keeps the cells for the next update.
  void take_in(const KnownMap& known, std::span<const int> revealed, Cell dock, bool allow_corner_cutting);

  /// True once the dock is known free: bring_up_to_date() can build the field.
  [[nodiscard]] bool ready() const { return ready_; }
  /// True once a bring_up_to_date() built the field (some decision asked for dock distances).
  [[nodiscard]] bool built() const { return field_ != nullptr; }
  /// True when built() and no revealed cell waits for the next update.
  [[nodiscard]] bool current() const { return field_ != nullptr && pending_.empty() && !rebuild_; }

  /// Builds the field, or applies the cells revealed since the last update, or builds it again
  /// (ready() only; working on a new field when a copy of this DockField shares it). Returns the
  /// cells settled (0 when the field was current).
  long bring_up_to_date(const KnownMap& known);

  /// Path length (metres) from the dock to `index` as of the last update; +infinity if
  /// unreachable. built() only.
  [[nodiscard]] double distance_m(int index) const { return field_->distance_m(index); }

  /// The number of revealed cells beyond which the next bring_up_to_date() builds the field
  /// again instead of updating it, on a map of `cells` cells: 1/16 of the map (but at least
  /// 1024), where an update's work approaches a full search's.
  [[nodiscard]] static std::size_t rebuild_after(int cells);

 private:
  std::shared_ptr<IncrementalDistanceField> field_;  // null until built(); shared by copies
  std::vector<int> pending_;                         // revealed since the last update
  bool rebuild_ = false;                             // too many revealed: build again
  bool ready_ = false;
  bool allow_corner_cutting_ = false;
  Cell dock_{};
};

}  // namespace sim
}  // namespace fsweep
