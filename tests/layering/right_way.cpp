// Compiled by tests/layering/check.cmake as part of the planners layer: must compile (the
// control case of wrong_way.cpp: the same layer including a header of a layer below it).
#include "planners/planner.hpp"
#include "world/world_map.hpp"
