#include "planners/planner.hpp"

#include <chrono>
#include <stdexcept>
#include <string>
#include <utility>

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

PlanResult Planner::plan(const KnownMap& known, const PlanRequest& request) {
  const auto started = StopCondition::Clock::now();
  if (request.start_heading < 0 || request.start_heading >= static_cast<int>(kDirections.size())) {
    throw std::invalid_argument(name() + ": start_heading " + std::to_string(request.start_heading) +
                                " is not in 0..7");
  }
  PlanResult result;

  // 1. Endpoints must be known free (outside the grid counts as occupied).
  result.status = check_endpoints(known, request);
  if (result.status == PlanStatus::Success) {
    // 2. The plugin's search under this query's budget.
    SearchResult found = search(known, request, StopCondition(budget_, started));
    result.status = found.status;
    result.expansions = found.expansions;
    result.progress = std::move(found.progress);
    if (found.status == PlanStatus::Success) {
      // 3. The shared motion accounting of a path that must start and end right.
      if (found.path.empty() || found.path.front() != request.start || found.path.back() != request.goal) {
        throw std::logic_error(name() + ": search returned a path that does not join start and goal");
      }
      result.path = std::move(found.path);
      const MotionCost cost = found.motion ? *found.motion
                                           : measure_path(result.path, request.start_heading, request.energy,
                                                          known.resolution_m());
      result.length_m = cost.length_m;
      result.energy = cost.energy;
      result.stops = cost.stops;
      result.turns = cost.turns;
    }
  }
  result.time_s = std::chrono::duration<double>(StopCondition::Clock::now() - started).count();
  return result;
}

}  // namespace planners
}  // namespace fsweep
