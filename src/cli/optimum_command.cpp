/// @file optimum_command.cpp
/// `fsweep optimum`: certified bounds on the offline optimum exploration route of one map and
/// robot (optimum/optimum.hpp, docs/competitive.md), written as optimum.csv and route.png.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <system_error>
#include <vector>

#include "cli/commands.hpp"
#include "cli/kv_options.hpp"
#include "cli/option_checks.hpp"
#include "cli/output_dir.hpp"
#include "core/config_error.hpp"
#include "core/csv_format.hpp"
#include "core/random.hpp"
#include "core/readable_number.hpp"
#include "optimum/optimum.hpp"
#include "report/runs_schema.hpp"
#include "sim/trajectory_image.hpp"
#include "world/map_spec.hpp"

namespace fsweep::cli {
namespace {

struct OptimumCliOptions {
  std::string map;
  std::vector<std::string> robot;
  std::uint64_t seed = 0;
  std::string out = "results/optimum";
  double time_limit_s = 0.0;
  const CLI::Option* time_limit = nullptr;  // given or not
  long max_expansions = ExactOptions{}.max_expansions;
  int png_scale = 0;
};

/// The longest --time-limit taken as a deadline (about 30 years); longer ones (inf) mean none,
/// and converting them to clock ticks would overflow.
constexpr double kMaxTimeLimitS = 1e9;

/// build_coverage_instance() with its robot problems named as the option that gave them:
/// "robot/sensor/model: ..." becomes "--robot: sensor.model: ...".
CoverageInstance build_instance(const RunSpec& spec) {
  try {
    return build_coverage_instance(spec);
  } catch (const ConfigError& e) {
    const std::string& where = e.where();
    if (where.rfind("robot/", 0) != 0) throw;
    std::string key = where.substr(6);
    std::replace(key.begin(), key.end(), '/', '.');
    const std::string what = e.what();
    throw ConfigError("--robot", key + ": " + what.substr(std::min(what.size(), where.size() + 2)));
  }
}

/// A number cell: empty for +-infinity and NaN (no value), else every digit.
std::string finite_cell(double v) { return std::isfinite(v) ? format_number(v) : std::string(); }

/// The route as a run's result for the picture: its cells, what it reveals and its recharges
/// (replay_route(), the run's sensor without misses).
RunResult route_result(const RunSpec& spec, const CoverageInstance& in, const OptimumResult& r) {
  RouteReplay replay = replay_route(in, spec, r.route);
  RunResult out;
  out.end = EndReason::Complete;
  out.dock = in.dock;
  for (const int cell : r.route) out.trajectory.push_back(in.truth.cell(cell));
  out.recharge_steps = std::move(replay.recharge_steps);
  RunMetrics& m = out.metrics;
  m.distance_m = replay.length_m;
  m.distance_to_final_coverage_m = replay.distance_to_final_coverage_m;
  m.recharges = static_cast<int>(out.recharge_steps.size());
  int known_nodes = 0;
  for (const int cell : in.node_cell) known_nodes += replay.known.is_free(cell) ? 1 : 0;
  m.coverage = in.nodes() > 0 ? static_cast<double>(known_nodes) / in.nodes() : 1.0;
  out.final_known = std::move(replay.known);
  return out;
}

/// The picture's second title line: what it shows and the bounds.
std::string route_title(const OptimumResult& r) {
  std::string text = "offline optimum route: lower bound " + readable_number(r.lower_m, 5) +
                     " m, upper bound " + readable_number(r.upper_m, 5) + " m";
  text += r.exact ? " (exact)" : ", gap " + readable_number(100.0 * r.gap(), 3) + "%";
  return text;
}

/// The run spec of the command's map (a random start drawn as `fsweep sim` and a sweep draw
/// it, so --seed <a run's seed> repeats it), robot and seed.
RunSpec optimum_spec(const OptimumCliOptions& o) {
  RunSpec spec;
  RunMap map = [&] {
    try {
      return load_run_map_spec(o.map);
    } catch (const ConfigError& e) {
      throw ConfigError("--map", e.what());
    }
  }();
  spec.robot = robot_params_from_json(kv_to_json(o.robot, "--robot"), "--robot");
  spec.seed = o.seed;
  if (map.random_start) {
    map.map.start =
        draw_region_cell(largest_free_region(map.map, spec.robot.allow_corner_cutting), spec.seed);
  }
  spec.map = std::make_shared<const WorldMap>(std::move(map.map));
  return spec;
}

/// optimum.csv's row.
Columns optimum_row(const OptimumCliOptions& o, const RunSpec& spec, const OptimumResult& r) {
  const nlohmann::json robot = spec.robot;
  return {
      {"map", o.map},
      {"map_hash", hex64(content_hash(*spec.map))},
      {"robot", robot.dump()},
      {"lower_m", finite_cell(r.lower_m)},
      {"upper_m", finite_cell(r.upper_m)},
      {"gap", finite_cell(r.gap())},
      {"exact", r.exact ? "1" : "0"},
      {"trips", std::to_string(r.trips)},
      {"time_s", format_number(r.time_s)},
      {"nodes", std::to_string(r.nodes)},
      {"targets", std::to_string(r.targets)},
      {"out_of_reach", std::to_string(r.out_of_reach)},
      {"witnesses", std::to_string(r.witnesses)},
      {"viewpoints", std::to_string(r.viewpoints)},
      {"lower_method", r.lower_method},
      {"upper_method", r.upper_method},
      {"exact_expansions", std::to_string(r.exact_expansions)},
      {"stopped_by_time", r.stopped_by_time ? "1" : "0"},
  };
}

/// The bounds and what they rest on, rounded for reading (5 significant digits); optimum.csv
/// keeps every digit.
void print_bounds(const RunSpec& spec, const OptimumResult& r) {
  const auto n = [](double v) { return readable_number(v, 5); };
  std::cout << "lower bound: " << n(r.lower_m) << " m (" << r.lower_method << ")\n";
  if (r.upper_m < kInfinity) {
    std::cout << "upper bound: " << n(r.upper_m) << " m (" << r.upper_method << "), " << r.trips
              << (r.trips == 1 ? " trip" : " trips") << " from the dock\n";
    std::cout << "gap: " << readable_number(100.0 * r.gap(), 3) << "%, exact: " << (r.exact ? "yes" : "no")
              << '\n';
  } else {
    const std::string why =
        r.upper_method.starts_with("none: ")
            ? r.upper_method.substr(6)
            : "no route was found whose replay reveals every explorable cell" +
                  std::string(std::isfinite(spec.robot.battery_capacity) ? " within each charge" : "");
    std::cout << "upper bound: none (" << why << ")\nexact: no\n";
  }
  std::cout << "explorable: " << readable_number(r.targets - r.out_of_reach) << " of "
            << readable_number(r.targets) << " observable cells, from " << readable_number(r.nodes)
            << " reachable free cells\n";
  if (r.out_of_reach > 0) {
    std::cout << "out of the battery's reach: " << readable_number(r.out_of_reach)
              << " observable cells; runs on this map cannot end complete, and the bounds are for the "
                 "reachable part\n";
  }
  std::cout << "witnesses: " << r.witnesses << ", viewpoints: " << r.viewpoints << ", exact search: ";
  if (r.exact_expansions > 0 || r.stopped_by_time) {
    std::cout << readable_number(static_cast<double>(r.exact_expansions)) << " expansions";
  } else if (r.targets - r.out_of_reach > kExactMaxTargets) {
    std::cout << "not run (more than " << kExactMaxTargets << " explorable cells)";
  } else {
    std::cout << "not run";
  }
  if (r.stopped_by_time) std::cout << " (stopped by --time-limit: the bounds depend on the machine's speed)";
  std::cout << "\ntime: " << readable_number(r.time_s, 3) << " s\n";
}

int run_optimum(const OptimumCliOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  const RunSpec spec = optimum_spec(o);
  OptimumOptions options;
  options.exact.max_expansions = o.max_expansions;
  if (o.time_limit->count() > 0 && o.time_limit_s < kMaxTimeLimitS) {
    options.exact.deadline = t0 + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                      std::chrono::duration<double>(o.time_limit_s));
  }

  check_trajectory_image(*spec.map, o.png_scale, "--png-scale");  // before any file
  check_output_dir(o.out, OutputKind::Optimum, "--out");
  // The robot's problems (a sensor the offline problem does not model) before the directory;
  // the solving, the expensive part, after it: a bad --out costs no search.
  const CoverageInstance instance = build_instance(spec);
  create_output_dir(o.out, OutputKind::Optimum, "--out");
  OptimumResult r = solve_optimum(instance, spec, options);
  r.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  write_csv(o.out + "/optimum.csv", {optimum_row(o, spec, r)});
  const bool has_route = !r.route.empty() && r.upper_m < kInfinity;
  if (has_route) {
    write_trajectory_png(o.out + "/route.png", *spec.map, route_result(spec, instance, r), o.png_scale,
                         TrajectoryTitle{o.map, route_title(r)});
  } else {
    std::error_code ec;  // a picture of an earlier solve in this directory would not be this one's
    std::filesystem::remove(o.out + "/route.png", ec);
  }
  print_bounds(spec, r);
  std::cout << "wrote " << o.out << "/optimum.csv (full precision)";
  if (has_route) {
    std::cout << ", " << o.out << "/route.png\n";
  } else {
    std::cout << "; no route.png (no route)\n";
  }
  return 0;
}

}  // namespace

Command add_optimum_command(CLI::App& app) {
  auto o = std::make_shared<OptimumCliOptions>();
  CLI::App* sub = app.add_subcommand(
      "optimum",
      "Bound the offline optimum exploration route of a map and robot; write optimum.csv, route.png");
  sub->add_option("--map", o->map,
                  "Map SPEC: a file (.map .yaml .png .pgm .txt .json) or a generator, e.g. "
                  "rooms:w=30,h=24,door=2,seed=3; start=random draws the start from --seed")
      ->required();
  sub->add_option(
      "--robot", o->robot,
      "Robot setting key=value (repeatable): sensor.range_m, energy (distance|mei2006|pioneer3dx), "
      "battery, dock=[x,y], start_heading, allow_corner_cutting, sensor.fov_deg; the sensor must be "
      "the grid model (sensor.miss_probability is ignored: the offline sensor never misses)");
  sub->add_option("--seed", o->seed, "Seed of a random start (start=random), as `fsweep sim --seed`")
      ->capture_default_str();
  sub->add_option("--out", o->out, "Output directory")->capture_default_str();
  o->time_limit = sub->add_option("--time-limit", o->time_limit_s,
                                  "Wall-clock limit (seconds, from the command's start) on the exact search; "
                                  "default none. The bounds stay valid, but then depend on the machine's "
                                  "speed (deterministic: --max-expansions)")
                      ->check(non_negative());
  sub->add_option("--max-expansions", o->max_expansions,
                  "Most states the exact search expands (a deterministic budget; it runs on maps with at "
                  "most 64 explorable cells)")
      ->capture_default_str()
      ->check(non_negative());
  sub->add_option("--png-scale", o->png_scale,
                  "Pixels per cell in route.png (0: automatic; the image at most 16384 pixels a side, "
                  "100 megapixels)");
  return [o] { return run_optimum(*o); };
}

}  // namespace fsweep::cli
