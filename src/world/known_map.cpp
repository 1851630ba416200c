#include "world/known_map.hpp"

#include "world/world_map.hpp"

namespace fsweep {
inline namespace world {

KnownMap fully_known(const WorldMap& map) {
  KnownMap known(map.width(), map.height(), map.resolution_m);
  for (int i = 0; i < known.size(); ++i) known.reveal(i, !map.is_free(i));
  return known;
}

}  // namespace world
}  // namespace fsweep
