#include "engine/world/known_map.hpp"

#include "engine/world/world_map.hpp"

namespace fsweep {

KnownMap fully_known(const WorldMap& map) {
  KnownMap known(map.width(), map.height(), map.resolution_m);
  for (int i = 0; i < known.size(); ++i) known.reveal(i, !map.is_free(i));
  return known;
}

}  // namespace fsweep
