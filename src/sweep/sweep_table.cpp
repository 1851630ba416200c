#include "sweep/sweep_table.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <stdexcept>

#include "core/csv_format.hpp"
#include "planners/registry.hpp"
#include "report/runs_schema.hpp"
#include "sim/competitive.hpp"
#include "sim/heuristics.hpp"
#include "sim/simulation.hpp"
#include "strategies/registry.hpp"

namespace fsweep {
inline namespace sweep {

namespace {

/// True when runs.csv column `column` is `name` or one of its nested keys (`name.key`).
bool is_column_of(const std::string& column, const std::string& name) {
  return column == name || column.rfind(name + ".", 0) == 0;
}

/// Names shown in a warning's lists at most.
constexpr std::size_t kListed = 6;

/// "a, b, c" of at most kListed names, then "and N more".
std::string listed(const std::vector<std::string>& names) {
  std::string out;
  for (std::size_t i = 0; i < names.size() && i < kListed; ++i) out += (i ? ", " : "") + names[i];
  if (names.size() > kListed) out += " and " + std::to_string(names.size() - kListed) + " more";
  return out;
}

/// True when the strategy configuration `params` of entry `e` draws from its seed.
bool seeded_strategy(const StrategyEntry& e, const nlohmann::json& params) {
  if (strategy_traits(e.name).seeded) return true;
  return params.is_object() && params.contains("target") && params["target"] == "random";
}

}  // namespace

std::string StarOptimum::check_text() const {
  switch (status) {
    case Status::NotApplicable:
      return "";
    case Status::Ok:
      return "ok";
    case Status::Clipped:
      return "clipped: half-width " + std::to_string(half_width_cells) + " < " +
             std::to_string(needed_cells) + " cells";
  }
  return "";
}

StarOptimum star_optimum(const SweepMap& map, const RobotParams& robot) {
  return star_optimum(*map.map, map.free_space, robot);
}

StarOptimum star_optimum(const WorldMap& world, bool free_space, const RobotParams& robot) {
  StarOptimum out;
  if (!free_space || !std::isfinite(robot.battery_capacity)) return out;
  const EnergyModel& e = robot.energy;
  const double resolution_m = world.resolution_m;
  const double per_metre = e.per_metre + e.per_cell / resolution_m;
  const double sensor_m = robot.sensor.range_m;
  if (!(per_metre > 0.0) || !(sensor_m > 0.0)) return out;
  // The star pattern is optimal only when travel is all that costs energy.
  if (e.per_stop != 0.0 ||
      std::any_of(e.per_turn.begin(), e.per_turn.end(), [](double t) { return t != 0.0; })) {
    return out;
  }
  const double range_m = robot.battery_capacity / per_metre;
  // The robot reaches the disc of radius r/2 around the dock and sees r_s beyond it; one more
  // cell keeps the border off the sensor band. The tolerance keeps an exact multiple of the
  // resolution (930 m / 10 m) from rounding up.
  constexpr double kTolerance = 1e-9;
  out.needed_cells = static_cast<int>(std::ceil((range_m / 2.0 + sensor_m) / resolution_m - kTolerance)) + 1;
  // The free generator's interior is a rectangle, so the four axis directions from the dock
  // decide whether the disc lies inside it.
  const Cell dock = robot.dock.value_or(world.start);
  out.half_width_cells = std::numeric_limits<int>::max();
  for (const Cell step : {Cell{1, 0}, Cell{-1, 0}, Cell{0, 1}, Cell{0, -1}}) {
    int k = 0;
    while (k < out.needed_cells && world.is_free(Cell{dock.x + (k + 1) * step.x, dock.y + (k + 1) * step.y}))
      ++k;
    out.half_width_cells = std::min(out.half_width_cells, k);
  }
  if (out.half_width_cells < out.needed_cells) {
    out.status = StarOptimum::Status::Clipped;
    return out;
  }
  out.status = StarOptimum::Status::Ok;
  out.optimum_m = star_pattern_optimum_m(range_m, sensor_m);
  return out;
}

double optimal_distance_m(const SweepMap& map, const RunSpec& spec) {
  return star_optimum(map, spec.robot).optimum_m;
}

std::string clipped_free_space_warning(const std::string& map_label, const WorldMap& world,
                                       const RobotParams& robot, const std::string& robot_label,
                                       const StarOptimum& check) {
  const Cell dock = robot.dock.value_or(world.start);
  return "map '" + map_label + "' (" + std::to_string(world.width()) + "x" + std::to_string(world.height()) +
         " cells of " + format_number(world.resolution_m) + " m, dock " + std::to_string(dock.x) + ";" +
         std::to_string(dock.y) + ")" + (robot_label.empty() ? std::string() : ", robot " + robot_label) +
         ": clips the free-space optimum: the disc the robot can reach (radius r/2) and its sensor "
         "band need a half-width of " +
         std::to_string(check.needed_cells) + " cells (r/2 + r_s + 1 cell), the map has " +
         std::to_string(check.half_width_cells) + "; optimal_distance_m and competitive_ratio stay empty";
}

std::vector<std::string> clipped_free_space_warnings(const SweepPlan& plan) {
  std::vector<std::string> out;
  for (const SweepMap& map : plan.maps()) {
    if (!map.free_space) continue;
    for (const RobotVariant& robot : plan.robots()) {
      const StarOptimum check = star_optimum(map, robot.params);
      if (check.status != StarOptimum::Status::Clipped) continue;
      out.push_back(clipped_free_space_warning(map.label, *map.map, robot.params,
                                               plan.robots().size() > 1 ? robot.label : std::string(),
                                               check) +
                    " (optimum_check in runs.csv, summary.csv and best.csv)");
    }
  }
  return out;
}

std::vector<std::string> identical_repetition_warnings(const SweepPlan& plan) {
  if (plan.repetitions() < 2 || plan.sim().stop_at_random) return {};
  // 1. Per axis, the items with nothing random; a configuration is fixed when all of its are.
  std::vector<std::string> classes;
  for (const SweepMap& m : plan.maps()) {
    if (m.start_regions == nullptr && std::find(classes.begin(), classes.end(), m.map_class) == classes.end())
      classes.push_back(m.map_class);
  }
  std::vector<std::string> strategies;
  std::uint64_t fixed_combos = 0, combos = 0;
  for (const StrategyEntry& e : plan.strategies()) {
    if (e.search) continue;
    std::uint64_t fixed = 0;
    for (std::uint64_t k = 0; k < e.count(); ++k) fixed += seeded_strategy(e, e.params_at(k)) ? 0 : 1;
    combos += e.count();
    fixed_combos += fixed;
    if (fixed == e.count()) {
      strategies.push_back(e.label);
    } else if (fixed > 0) {
      strategies.push_back(e.label + " (" + std::to_string(fixed) + " of " + std::to_string(e.count()) + ")");
    }
  }
  std::vector<std::string> planners;
  for (const SweepPlanner& p : plan.planners()) {
    const auto caps = planner_capabilities(p.name);
    if (!caps || !caps->seeded) planners.push_back(p.name);
  }
  std::vector<std::string> robots;
  for (const RobotVariant& r : plan.robots()) {
    if (!(r.params.sensor.miss_probability > 0.0)) robots.push_back(r.label);
  }
  const std::uint64_t fixed = classes.size() * fixed_combos * planners.size() * robots.size();
  if (fixed == 0) return {};
  std::set<std::string> all_classes;
  for (const SweepMap& m : plan.maps()) all_classes.insert(m.map_class);
  const std::uint64_t total = all_classes.size() * combos * plan.planners().size() * plan.robots().size();
  // 2. One warning naming them.
  const std::string reps = std::to_string(plan.repetitions());
  std::string line =
      std::to_string(fixed) + " of " + std::to_string(total) +
      " configurations have nothing random in them (no sensor misses, a fixed start, no seeded "
      "strategy or planner), so their " +
      reps + " repetitions on a map instance will be " + reps +
      " copies of one run and summary.csv's n counts each run " + reps + " times: map classes " +
      listed(classes) + "; strategies " + listed(strategies) + "; planners " + listed(planners);
  if (plan.robots().size() > 1) line += "; robots " + listed(robots);
  line +=
      ". For repetitions that mean something, give the map generators several seeds (\"seeds\": {\"range\": "
      "[1, "
      "10]}) or a random start (start=random in a map's SPEC; not on free maps), or a sensor "
      "miss_probability; "
      "else set \"repetitions\": 1";
  return {line};
}

std::vector<std::string> sweep_warnings(const SweepPlan& plan) {
  std::vector<std::string> out = plan.path_warnings();
  for (const SkippedMap& m : plan.skipped_maps()) {
    out.push_back(m.where + ": skipped plan " + m.file + " (\"on_bad_map\": \"skip\"): " + m.reason);
  }
  for (std::string& line : clipped_free_space_warnings(plan)) out.push_back(std::move(line));
  for (std::string& line : identical_repetition_warnings(plan)) out.push_back(std::move(line));
  if (plan.competitive() && !plan.search_units().empty()) {
    out.push_back(
        "competitive: the offline optimum's certified bounds and the competitive ratios between them "
        "(optimum_lower_m, ..., competitive_ratio_max) are computed for the sweep's runs (runs.csv) only; "
        "exact weight searches' behaviours.csv has its own optimal_distance_m and competitive_ratio, not "
        "these");
  }
  return out;
}

namespace {

/// What the config columns of an entry's representative runs depend on beside the planner and
/// robot: its strategy, the names of its representative's resolved parameters (a parameter
/// omitted at its default has no column there) and whether it has heuristics; and every
/// parameter the entry gives (each gets a column).
std::string column_signature(const StrategyEntry& entry) {
  nlohmann::json params = entry.params_at(0);
  std::string out = entry.name;
  if (params.is_object() && params.contains("heuristics")) {
    out += "|heuristics";
    params.erase("heuristics");
    if (params.empty()) params = nullptr;
  }
  out += '|';
  const StrategyConfig resolved = configure_strategy(entry.name, params);
  for (const auto& [name, value] : resolved.params.items()) out += name + ',';
  out += '|';
  for (const StrategyEntry::Group& group : entry.groups) {
    for (const std::string& name : group.names) out += name + ',';
  }
  return out;
}

}  // namespace

std::uint64_t representative_run(const SweepPlan& plan, std::size_t strategy_entry, std::size_t planner,
                                 std::size_t robot) {
  const auto axes = plan.axes();
  if (axes.size() != 5) throw std::logic_error("SweepPlan::axes(): expected 5 axes");
  const std::uint64_t planners = axes[2].second;
  const std::uint64_t robots = axes[3].second;
  const auto reps = static_cast<std::uint64_t>(plan.repetitions());
  const std::uint64_t strategy = plan.strategy_offset(strategy_entry);
  const std::uint64_t index = ((strategy * planners + planner) * robots + robot) * reps;
  const RunCoordinates c = plan.coordinates(index);
  if (c.strategy_entry != strategy_entry || c.strategy_combo != 0 || c.planner != planner ||
      c.robot != robot || c.map != 0 || c.repetition != 0 || strategy >= axes[1].second) {
    throw std::logic_error("SweepPlan run order differs from the documented one");
  }
  return index;
}

SweepTable::SweepTable(const SweepPlan& plan) {
  // 1. Config columns: each representative's list merged in, a new column going right after
  //    the column that precedes it in that list (so strategy.w1..w4 join strategy.distance).
  std::vector<std::string> config;
  const auto axes = plan.axes();
  // Entries whose representatives resolve to the same parameter names (and heuristics or none)
  // give the same columns: merged once (a sweep may have 100,000 entries of one vector each).
  std::set<std::string> merged;
  if (plan.run_count() > 0) {
    for (std::size_t e = 0; e < plan.strategies().size(); ++e) {
      if (plan.strategies()[e].search) continue;  // no runs: its results are the search's files
      if (!merged.insert(column_signature(plan.strategies()[e])).second) continue;
      for (std::size_t p = 0; p < axes.at(2).second; ++p) {
        for (std::size_t r = 0; r < axes.at(3).second; ++r) {
          std::size_t cursor = 0;  // insertion point
          for (const auto& [name, value] : config_columns(plan.run_spec(representative_run(plan, e, p, r)))) {
            if (name == kSeedColumn) continue;
            const auto it = std::find(config.begin(), config.end(), name);
            if (it != config.end()) {
              cursor = static_cast<std::size_t>(it - config.begin()) + 1;
            } else {
              config.insert(config.begin() + static_cast<std::ptrdiff_t>(cursor), name);
              ++cursor;
            }
          }
        }
      }
      // A parameter recorded only away from its default (ParamSpec::omitted_at_default) is
      // missing from a representative at its default but present in the entry's other values:
      // every parameter the entry gives has a column, after the strategy's others.
      for (const StrategyEntry::Group& group : plan.strategies()[e].groups) {
        for (const std::string& param : group.names) {
          const std::string column = "strategy." + param;
          if (std::any_of(config.begin(), config.end(),
                          [&](const std::string& c) { return is_column_of(c, column); })) {
            continue;
          }
          const auto last = std::find_if(config.rbegin(), config.rend(),
                                         [](const std::string& c) { return is_column_of(c, "strategy"); });
          config.insert(last.base(), column);
        }
      }
    }
  }
  // 2. With a free-space map, whether each run's star-pattern optimum applies (last config
  //    column: it depends on the map and the robot, not on the strategy).
  if (std::any_of(plan.maps().begin(), plan.maps().end(), [](const SweepMap& m) { return m.free_space; })) {
    config.emplace_back(kOptimumCheckColumn);
  }
  // 3. The whole row (runs_schema.hpp's order).
  competitive_ = plan.competitive();
  for (const auto& name : sweep_runs_columns(config, competitive_)) {
    if (position_.emplace(name, columns_.size()).second) columns_.push_back(name);
  }
}

std::string SweepTable::header() const { return csv_record(columns_); }

std::string SweepTable::progress_header() { return csv_record(sweep_progress_columns()); }

std::size_t SweepTable::column(std::string_view name) const { return position_.at(std::string(name)); }

std::size_t SweepTable::progress_column(std::string_view name) {
  const std::vector<std::string> columns = sweep_progress_columns();
  const auto it = std::find(columns.begin(), columns.end(), name);
  if (it == columns.end()) throw std::out_of_range("no progress.csv column '" + std::string(name) + "'");
  return static_cast<std::size_t>(it - columns.begin());
}

std::vector<std::string> SweepTable::describe(const SweepPlan& plan, const SweepRun& run) const {
  std::vector<std::string> fields(columns_.size());
  fill_description(plan, run, fields);
  return fields;
}

void SweepTable::fill_description(const SweepPlan& plan, const SweepRun& run,
                                  std::vector<std::string>& fields) const {
  fields[position_.at(kRunIndexColumn)] = std::to_string(run.at.index);
  fields[position_.at(kRunKeyColumn)] = run.key;
  const auto set = [&](const std::string& name, std::string value) {
    const auto it = position_.find(name);
    if (it == position_.end()) {
      throw std::runtime_error("column '" + name +
                               "' of this run is not in the sweep's runs.csv header "
                               "(the representative run of its strategy entry lacks it)");
    }
    fields[it->second] = std::move(value);
  };
  const RunSpec& spec = run.spec;
  const RunCoordinates& at = run.at;
  set(kMapClassColumn, plan.maps().at(at.map).map_class);
  // The entry's label, plus "+rr", "+seg" for the heuristics on (src/sim/heuristics.hpp).
  const std::string heuristics = heuristics_text(spec.heuristics.value_or(Heuristics{}));
  set(kStrategyLabelColumn,
      plan.strategies().at(at.strategy_entry).label + (heuristics.empty() ? "" : "+" + heuristics));
  for (auto& [name, value] : config_columns(spec)) set(name, std::move(value));
  const StarOptimum star = star_optimum(plan.maps().at(at.map), spec.robot);
  if (star.status != StarOptimum::Status::NotApplicable) set(kOptimumCheckColumn, star.check_text());
}

void SweepTable::fill_competitive(const SweepPlan& plan, const SweepRun& run, const RunResult* result,
                                  std::vector<std::string>& fields) const {
  if (!competitive_) return;
  const SweepMap& map = plan.maps().at(run.at.map);
  std::optional<OptimumBounds> solved;
  const OptimumBounds* optimum = nullptr;
  if (map.competitive) {
    optimum = optima_ ? optima_->find(run.spec) : nullptr;
    if (optimum == nullptr) optimum = &solved.emplace(compute_optimum(run.spec));
  }
  std::vector<std::string> cells = competitive_cells(map, optimum, result);
  for (std::size_t i = 0; i < kCompetitiveColumns.size(); ++i)
    fields[position_.at(kCompetitiveColumns[i])] = std::move(cells[i]);
}

RunRows SweepTable::run(const SweepPlan& plan, const SweepRun& run) const {
  const std::uint64_t index = run.at.index;
  RunRows out;
  std::vector<std::string> fields(columns_.size());
  try {
    fill_description(plan, run, fields);  // what a throw leaves filled stays in the error row
    const RunSpec& spec = run.spec;
    const StarOptimum star = star_optimum(plan.maps().at(run.at.map), spec.robot);
    const RunResult result = simulate(spec);
    for (auto& [name, value] : metric_columns(result)) fields[position_.at(name)] = std::move(value);
    if (star.status == StarOptimum::Status::Ok) {
      fields[position_.at(kSweepMetricColumns[0])] = format_number(star.optimum_m);
      fields[position_.at(kSweepMetricColumns[1])] =
          format_number(result.metrics.distance_m / star.optimum_m);
    }
    fill_competitive(plan, run, &result, fields);
    out.failed = result.end == EndReason::Error;
    const std::string prefix = std::to_string(index) + ',' + csv_field(run.key) + ',';
    for (const ProgressSample& s : result.progress) out.progress_rows += prefix + progress_cells(s) + '\n';
  } catch (const std::exception& e) {
    // The run failed before producing a result: the metric cells stay empty.
    for (const auto& [name, value] : metric_columns(RunResult{})) fields[position_.at(name)].clear();
    for (const char* name : kSweepMetricColumns) fields[position_.at(name)].clear();
    for (const char* name : kCompetitiveColumns) {
      if (competitive_) fields[position_.at(name)].clear();
    }
    try {
      fill_competitive(plan, run, nullptr, fields);
    } catch (const std::exception&) {  // NOLINT(bugprone-empty-catch): the run's error is the one to report
    }
    fields[position_.at(kEndReasonColumn)] = std::string(to_string(EndReason::Error));
    fields[position_.at(kEndDetailColumn)] = e.what();
    out.progress_rows.clear();
    out.failed = true;
  }
  out.run_row = csv_record(fields) + '\n';
  return out;
}

}  // namespace sweep
}  // namespace fsweep
