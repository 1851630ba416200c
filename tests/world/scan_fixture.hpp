#pragma once
/// @file scan_fixture.hpp
/// Maps, one-scan and parameter helpers shared by the sensor tests (test_sensor.cpp,
/// test_beam_lidar.cpp).

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/config_error.hpp"
#include "core/random.hpp"
#include "world/ascii_world.hpp"
#include "world/sensor.hpp"

namespace fsweep::test {

/// A width x height map without obstacles, at 1 m per cell.
inline WorldMap open_world(int width, int height) {
  return ascii_world(std::vector<std::string>(static_cast<std::size_t>(height),
                                              std::string(static_cast<std::size_t>(width), '.')));
}

/// Obstacles with probability p (seeded), the start cell (the centre) free.
inline WorldMap random_world(int width, int height, double p, std::uint64_t seed) {
  WorldMap map = open_world(width, height);
  Rng rng = make_rng(seed, "test-map");
  for (int i = 0; i < map.occupied.size(); ++i) map.occupied[i] = uniform01(rng) < p ? 1 : 0;
  map.start = Cell{width / 2, height / 2};
  map.occupied.at(map.start) = 0;
  return map;
}

/// The known map after one scan and the cells it revealed, in scan() order.
struct ScanResult {
  KnownMap known;
  std::vector<int> revealed;
};

/// One scan from a fresh KnownMap (noise stream "sensor" of `seed`).
inline ScanResult scan_fresh(const WorldMap& map, const SensorParams& params, Cell at,
                             double heading_rad = 0.0, std::uint64_t seed = 1) {
  Sensor sensor(params, map.resolution_m);
  ScanResult r{KnownMap(map.width(), map.height(), map.resolution_m), {}};
  Rng rng = make_rng(seed, "sensor");
  const auto revealed = sensor.scan(map, r.known, at, heading_rad, rng);
  r.revealed.assign(revealed.begin(), revealed.end());
  return r;
}

/// True when the scan left `c` known.
inline bool known(const ScanResult& r, Cell c) { return r.known.state(c) != CellState::Unknown; }

/// The message of the ConfigError that sensor_params_from_json(j, where) throws, or "" when it
/// throws none.
inline std::string sensor_params_error(const nlohmann::json& j, const std::string& where) {
  try {
    (void)sensor_params_from_json(j, where);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

}  // namespace fsweep::test
