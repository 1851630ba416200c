#include "planners/reproducibility.hpp"

#include <charconv>

#include "planners/registry.hpp"

namespace fsweep {
inline namespace planners {
namespace {

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
  const std::optional<PlannerCapabilities> capabilities = planner_capabilities(planner);
  if (!capabilities) return false;
  switch (capabilities->determinism) {
    case Determinism::Always:
      return true;
    case Determinism::WithMaxIterations:
      // Even RRTConnect and KPIECE1, which stop at their first path, search until the time
      // limit on a query they cannot solve (the nightly suite saw KPIECE1's expansions differ).
      return max_iterations(params) > 0;
    case Determinism::Never:
      return false;
  }
  return false;
}

}  // namespace planners
}  // namespace fsweep
