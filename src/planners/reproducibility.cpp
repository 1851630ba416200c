#include "planners/reproducibility.hpp"

#include <array>
#include <charconv>
#include <optional>

#include "planners/ompl_planner.hpp"
#include "planners/registry.hpp"

namespace fsweep {
inline namespace planners {
namespace {

constexpr std::array kOmplKinds{OmplPlannerKind::RRTConnect,      OmplPlannerKind::RRTstar,
                                OmplPlannerKind::InformedRRTstar, OmplPlannerKind::BITstar,
                                OmplPlannerKind::PRMstar,         OmplPlannerKind::LazyPRMstar,
                                OmplPlannerKind::KPIECE1};

std::optional<OmplPlannerKind> ompl_kind_of(std::string_view name) {
  for (const OmplPlannerKind kind : kOmplKinds) {
    if (ompl_planner_name(kind) == name) return kind;
  }
  return std::nullopt;
}

/// max_iterations of `params` (0 when missing, empty or not an integer).
long max_iterations(const std::map<std::string, std::string>& params) {
  const auto it = params.find("max_iterations");
  if (it == params.end()) return 0;
  const std::string& text = it->second;
  long value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size()) return 0;
  return value;
}

}  // namespace

bool planner_reproducible(std::string_view planner, const std::map<std::string, std::string>& params) {
  if (const auto kind = ompl_kind_of(planner)) {
    // Even RRTConnect and KPIECE1, which stop at their first path, search until the time
    // limit on a query they cannot solve (the nightly suite saw KPIECE1's expansions differ).
    if (!ompl_planner_single_threaded(*kind)) return false;
    return max_iterations(params) > 0;
  }
  if (planner.starts_with("ompl:")) return false;
  for (const std::string& name : planner_names()) {
    if (name == planner) return true;
  }
  return false;
}

}  // namespace planners
}  // namespace fsweep
