#include "evaluation/ompl_benchmark_log.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>
#include <utility>

#include "core/csv_format.hpp"

namespace fsweep {
inline namespace evaluation {
namespace {

/// `text` as one word: every whitespace character becomes '_'; `fallback` when empty.
std::string one_word(std::string text, const char* fallback) {
  if (text.empty()) return fallback;
  std::replace_if(
      text.begin(), text.end(), [](unsigned char c) { return std::isspace(c) != 0; }, '_');
  return text;
}

/// A multi-line block: "<<<|", the lines of `text` (a line that would end the block gets a
/// leading space), "|>>>".
std::string block(const std::string& text) {
  std::string out = "<<<|\n";
  std::size_t begin = 0;
  while (begin < text.size()) {
    std::size_t end = text.find('\n', begin);
    if (end == std::string::npos) end = text.size();
    const std::string_view line(text.data() + begin, end - begin);
    if (line.starts_with("|>>>")) out += ' ';
    out.append(line) += '\n';
    begin = end + 1;
  }
  return out + "|>>>\n";
}

/// The common properties of a planner: its parameters, nested keys joined by '.', values as JSON
/// text (strings without quotes).
void settings_of(const nlohmann::json& params, const std::string& prefix,
                 std::vector<std::pair<std::string, std::string>>& out) {
  if (!params.is_object()) return;
  for (const auto& [key, value] : params.items()) {
    std::string name = prefix;
    if (!name.empty()) name += '.';
    name += key;
    if (value.is_object()) {
      settings_of(value, name, out);
    } else {
      std::string text = value.is_string() ? value.get<std::string>() : value.dump();
      std::replace(text.begin(), text.end(), '\n', ' ');
      out.emplace_back(name, std::move(text));
    }
  }
}

/// The cells of one run row, in kBenchRunProperties order.
std::vector<std::string> run_values(const BenchQuery& query, std::size_t index, const BenchPlan& plan) {
  const bool solved = plan.status == PlanStatus::Success;
  const auto if_solved = [solved](std::string text) { return solved ? std::move(text) : std::string(); };
  return {format_number(plan.time_s),
          solved ? "1" : "0",
          std::to_string(static_cast<int>(plan.status)),
          if_solved(format_number(plan.length_cells)),
          if_solved(format_number(plan.length_ratio)),
          if_solved(format_number(plan.energy)),
          if_solved(std::to_string(plan.turns)),
          std::to_string(index),
          std::to_string(query.start.x),
          std::to_string(query.start.y),
          std::to_string(query.goal.x),
          std::to_string(query.goal.y),
          format_number(query.optimal_cells)};
}

/// The progress properties of a planner's runs: those of every run that sampled any (they must
/// agree), empty when none did.
std::vector<std::string> progress_properties(const std::string& planner, const std::vector<BenchPlan>& runs) {
  std::vector<std::string> properties;
  for (const BenchPlan& run : runs) {
    if (run.progress.properties.empty()) continue;
    if (properties.empty()) {
      properties = run.progress.properties;
    } else if (run.progress.properties != properties) {
      throw std::invalid_argument("ompl_benchmark_log: runs of " + planner +
                                  " report different progress properties");
    }
  }
  return properties;
}

/// One run's progress line: every sample as "time,value,...,;" (the script reads a value before
/// each ',' and a sample before each ';').
std::string progress_line(const std::string& planner, const PlanProgress& progress) {
  std::string line;
  for (const PlanProgress::Sample& s : progress.samples) {
    line += format_number(s.time_s) + ',';
    for (const std::string& v : s.values) {
      if (v.find_first_of(",; \t\n\r") != std::string::npos) {
        std::string what = "ompl_benchmark_log: a progress value of " + planner + " holds a separator: '";
        what += v;
        throw std::invalid_argument(what + "'");
      }
      (line += v) += ',';
    }
    line += ';';
  }
  return line;
}

}  // namespace

std::string plan_bench_experiment_name(const std::string& map_spec, const std::string& scen, int pairs,
                                       std::uint64_t seed) {
  const auto last_component = [](const std::string& path) {
    const auto slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
  };
  const std::string queries = scen.empty()
                                  ? "pairs=" + std::to_string(pairs) + ",seed=" + std::to_string(seed)
                                  : last_component(scen);
  return last_component(map_spec) + "+" + queries;
}

std::string ompl_benchmark_log(const BenchmarkLogExperiment& experiment,
                               const std::vector<BenchQuery>& queries,
                               const std::vector<BenchmarkLogPlanner>& planners,
                               const std::vector<std::vector<BenchPlan>>& plans) {
  if (plans.size() != planners.size()) {
    throw std::invalid_argument("ompl_benchmark_log: " + std::to_string(planners.size()) + " planners but " +
                                std::to_string(plans.size()) + " rows of plans");
  }
  // 1. Preamble (OMPL's order: version, experiment, its properties, host, date, setup, cpuinfo,
  //    seed, limits, run count, total time, enums, planner count).
  std::string out = "OMPL version " + experiment.ompl_version + "\n";
  out += "Experiment " + one_word(experiment.name, "NO_NAME") + "\n";
  if (!experiment.properties.empty()) {
    out += std::to_string(experiment.properties.size()) + " experiment properties\n";
    for (const LogProperty& p : experiment.properties) out += p.name + " " + p.type + " = " + p.value + "\n";
  }
  out += "Running on " + one_word(experiment.host, "UNKNOWN") + "\n";
  out += "Starting at " + experiment.date + "\n";
  out += block(experiment.setup);
  out += block(experiment.cpuinfo);
  out += std::to_string(experiment.seed) + " is the random seed\n";
  out += format_number(experiment.time_limit_s) + " seconds per run\n";
  out += "0 MB per run\n";
  out += std::to_string(queries.size()) + " runs per planner\n";
  out += format_number(experiment.total_time_s) + " seconds spent to collect the data\n";
  out += "1 enum type\n";
  out += kPlanStatusEnum;
  for (int s = static_cast<int>(PlanStatus::Success); s <= static_cast<int>(PlanStatus::Timeout); ++s) {
    (out += '|') += to_string(static_cast<PlanStatus>(s));
  }
  out += "\n" + std::to_string(planners.size()) + " planners\n";

  // 2. Per planner: name, settings, run properties and rows, progress, ".".
  for (std::size_t i = 0; i < planners.size(); ++i) {
    const std::string& name = planners[i].name;
    if (name.empty() || name.find_first_of("\n\r") != std::string::npos) {
      throw std::invalid_argument("ompl_benchmark_log: planner name '" + name +
                                  "' is empty or has a line break");
    }
    if (plans[i].size() != queries.size()) {
      throw std::invalid_argument("ompl_benchmark_log: " + name + " has " + std::to_string(plans[i].size()) +
                                  " plans for " + std::to_string(queries.size()) + " queries");
    }
    out += name + "\n";
    std::vector<std::pair<std::string, std::string>> settings;
    settings_of(planners[i].params, "", settings);
    out += std::to_string(settings.size()) + " common properties\n";
    for (const auto& [key, value] : settings) ((out += key) += " = ").append(value) += '\n';
    out += std::to_string(kBenchRunProperties.size()) + " properties for each run\n";
    for (const std::string_view property : kBenchRunProperties) (out += property) += '\n';
    out += std::to_string(queries.size()) + " runs\n";
    for (std::size_t q = 0; q < queries.size(); ++q) {
      for (const std::string& value : run_values(queries[q], q, plans[i][q])) out += value + "; ";
      out += '\n';
    }
    const std::vector<std::string> progress = progress_properties(name, plans[i]);
    if (!progress.empty()) {
      out += std::to_string(progress.size() + 1) + " progress properties for each run\ntime REAL\n";
      for (const std::string& property : progress) out += property + "\n";
      out += std::to_string(queries.size()) + " runs\n";
      for (const BenchPlan& plan : plans[i]) out += progress_line(name, plan.progress) + "\n";
    }
    out += ".\n";
  }
  return out;
}

}  // namespace evaluation
}  // namespace fsweep
