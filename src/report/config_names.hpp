#pragma once
/// @file config_names.hpp
/// Short names for configurations, for people: which config columns tell a table's rows apart
/// (the report's rankings, paired.csv's variants), and a strategy configuration's name (its label,
/// plus the parameters that differ within the label: "EA w1=10 w3=9").

#include <cstddef>
#include <string>
#include <vector>

namespace fsweep {
inline namespace report {

/// Of the columns `names` of `rows` (a row has one cell per name), those that tell the rows
/// apart, as indices into `names`, ascending: the columns with more than one value, less those a
/// kept naming column determines (over `rows`, each of its values comes with one value of the
/// other): `map_class` (its maps' resolution), `strategy_label` (its strategy and parameters),
/// `planner` (its parameters) and any `*.preset` column (robot.energy.preset: the energy model's
/// numbers and unit).
[[nodiscard]] std::vector<std::size_t> telling_columns(const std::vector<std::string>& names,
                                                       const std::vector<std::vector<std::string>>& rows);

/// A config column's name for a heading people read: without its `strategy.`, `robot.`,
/// `planner.` or `sim.` prefix, a preset column as its model ("robot.energy.preset" -> "energy",
/// "robot.sensor.range_m" -> "sensor.range_m"), as tools/plot.py names them.
[[nodiscard]] std::string column_title(std::string name);

/// The name of each strategy configuration of `rows`: cells of `columns`, among them
/// strategy_label, strategy and the strategy.* parameters. A configuration is named by its label
/// alone when the label holds one configuration in `rows`, else by the label and each column
/// but the label whose cells differ within the label, as `name=value` (the `strategy.` prefix
/// left out; empty cells left out), in column order. Without a strategy_label column, by the
/// strategy column.
[[nodiscard]] std::vector<std::string> strategy_names(const std::vector<std::string>& columns,
                                                      const std::vector<std::vector<std::string>>& rows);

}  // namespace report
}  // namespace fsweep
