#include "planners/reproducibility.hpp"

#include <array>
#include <charconv>
#include <optional>

#include "planners/ompl_planner.hpp"
#include "planners/registry.hpp"

namespace fsweep {
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

/// True if `kind` returns at its first exact solution; false for the anytime planners, which
/// keep improving until their budget ends (README, OMPL planners, Failure).
bool stops_at_first_path(OmplPlannerKind kind) {
  switch (kind) {
    case OmplPlannerKind::RRTConnect:
    case OmplPlannerKind::KPIECE1:
      return true;
    case OmplPlannerKind::RRTstar:
    case OmplPlannerKind::InformedRRTstar:
    case OmplPlannerKind::BITstar:
    case OmplPlannerKind::PRMstar:
    case OmplPlannerKind::LazyPRMstar:
      return false;
  }
  return false;
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
    if (!ompl_planner_single_threaded(*kind)) return false;
    return stops_at_first_path(*kind) || max_iterations(params) > 0;
  }
  if (planner.starts_with("ompl:")) return false;
  for (const std::string& name : planner_names()) {
    if (name == planner) return true;
  }
  return false;
}

}  // namespace fsweep
