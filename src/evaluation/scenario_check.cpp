#include "evaluation/scenario_check.hpp"

#include <chrono>
#include <cmath>
#include <string>
#include <utility>

#include "core/config_error.hpp"
#include "world/known_map.hpp"

namespace fsweep {
inline namespace evaluation {

ScenarioReport check_scenario(const WorldMap& map, const std::vector<ScenarioQuery>& queries,
                              Planner& planner, double tolerance_abs) {
  const auto started = std::chrono::steady_clock::now();
  ScenarioReport report;
  const KnownMap known = fully_known(map);
  report.queries.reserve(queries.size());

  for (std::size_t i = 0; i < queries.size(); ++i) {
    const ScenarioQuery& q = queries[i];
    // 1. A scenario for another map is a configuration error, not a mismatch.
    if ((q.map_width != 0 && q.map_width != map.width()) ||
        (q.map_height != 0 && q.map_height != map.height())) {
      throw ConfigError("scenario query " + std::to_string(i + 1),
                        "is for a " + std::to_string(q.map_width) + "x" + std::to_string(q.map_height) +
                            " map (" + q.map_name + "), but " + map.source + " is " +
                            std::to_string(map.width()) + "x" + std::to_string(map.height()));
    }

    // 2. Plan.
    PlanRequest request;
    request.start = q.start;
    request.goal = q.goal;
    const PlanResult plan = planner.plan(known, request);

    // 3. Compare.
    ScenarioQueryResult r;
    r.query = q;
    r.status = plan.status;
    r.length_cells = plan.status == PlanStatus::Success ? plan.length_m / map.resolution_m : 0.0;
    r.optimal_cells = q.optimal_length;
    r.unreachable_expected = q.optimal_length == 0.0 && !(q.start == q.goal);
    r.expansions = plan.expansions;
    r.time_s = plan.time_s;
    if (r.unreachable_expected) {
      r.match = plan.status == PlanStatus::NoPath;
    } else if (plan.status == PlanStatus::Success) {
      const double diff = std::abs(r.length_cells - r.optimal_cells);
      r.match = diff <= tolerance_abs || diff <= kScenarioToleranceRel * std::abs(r.optimal_cells);
    }

    ++report.total;
    ++(r.match ? report.matches : report.mismatches);
    if (r.unreachable_expected) ++report.unreachable_expected;
    report.expansions += r.expansions;
    report.plan_time_s += r.time_s;
    report.queries.push_back(std::move(r));
  }
  report.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return report;
}

}  // namespace evaluation
}  // namespace fsweep
