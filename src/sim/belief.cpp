#include "sim/belief.hpp"

#include <cmath>

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
  const auto revealed = sensor.scan(setup.map(), known_, at, heading_angle(heading), sensor_rng_);
  frontiers_.update(known_, revealed);
  clusters_.revealed(revealed);
  dock_field_.take_in(known_, revealed, dock, setup.allow_corner_cutting());
  for (const int i : revealed) {
    if (known_.is_free(i) && setup.reachable[i] != 0) ++known_reachable_;
    if (setup.observable[i] != 0) ++known_observable_;
  }
  return static_cast<int>(revealed.size());
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

double Belief::coverage(const RunSetup& setup) const {
  return setup.reachable_count > 0 ? static_cast<double>(known_reachable_) / setup.reachable_count : 1.0;
}

double Belief::completeness(const RunSetup& setup) const {
  return setup.observable_count > 0 ? static_cast<double>(known_observable_) / setup.observable_count : 1.0;
}

}  // namespace sim
}  // namespace fsweep
