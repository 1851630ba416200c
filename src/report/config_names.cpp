/// @file config_names.cpp
/// telling_columns() and strategy_names() (config_names.hpp).

#include "report/config_names.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <unordered_map>

#include "report/runs_schema.hpp"

namespace fsweep {
inline namespace report {
namespace {

/// True for the columns whose value names others: map_class, strategy_label, planner, *.preset.
bool naming_column(const std::string& name) {
  return name == kMapClassColumn || name == kStrategyLabelColumn || name == kPlannerColumn ||
         name.ends_with(".preset");
}

/// True when, over `rows`, the cell of column `by` determines that of column `of`.
bool determines(std::size_t by, std::size_t of, const std::vector<std::vector<std::string>>& rows) {
  std::unordered_map<std::string, const std::string*> seen;
  for (const auto& row : rows) {
    const auto [it, added] = seen.try_emplace(row[by], &row[of]);
    if (!added && *it->second != row[of]) return false;
  }
  return true;
}

}  // namespace

std::vector<std::size_t> telling_columns(const std::vector<std::string>& names,
                                         const std::vector<std::vector<std::string>>& rows) {
  std::vector<std::size_t> varying, naming;
  for (std::size_t c = 0; c < names.size(); ++c) {
    std::set<std::string> values;
    for (const auto& row : rows) values.insert(row[c]);
    if (values.size() < 2) continue;
    varying.push_back(c);
    if (naming_column(names[c])) naming.push_back(c);
  }
  std::vector<std::size_t> kept;
  for (const std::size_t c : varying) {
    const bool implied =
        !naming_column(names[c]) &&
        std::any_of(naming.begin(), naming.end(), [&](std::size_t k) { return determines(k, c, rows); });
    if (!implied) kept.push_back(c);
  }
  return kept;
}

std::string column_title(std::string name) {
  if (name.ends_with(".preset")) name.resize(name.size() - 7);
  for (const char* prefix : {"strategy.", "robot.", "planner.", "sim."}) {
    if (name.starts_with(prefix)) return name.substr(std::string_view(prefix).size());
  }
  return name;
}

std::vector<std::string> strategy_names(const std::vector<std::string>& columns,
                                        const std::vector<std::vector<std::string>>& rows) {
  const auto find = [&](const char* name) {
    const auto it = std::find(columns.begin(), columns.end(), name);
    return it == columns.end() ? columns.size() : static_cast<std::size_t>(it - columns.begin());
  };
  std::size_t label = find(kStrategyLabelColumn);
  if (label == columns.size()) label = find("strategy");
  std::vector<std::string> names;
  if (label == columns.size()) return std::vector<std::string>(rows.size());
  // Per label, the distinct cells of each column.
  std::map<std::string, std::vector<std::set<std::string>>> cells;
  for (const auto& row : rows) {
    auto& sets = cells[row[label]];
    sets.resize(columns.size());
    for (std::size_t c = 0; c < columns.size(); ++c) sets[c].insert(row[c]);
  }
  for (const auto& row : rows) {
    std::string name = row[label];
    const auto& sets = cells[row[label]];
    for (std::size_t c = 0; c < columns.size(); ++c) {
      if (c == label || sets[c].size() < 2 || row[c].empty()) continue;
      const std::string& column = columns[c];
      name += " " + (column.starts_with("strategy.") ? column.substr(9) : column) + "=" + row[c];
    }
    names.push_back(std::move(name));
  }
  return names;
}

}  // namespace report
}  // namespace fsweep
