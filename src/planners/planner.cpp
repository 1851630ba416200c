#include "planners/planner.hpp"

#include "world/motion.hpp"

namespace fsweep {
inline namespace planners {

std::string_view to_string(PlanStatus s) {
  switch (s) {
    case PlanStatus::Success:
      return "Success";
    case PlanStatus::StartInvalid:
      return "StartInvalid";
    case PlanStatus::GoalInvalid:
      return "GoalInvalid";
    case PlanStatus::NoPath:
      return "NoPath";
    case PlanStatus::Timeout:
      return "Timeout";
  }
  return "Unknown";
}

PlanStatus check_endpoints(const KnownMap& known, const PlanRequest& request) {
  if (!known.is_free(request.start)) return PlanStatus::StartInvalid;
  if (!known.is_free(request.goal)) return PlanStatus::GoalInvalid;
  return PlanStatus::Success;
}

void set_path(PlanResult& result, std::vector<Cell> path, const PlanRequest& request, double resolution_m) {
  result.status = PlanStatus::Success;
  result.path = std::move(path);
  const MotionCost cost = measure_path(result.path, request.start_heading, request.energy, resolution_m);
  result.length_m = cost.length_m;
  result.energy = cost.energy;
  result.stops = cost.stops;
  result.turns = cost.turns;
}

}  // namespace planners
}  // namespace fsweep
