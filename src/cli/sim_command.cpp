/// @file sim_command.cpp
/// `fsweep sim`: one exploration run, written as run.csv, progress.csv and trajectory.png.

#include <filesystem>
#include <iostream>
#include <memory>

#include "cli/commands.hpp"
#include "cli/kv_options.hpp"
#include "cli/output_dir.hpp"
#include "core/csv_format.hpp"
#include "core/readable_number.hpp"
#include "report/runs_schema.hpp"
#include "sim/simulation.hpp"
#include "sim/trajectory_image.hpp"
#include "sweep/sweep_table.hpp"
#include "world/map_spec.hpp"

namespace fsweep::cli {
namespace {

struct SimOptions {
  std::string map;
  std::string strategy = "closest_frontier";
  std::vector<std::string> params;
  std::string planner = "astar";
  std::vector<std::string> planner_params;
  std::vector<std::string> heuristics;
  std::vector<std::string> robot;
  std::vector<std::string> sim;
  std::uint64_t seed = 0;
  std::string out = "results/sim";
  int png_scale = 0;
};

int run_sim(const SimOptions& o) {
  RunSpec spec;
  RunMap map = load_run_map_spec(o.map);
  spec.strategy = configure_strategy(o.strategy, kv_to_json(o.params, "--param"), "--strategy", "--param");
  if (!o.heuristics.empty()) {
    nlohmann::json names = nlohmann::json::array();
    for (const std::string& h : o.heuristics) names.push_back(h);
    spec.heuristics = heuristics_from_json(names, "--heuristics");
  }
  spec.planner = configure_planner(o.planner, kv_to_json(o.planner_params, "--planner-param"), "--planner",
                                   "--planner-param");
  spec.robot = robot_params_from_json(kv_to_json(o.robot, "--robot"), "--robot");
  spec.sim = sim_params_from_json(kv_to_json(o.sim, "--sim"), "--sim");
  spec.seed = o.seed;
  if (map.random_start) {  // as a sweep draws it (SweepPlan::spec_at), so --seed <a run's seed> repeats it
    map.map.start =
        draw_region_cell(largest_free_region(map.map, spec.robot.allow_corner_cutting), spec.seed);
  }
  spec.map = std::make_shared<const WorldMap>(std::move(map.map));

  check_trajectory_image(*spec.map, o.png_scale, "--png-scale");  // before the run and any file
  create_output_dir(o.out, OutputKind::Sim, "--out");             // before the run: a bad --out costs nothing
  // The free-space optimum d* (the star pattern), as a sweep's runs.csv records it.
  const bool free_space = map_spec_object(o.map).value("generator", std::string()) == "free";
  const StarOptimum star = star_optimum(*spec.map, free_space, spec.robot);
  if (star.status == StarOptimum::Status::Clipped) {
    std::cerr << "fsweep: warning: " << clipped_free_space_warning(o.map, *spec.map, spec.robot, "", star)
              << " (optimum_check in run.csv)\n";
  }
  const RunResult result = simulate(spec);

  Columns row = config_columns(spec);
  if (star.status != StarOptimum::Status::NotApplicable)
    row.emplace_back(kOptimumCheckColumn, star.check_text());
  const Columns metrics = metric_columns(result);
  row.insert(row.end(), metrics.begin(), metrics.end());
  const double ratio = result.metrics.distance_m / star.optimum_m;
  if (star.status != StarOptimum::Status::NotApplicable) {
    const bool ok = star.status == StarOptimum::Status::Ok;
    row.emplace_back(kSweepMetricColumns[0], ok ? format_number(star.optimum_m) : "");
    row.emplace_back(kSweepMetricColumns[1], ok ? format_number(ratio) : "");
  }
  write_csv(o.out + "/run.csv", {row});
  write_progress_csv(o.out + "/progress.csv", result);
  write_trajectory_png(o.out + "/trajectory.png", *spec.map, result, o.png_scale, trajectory_title(spec));

  const RunMetrics& m = result.metrics;
  // Rounded for reading (5 significant digits); run.csv keeps every digit.
  const auto r = [](double v) { return readable_number(v, 5); };
  std::cout << "end: " << to_string(result.end)
            << (result.end_detail.empty() ? "" : " (" + result.end_detail + ")")
            << "\ndistance: " << r(m.distance_m) << " m (" << r(m.distance_to_final_coverage_m)
            << " m to the final coverage), energy: " << r(m.energy) << ' ' << spec.robot.energy.unit
            << ", coverage: " << readable_number(100.0 * m.coverage, 4)
            << "%, explored: " << r(m.explored_area_m2) << " m², decisions: " << m.decisions
            << ", recharges: " << m.recharges;
  if (star.status == StarOptimum::Status::Ok) {
    std::cout << "\nfree-space optimum (star pattern): " << r(star.optimum_m)
              << " m, competitive ratio: " << readable_number(ratio, 4);
  }
  std::cout << "\nwrote " << o.out << "/run.csv (full precision), " << o.out << "/progress.csv, " << o.out
            << "/trajectory.png\n";
  return 0;
}

}  // namespace

Command add_sim_command(CLI::App& app) {
  auto o = std::make_shared<SimOptions>();
  CLI::App* sub =
      app.add_subcommand("sim", "Run one exploration and write run.csv, progress.csv, trajectory.png");
  sub->add_option("--map", o->map,
                  "Map SPEC: a file (.map .yaml .png .pgm .txt .json) or a generator, e.g. "
                  "rooms:w=120,h=80,door=3,seed=4; "
                  "start=random draws the start from --seed")
      ->required();
  sub->add_option("--strategy", o->strategy, "Strategy name")->capture_default_str();
  sub->add_option("--param", o->params, "Strategy parameter key=value (repeatable), e.g. w1=10");
  sub->add_option("--heuristics", o->heuristics, "Heuristics of Holz 2010 IV-D (repeatable): rr, seg")
      ->delimiter(',');
  sub->add_option("--planner", o->planner, "Planner name")->capture_default_str();
  sub->add_option("--planner-param", o->planner_params, "Planner parameter key=value (repeatable)");
  sub->add_option(
      "--robot", o->robot,
      "Robot setting key=value (repeatable): sensor.range_m, sensor.fov_deg, sensor.miss_probability, "
      "sensor.model (grid|beams), sensor.beams, energy (distance|mei2006|pioneer3dx), battery, dock=[x,y], "
      "start_heading, allow_corner_cutting");
  sub->add_option("--sim", o->sim,
                  "Loop setting key=value (repeatable): cluster_max_length_m, max_steps, stuck_decisions, "
                  "progress_step_m");
  sub->add_option("--seed", o->seed, "Run seed")->capture_default_str();
  sub->add_option("--out", o->out, "Output directory")->capture_default_str();
  sub->add_option("--png-scale", o->png_scale,
                  "Pixels per cell in trajectory.png (0: automatic; the image at most 16384 pixels a side, "
                  "100 megapixels)");
  return [o] { return run_sim(*o); };
}

}  // namespace fsweep::cli
