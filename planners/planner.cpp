#include "planners/planner.hpp"

namespace fsweep {

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

}  // namespace fsweep
