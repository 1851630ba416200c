/// @file report_tables.cpp
/// The ranking per map class and the paired comparisons of report.html (report_tables.hpp).

#include "report/report_tables.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "core/csv_reader.hpp"
#include "core/readable_number.hpp"
#include "report/config_names.hpp"
#include "report/html.hpp"
#include "report/runs_schema.hpp"

namespace fsweep {
inline namespace report {
namespace {

/// The metrics of the ranking besides the objective, when summary.csv has values of them (the
/// offline optimum's ratios only in a sweep with a competitive map).
constexpr const char* kRankingMetrics[] = {"distance_m",
                                           "energy",
                                           "coverage",
                                           "explored_area_m2",
                                           "competitive_ratio",
                                           "competitive_ratio_min",
                                           "competitive_ratio_max",
                                           "decisions",
                                           "recharges"};

/// A table cell: its text (escaped when written) and whether it holds a number (right-aligned).
struct TableCell {
  std::string text;
  bool number = false;
};

/// A <table> with a header row, rows of cells and a class per row ("" for none).
std::string table_html(const std::vector<std::string>& header,
                       const std::vector<std::vector<TableCell>>& rows,
                       const std::vector<std::string>& row_classes) {
  std::ostringstream out;
  out << "<div class='scroll'><table class='readable'><tr>";
  for (const auto& h : header) out << "<th>" << html_escape(h) << "</th>";
  out << "</tr>\n";
  for (std::size_t r = 0; r < rows.size(); ++r) {
    out << (row_classes[r].empty() ? "<tr>" : "<tr class='" + row_classes[r] + "'>");
    for (const TableCell& c : rows[r])
      out << (c.number ? "<td class='num'>" : "<td>") << html_escape(c.text) << "</td>";
    out << "</tr>\n";
  }
  out << "</table></div>\n";
  return out.str();
}

/// Index of column `name` in `header`, or -1.
int index_of(const std::vector<std::string>& header, const std::string& name) {
  const auto it = std::find(header.begin(), header.end(), name);
  return it == header.end() ? -1 : static_cast<int>(it - header.begin());
}

/// A number cell of `text` (a CSV cell) rounded for reading; the text itself when not a number.
std::string readable_cell(const std::string& text) {
  const auto v = parse_number(text);
  return v ? readable_number(*v) : text;
}

/// The columns of summary.csv the ranking reads.
struct SummaryColumns {
  std::vector<std::size_t> config;  ///< between config_id and n, map_class aside
  std::size_t n = 0;
  int n_distinct = -1;
  std::vector<std::size_t> ends;  ///< end.* columns
  int energy_unit = -1;
};

SummaryColumns summary_columns(const std::vector<std::string>& h) {
  SummaryColumns c;
  const int id = index_of(h, "config_id");
  c.n = static_cast<std::size_t>(std::max(index_of(h, "n"), 0));
  for (std::size_t k = static_cast<std::size_t>(id) + 1; k < c.n; ++k) {
    if (h[k] != kMapClassColumn) c.config.push_back(k);
  }
  c.n_distinct = index_of(h, "n_distinct");
  for (std::size_t k = c.n + 1; k < h.size(); ++k) {
    if (h[k].starts_with("end.")) c.ends.push_back(k);
  }
  c.energy_unit = index_of(h, "robot.energy.unit");
  return c;
}

/// The cells of `columns` of each row.
std::vector<std::vector<std::string>> project(const std::vector<const std::vector<std::string>*>& rows,
                                              const std::vector<std::size_t>& columns) {
  std::vector<std::vector<std::string>> out;
  for (const auto* row : rows) {
    auto& cells = out.emplace_back();
    for (const std::size_t c : columns) cells.push_back((*row)[c]);
  }
  return out;
}

/// "complete 8, range_limited 2" of a summary row's end.* counts.
std::string ends_text(const std::vector<std::string>& h, const std::vector<std::string>& row,
                      const std::vector<std::size_t>& ends) {
  std::string out;
  for (const std::size_t c : ends) {
    if (row[c] != "0" && !row[c].empty()) out += (out.empty() ? "" : ", ") + h[c].substr(4) + " " + row[c];
  }
  return out;
}

/// The metrics the ranking shows: the objective, then kRankingMetrics with a value in some row.
std::vector<std::string> ranking_metrics(const std::vector<std::string>& h, const std::string& objective,
                                         const std::vector<const std::vector<std::string>*>& rows) {
  std::vector<std::string> out;
  if (!objective.empty()) out.push_back(objective);
  for (const char* m : kRankingMetrics) {
    const int c = index_of(h, std::string(m) + ".median");
    if (c < 0 || m == objective) continue;
    if (std::any_of(rows.begin(), rows.end(),
                    [&](const auto* row) { return !(*row)[static_cast<std::size_t>(c)].empty(); }))
      out.emplace_back(m);
  }
  return out;
}

/// "Equal in every row: a = x; b = y" for the columns of `columns` with one non-empty value.
std::string equal_line(const std::vector<std::string>& h,
                       const std::vector<const std::vector<std::string>*>& rows,
                       const std::vector<std::size_t>& columns) {
  std::string same;
  for (const std::size_t c : columns) {
    const std::string& first = (*rows.front())[c];
    if (first.empty()) continue;
    if (std::all_of(rows.begin(), rows.end(), [&](const auto* row) { return (*row)[c] == first; }))
      same += (same.empty() ? "" : "; ") + h[c] + " = " + first;
  }
  return same.empty() ? "" : "<p class='same'>Equal in every row: " + html_escape(same) + "</p>\n";
}

}  // namespace

std::string metric_title(const std::string& column, const std::string& energy_unit) {
  std::string unit(metric_unit(column));
  std::string name = column;
  for (const char* suffix : {"_m2", "_m", "_s", "_deg"}) {
    if (!unit.empty() && name.ends_with(suffix)) {
      name.resize(name.size() - std::string_view(suffix).size());
      break;
    }
  }
  if (column == "energy") unit = energy_unit;
  std::replace(name.begin(), name.end(), '_', ' ');
  return unit.empty() ? name : name + " (" + unit + ")";
}

std::string ranking_html(const ResultDir& r) {
  const std::vector<std::string>& h = r.summary.header;
  std::vector<const std::vector<std::string>*> rows;
  for (const ClassRanking& c : r.rankings) {
    for (const auto& row : c.rows) rows.push_back(&row);
  }
  if (rows.empty() || index_of(h, "config_id") < 0 || index_of(h, "n") < 0)
    return "<p>No configurations.</p>\n";
  const SummaryColumns cols = summary_columns(h);
  // 1. What names a row: the strategy, then the other config columns that tell rows apart.
  std::vector<std::size_t> side, other;
  // map_class names its own tables, but tells what it determines (the maps' resolution).
  const int map_class = index_of(h, kMapClassColumn);
  if (map_class >= 0) other.push_back(static_cast<std::size_t>(map_class));
  for (const std::size_t c : cols.config) {
    const bool is_side = h[c] == kStrategyLabelColumn || h[c] == "strategy" || h[c].starts_with("strategy.");
    (is_side ? side : other).push_back(c);
  }
  std::vector<std::string> side_names, other_names;
  for (const std::size_t c : side) side_names.push_back(h[c]);
  for (const std::size_t c : other) other_names.push_back(h[c]);
  const std::vector<std::string> names = strategy_names(side_names, project(rows, side));
  std::vector<std::size_t> variant;
  for (const std::size_t k : telling_columns(other_names, project(rows, other))) {
    if (static_cast<int>(other[k]) != map_class) variant.push_back(other[k]);
  }
  // 2. The numbers: objective and metrics, the energy unit, the end reasons.
  const std::string objective = r.best.header.size() > 3 && r.best.header[3].ends_with(".median")
                                    ? r.best.header[3].substr(0, r.best.header[3].size() - 7)
                                    : "";
  const std::vector<std::string> metrics = ranking_metrics(h, objective, rows);
  std::set<std::string> units;
  for (const auto* row : rows)
    units.insert(cols.energy_unit < 0 ? "" : (*row)[static_cast<std::size_t>(cols.energy_unit)]);
  const std::string energy_unit = units.size() == 1 ? *units.begin() : "";
  const bool show_ends = std::any_of(rows.begin(), rows.end(), [&](const auto* row) {
    return ends_text(h, *row, cols.ends) != "complete " + (*row)[cols.n];
  });
  std::vector<std::string> header{"rank", "strategy"};
  for (const std::size_t c : variant) header.push_back(column_title(h[c]));
  header.emplace_back("runs");
  for (const auto& m : metrics) {
    header.push_back(metric_title(m, energy_unit) + (m == objective ? ", median [q05, q95]" : ", median"));
  }
  if (show_ends) header.emplace_back("ended");
  // 3. A table per class.
  std::ostringstream out;
  out << equal_line(h, rows, cols.config);
  bool copies = false;
  std::size_t k = 0;
  for (const ClassRanking& c : r.rankings) {
    if (r.rankings.size() > 1 || !c.map_class.empty())
      out << "<h3>map class " << html_escape(c.map_class) << "</h3>\n";
    std::vector<std::vector<TableCell>> table;
    std::vector<std::string> classes;
    for (std::size_t i = 0; i < c.rows.size(); ++i, ++k) {
      const auto& row = c.rows[i];
      auto& cells = table.emplace_back();
      cells.push_back({std::to_string(c.ranks[i]), true});
      cells.push_back({names[k], false});
      for (const std::size_t v : variant) cells.push_back({row[v], false});
      const std::string distinct =
          cols.n_distinct < 0 ? row[cols.n] : row[static_cast<std::size_t>(cols.n_distinct)];
      const bool repeated = distinct != row[cols.n];
      copies = copies || repeated;
      cells.push_back({row[cols.n] + (repeated ? " (" + distinct + " distinct) ⚠" : ""), true});
      for (const auto& m : metrics) {
        const int median = index_of(h, m + ".median");
        std::string text = readable_cell(row[static_cast<std::size_t>(median)]);
        if (m == "energy" && energy_unit.empty() && cols.energy_unit >= 0 && !text.empty())
          text += " " + row[static_cast<std::size_t>(cols.energy_unit)];
        if (m == objective && !text.empty()) {
          text += " [" + readable_cell(row[static_cast<std::size_t>(index_of(h, m + ".q05"))]) + ", " +
                  readable_cell(row[static_cast<std::size_t>(index_of(h, m + ".q95"))]) + "]";
        }
        cells.push_back({text, true});
      }
      if (show_ends) cells.push_back({ends_text(h, row, cols.ends), false});
      classes.emplace_back(repeated ? "copies" : "");
    }
    out << table_html(header, table, classes);
    if (c.total > c.rows.size()) {
      out << "<p>The best " << c.rows.size() << " of the class's " << c.total
          << " configurations; every one is in <code>best.csv</code> and <code>summary.csv</code>.</p>\n";
    }
  }
  if (copies) {
    out << "<p class='warn'>⚠ Rows marked so have runs that came out identical: <em>runs</em> counts every "
           "run "
           "(summary.csv's n), the number in brackets the distinct ones (n_distinct). Repetitions with "
           "nothing "
           "random in them (no sensor misses, a fixed start, no seeded strategy or planner) are copies of "
           "one "
           "run; give the maps several generator seeds or a random start instead.</p>\n";
  }
  return out.str();
}

std::string paired_html(const PairedTable& table, const std::string& baseline_from) {
  std::ostringstream out;
  out << "<p>Each strategy against <b>" << html_escape(table.baseline) << "</b> ("
      << html_escape(baseline_from)
      << "), run by run on the same map instance, robot, planner and seed. Differences are the strategy's "
         "value "
         "minus the baseline's; lower is better for distances and energy, higher for area per metre. The "
         "interval is a 95% bootstrap interval of the mean difference that resamples map instances (with "
         "their "
         "repetitions); p is the two-sided Wilcoxon signed-rank test on the pairs, then Holm-adjusted over "
         "the "
         "strategies of one table and metric. <code>fsweep paired</code> writes all of it, at full "
         "precision, "
         "to paired.csv.</p>\n";
  std::string block, metric_of_last;
  std::vector<std::vector<TableCell>> rows;
  const std::vector<std::string> header{"metric",
                                        "strategy",
                                        "pairs",
                                        "mean difference [95% interval]",
                                        "median difference",
                                        "median relative",
                                        "wins / ties / losses",
                                        "p",
                                        "p (Holm)",
                                        "reading"};
  const auto flush = [&] {
    if (!rows.empty()) out << table_html(header, rows, std::vector<std::string>(rows.size()));
    rows.clear();
  };
  for (const PairedRow& r : table.rows) {
    std::string b = (r.source == "runs" ? "" : r.source + ", ") + "map class " + r.map_class;
    for (std::size_t v = 0; v < r.variant.size() && v < table.variant_columns.size(); ++v)
      b += ", " + column_title(table.variant_columns[v]) + " = " + r.variant[v];
    if (b != block) {
      flush();
      out << "<h3>" << html_escape(b) << "</h3>\n";
      block = b;
    }
    const auto diff = [&](double v) { return readable_number(v, 4, Sign::Always); };
    const bool lower = metric_direction(r.metric) == Direction::Minimize;
    std::string pairs = std::to_string(r.n_pairs);
    if (r.mixed_end + r.unpaired + r.no_value > 0) {
      pairs += " (left out: " + std::to_string(r.mixed_end) + " ended differently, " +
               std::to_string(r.unpaired) + " unpaired, " + std::to_string(r.no_value) + " without a value)";
    }
    std::string reading = "no pairs";
    if (r.n_pairs > 0 && !r.ci) reading = "one map instance: no interval";
    if (r.ci) {
      const bool above = r.ci->lo > 0.0, below = r.ci->hi < 0.0;
      reading = !above && !below ? "no clear difference" : (below == lower ? "better" : "worse");
    }
    const std::string unit = r.unit.empty() ? "" : " " + r.unit;
    const std::string title = metric_title(r.metric, r.unit);
    const bool same_metric = !rows.empty() && metric_of_last == title;
    metric_of_last = title;
    rows.push_back(
        {{same_metric ? "" : title, false},
         {r.side, false},
         {pairs, true},
         {r.n_pairs == 0
              ? ""
              : diff(r.mean_diff) + unit + (r.ci ? " [" + diff(r.ci->lo) + ", " + diff(r.ci->hi) + "]" : ""),
          true},
         {r.n_pairs == 0 ? "" : diff(r.median_diff) + unit, true},
         {std::isnan(r.rel_diff_pct) ? "" : readable_number(r.rel_diff_pct, 2, Sign::Always) + "%", true},
         {std::to_string(r.wins) + " / " + std::to_string(r.ties) + " / " + std::to_string(r.losses), true},
         {r.wilcoxon ? readable_number(r.wilcoxon->p_value, 2) + " (" +
                           std::string(to_string(r.wilcoxon->method)) + ")"
                     : "",
          true},
         {r.p_holm ? readable_number(*r.p_holm, 2) : "", true},
         {reading, false}});
  }
  flush();
  for (const auto& note : table.notes) out << "<p>Note: " << html_escape(note) << "</p>\n";
  return out.str();
}

std::string optimum_html(const std::string& runs_csv) {
  CsvReader in(runs_csv);
  const int lower = in.column("optimum_lower_m");
  if (lower < 0) return {};
  const std::size_t upper = in.require_column("optimum_upper_m");
  const std::size_t exact = in.require_column("optimum_exact");
  const std::size_t map = in.require_column("map");
  const std::size_t ratio_min = in.require_column("competitive_ratio_min");
  const std::size_t note = in.require_column(kCompetitiveNoteColumn);
  const int star = in.column("optimal_distance_m");
  std::vector<std::size_t> robot;
  for (std::size_t c = 0; c < in.header().size(); ++c) {
    if (in.header()[c].starts_with("robot.")) robot.push_back(c);
  }
  // One row per map instance and robot, in the order of first appearance.
  struct Row {
    std::vector<std::string> robot;
    std::string map, lower, upper, exact, star;
    int runs = 0;
    int with_ratio = 0;
    std::map<std::string, int> notes;
  };
  std::vector<Row> rows;
  std::map<std::vector<std::string>, std::size_t> row_of;
  while (in.next()) {
    const std::vector<std::string>& f = in.fields();
    if (f[note] == kNotCompetitiveNote) continue;
    std::vector<std::string> key{f[map]};
    for (const std::size_t c : robot) key.push_back(f[c]);
    auto [it, added] = row_of.try_emplace(key, rows.size());
    if (added) {
      Row r;
      r.map = f[map];
      for (const std::size_t c : robot) r.robot.push_back(f[c]);
      r.lower = f[static_cast<std::size_t>(lower)];
      r.upper = f[upper];
      r.exact = f[exact];
      if (star >= 0) r.star = f[static_cast<std::size_t>(star)];
      rows.push_back(std::move(r));
    }
    Row& r = rows[it->second];
    ++r.runs;
    if (!f[ratio_min].empty()) ++r.with_ratio;
    if (!f[note].empty()) ++r.notes[f[note]];
  }
  if (rows.empty()) return {};
  // The robot columns that differ between rows name the robot.
  std::vector<std::size_t> differ;
  for (std::size_t k = 0; k < robot.size(); ++k) {
    if (std::any_of(rows.begin(), rows.end(), [&](const Row& r) { return r.robot[k] != rows[0].robot[k]; }))
      differ.push_back(k);
  }
  const bool any_star = std::any_of(rows.begin(), rows.end(), [](const Row& r) { return !r.star.empty(); });
  std::vector<std::string> header{"map"};
  for (const std::size_t k : differ) header.push_back(in.header()[robot[k]]);
  header.insert(header.end(), {"lower bound (m)", "upper bound (m)", "gap", "exact"});
  if (any_star) header.push_back("star optimum (m)");
  header.insert(header.end(), {"runs with a ratio", "why not (runs)"});
  std::vector<std::vector<TableCell>> cells;
  for (const Row& r : rows) {
    std::vector<TableCell> line{{r.map, false}};
    for (const std::size_t k : differ) line.push_back({r.robot[k], false});
    const auto lo = parse_number(r.lower);
    const auto up = parse_number(r.upper);
    line.push_back({readable_cell(r.lower), true});
    line.push_back({readable_cell(r.upper), true});
    line.push_back({lo && up && *lo > 0.0 ? readable_number(100.0 * (*up - *lo) / *lo, 3) + "%" : "", true});
    line.push_back({r.exact == "1" ? "yes" : r.exact == "0" ? "no" : "", false});
    if (any_star) line.push_back({readable_cell(r.star), true});
    line.push_back({std::to_string(r.with_ratio) + " of " + std::to_string(r.runs), true});
    std::string why;
    for (const auto& [text, count] : r.notes)
      why += (why.empty() ? "" : "; ") + text + " (" + std::to_string(count) + ")";
    line.push_back({why, false});
    cells.push_back(std::move(line));
  }
  std::string out =
      "<p>Per map instance and robot, the certified bounds on the offline optimum (the shortest route "
      "that reveals every cell in the battery's reach, optima.csv) and their gap, (upper - lower) / lower. "
      "A run's competitive ratio lies between its distance to final coverage over the upper bound and over "
      "the lower one (competitive_ratio_min and _max in runs.csv), for runs that end complete with "
      "completeness 1.";
  if (any_star)
    out +=
        " On free maps the star optimum is Rappaport's continuous-space figure pi r^2 / (2 r_s) "
        "(optimal_distance_m): the grid's robot moves in octile steps and sees whole cells, so it is "
        "not bound to lie between the grid's bounds.";
  out += "</p>\n";
  return out + table_html(header, cells, std::vector<std::string>(cells.size()));
}

}  // namespace report
}  // namespace fsweep
