#include "sim/belief.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "search/distance_field.hpp"

namespace fsweep {
inline namespace sim {

Belief::Belief(const RunSetup& setup)
    : known_(setup.map().width(), setup.map().height(), setup.resolution_m),
      frontiers_(known_),
      clusters_(known_, setup.cluster_max_length_m, setup.allow_corner_cutting()),
      sensor_rng_(make_rng(setup.spec.seed, "sensor")),
      dropped_(static_cast<std::size_t>(known_.size()), 0) {}

int Belief::sense(Sensor& sensor, const RunSetup& setup, Cell at, int heading, Cell dock) {
  const auto revealed = sensor.scan(setup.map(), known_, at, heading_angle(heading), sensor_rng_,
                                    setup.observable.data().data(), setup.sight());
  frontiers_.update(known_, revealed);
  clusters_.revealed(revealed);
  keep_margin(setup, revealed);
  dock_field_.take_in(known_, revealed, dock, setup.allow_corner_cutting());
  for (const int i : revealed) {
    if (known_.is_free(i) && setup.reachable[i] != 0) {
      ++known_reachable_;
      const std::int32_t bin = reveal_ != nullptr ? reveal_->bin[static_cast<std::size_t>(i)] : -1;
      if (bin >= 0) --unknown_by_bin_[static_cast<std::size_t>(bin)];
    }
    if (setup.observable[i] != 0) ++known_observable_;
  }
  return static_cast<int>(revealed.size());
}

std::span<const int> Belief::unknown_by_bin(const RevealGeometry& reveal) const {
  if (reveal_ == nullptr) {
    reveal_ = &reveal;
    unknown_by_bin_.assign(static_cast<std::size_t>(reveal.bins), 0);
    for (int i = 0; i < known_.size(); ++i) {
      const std::int32_t bin = reveal.bin[static_cast<std::size_t>(i)];
      if (bin >= 0 && !known_.is_free(i)) ++unknown_by_bin_[static_cast<std::size_t>(bin)];
    }
  }
  return unknown_by_bin_;
}

const std::vector<FrontierCluster>& Belief::clusters() {
  return clusters_.clusters(known_, frontiers_, dropped_);
}

void Belief::drop(Cell goal) {
  const int i = known_.index(goal);
  if (dropped_[static_cast<std::size_t>(i)] != 0) return;
  dropped_[static_cast<std::size_t>(i)] = 1;
  clusters_.exclusion_changed(i);
}

GridDistanceOracle Belief::distance_oracle(const RunSetup& setup, Cell robot, Cell dock,
                                           DistanceScratch& scratch) {
  return GridDistanceOracle(known_, robot, dock, setup.allow_corner_cutting(), &dock_field_, scratch);
}

bool Belief::frontier_reachable_from(Cell from, Cell dock, const RunSetup& setup, DistanceScratch& scratch) {
  // When the dock field is built and reaches `from`, `from` reaches exactly what the dock
  // reaches (moves are symmetric, and the field follows the same corner rule): no search needed.
  if (dock_field_.built()) {
    (void)dock_field_.bring_up_to_date(known_);
    if (std::isfinite(dock_field_.distance_m(known_.index(from)))) {
      for (const int i : frontiers_.cells()) {
        if (dropped_[static_cast<std::size_t>(i)] == 0 && std::isfinite(dock_field_.distance_m(i)))
          return true;
      }
      return false;
    }
  }
  std::vector<int> open;
  for (const int i : frontiers_.cells()) {
    if (dropped_[static_cast<std::size_t>(i)] == 0) open.push_back(i);
  }
  // The nearest of them is -1 only when none is reachable.
  return distance_oracle(setup, from, dock, scratch).nearest_from_robot(open) >= 0;
}

void Belief::keep_margin(const RunSetup& setup, std::span<const int> revealed) {
  const double margin_m = setup.spec.sim.target_margin_m;
  if (!(margin_m > 0.0)) return;
  // A cell at offset (dx, dy) cells from an obstacle cell is that close to the obstacle's square:
  // res * hypot(max(|dx| - 1/2, 0), max(|dy| - 1/2, 0)).
  const double margin = margin_m / known_.resolution_m();
  const int reach = static_cast<int>(std::ceil(margin + 0.5));
  const auto gap = [](int d) { return std::max(std::abs(d) - 0.5, 0.0); };
  for (const int i : revealed) {
    if (known_.state(i) != CellState::Occupied) continue;
    const Cell o = known_.cell(i);
    for (int dy = -reach; dy <= reach; ++dy) {
      for (int dx = -reach; dx <= reach; ++dx) {
        const Cell c{o.x + dx, o.y + dy};
        if (!known_.in_bounds(c) || std::hypot(gap(dx), gap(dy)) >= margin) continue;
        const int k = known_.index(c);
        if (dropped_[static_cast<std::size_t>(k)] != 0) continue;
        dropped_[static_cast<std::size_t>(k)] = 1;
        // A cell that is no frontier cell yet is in no cluster; the clusters read the flag when
        // it becomes one.
        if (frontiers_.is_frontier(k)) clusters_.exclusion_changed(k);
      }
    }
  }
}

double Belief::coverage(const RunSetup& setup) const {
  return setup.reachable_count > 0 ? static_cast<double>(known_reachable_) / setup.reachable_count : 1.0;
}

double Belief::completeness(const RunSetup& setup) const {
  return setup.observable_count > 0 ? static_cast<double>(known_observable_) / setup.observable_count : 1.0;
}

}  // namespace sim
}  // namespace fsweep
