/// @file plan_bench_command.cpp
/// `fsweep plan-bench`: every (or every listed) planner on the same queries of one fully known
/// map, against the optimal octile length. The logic is in src/evaluation/plan_bench.hpp; this file
/// parses options, prints the table and writes the files.

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <thread>

#include "cli/commands.hpp"
#include "cli/kv_options.hpp"
#include "cli/output_dir.hpp"
#include "cli/text_table.hpp"
#include "core/config_error.hpp"
#include "core/csv_format.hpp"
#include "core/files.hpp"
#include "core/host_info.hpp"
#include "evaluation/ompl_benchmark_log.hpp"
#include "evaluation/plan_bench.hpp"
#include "planners/ompl_planner.hpp"
#include "planners/registry.hpp"
#include "sweep/manifest.hpp"
#include "world/energy_model.hpp"
#include "world/known_map.hpp"
#include "world/map_loaders.hpp"
#include "world/map_spec.hpp"

namespace fsweep::cli {
namespace {

struct PlanBenchOptions {
  std::string map;
  std::string scen;
  std::vector<std::string> planners;
  std::vector<std::string> planner_params;
  int pairs = 100;
  std::uint64_t seed = 1;
  std::string energy = "distance";
  bool allow_corner_cutting = false;
  double progress_interval_s = 0.05;
  std::string out;
};

/// A number for the table: fixed decimals, "-" for NaN.
void write_queries_csv(const std::string& path, const std::vector<std::string>& names,
                       const std::vector<BenchQuery>& queries,
                       const std::vector<std::vector<BenchPlan>>& plans) {
  std::ostringstream f;  // written whole at the end (write_file_atomically: IoError)
  f << "query,start_x,start_y,goal_x,goal_y,optimal_cells";
  for (const std::string& n : names) {
    for (const char* col : {"status", "length_ratio", "energy", "turns", "time_s"})
      f << ',' << n << '.' << col;
  }
  f << '\n';
  for (std::size_t q = 0; q < queries.size(); ++q) {
    const BenchQuery& b = queries[q];
    f << q << ',' << b.start.x << ',' << b.start.y << ',' << b.goal.x << ',' << b.goal.y << ','
      << format_number(b.optimal_cells);
    for (const auto& row : plans) {
      const BenchPlan& p = row[q];
      f << ',' << to_string(p.status) << ',' << format_number(p.length_ratio) << ','
        << format_number(p.energy) << ',' << p.turns << ',' << format_number(p.time_s);
    }
    f << '\n';
  }
  write_file_atomically(path, f.str());
}

void write_bench_summary_csv(const std::string& path, const std::vector<std::string>& names,
                             const std::vector<BenchSummary>& summaries) {
  std::ostringstream f;  // written whole at the end (write_file_atomically: IoError)
  f << "planner,queries,solved,timeouts,success_rate";
  for (const char* metric : {"length_ratio", "energy", "turns", "time_ms"}) {
    for (const char* stat : {"mean", "q05", "q25", "median", "q75", "q95"}) f << ',' << metric << '_' << stat;
  }
  f << '\n';
  for (std::size_t i = 0; i < names.size(); ++i) {
    const BenchSummary& s = summaries[i];
    f << names[i] << ',' << s.queries << ',' << s.solved << ',' << s.timeouts << ','
      << format_number(s.success_rate);
    for (const SampleSummary& x : {s.length_ratio, s.energy, s.turns, s.time_ms}) {
      for (const double v : {x.mean, x.q05, x.q25, x.median, x.q75, x.q95}) f << ',' << number_cell(v);
    }
    f << '\n';
  }
  write_file_atomically(path, f.str());
}

/// The preamble of ompl_benchmark.log: what was benchmarked (the setup block), on what machine.
BenchmarkLogExperiment log_experiment(const PlanBenchOptions& o, const KnownMap& known, std::size_t queries,
                                      const std::vector<std::unique_ptr<Planner>>& planners) {
  BenchmarkLogExperiment e;
  e.name = plan_bench_experiment_name(o.map, o.scen, o.pairs, o.seed);
  e.ompl_version = ompl_version();
  e.host = host_name();
  e.date = utc_now_iso8601();
  e.setup = "fsweep plan-bench\nmap: " + o.map + " (" + std::to_string(known.width()) + "x" +
            std::to_string(known.height()) + " cells of " + format_number(known.resolution_m()) + " m)\n" +
            "queries: " + std::to_string(queries) +
            (o.scen.empty()
                 ? " random reachable pairs, seed " + std::to_string(o.seed) + ", optimal lengths from astar"
                 : " of " + o.scen + ", optimal lengths from the scenario") +
            "\nrequest: start heading 0, energy model " + o.energy + ", corner cutting " +
            (o.allow_corner_cutting ? "allowed" : "not allowed") + ", seed of query q derive_seed(" +
            std::to_string(o.seed) + ", \"plan_bench\") + q\nprogress samples every " +
            format_number(o.progress_interval_s) + " s (0: none)\n";
  e.cpuinfo = "model name: " + cpu_model() +
              "\nlogical CPUs: " + std::to_string(std::thread::hardware_concurrency()) + "\n";
  e.seed = o.seed;
  for (const auto& p : planners) e.time_limit_s = std::max(e.time_limit_s, p->budget().time_limit_s);
  e.properties = {{"map_width", "INTEGER", std::to_string(known.width())},
                  {"map_height", "INTEGER", std::to_string(known.height())},
                  {"resolution_m", "REAL", format_number(known.resolution_m())},
                  {"allow_corner_cutting", "BOOLEAN", o.allow_corner_cutting ? "1" : "0"}};
  return e;
}

int run_plan_bench_command(const PlanBenchOptions& o) {
  // 1. Planners (all registered by default) with their parameters, energy model, map, queries.
  if (!o.out.empty()) check_output_dir(o.out, OutputKind::PlanBench, "--out");  // before the planning
  const std::vector<std::string> names = o.planners.empty() ? planner_names() : o.planners;
  const nlohmann::json params = kv_to_json(o.planner_params, "--planner-param");
  std::set<std::string> seen;
  for (const std::string& name : names) {
    if (!seen.insert(name).second) throw ConfigError("--planners", "planner '" + name + "' is listed twice");
  }
  if (params.is_object()) {
    for (const auto& [name, value] : params.items()) {
      if (seen.count(name) == 0) {
        throw ConfigError("--planner-param",
                          "'" + name +
                              "' is not a benchmarked planner; write <planner>.<key>=<value>, e.g. "
                              "ompl:RRTstar.time_limit_s=0.1");
      }
    }
  }
  if (o.progress_interval_s < 0.0) {
    throw ConfigError("--progress-interval",
                      "must be >= 0 s (0: no progress samples), got " + format_number(o.progress_interval_s));
  }
  std::vector<std::unique_ptr<Planner>> planners;
  std::vector<BenchmarkLogPlanner> log_planners;
  for (const std::string& name : names) {
    const nlohmann::json p =
        params.is_object() && params.contains(name) ? params.at(name) : nlohmann::json::object();
    const PlannerConfig config = configure_planner(name, p, "--planner-param/" + name);
    planners.push_back(config.make());
    log_planners.push_back(BenchmarkLogPlanner{name, config.params});
  }
  const EnergyModel energy = energy_model_from_json(nlohmann::json{{"preset", o.energy}}, "--energy");
  const KnownMap known = fully_known(load_map_spec(o.map));
  std::vector<BenchQuery> queries;
  if (!o.scen.empty()) {
    queries = bench_queries_from_scenario(load_scenario(o.scen));
  } else {
    PairDrawOptions draw;
    draw.count = o.pairs;
    draw.seed = o.seed;
    draw.start_heading = 0;
    draw.allow_corner_cutting = o.allow_corner_cutting;
    queries = bench_queries_from_pairs(known, draw);
  }
  if (queries.empty()) throw ConfigError(o.scen, "no query with a positive optimal length");

  // 2. Plans and statistics.
  BenchSettings settings;
  settings.energy = energy;
  settings.allow_corner_cutting = o.allow_corner_cutting;
  settings.seed = o.seed;
  settings.progress_interval_s = o.out.empty() ? 0.0 : o.progress_interval_s;  // only the log has them
  BenchmarkLogExperiment experiment = log_experiment(o, known, queries.size(), planners);
  const auto started = std::chrono::steady_clock::now();
  const auto plans = run_plan_bench(known, queries, planners, settings);
  experiment.total_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  std::vector<BenchSummary> summaries;
  summaries.reserve(plans.size());
  for (const auto& row : plans) summaries.push_back(summarize_plan_bench(row));

  // 3. Table and files.
  std::printf("plan-bench: map %s (%dx%d), %zu queries (%s), seed %llu, energy %s%s\n", o.map.c_str(),
              known.width(), known.height(), queries.size(),
              o.scen.empty() ? "random reachable pairs, optimal = astar" : o.scen.c_str(),
              static_cast<unsigned long long>(o.seed), energy.preset.c_str(),
              o.allow_corner_cutting ? ", corner cutting" : "");
  std::printf("%-24s %8s %8s %8s %8s %8s %8s %8s %10s %10s\n", "planner", "success", "timeout", "len/opt",
              "q50", "q95", "energy", "turns", "ms q50", "ms q95");
  for (std::size_t i = 0; i < names.size(); ++i) {
    const BenchSummary& s = summaries[i];
    std::printf("%-24s %8s %8d %8s %8s %8s %8s %8s %10s %10s\n", names[i].c_str(),
                fixed_decimals(100.0 * s.success_rate, 1).c_str(), s.timeouts,
                fixed_decimals(s.length_ratio.mean, 4).c_str(),
                fixed_decimals(s.length_ratio.median, 4).c_str(),
                fixed_decimals(s.length_ratio.q95, 4).c_str(), fixed_decimals(s.energy.mean, 2).c_str(),
                fixed_decimals(s.turns.mean, 2).c_str(), fixed_decimals(s.time_ms.median, 3).c_str(),
                fixed_decimals(s.time_ms.q95, 3).c_str());
  }
  std::printf(
      "(success in %%; len/opt = path length / optimal octile length, mean and quantiles over solved "
      "queries; energy and turns means over solved; time quantiles over all queries)\n");
  if (!o.out.empty()) {
    create_output_dir(o.out, OutputKind::PlanBench, "--out");
    write_queries_csv(o.out + "/queries.csv", names, queries, plans);
    write_bench_summary_csv(o.out + "/summary.csv", names, summaries);
    write_file_atomically(o.out + "/ompl_benchmark.log",
                          ompl_benchmark_log(experiment, queries, log_planners, plans));
    std::printf("wrote %s/{queries.csv,summary.csv,ompl_benchmark.log}\n", o.out.c_str());
  }
  return 0;
}

}  // namespace

Command add_plan_bench_command(CLI::App& app) {
  auto o = std::make_shared<PlanBenchOptions>();
  CLI::App* sub = app.add_subcommand(
      "plan-bench", "Benchmark planners on the same queries against the optimal octile length");
  sub->add_option("--map", o->map, "Map SPEC (fully known)")->required();
  sub->add_option("--scen", o->scen, "MovingAI scenario file (default: --pairs random reachable pairs)");
  sub->add_option("--planners", o->planners,
                  "Comma-separated planner names (default: every registered planner)")
      ->delimiter(',');
  sub->add_option(
      "--planner-param", o->planner_params,
      "Planner parameter <planner>.<key>=<value> (repeatable), e.g. ompl:RRTstar.time_limit_s=0.1");
  sub->add_option("--pairs", o->pairs, "Number of random reachable pairs (without --scen)")
      ->capture_default_str();
  sub->add_option("--seed", o->seed, "Seed of the pairs and of the sampling planners")->capture_default_str();
  sub->add_option("--energy", o->energy, "Energy model preset: distance, mei2006, pioneer3dx")
      ->capture_default_str();
  sub->add_flag("--allow-corner-cutting", o->allow_corner_cutting,
                "Diagonal moves may pass a blocked corner");
  sub->add_option("--progress-interval", o->progress_interval_s,
                  "Seconds between samples of the OMPL planners' progress properties for "
                  "ompl_benchmark.log (0: none)")
      ->capture_default_str();
  sub->add_option("--out", o->out,
                  "Directory for queries.csv, summary.csv and ompl_benchmark.log (OMPL's benchmark log)");
  return [o] { return run_plan_bench_command(*o); };
}

}  // namespace fsweep::cli
