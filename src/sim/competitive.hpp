#pragma once
/// @file competitive.hpp
/// Optimal exploration lengths where they are known (Rappaport 2016 section 4.4).

#include <cmath>

namespace fsweep {
inline namespace sim {

/// The star pattern in free space: with range r per charge (metres) and sensor range r_s, the
/// robot visits n = pi r / (2 r_s) points at distance r/2 from the dock, out and back, so
/// d* = n r = pi r^2 / (2 r_s) (eq. 11). Valid when the disc of radius r/2 around the dock lies
/// inside the free map.
[[nodiscard]] inline double star_pattern_optimum_m(double range_m, double sensor_range_m) {
  return M_PI * range_m * range_m / (2.0 * sensor_range_m);
}

}  // namespace sim
}  // namespace fsweep
