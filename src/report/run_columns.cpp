/// @file run_columns.cpp
/// The writer side of runs_schema.hpp: a run's configuration and metrics as columns.

#include <sstream>

#include "core/config_error.hpp"
#include "core/csv_format.hpp"
#include "core/files.hpp"
#include "report/runs_schema.hpp"

namespace fsweep {
inline namespace report {
namespace {

void flatten(const nlohmann::json& j, const std::string& prefix, Columns& out) {
  if (j.is_object()) {
    for (const auto& [k, v] : j.items()) flatten(v, std::string(prefix).append(".").append(k), out);
  } else if (j.is_number()) {
    out.emplace_back(prefix, format_number(j.get<double>()));
  } else if (j.is_string()) {
    out.emplace_back(prefix, j.get<std::string>());
  } else if (j.is_null()) {
    out.emplace_back(prefix, "");
  } else {
    out.emplace_back(prefix, j.dump());
  }
}

}  // namespace

Columns config_columns(const RunSpec& spec) {
  Columns c;
  const WorldMap& m = *spec.map;
  c.emplace_back(kMapColumn, m.source);
  c.emplace_back(kMapWidthColumn, std::to_string(m.width()));
  c.emplace_back(kMapHeightColumn, std::to_string(m.height()));
  c.emplace_back("map.resolution_m", format_number(m.resolution_m));
  c.emplace_back(kMapStartColumn, std::to_string(m.start.x) + ";" + std::to_string(m.start.y));
  c.emplace_back("strategy", spec.strategy.name);
  flatten(recorded_strategy_params(spec), "strategy", c);
  c.emplace_back("planner", spec.planner.name);
  flatten(spec.planner.params, "planner", c);  // every resolved parameter, defaults included
  nlohmann::json robot = spec.robot;
  // A dock left at its default is the map's start: written as "start", so runs on several
  // maps of one class (whose starts differ) share the configuration; map.start has the cell.
  robot["dock"] = spec.robot.dock
                      ? std::to_string(spec.robot.dock->x) + ";" + std::to_string(spec.robot.dock->y)
                      : std::string("start");
  flatten(robot, "robot", c);
  flatten(nlohmann::json(spec.sim), "sim", c);
  c.emplace_back(kSeedColumn, std::to_string(spec.seed));
  return c;
}

Columns metric_columns(const RunResult& r) {
  const RunMetrics& m = r.metrics;
  return Columns{
      {kEndReasonColumn, std::string(to_string(r.end))},
      {kEndDetailColumn, r.end_detail},
      {"distance_m", format_number(m.distance_m)},
      {"energy", format_number(m.energy)},
      {"stops", std::to_string(m.stops)},
      {"turns", std::to_string(m.turns)},
      {"turned_deg", format_number(m.turned_deg)},
      {"decisions", std::to_string(m.decisions)},
      {"recharges", std::to_string(m.recharges)},
      {"steps", std::to_string(m.steps)},
      {"distance_to_final_coverage_m", format_number(m.distance_to_final_coverage_m)},
      {"explored_area_m2", format_number(m.explored_area_m2)},
      {"area_per_metre", format_number(m.area_per_metre)},
      {"known_area_m2", format_number(m.known_area_m2)},
      {"reachable_area_m2", format_number(m.reachable_area_m2)},
      {"coverage", format_number(m.coverage)},
      {"residual_unknown_m2", format_number(m.residual_unknown_m2)},
      {"frontier_cells_left", std::to_string(m.frontier_cells_left)},
      {"dropped_goals", std::to_string(m.dropped_goals)},
      {"plan_failures", std::to_string(m.plan_failures)},
      {"planner_expansions", std::to_string(m.planner_expansions)},
      {"planner_time_s", format_number(m.planner_time_s)},
      {"decision_time_s", format_number(m.decision_time_s)},
      {"wall_time_s", format_number(m.wall_time_s)},
      {"completeness", format_number(m.completeness)},
      {"rr_redecisions", std::to_string(m.rr_redecisions)},
      {"segmentation_time_s", format_number(m.segmentation_time_s)},
      {"target_path_m", format_number(m.target_path_m)},
      {"target_shortest_m", format_number(m.target_shortest_m)},
      {"target_path_ratio", format_number(m.target_path_ratio)},
      {"target_x", std::to_string(m.target_x)},
      {"target_y", std::to_string(m.target_y)},
      {"distance_to_coverage_target_m",
       m.distance_to_coverage_target_m ? format_number(*m.distance_to_coverage_target_m) : std::string()},
  };
}

std::vector<std::string> sweep_runs_columns(const std::vector<std::string>& config_names, bool competitive) {
  std::vector<std::string> out{kRunIndexColumn, kRunKeyColumn, kMapClassColumn, kStrategyLabelColumn};
  out.insert(out.end(), config_names.begin(), config_names.end());
  out.emplace_back(kSeedColumn);
  for (auto& [name, value] : metric_columns(RunResult{})) out.push_back(std::move(name));
  out.insert(out.end(), kSweepMetricColumns.begin(), kSweepMetricColumns.end());
  if (competitive) out.insert(out.end(), kCompetitiveColumns.begin(), kCompetitiveColumns.end());
  return out;
}

std::vector<std::string> sweep_progress_columns() {
  std::vector<std::string> out{kRunIndexColumn, kRunKeyColumn};
  out.insert(out.end(), kProgressColumns.begin(), kProgressColumns.end());
  return out;
}

std::string progress_cells(const ProgressSample& s) {
  return format_number(s.distance_m) + ',' + format_number(s.explored_area_m2) + ',' +
         format_number(s.coverage) + ',' + format_number(s.energy);
}

void write_csv(const std::string& path, const std::vector<Columns>& rows) {
  std::ostringstream f;  // written whole at the end (write_file_atomically: IoError)
  std::vector<std::string> cells;
  if (!rows.empty()) {
    for (const auto& [name, value] : rows[0]) cells.push_back(name);
    f << csv_record(cells) << '\n';
  }
  for (const auto& row : rows) {
    cells.clear();
    for (const auto& [name, value] : row) cells.push_back(value);
    f << csv_record(cells) << '\n';
  }
  write_file_atomically(path, f.str());
}

void write_progress_csv(const std::string& path, const RunResult& result) {
  std::ostringstream f;  // written whole at the end (write_file_atomically: IoError)
  f << csv_record({kProgressColumns.begin(), kProgressColumns.end()}) << '\n';
  for (const auto& s : result.progress) f << progress_cells(s) << '\n';
  write_file_atomically(path, f.str());
}

}  // namespace report
}  // namespace fsweep
