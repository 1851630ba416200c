/// @file expand_command.cpp
/// `fsweep expand`: validates a sweep and shows its size, its axes and its first runs, without
/// running or writing anything (a dry run before a long sweep).

#include <algorithm>
#include <cstdint>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/option_checks.hpp"
#include "cli/sweep_warnings.hpp"
#include "core/config_error.hpp"
#include "core/csv_format.hpp"
#include "sweep/sweep_plan.hpp"

namespace fsweep::cli {
namespace {

struct ExpandOptions {
  std::string sweep;
  std::vector<std::string> overrides;
  std::uint64_t limit = 10;
  std::uint64_t from = 0;
};

/// Items of one axis listed before "... and N more".
constexpr std::size_t kListed = 8;

std::string thousands(std::uint64_t n) {
  const std::string digits = std::to_string(n);
  std::string out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

std::string text(const nlohmann::json& v) { return v.is_string() ? v.get<std::string>() : v.dump(); }

/// "w1=0 w2=10 distance=path" (empty for defaults).
std::string params_text(const nlohmann::json& params) {
  std::string out;
  if (!params.is_object()) return out;
  for (const auto& [k, v] : params.items()) out += (out.empty() ? "" : " ") + k + "=" + text(v);
  return out;
}

/// One parameter group of a strategy entry: "w1: 251 values 0 .. 250", "w3=9", "(w1, w2): 3 zipped".
std::string group_text(const StrategyEntry::Group& g) {
  std::string names;
  for (const auto& n : g.names) names += (names.empty() ? "" : ", ") + n;
  if (g.combos.size() == 1) {
    std::string out;
    for (std::size_t i = 0; i < g.names.size(); ++i)
      out += (out.empty() ? "" : " ") + g.names[i] + "=" + text(g.combos[0][i]);
    return out;
  }
  if (g.names.size() > 1) return "(" + names + "): " + thousands(g.combos.size()) + " zipped values";
  return names + ": " + thousands(g.combos.size()) + " values " + text(g.combos.front()[0]) + " .. " +
         text(g.combos.back()[0]);
}

void print_list(const std::vector<std::string>& items) {
  for (std::size_t i = 0; i < items.size() && i < kListed; ++i) std::cout << "      " << items[i] << '\n';
  if (items.size() > kListed) std::cout << "      ... and " << thousands(items.size() - kListed) << " more\n";
}

void print_axes(const SweepPlan& plan) {
  std::cout << "axes (runs in this order, the last varying fastest):\n";
  for (const auto& [name, size] : plan.axes()) {
    std::cout << "  " << name << ": " << thousands(size) << '\n';
    std::vector<std::string> items;
    if (name == "maps") {
      // "(competitive)": the offline optimum's columns (sweep_plan.hpp, `competitive`).
      for (const auto& m : plan.maps()) items.push_back(m.label + (m.competitive ? " (competitive)" : ""));
    } else if (name == "strategy configurations") {
      for (const auto& e : plan.strategies()) {
        std::string groups;
        for (const auto& g : e.groups) groups += (groups.empty() ? "" : "; ") + group_text(g);
        items.push_back(e.label + (e.label != e.name ? " (" + e.name + ")" : "") + ": " +
                        thousands(e.count()) + (groups.empty() ? "" : " [" + groups + "]") +
                        (e.search ? " (an exact weight search: see below)" : ""));
      }
    } else if (name == "planners") {
      for (const auto& p : plan.planners())
        items.push_back(p.name + (p.params.is_null() ? "" : " " + p.params.dump()));
    } else if (name == "robots") {
      for (const auto& r : plan.robots()) items.push_back(r.label);
    }
    print_list(items);
  }
}

/// The exact weight searches (after the runs): their boxes and instances.
void print_searches(const SweepPlan& plan) {
  const std::vector<SearchUnit> units = plan.search_units();
  if (units.empty()) return;
  std::cout << "exact weight searches (after the runs): " << units.size() << '\n';
  for (std::size_t id = 0; id < units.size(); ++id) {
    const SearchUnit& u = units[id];
    const WeightSearch& s = *plan.strategies()[u.entry].search;
    std::string box;
    for (std::size_t k = 0; k < s.weights.size(); ++k) {
      const std::vector<double>& v = s.values[k];
      box += (k == 0 ? "" : " x ") + s.weights[k] + " " +
             (v.size() == 1 ? format_number(v.front())
                            : format_number(v.front()) + ".." + format_number(v.back()) + " (" +
                                  thousands(v.size()) + " values)");
    }
    const SweepPlanner& planner = plan.planners()[u.planner];
    const std::uint64_t instances = u.maps.size() * static_cast<std::uint64_t>(plan.repetitions());
    std::cout << "  " << id << ": " << plan.strategies()[u.entry].label << ", mode "
              << (s.mode == WeightSearch::Mode::All ? "all" : "best") << ", map class " << u.map_class << " ("
              << thousands(instances) << (instances == 1 ? " instance), " : " instances), ") << planner.name
              << ", robot " << plan.robots()[u.robot].label << ": " << box << " = " << thousands(s.vectors())
              << " vectors\n";
  }
}

void print_runs(const SweepPlan& plan, std::uint64_t from, std::uint64_t limit) {
  const std::uint64_t end = from + std::min(limit, plan.run_count() - from);
  std::vector<std::vector<std::string>> rows{
      {"index", "run_key", "map", "strategy", "planner", "robot", "rep", "seed"}};
  for (std::uint64_t i = from; i < end; ++i) {
    const SweepRun run = plan.run(i);
    const RunCoordinates& c = run.at;
    const RunSpec& spec = run.spec;
    const StrategyEntry& entry = plan.strategies()[c.strategy_entry];
    const std::string params = params_text(entry.params_at(c.strategy_combo));  // as written
    const SweepPlanner& planner = plan.planners()[c.planner];
    rows.push_back({std::to_string(i), run.key, plan.maps()[c.map].label,
                    entry.label + (params.empty() ? "" : " " + params),
                    planner.name + (planner.params.is_null() ? "" : " " + planner.params.dump()),
                    plan.robots()[c.robot].label, std::to_string(c.repetition), std::to_string(spec.seed)});
  }
  std::vector<std::size_t> width(rows[0].size(), 0);
  for (const auto& row : rows) {
    for (std::size_t k = 0; k < row.size(); ++k) width[k] = std::max(width[k], row[k].size());
  }
  std::cout << (from == 0 ? "first " : "runs from index " + thousands(from) + ", ") << thousands(end - from)
            << (end - from == 1 ? " run" : " runs") << " of " << thousands(plan.run_count()) << ":\n";
  for (const auto& row : rows) {
    std::string line = " ";
    for (std::size_t k = 0; k < row.size(); ++k) {
      line += ' ' + row[k];
      if (k + 1 < row.size()) line += std::string(width[k] - row[k].size(), ' ');
    }
    std::cout << line << '\n';
  }
}

int run_expand(const ExpandOptions& o) {
  const SweepPlan plan = SweepPlan::from_file(o.sweep, o.overrides);
  print_sweep_warnings(plan, o.sweep);
  if (o.from > 0 && o.from >= plan.run_count()) {
    throw ConfigError("--from", "index " + std::to_string(o.from) + " out of range; allowed: 0 .. " +
                                    std::to_string(plan.run_count() - 1));
  }
  std::cout << "sweep: " << plan.name() << " (" << o.sweep << ")\n";
  if (!plan.overrides().empty()) {
    std::cout << "overrides:";
    for (const std::string& text : plan.overrides()) std::cout << ' ' << text;
    std::cout << '\n';
  }
  if (!plan.description().empty()) std::cout << "description: " << plan.description() << '\n';
  std::cout << "runs: " << thousands(plan.run_count()) << '\n';
  std::cout << "configurations: " << thousands(plan.configuration_count()) << " (x "
            << thousands(static_cast<std::uint64_t>(plan.repetitions()))
            << (plan.repetitions() == 1 ? " repetition" : " repetitions") << ")\n";
  print_axes(plan);
  print_searches(plan);
  std::cout << "sim: " << nlohmann::json(plan.sim()).dump() << '\n';
  std::cout << "seed: " << plan.seed() << " (run seed = derive_seed(seed, \"repetition/<r>\"))\n";
  std::cout << "output: " << plan.output_dir() << " (objective: " << plan.objective() << ")\n";
  if (o.limit > 0 && plan.run_count() > 0) print_runs(plan, o.from, o.limit);
  std::cout << "nothing was run or written.\n";
  return 0;
}

}  // namespace

Command add_expand_command(CLI::App& app) {
  auto o = std::make_shared<ExpandOptions>();
  CLI::App* sub = app.add_subcommand("expand",
                                     "Validate a sweep and show its run count, axes and first runs "
                                     "(a dry run: nothing is run or written)");
  add_sweep_positionals(*sub, o->sweep, o->overrides);
  sub->add_option("--limit", o->limit, "Runs to list (0: none)")->capture_default_str();
  sub->add_option("--from", o->from, "Index of the first run listed")->capture_default_str();
  return [o] { return run_expand(*o); };
}

}  // namespace fsweep::cli
