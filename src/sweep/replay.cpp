#include "sweep/replay.hpp"

#include <stdexcept>
#include <string>
#include <utility>

#include "core/config_error.hpp"
#include "sim/simulation.hpp"
#include "sim/trajectory_image.hpp"

namespace fsweep {
inline namespace sweep {
namespace {

/// Compares the recorded cells of `run` with the re-simulated `result`'s, by column name.
void compare_cells(const ShownRun& run, const RunResult& result, Replay& out) {
  const Columns now = metric_columns(result);
  for (const auto& [name, recorded] : run.recorded) {
    for (const auto& [column, value] : now) {
      if (column != name) continue;
      ++out.compared;
      if (value != recorded) {
        std::string difference = name + ": recorded '";
        difference.append(recorded).append("', re-simulated '").append(value).append("'");
        out.differences.push_back(std::move(difference));
      }
    }
  }
}

/// Instance 0 of the search `run` names, with its weights.
RunResult replay_behaviour(const SweepPlan& plan, const ShownRun& run, Replay& out) {
  const std::vector<SearchUnit> units = plan.search_units();
  const std::size_t id = *run.search_id;
  if (id >= units.size()) {
    throw ConfigError("search " + std::to_string(id),
                      "the sweep has " + std::to_string(units.size()) + " exact weight searches");
  }
  const SearchUnit& unit = units[id];
  out.map = plan.maps().at(unit.maps.at(0)).label;
  const RunSpec spec = plan.search_instance(unit, 0);
  Simulation sim(spec);
  try {
    sim.set_weights(run.weights);
  } catch (const std::exception& e) {
    throw ConfigError("search " + std::to_string(id) + ", behaviour " + run.behaviour_id, e.what());
  }
  while (sim.step()) {
  }
  RunResult result = std::move(sim).result();
  const std::vector<std::string> names = plan.strategies().at(unit.entry).search->weights;
  out.png = trajectory_png(*spec.map, result, 0,
                           TrajectoryTitle{out.map, trajectory_strategy_text(spec, names, run.weights)});
  return result;
}

}  // namespace

Replay replay(const SweepPlan& plan, const ShownRun& run) {
  Replay out;
  RunResult result;
  if (run.search_id) {
    result = replay_behaviour(plan, run, out);
  } else {
    if (!run.run_index || *run.run_index >= plan.run_count()) {
      throw ConfigError("run " + (run.run_index ? std::to_string(*run.run_index) : std::string("?")),
                        "not a run of the sweep (" + std::to_string(plan.run_count()) + " runs)");
    }
    const SweepRun sweep_run = plan.run(*run.run_index);
    if (sweep_run.key != run.run_key) {
      throw ConfigError("run " + std::to_string(*run.run_index),
                        "the sweep's run key is " + sweep_run.key + ", runs.csv recorded " + run.run_key +
                            ": the sweep in manifest.json is not the one that ran (or a map file it names "
                            "was edited since)");
    }
    out.map = plan.maps().at(sweep_run.at.map).label;
    result = simulate(sweep_run.spec);
    out.png = trajectory_png(*sweep_run.spec.map, result, 0, trajectory_title(sweep_run.spec, out.map));
  }
  compare_cells(run, result, out);
  return out;
}

}  // namespace sweep
}  // namespace fsweep
