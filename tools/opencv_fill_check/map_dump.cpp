// Prints a HouseExpo plan as load_houseexpo() draws it: one row per grid row, 1 free, 0 wall.
// Usage: map_dump PLAN.json RES   (see check.py)
#include <cstdio>
#include <cstdlib>

#include "world/map_loaders.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: map_dump PLAN.json RES\n");
    return 2;
  }
  const fsweep::WorldMap m = fsweep::load_houseexpo(argv[1], std::atof(argv[2]));
  for (int y = 0; y < m.height(); ++y) {
    for (int x = 0; x < m.width(); ++x) std::putchar(m.is_free(fsweep::Cell{x, y}) ? '1' : '0');
    std::putchar('\n');
  }
  return 0;
}
