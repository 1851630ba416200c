#include "sweep/search_tables.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/csv_format.hpp"
#include "core/files.hpp"
#include "core/replacing_file.hpp"
#include "core/statistics.hpp"
#include "report/search_objective.hpp"
#include "report/search_schema.hpp"
#include "sweep/weight_search_runner.hpp"

namespace fsweep {
inline namespace sweep {

using nlohmann::json;

std::size_t distinct_outcomes(const std::vector<FoundBehaviour>& found) {
  std::set<std::vector<std::string>> outcomes;
  for (const FoundBehaviour& f : found) {
    std::vector<std::string> key;
    for (const Columns& cells : f.cells) {
      for (const auto& [name, cell] : cells) {
        if (!is_effort_column(name)) key.push_back(cell);
      }
    }
    outcomes.insert(std::move(key));
  }
  return outcomes.size();
}

bool better_objective(double a, double b, Direction direction) {
  if (std::isnan(a) || std::isnan(b)) return !std::isnan(a) && std::isnan(b);
  return direction == Direction::Minimize ? a < b : a > b;
}

std::string planner_label(const SweepPlanner& p) {
  return p.params.is_null() ? p.name : p.name + " " + p.params.dump();
}

HeatMaps::HeatMaps(const WeightGrid& grid, Direction direction, bool wanted)
    : grid_(grid), direction_(direction) {
  const int w = wanted ? grid.weights() : 0;
  for (int a = 0; a < w; ++a) {
    for (int b = a + 1; b < w; ++b) {
      const std::size_t cells = grid.values(a).size() * grid.values(b).size();
      maps_.push_back({a, b, std::vector<double>(cells, std::numeric_limits<double>::quiet_NaN()),
                       std::vector<HeatMaps::Point>(cells), std::vector<std::uint8_t>(cells, 0)});
    }
  }
}

void HeatMaps::add(const WeightRegion& region, double objective, const HeatMaps::Point& representative) {
  for (Map& m : maps_) {
    const std::size_t nb = grid_.values(m.b).size();
    grid_.for_each_projection(region, m.a, m.b, [&](int ia, int ib) {
      const std::size_t cell = static_cast<std::size_t>(ia) * nb + static_cast<std::size_t>(ib);
      const bool take =
          m.set[cell] == 0 || better_objective(objective, m.best[cell], direction_) ||
          (!better_objective(m.best[cell], objective, direction_) && representative < m.owner[cell]);
      if (!take) return;
      m.set[cell] = 1;
      m.best[cell] = objective;
      m.owner[cell] = representative;
    });
  }
}

SearchTables::SearchTables(const SweepPlan& plan, const SearchUnit& unit, std::size_t id,
                           const Objective& objective)
    : plan_(plan),
      unit_(unit),
      id_(std::to_string(id)),
      search_(*plan.strategies().at(unit.entry).search),
      objective_(objective),
      grid_(search_.values),
      heat_(grid_, objective.direction, search_.mode == WeightSearch::Mode::All) {
  for (const std::vector<double>& vector : search_.rank) {
    HeatMaps::Point at{};
    for (int k = 0; k < grid_.weights(); ++k) {
      const auto values = grid_.values(k);
      at[static_cast<std::size_t>(k)] = static_cast<int>(
          std::lower_bound(values.begin(), values.end(), vector[static_cast<std::size_t>(k)]) -
          values.begin());
    }
    rank_points_.push_back(at);
  }
}

void SearchTables::admit(FoundBehaviour& f) {
  if (search_.mode != WeightSearch::Mode::All) return;
  for (std::size_t r = 0; r < rank_points_.size(); ++r) {
    if (grid_.contains(f.behaviour.region, rank_points_[r])) f.ranked.push_back(r);
  }
  heat_.add(f.behaviour.region, f.objective, f.behaviour.representative);
  if (!search_.write_vectors) f.behaviour.region = WeightRegion{};
}

void SearchTables::format(std::vector<FoundBehaviour>& found, const std::vector<RunSpec>& specs,
                          SearchRows& rows) const {
  std::sort(found.begin(), found.end(), [](const FoundBehaviour& a, const FoundBehaviour& b) {
    return a.behaviour.representative < b.behaviour.representative;
  });
  for (FoundBehaviour& f : found) {
    for (const Columns& cells : f.cells) {
      std::vector<double> values;
      for (const auto& [name, cell] : cells) values.push_back(metric_number(cell));
      f.values.push_back(std::move(values));
    }
  }
  write_behaviours(found, specs, rows);
  write_best_and_ranks(found, rows);
  if (search_.mode == WeightSearch::Mode::All) {
    write_summary(found, specs.size(), rows);
    write_heatmaps(found, rows);
  }
  if (search_.write_vectors) write_vectors(found, rows);
}

std::string SearchTables::behaviours_header(const WeightSearch& s) {
  return csv_record(behaviours_columns(s.weights));
}
std::string SearchTables::summary_header() { return csv_record(search_summary_columns()); }
std::string SearchTables::best_header(const WeightSearch& s) {
  return csv_record(search_best_columns(s.weights));
}
std::string SearchTables::ranks_header(const WeightSearch& s) {
  return csv_record(search_ranks_columns(s.weights));
}
std::string SearchTables::heatmaps_header() { return csv_record(search_heatmaps_columns()); }
std::string SearchTables::vectors_header(const WeightSearch& s) {
  return csv_record(vectors_columns(s.weights));
}

std::string SearchTables::value_at(int k, int index) const {
  return format_number(grid_.values(k)[static_cast<std::size_t>(index)]);
}

void SearchTables::write_behaviours(const std::vector<FoundBehaviour>& found,
                                    const std::vector<RunSpec>& specs, SearchRows& rows) const {
  const int w = grid_.weights();
  for (std::size_t b = 0; b < found.size(); ++b) {
    const Behaviour& be = found[b].behaviour;
    std::vector<std::string> head{id_, std::to_string(b), std::to_string(be.vectors)};
    for (int k = 0; k < w; ++k) head.push_back(value_at(k, be.representative[static_cast<std::size_t>(k)]));
    for (int k = 0; k < w; ++k) {
      head.push_back(value_at(k, be.bounds[static_cast<std::size_t>(k)][0]));
      head.push_back(value_at(k, be.bounds[static_cast<std::size_t>(k)][1]));
    }
    head.push_back(number_cell(found[b].objective));
    for (std::size_t i = 0; i < found[b].cells.size(); ++i) {
      std::vector<std::string> row = head;
      const std::size_t map = unit_.maps[i / static_cast<std::size_t>(plan_.repetitions())];
      row.push_back(std::to_string(i));
      row.push_back(plan_.maps().at(map).label);
      row.push_back(std::to_string(specs[i].seed));
      for (const auto& [name, cell] : found[b].cells[i]) row.push_back(cell);
      rows.behaviours += csv_record(row) + '\n';
    }
  }
}

void SearchTables::write_summary(const std::vector<FoundBehaviour>& found, std::size_t instances,
                                 SearchRows& rows) const {
  const StrategyEntry& entry = plan_.strategies().at(unit_.entry);
  std::vector<std::string> row{id_,
                               entry.label,
                               unit_.map_class,
                               planner_label(plan_.planners().at(unit_.planner)),
                               plan_.robots().at(unit_.robot).label,
                               std::to_string(instances),
                               std::to_string(grid_.size()),
                               std::to_string(found.size())};
  // End reasons, weighted.
  for (int r = static_cast<int>(EndReason::Complete); r <= static_cast<int>(EndReason::Error); ++r) {
    const std::string reason(to_string(static_cast<EndReason>(r)));
    std::uint64_t count = 0;
    for (const FoundBehaviour& f : found) {
      for (const Columns& c : f.cells) count += c.front().second == reason ? f.behaviour.vectors : 0;
    }
    row.push_back(std::to_string(count));
  }
  // Metrics: counted values over vectors x instances.
  const Columns& names = found.front().cells.front();
  for (std::size_t m = 0; m < names.size(); ++m) {
    if (names[m].first == kEndReasonColumn || names[m].first == kEndDetailColumn ||
        is_effort_column(names[m].first)) {
      continue;
    }
    std::vector<CountedValue> values;
    for (const FoundBehaviour& f : found) {
      for (const auto& v : f.values) {
        if (!std::isnan(v[m])) values.push_back({v[m], f.behaviour.vectors});
      }
    }
    if (values.empty()) {
      row.insert(row.end(), kStatisticNames.size(), std::string());
      continue;
    }
    for (const double s : describe_counted(values)) row.push_back(format_number(s));
  }
  rows.summary = csv_record(row) + '\n';
}

std::pair<std::uint64_t, std::uint64_t> SearchTables::standing(const std::vector<FoundBehaviour>& found,
                                                               double objective) const {
  std::uint64_t better_count = 0;
  std::uint64_t tied = 0;
  for (const FoundBehaviour& f : found) {
    if (better_objective(f.objective, objective, objective_.direction)) better_count += f.behaviour.vectors;
    const bool equal = f.objective == objective || (std::isnan(f.objective) && std::isnan(objective));
    if (equal) tied += f.behaviour.vectors;
  }
  return {better_count, tied};
}

void SearchTables::write_best_and_ranks(const std::vector<FoundBehaviour>& found, SearchRows& rows) const {
  std::vector<std::size_t> order(found.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return better_objective(found[a].objective, found[b].objective, objective_.direction);
  });
  std::uint64_t before = 0;        // vectors of the behaviours listed so far
  std::uint64_t better_count = 0;  // vectors strictly better than this behaviour
  for (std::size_t r = 0; r < order.size(); ++r) {
    const FoundBehaviour& f = found[order[r]];
    if (r == 0 || better_objective(found[order[r - 1]].objective, f.objective, objective_.direction))
      better_count = before;
    if (search_.mode == WeightSearch::Mode::Best && better_count > 0) break;
    std::vector<std::string> row{id_,
                                 std::to_string(better_count + 1),
                                 std::to_string(order[r]),
                                 std::to_string(f.behaviour.vectors),
                                 std::to_string(better_count),
                                 number_cell(f.objective)};
    for (int k = 0; k < grid_.weights(); ++k) {
      row.push_back(value_at(k, f.behaviour.representative[static_cast<std::size_t>(k)]));
    }
    rows.best += csv_record(row) + '\n';
    before += f.behaviour.vectors;
  }
  for (std::size_t r = 0; r < search_.rank.size(); ++r) {
    const std::vector<double>& vector = search_.rank[r];
    const auto owner = std::find_if(found.begin(), found.end(), [&](const FoundBehaviour& f) {
      return std::find(f.ranked.begin(), f.ranked.end(), r) != f.ranked.end();
    });
    if (owner == found.end()) throw std::logic_error("exact search: a vector of the box in no behaviour");
    const auto [better_count, tied] = standing(found, owner->objective);
    std::vector<std::string> row{id_};
    for (const double v : vector) row.push_back(format_number(v));
    row.push_back(std::to_string(owner - found.begin()));
    row.push_back(number_cell(owner->objective));
    row.push_back(std::to_string(better_count + 1));
    row.push_back(std::to_string(better_count));
    row.push_back(std::to_string(tied));
    row.push_back(
        format_number(100.0 * static_cast<double>(better_count) / static_cast<double>(grid_.size())));
    rows.ranks += csv_record(row) + '\n';
  }
}

void SearchTables::write_heatmaps(const std::vector<FoundBehaviour>& found, SearchRows& rows) const {
  // found is in id order, which is the order of the representatives.
  const auto id_of = [&](const HeatMaps::Point& representative) {
    const auto it = std::lower_bound(
        found.begin(), found.end(), representative,
        [](const FoundBehaviour& f, const HeatMaps::Point& p) { return f.behaviour.representative < p; });
    return static_cast<std::int64_t>(it - found.begin());
  };
  for (const HeatMaps::Map& m : heat_.maps()) {
    const std::size_t nb = grid_.values(m.b).size();
    for (std::size_t cell = 0; cell < m.best.size(); ++cell) {
      rows.heatmaps += csv_record({id_, search_.weights[static_cast<std::size_t>(m.a)],
                                   search_.weights[static_cast<std::size_t>(m.b)],
                                   value_at(m.a, static_cast<int>(cell / nb)),
                                   value_at(m.b, static_cast<int>(cell % nb)), number_cell(m.best[cell]),
                                   std::to_string(m.set[cell] != 0 ? id_of(m.owner[cell]) : -1)}) +
                       '\n';
    }
  }
}

void SearchTables::write_vectors(const std::vector<FoundBehaviour>& found, SearchRows& rows) const {
  // The owner of every vector, by its lexicographic position in the box.
  const int w = grid_.weights();
  std::vector<std::uint32_t> owner(grid_.size());
  for (std::size_t f = 0; f < found.size(); ++f) {
    grid_.for_each_point(found[f].behaviour.region, [&](const HeatMaps::Point& at) {
      std::uint64_t index = 0;
      for (int k = 0; k < w; ++k)
        index = index * grid_.values(k).size() + static_cast<std::uint64_t>(at[static_cast<std::size_t>(k)]);
      owner[index] = static_cast<std::uint32_t>(f);
    });
  }
  HeatMaps::Point at{};
  for (std::uint64_t index = 0; index < owner.size(); ++index) {
    std::uint64_t rest = index;
    for (int k = w - 1; k >= 0; --k) {
      const std::uint64_t size = grid_.values(k).size();
      at[static_cast<std::size_t>(k)] = static_cast<int>(rest % size);
      rest /= size;
    }
    rows.vectors += id_;
    for (int k = 0; k < w; ++k) rows.vectors += ',' + value_at(k, at[static_cast<std::size_t>(k)]);
    rows.vectors += ',' + std::to_string(owner[index]) + '\n';
  }
}

void write_search_files(const SweepPlan& plan, const std::vector<SearchUnit>& units,
                        std::vector<SearchRows> rows, const std::string& out_dir, SearchRunReport& report) {
  const WeightSearch& first = *plan.strategies().at(units.front().entry).search;
  bool any_vectors = false;
  bool any_all = false;
  for (const SearchUnit& unit : units) {
    const WeightSearch& s = *plan.strategies().at(unit.entry).search;
    any_vectors = any_vectors || s.write_vectors;
    any_all = any_all || s.mode == WeightSearch::Mode::All;
  }
  // Each file streamed: its header, then every search's rows, each released once written, so
  // the files' text is held once (in the rows), not copied whole beside them.
  const std::filesystem::path dir(out_dir);
  const auto write = [&](const char* name, const std::string& header, std::string SearchRows::*part) {
    ReplacingFile file((dir / name).string());
    file.write(header + '\n');
    for (SearchRows& r : rows) {
      file.write(r.*part);
      std::string().swap(r.*part);
    }
    file.commit();
    report.files.emplace_back(name);
  };
  write(kBehavioursFile, SearchTables::behaviours_header(first), &SearchRows::behaviours);
  write(kSearchBestFile, SearchTables::best_header(first), &SearchRows::best);
  if (any_all) {
    write(kSearchSummaryFile, SearchTables::summary_header(), &SearchRows::summary);
    write(kSearchRanksFile, SearchTables::ranks_header(first), &SearchRows::ranks);
    write(kSearchHeatmapsFile, SearchTables::heatmaps_header(), &SearchRows::heatmaps);
  }
  if (any_vectors) write(kVectorsFile, SearchTables::vectors_header(first), &SearchRows::vectors);
  json searches = json::array();
  for (std::size_t id = 0; id < units.size(); ++id) {
    const WeightSearch& s = *plan.strategies().at(units[id].entry).search;
    (s.mode == WeightSearch::Mode::All ? report.behaviours : report.optimal) +=
        rows[id].record.at("behaviours").get<std::uint64_t>();
    report.vectors += s.vectors();
    searches.push_back(std::move(rows[id].record));
  }
  // Last: its presence marks the search files as complete.
  write_file_atomically((dir / kSearchesFile).string(), json{{"searches", searches}}.dump(2) + '\n');
  report.files.emplace_back(kSearchesFile);
  report.searches = units.size();
}

}  // namespace sweep
}  // namespace fsweep
