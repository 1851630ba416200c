/// @file plan_command.cpp
/// `fsweep plan`: one query, or every query of a MovingAI `.scen` file checked against its
/// optimal lengths.

#include <cstdio>
#include <iostream>
#include <memory>

#include "cli/commands.hpp"
#include "cli/kv_options.hpp"
#include "core/config_error.hpp"
#include "core/csv_format.hpp"
#include "evaluation/scenario_check.hpp"
#include "planners/registry.hpp"
#include "world/map_loaders.hpp"
#include "world/map_spec.hpp"

namespace fsweep::cli {
namespace {

struct PlanOptions {
  std::string map;
  std::string scen;
  std::string planner = "astar";
  std::vector<std::string> planner_params;
  std::vector<int> from;
  std::vector<int> to;
  double tolerance = 1e-2;
  bool quiet = false;
};

/// On stderr: how many queries of `scen` had a start or goal outside `map` or occupied (status
/// StartInvalid or GoalInvalid), and the first of them. Nothing when there are none.
void report_invalid_endpoints(const std::string& scen, const WorldMap& map, const ScenarioReport& report) {
  int invalid = 0;
  std::string first;
  for (std::size_t i = 0; i < report.queries.size(); ++i) {
    const ScenarioQueryResult& q = report.queries[i];
    if (q.status != PlanStatus::StartInvalid && q.status != PlanStatus::GoalInvalid) continue;
    if (invalid++ == 0) {
      const bool start = q.status == PlanStatus::StartInvalid;
      const Cell c = start ? q.query.start : q.query.goal;
      first = "query " + std::to_string(i) + ": " + (start ? "start" : "goal") + " cell (" +
              std::to_string(c.x) + ", " + std::to_string(c.y) + ") " +
              (map.occupied.in_bounds(c) ? "is occupied" : "is outside the map");
    }
  }
  if (invalid == 0) return;
  std::cerr << "fsweep: warning: " << scen << ": " << invalid << " of " << report.total
            << (report.total == 1 ? " query has" : " queries have") << " a start or goal outside the "
            << map.width() << "x" << map.height() << " map or occupied (first: " << first << ")\n";
}

int run_scenario(const PlanOptions& o, const WorldMap& map, Planner& planner) {
  const ScenarioReport report = check_scenario(map, load_scenario(o.scen), planner, o.tolerance);
  if (!o.quiet) {
    std::printf("%6s %6s %5s %5s %5s %5s %12s %12s  %s\n", "query", "bucket", "sx", "sy", "gx", "gy",
                "computed", "optimal", "result");
  }
  int index = 0;
  for (const auto& q : report.queries) {
    const bool show = !o.quiet || !q.match;
    if (show) {
      const char* verdict = q.match
                                ? (q.unreachable_expected ? "ok (unreachable)" : "ok")
                                : (q.unreachable_expected ? "MISMATCH (expected unreachable)" : "MISMATCH");
      std::printf("%6d %6d %5d %5d %5d %5d %12.6f %12.6f  %s%s%s\n", index, q.query.bucket, q.query.start.x,
                  q.query.start.y, q.query.goal.x, q.query.goal.y, q.length_cells, q.optimal_cells, verdict,
                  q.status == PlanStatus::Success ? "" : " status=",
                  q.status == PlanStatus::Success ? "" : std::string(to_string(q.status)).c_str());
    }
    ++index;
  }
  std::printf(
      "total: %d queries, %d match, %d mismatches, %d expected unreachable; planner %s, %ld expansions, "
      "%.3f s planning, %.3f s wall\n",
      report.total, report.matches, report.mismatches, report.unreachable_expected, planner.name().c_str(),
      report.expansions, report.plan_time_s, report.wall_time_s);
  report_invalid_endpoints(o.scen, map, report);
  return report.mismatches == 0 ? 0 : 1;
}

/// Throws ConfigError naming `option` and the cell if `c` is outside `map` or occupied.
void require_free_endpoint(const WorldMap& map, Cell c, const std::string& option, const std::string& spec) {
  const std::string cell = "cell (" + std::to_string(c.x) + ", " + std::to_string(c.y) + ")";
  if (!map.occupied.in_bounds(c)) {
    throw ConfigError(option, cell + " is outside the " + std::to_string(map.width()) + "x" +
                                  std::to_string(map.height()) + " map " + spec + "; allowed: 0 <= x < " +
                                  std::to_string(map.width()) + ", 0 <= y < " + std::to_string(map.height()));
  }
  if (!map.is_free(c))
    throw ConfigError(option, cell + " is occupied in the map " + spec + "; allowed: a free cell");
}

int run_single(const PlanOptions& o, const WorldMap& map, Planner& planner) {
  if (o.from.size() != 2 || o.to.size() != 2) {
    throw ConfigError("fsweep plan", "give --scen FILE, or both --from X Y and --to X Y");
  }
  PlanRequest request;
  request.start = Cell{o.from[0], o.from[1]};
  request.goal = Cell{o.to[0], o.to[1]};
  require_free_endpoint(map, request.start, "--from", o.map);
  require_free_endpoint(map, request.goal, "--to", o.map);
  const PlanResult r = planner.plan(fully_known(map), request);
  std::cout << "status: " << to_string(r.status) << "\nlength_m: " << format_number(r.length_m)
            << "\nlength_cells: " << format_number(r.length_m / map.resolution_m)
            << "\nenergy: " << format_number(r.energy) << "\nstops: " << r.stops << "\nturns: " << r.turns
            << "\nexpansions: " << r.expansions << "\ntime_s: " << format_number(r.time_s) << '\n';
  return r.status == PlanStatus::Success ? 0 : 1;
}

}  // namespace

Command add_plan_command(CLI::App& app) {
  auto o = std::make_shared<PlanOptions>();
  CLI::App* sub = app.add_subcommand("plan", "Plan one query, or check every query of a MovingAI .scen file");
  sub->add_option("--map", o->map, "Map SPEC (a .map file for scenarios)")->required();
  sub->add_option("--scen", o->scen,
                  "MovingAI scenario file: plan every query, compare with optimal lengths");
  sub->add_option("--planner", o->planner, "Planner name")->capture_default_str();
  sub->add_option("--planner-param", o->planner_params, "Planner parameter key=value (repeatable)");
  sub->add_option("--from", o->from, "Start cell X Y")->expected(2);
  sub->add_option("--to", o->to, "Goal cell X Y")->expected(2);
  sub->add_option("--tolerance", o->tolerance, "Absolute length tolerance (cells)")->capture_default_str();
  sub->add_flag("--quiet", o->quiet, "Print only mismatches and the total");
  return [o] {
    const WorldMap map = load_map_spec(o->map);
    auto planner = make_planner(o->planner, kv_to_json(o->planner_params, "--planner-param"), "--planner");
    return o->scen.empty() ? run_single(*o, map, *planner) : run_scenario(*o, map, *planner);
  };
}

}  // namespace fsweep::cli
