/// @file runs_schema.cpp
/// The reader side of runs_schema.hpp: column roles, configuration keys, objectives.

#include "report/runs_schema.hpp"

#include <algorithm>

#include "core/config_error.hpp"
#include "core/csv_reader.hpp"

namespace fsweep {
inline namespace report {
namespace {

void append_key_value(std::string& key, std::string_view value) { (key += value) += kKeySeparator; }

}  // namespace

bool is_effort_column(std::string_view name) {
  return name.ends_with("_time_s") || name.ends_with("_expansions");
}

bool is_note_column(std::string_view name) { return name == kCompetitiveNoteColumn; }

bool successful_end(std::string_view end_reason) {
  return end_reason == to_string(EndReason::Complete) || end_reason == to_string(EndReason::TargetReached);
}

RunsHeader::RunsHeader(std::vector<std::string> names, const std::string& path)
    : names_(std::move(names)), roles_(names_.size(), ColumnRole::Other) {
  const auto require = [&](const char* name) {
    const int i = column(name);
    if (i < 0) throw ConfigError(path + ":1", "no column '" + std::string(name) + "' in the header");
    return static_cast<std::size_t>(i);
  };
  run_key_ = require(kRunKeyColumn);
  const std::size_t seed = require(kSeedColumn);
  end_reason_ = require(kEndReasonColumn);
  const int end_detail = column(kEndDetailColumn);
  const std::size_t first_metric = (end_detail >= 0 ? static_cast<std::size_t>(end_detail) : end_reason_) + 1;
  for (std::size_t i = 0; i < names_.size(); ++i) {
    const std::string& name = names_[i];
    ColumnRole& role = roles_[i];
    if (i < seed) {
      if (name == kRunIndexColumn || name == kRunKeyColumn) {
        role = ColumnRole::Identity;
      } else if (name == kMapColumn || name == kMapStartColumn || name == kMapWidthColumn ||
                 name == kMapHeightColumn) {
        role = ColumnRole::Instance;
      } else {
        role = ColumnRole::Config;
        config_.push_back(i);
      }
    } else if (i == seed) {
      role = ColumnRole::Instance;
    } else if (i == end_reason_ || static_cast<int>(i) == end_detail) {
      role = ColumnRole::Outcome;
      quality_.push_back(i);
    } else if (i >= first_metric && !is_note_column(name)) {
      role = ColumnRole::Metric;
      metrics_.push_back(i);
      if (!is_effort_column(name)) quality_.push_back(i);
    }
  }
}

int RunsHeader::column(std::string_view name) const {
  const auto it = std::find(names_.begin(), names_.end(), name);
  return it == names_.end() ? -1 : static_cast<int>(it - names_.begin());
}

std::vector<std::string> RunsHeader::names_of(const std::vector<std::size_t>& columns) const {
  std::vector<std::string> out;
  out.reserve(columns.size());
  for (const std::size_t c : columns) out.push_back(names_[c]);
  return out;
}

std::string RunsHeader::config_key(const std::vector<std::string>& fields) const {
  std::string key;
  for (const std::size_t c : config_) append_key_value(key, fields[c]);
  return key;
}

std::optional<double> metric_value(const std::string& text, const std::string& column, const CsvReader& in) {
  if (text.empty()) return std::nullopt;
  const auto v = parse_number(text);
  if (!v) throw ConfigError(in.where(), "column '" + column + "': '" + text + "' is not a number");
  return v;
}

std::string config_key(const std::vector<std::string>& fields, const std::vector<int>& columns) {
  std::string key;
  for (const int c : columns)
    append_key_value(key, c >= 0 ? fields[static_cast<std::size_t>(c)] : std::string());
  return key;
}

std::vector<std::string> split_config_key(const std::string& key) {
  std::vector<std::string> out;
  std::string value;
  for (const char ch : key) {
    if (ch == kKeySeparator) {
      out.push_back(value);
      value.clear();
    } else {
      value += ch;
    }
  }
  return out;
}

const Objective* find_objective(std::string_view name) {
  const auto it = std::find_if(kObjectives.begin(), kObjectives.end(),
                               [&](const Objective& o) { return o.name == name; });
  return it == kObjectives.end() ? nullptr : &*it;
}

const Objective& require_objective(std::string_view name, const std::string& where) {
  if (const Objective* o = find_objective(name)) return *o;
  throw ConfigError(
      where, "unknown objective '" + std::string(name) + "'; allowed: " + join_names(objective_names()));
}

std::vector<std::string> objective_names() {
  std::vector<std::string> out;
  out.reserve(kObjectives.size());
  for (const Objective& o : kObjectives) out.emplace_back(o.name);
  return out;
}

Direction metric_direction(std::string_view column) {
  constexpr std::array<std::string_view, 5> kLargerIsBetter{"area_per_metre", "coverage", "completeness",
                                                            "explored_area_m2", "known_area_m2"};
  return std::find(kLargerIsBetter.begin(), kLargerIsBetter.end(), column) != kLargerIsBetter.end()
             ? Direction::Maximize
             : Direction::Minimize;
}

std::string_view metric_unit(std::string_view column) {
  if (column == "area_per_metre") return "m²/m";
  if (column == "turned_deg") return "°";
  if (column.ends_with("_m2")) return "m²";
  if (column.ends_with("_m")) return "m";
  if (column.ends_with("_s")) return "s";
  return "";
}

}  // namespace report
}  // namespace fsweep
