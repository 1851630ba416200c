#include "report/search_objective.hpp"

#include <limits>
#include <stdexcept>
#include <string>

#include "core/csv_reader.hpp"

namespace fsweep {
inline namespace report {

double metric_number(std::string_view cell) {
  return parse_number(cell).value_or(std::numeric_limits<double>::quiet_NaN());
}

double metric_value(const RunResult& result, std::string_view column) {
  for (const auto& [name, cell] : metric_columns(result)) {
    if (name == column) return metric_number(cell);
  }
  throw std::logic_error("no metric column " + std::string(column));
}

double class_objective(std::span<const RunResult> results, const Objective& objective) {
  double sum = 0.0;
  for (const RunResult& r : results) sum += metric_value(r, objective.column);
  return sum / static_cast<double>(results.size());
}

double class_lower_bound(std::span<const Simulation> sims, const Objective& objective) {
  double sum = 0.0;
  for (const Simulation& s : sims) {
    const RunMetrics& m = s.metrics_so_far();
    if (objective.column == "distance_to_final_coverage_m") {
      sum += m.distance_to_final_coverage_m;
    } else if (objective.column == "energy") {
      sum += m.energy;
    } else if (objective.column == "distance_to_coverage_target_m") {
      sum += s.coverage_target_bound_m();
    } else {
      return -std::numeric_limits<double>::infinity();
    }
  }
  return sum / static_cast<double>(sims.size());
}

}  // namespace report
}  // namespace fsweep
