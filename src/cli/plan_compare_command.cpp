/// @file plan_compare_command.cpp
/// `fsweep plan-compare`: several planners on the same random reachable query pairs of a fully
/// known map, compared pair by pair (Mei et al. 2006 section V-B). The logic is in
/// src/evaluation/plan_compare.hpp; this file parses options, prints the table and writes the files.

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <sstream>

#include "cli/commands.hpp"
#include "cli/kv_options.hpp"
#include "cli/output_dir.hpp"
#include "cli/text_table.hpp"
#include "core/config_error.hpp"
#include "core/csv_format.hpp"
#include "core/files.hpp"
#include "evaluation/plan_compare.hpp"
#include "planners/registry.hpp"
#include "world/energy_model.hpp"
#include "world/known_map.hpp"
#include "world/map_spec.hpp"

namespace fsweep::cli {
namespace {

struct PlanCompareOptions {
  std::string map;
  std::vector<std::string> planners;
  int pairs = 4000;
  std::uint64_t seed = 1;
  std::string energy = "mei2006";
  std::vector<std::string> energy_params;
  std::string start_heading = "random";
  bool allow_corner_cutting = false;
  std::string out;
};

/// "random" -> nullopt; "0".."7" -> the heading; anything else is a ConfigError.
std::optional<int> parse_start_heading(const std::string& text) {
  if (text == "random") return std::nullopt;
  int h = -1;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), h);
  if (ec != std::errc() || end != text.data() + text.size() || h < 0 || h > 7) {
    throw ConfigError(
        "--start-heading",
        "must be 'random' or an integer 0..7 (0 east, 2 south, 4 west, 6 north; odd = diagonal), got '" +
            text + "'");
  }
  return h;
}

/// A number for the table: fixed decimals, "-" for NaN.
void print_compare_table(const PlanCompareOptions& o, const KnownMap& known, const EnergyModel& energy,
                         const CompareSummary& s, std::size_t n_pairs) {
  int free_cells = 0;
  for (int i = 0; i < known.size(); ++i) free_cells += known.is_free(i) ? 1 : 0;
  std::printf(
      "plan-compare: map %s (%dx%d, %d free cells), %zu pairs, seed %llu, energy %s, start heading %s%s\n",
      o.map.c_str(), known.width(), known.height(), free_cells, n_pairs,
      static_cast<unsigned long long>(o.seed), energy.preset.c_str(), o.start_heading.c_str(),
      o.allow_corner_cutting ? ", corner cutting" : "");
  std::printf("note: %s\n\n", baseline_tie_breaking_note().c_str());

  std::printf("%-24s %7s %10s %10s %8s %8s %11s %10s\n", "planner", "solved", "length_m", "energy", "stops",
              "turns", "expansions", "time_ms");
  for (std::size_t p = 0; p < o.planners.size(); ++p) {
    const PlannerTotals& t = s.totals[p];
    std::printf("%-24s %7d %10s %10s %8s %8s %11s %10s\n", o.planners[p].c_str(), t.solved,
                fixed_decimals(t.mean_length_m, 3).c_str(), fixed_decimals(t.mean_energy, 3).c_str(),
                fixed_decimals(t.mean_stops, 2).c_str(), fixed_decimals(t.mean_turns, 2).c_str(),
                fixed_decimals(t.mean_expansions, 0).c_str(), fixed_decimals(t.mean_time_s * 1e3, 4).c_str());
  }
  std::printf("(means per query over solved pairs)\n\n");

  std::printf("%-44s %-18s %7s %7s %7s %7s %7s %7s %8s\n", "baseline -> candidate", "per pair, %", "mean",
              "q05", "q25", "median", "q75", "q95", "totals");
  for (const PlannerContrast& c : s.contrasts) {
    const std::string label = o.planners[static_cast<std::size_t>(c.baseline)] + " -> " +
                              o.planners[static_cast<std::size_t>(c.candidate)];
    const auto row = [&](const char* name, const SampleSummary& x, double total, const std::string& first) {
      std::printf("%-44s %-18s %7s %7s %7s %7s %7s %7s %8s\n", first.c_str(), name,
                  fixed_decimals(x.mean, 2).c_str(), fixed_decimals(x.q05, 2).c_str(),
                  fixed_decimals(x.q25, 2).c_str(), fixed_decimals(x.median, 2).c_str(),
                  fixed_decimals(x.q75, 2).c_str(), fixed_decimals(x.q95, 2).c_str(),
                  fixed_decimals(total, 2).c_str());
    };
    row("energy saving", c.energy_saving_pct, c.total_energy_saving_pct, label);
    row("length increase", c.length_increase_pct, c.total_length_increase_pct, "");
    std::printf("%-44s candidate cheaper %.1f%%, equal %.1f%%, dearer %.1f%% of %d pairs\n", "",
                100.0 * c.share_cheaper, 100.0 * c.share_equal, 100.0 * c.share_dearer, c.pairs_used);
  }
  std::printf(
      "(saving = 100 (E_base - E_cand) / E_base, increase = 100 (L_cand - L_base) / L_base; "
      "totals = the same on sums over the pairs)\n");
}

void write_pairs_csv(const std::string& path, const std::vector<std::string>& names,
                     const std::vector<ComparePair>& pairs, const std::vector<std::vector<PairPlan>>& plans) {
  std::ostringstream f;  // written whole at the end (write_file_atomically: IoError)
  f << "pair,source_x,source_y,target_x,target_y,start_heading";
  for (const std::string& n : names) {
    for (const char* col : {"status", "length_m", "energy", "stops", "turns", "expansions", "time_s"}) {
      f << ',' << n << '.' << col;
    }
  }
  f << '\n';
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const ComparePair& p = pairs[k];
    f << k << ',' << p.source.x << ',' << p.source.y << ',' << p.target.x << ',' << p.target.y << ','
      << p.start_heading;
    for (const auto& runs : plans) {
      const PairPlan& r = runs[k];
      f << ',' << to_string(r.status) << ',' << format_number(r.length_m) << ',' << format_number(r.energy)
        << ',' << r.stops << ',' << r.turns << ',' << r.expansions << ',' << format_number(r.time_s);
    }
    f << '\n';
  }
  write_file_atomically(path, f.str());
}

void write_compare_summary_csv(const std::string& path, const std::vector<std::string>& names,
                               const CompareSummary& s) {
  std::ostringstream f;  // written whole at the end (write_file_atomically: IoError)
  f << "baseline,candidate,pairs_used";
  for (const char* metric : {"energy_saving_pct", "length_increase_pct"}) {
    for (const char* stat : {"mean", "q05", "q25", "median", "q75", "q95"}) f << ',' << metric << '_' << stat;
  }
  f << ",total_energy_saving_pct,total_length_increase_pct,share_cheaper,share_equal,share_dearer";
  for (const char* who : {"baseline", "candidate"}) {
    for (const char* col : {"solved", "mean_length_m", "mean_energy", "mean_stops", "mean_turns",
                            "mean_expansions", "mean_time_s"}) {
      f << ',' << who << '_' << col;
    }
  }
  f << '\n';
  for (const PlannerContrast& c : s.contrasts) {
    f << names[static_cast<std::size_t>(c.baseline)] << ',' << names[static_cast<std::size_t>(c.candidate)]
      << ',' << c.pairs_used;
    for (const SampleSummary& x : {c.energy_saving_pct, c.length_increase_pct}) {
      for (const double v : {x.mean, x.q05, x.q25, x.median, x.q75, x.q95}) f << ',' << number_cell(v);
    }
    f << ',' << number_cell(c.total_energy_saving_pct) << ',' << number_cell(c.total_length_increase_pct)
      << ',' << format_number(c.share_cheaper) << ',' << format_number(c.share_equal) << ','
      << format_number(c.share_dearer);
    for (const int idx : {c.baseline, c.candidate}) {
      const PlannerTotals& t = s.totals[static_cast<std::size_t>(idx)];
      f << ',' << t.solved << ',' << format_number(t.mean_length_m) << ',' << format_number(t.mean_energy)
        << ',' << format_number(t.mean_stops) << ',' << format_number(t.mean_turns) << ','
        << format_number(t.mean_expansions) << ',' << format_number(t.mean_time_s);
    }
    f << '\n';
  }
  write_file_atomically(path, f.str());
}

void write_manifest(const std::string& path, const PlanCompareOptions& o, const KnownMap& known,
                    const EnergyModel& energy, std::size_t n_pairs) {
  nlohmann::json j;
  j["command"] = "plan-compare";
  j["map"] = o.map;
  j["map_width"] = known.width();
  j["map_height"] = known.height();
  j["map_resolution_m"] = known.resolution_m();
  j["pairs"] = n_pairs;
  j["seed"] = o.seed;
  j["pair_streams"] = {"plan_compare.pairs", "plan_compare.headings"};
  j["start_heading"] =
      o.start_heading == "random" ? nlohmann::json("random") : nlohmann::json(std::stoi(o.start_heading));
  j["allow_corner_cutting"] = o.allow_corner_cutting;
  j["energy"] = energy;
  j["planners"] = o.planners;
  j["baseline"] = o.planners.front();
  j["baseline_tie_breaking"] = baseline_tie_breaking_note();
  j["pair_rule"] =
      "distinct unordered {source, target} of distinct known-free cells reachable from each other, "
      "source and target uniform over free cells (rejection sampling)";
  std::ostringstream f;  // written whole at the end (write_file_atomically: IoError)
  f << j.dump(2) << '\n';
  write_file_atomically(path, f.str());
}

int run_plan_compare(const PlanCompareOptions& o) {
  // 1. Resolve and check every input before planning.
  if (!o.out.empty()) check_output_dir(o.out, OutputKind::PlanCompare, "--out");
  if (o.planners.size() < 2) {
    throw ConfigError(
        "--planners",
        "give at least 2 planners, comma-separated (the first is the baseline), e.g. "
        "dijkstra,shortest_fewest_turns,lattice; known: " +
            [] {
              std::string s;
              for (const auto& n : planner_names()) s += (s.empty() ? "" : ", ") + n;
              return s;
            }());
  }
  std::set<std::string> seen;
  std::vector<std::unique_ptr<Planner>> planners;
  for (const std::string& name : o.planners) {
    if (!seen.insert(name).second) throw ConfigError("--planners", "planner '" + name + "' is listed twice");
    planners.push_back(make_planner(name, nlohmann::json::object(), "--planners"));
  }
  const std::optional<int> heading = parse_start_heading(o.start_heading);
  nlohmann::json energy_json = kv_to_json(o.energy_params, "--energy-param");
  if (energy_json.is_null()) energy_json = nlohmann::json::object();
  energy_json["preset"] = o.energy;
  const EnergyModel energy = energy_model_from_json(energy_json, "--energy");
  const KnownMap known = fully_known(load_map_spec(o.map));

  // 2. Pairs, plans, statistics.
  PairDrawOptions draw;
  draw.count = o.pairs;
  draw.seed = o.seed;
  draw.start_heading = heading;
  draw.allow_corner_cutting = o.allow_corner_cutting;
  const std::vector<ComparePair> pairs = draw_compare_pairs(known, draw);
  const auto plans = plan_compare_pairs(known, pairs, planners, energy, o.allow_corner_cutting);
  const CompareSummary summary = summarize_comparison(plans);

  // 3. Outputs.
  print_compare_table(o, known, energy, summary, pairs.size());
  if (!o.out.empty()) {
    create_output_dir(o.out, OutputKind::PlanCompare, "--out");
    write_pairs_csv(o.out + "/pairs.csv", o.planners, pairs, plans);
    write_compare_summary_csv(o.out + "/summary.csv", o.planners, summary);
    write_manifest(o.out + "/manifest.json", o, known, energy, pairs.size());
    std::printf("wrote %s/{pairs.csv,summary.csv,manifest.json}\n", o.out.c_str());
  }
  return 0;
}

}  // namespace

Command add_plan_compare_command(CLI::App& app) {
  auto o = std::make_shared<PlanCompareOptions>();
  CLI::App* sub = app.add_subcommand(
      "plan-compare", "Compare planners pair by pair on random reachable queries (Mei 2006 section V-B)");
  sub->add_option("--map", o->map, "Map SPEC (fully known)")->required();
  sub->add_option("--planners", o->planners,
                  "Comma-separated planner names, at least 2; the first is the baseline")
      ->delimiter(',')
      ->required();
  sub->add_option("--pairs", o->pairs, "Number of distinct random (source, target) pairs")
      ->capture_default_str();
  sub->add_option("--seed", o->seed, "Seed of the pairs and start headings")->capture_default_str();
  sub->add_option("--energy", o->energy, "Energy model preset: distance, mei2006, pioneer3dx")
      ->capture_default_str();
  sub->add_option("--energy-param", o->energy_params, "Energy model override key=value (repeatable)");
  sub->add_option("--start-heading", o->start_heading, "Start heading: random (per pair, seeded) or 0..7")
      ->capture_default_str();
  sub->add_flag("--allow-corner-cutting", o->allow_corner_cutting,
                "Diagonal moves may pass a blocked corner");
  sub->add_option("--out", o->out, "Directory for pairs.csv, summary.csv and manifest.json");
  return [o] { return run_plan_compare(*o); };
}

}  // namespace fsweep::cli
