#pragma once
/// @file dock_field.hpp
/// Path lengths from the dock over the known free space, for the strategies' dock distances:
/// started once the dock is known free, then brought up to date lazily (only when a decision
/// asks), and shared copy-on-write between a run and its forks.

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
class DockField {
 public:
  /// Takes in the cells one scan revealed on `known`: starts the field from `dock` once the
  /// dock is known free (the run's corner rule), afterwards keeps the cells for the next
  /// update.
  void take_in(const KnownMap& known, std::span<const int> revealed, Cell dock, bool allow_corner_cutting);

  /// True once the field is started (the dock is known free).
  [[nodiscard]] bool ready() const { return field_ != nullptr; }
  /// True when ready() and no revealed cell waits for the next update.
  [[nodiscard]] bool current() const { return field_ != nullptr && pending_.empty(); }

  /// Applies the cells revealed since the last update (ready() only; copying the field first
  /// when a copy of this DockField shares it). Returns the cells settled by that update (0 when
  /// nothing was pending).
  long bring_up_to_date(const KnownMap& known);

  /// Path length (metres) from the dock to `index` as of the last update; +infinity if
  /// unreachable. ready() only.
  [[nodiscard]] double distance_m(int index) const { return field_->distance_m(index); }

 private:
  std::shared_ptr<IncrementalDistanceField> field_;  // null until ready(); shared by copies
  std::vector<int> pending_;
};

}  // namespace sim
}  // namespace fsweep
