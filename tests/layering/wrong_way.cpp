// Compiled by tests/layering/check.cmake as part of the planners layer: must fail, because
// the planners layer does not see the sim layer above it.
#include "planners/planner.hpp"
#include "sim/simulation.hpp"
