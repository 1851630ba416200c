/// @file report_page.cpp
/// report.html (report_page.hpp): the sections in the order of the file comment there.

#include "report/report_page.hpp"

#include <algorithm>
#include <cctype>
#include <set>
#include <sstream>
#include <string_view>

#include "core/csv_format.hpp"
#include "core/csv_reader.hpp"
#include "core/readable_number.hpp"
#include "report/html.hpp"
#include "report/report_tables.hpp"

namespace fsweep {
inline namespace report {
namespace {

/// best.csv's columns before the config columns: rank, config_id, n and the objective's median,
/// q05 and q95 (aggregate.hpp).
constexpr std::size_t kBestLeadingColumns = 6;

/// A manifest value as text: strings as they are, numbers as the CSV files write them.
std::string json_text(const nlohmann::json& j) {
  if (j.is_string()) return j.get<std::string>();
  if (j.is_number_float()) return format_number(j.get<double>());
  if (j.is_null()) return "";
  return j.dump();
}

/// The manifest's value at `pointer` as text, empty when absent.
std::string field(const nlohmann::json& manifest, const char* pointer) {
  const nlohmann::json::json_pointer p(pointer);
  return manifest.contains(p) ? json_text(manifest.at(p)) : std::string();
}

/// A number's text rounded for reading (readable_number()); other text as it is.
std::string readable_text(const std::string& text) {
  const auto v = parse_number(text);
  return v ? readable_number(*v) : text;
}

/// `t` with its number cells rounded for reading (readable_text()).
CsvExcerpt readable_excerpt(CsvExcerpt t) {
  for (auto& row : t.rows) {
    for (auto& cell : row) cell = readable_text(cell);
  }
  return t;
}

/// A POSIX shell word: as it is when it has only safe characters, else single-quoted.
std::string shell_word(const std::string& s) {
  const bool safe = !s.empty() && std::all_of(s.begin(), s.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 ||
           std::string_view("/._-+=:,@%").find(c) != std::string_view::npos;
  });
  if (safe) return s;
  std::string out = "'";
  for (const char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

/// The table of `t`'s columns `keep` (indices), after one line listing the columns `fold`
/// whose cells are equal in every row shown, and a line saying how many rows are left out.
std::string folded_table(const CsvExcerpt& t, std::vector<std::size_t> keep,
                         const std::vector<std::size_t>& fold) {
  std::ostringstream out;
  std::string same;
  for (const std::size_t c : fold) {
    const bool constant = std::all_of(t.rows.begin(), t.rows.end(),
                                      [&](const auto& row) { return row[c] == t.rows.front()[c]; });
    if (constant && !t.rows.empty()) {
      if (!t.rows.front()[c].empty())
        same += (same.empty() ? "" : "; ") + t.header[c] + " = " + t.rows.front()[c];
    } else {
      keep.push_back(c);
    }
  }
  std::sort(keep.begin(), keep.end());
  if (!same.empty()) out << "<p class='same'>Equal in every row shown: " << html_escape(same) << "</p>\n";
  std::vector<std::string> header;
  header.reserve(keep.size());
  for (const std::size_t c : keep) header.push_back(t.header[c]);
  std::vector<std::vector<std::string>> rows;
  for (const auto& row : t.rows) {
    rows.emplace_back();
    for (const std::size_t c : keep) rows.back().push_back(row[c]);
  }
  out << "<div class='scroll'>" << html_table(header, rows) << "</div>\n";
  if (t.total_rows > t.rows.size()) {
    out << "<p>The first " << t.rows.size() << " of " << t.total_rows << " rows; every row is in <code>"
        << html_escape(t.path) << "</code>.</p>\n";
  }
  return out.str();
}

void what_ran(std::ostringstream& out, const ResultDir& r) {
  const nlohmann::json& m = r.manifest;
  std::vector<std::vector<std::string>> rows;
  const auto add = [&](const std::string& key, const std::string& value) {
    if (!value.empty()) rows.push_back({key, value});
  };
  add("result directory", r.dir);
  add("sweep file", field(m, "/sweep_file"));
  if (m.contains("overrides") && m["overrides"].is_array()) {
    std::string overrides;  // PATH=VALUE arguments of `fsweep run` (the sweep below is the overridden one)
    for (const nlohmann::json& o : m["overrides"]) {
      if (o.is_string()) overrides += (overrides.empty() ? "" : "  ") + o.get<std::string>();
    }
    add("command-line overrides", overrides);
  }
  add("sweep hash", field(m, "/sweep_hash"));
  add("status", field(m, "/status"));
  add("objective (best.csv)", field(m, "/objective"));
  add("seed, repetitions", field(m, "/seed") + ", " + field(m, "/repetitions"));
  const nlohmann::json no_sessions = nlohmann::json::array();
  const nlohmann::json& sessions =
      m.contains("sessions") && m["sessions"].is_array() ? m["sessions"] : no_sessions;
  const std::string over_sessions =
      sessions.size() > 1 ? " over " + std::to_string(sessions.size()) + " sessions" : std::string();
  const std::string skipped = over_sessions.empty()
                                  ? ", skipped as done before " + field(m, "/runs/skipped")
                                  : " (the last found " + field(m, "/runs/skipped") + " done)";
  add("runs (manifest)", "total " + field(m, "/runs/total") + ", done " + field(m, "/runs/done") + ", ran " +
                             field(m, "/runs/ran") + over_sessions + skipped + ", failed " +
                             field(m, "/runs/failed"));
  std::string ends;
  for (const auto& [reason, n] : r.end_reasons)
    ends += (ends.empty() ? ": " : ", ") + reason + " " + std::to_string(n);
  add("runs.csv", std::to_string(r.runs) + " runs" + ends);
  if (!field(m, "/shard/merged_from").empty()) {
    add("shards", "merged from " + field(m, "/shard/merged_from") + " shards (fsweep merge)");
  } else if (field(m, "/shard/count") != "1" && !field(m, "/shard/count").empty()) {
    add("shard", field(m, "/shard/index") + " of " + field(m, "/shard/count"));
  }
  add("fsweep version", field(m, "/fsweep_version"));
  add("version (git revision)", field(m, "/git_revision"));
  add("compiler", field(m, "/compiler"));
  std::string libraries;
  if (m.contains("libraries") && m["libraries"].is_object()) {
    for (const auto& [name, version] : m["libraries"].items())
      libraries += (libraries.empty() ? "" : ", ") + name + " " + json_text(version);
  }
  add("libraries", libraries);
  add("host, CPU", field(m, "/host") + ", " + field(m, "/cpu_model"));
  add("threads", field(m, "/threads"));
  add("started, ended (UTC)", field(m, "/start_utc") + ", " + field(m, "/end_utc"));
  add("wall time (s)", readable_text(field(m, "/wall_s")) + over_sessions);
  // Over the sessions that simulated runs; none (e.g. a rerun of a finished sweep by an fsweep
  // that kept only the last session) shows no figure rather than 0.
  if (const auto per_s = parse_number(field(m, "/runs_per_s")); per_s && *per_s > 0.0) {
    add("runs per second",
        readable_number(*per_s) + (over_sessions.empty() ? "" : " (over the sessions that simulated runs)"));
  }
  out << "<h2 id='what-ran'>What ran</h2>\n<table>";
  for (const auto& row : rows)
    out << "<tr><th>" << html_escape(row[0]) << "</th><td>" << html_escape(row[1]) << "</td></tr>";
  out << "</table>\n";
  if (sessions.size() > 1) {  // the invocations: a resumed or extended sweep's history
    std::vector<std::vector<std::string>> session_rows;
    for (const nlohmann::json& s : sessions) {
      const std::string shard = field(s, "/shard/count").empty() || field(s, "/shard/count") == "1"
                                    ? std::string()
                                    : field(s, "/shard/index") + "/" + field(s, "/shard/count");
      session_rows.push_back({field(s, "/start_utc"), field(s, "/end_utc"), field(s, "/status"),
                              field(s, "/sweep_hash"), field(s, "/runs/ran"), field(s, "/runs/skipped"),
                              readable_text(field(s, "/wall_s")),
                              field(s, "/runs/ran") == "0" ? "" : readable_text(field(s, "/runs_per_s")),
                              field(s, "/threads"), shard, field(s, "/host")});
    }
    out << "<p>Sessions (one per <code>fsweep run</code> on the directory, oldest first):</p>\n<div "
           "class='scroll'>"
        << html_table({"started (UTC)", "ended (UTC)", "status", "sweep hash", "ran", "already done",
                       "wall (s)", "runs/s", "threads", "shard", "host"},
                      session_rows)
        << "</div>\n";
  }
  if (m.contains("warnings") && m["warnings"].is_array()) {
    for (const auto& w : m["warnings"])
      out << "<div class='warn'>warning: " << html_escape(json_text(w)) << "</div>\n";
  }
  for (const auto& n : r.notes) out << "<p>" << html_escape(n) << "</p>\n";
  out << "<details><summary>The sweep (manifest.json's copy of the sweep file)</summary><pre>"
      << html_escape(m["sweep"].dump(2)) << "</pre></details>\n";
}

/// The files in full, folded: best.csv and summary.csv, cells as the files write them.
void files_section(std::ostringstream& out, const ResultDir& r) {
  out << "<h2 id='files'>The files in full</h2>\n<p>The ranking's files at full precision, as they hold "
         "them: open a table to see it.</p>\n";
  out << "<details id='best'><summary>best.csv: every configuration ranked by the median of the objective "
         "(rank 1 best)</summary>\n";
  if (r.best.total_rows == 0) {
    out << "<p>No configurations: the sweep has no runs of its own.</p>\n";
  } else {
    // rank, config_id, n and the objective's three columns, then the config columns.
    std::vector<std::size_t> keep, fold;
    for (std::size_t c = 0; c < r.best.header.size(); ++c)
      (c < kBestLeadingColumns ? keep : fold).push_back(c);
    out << folded_table(r.best, keep, fold);
  }
  out << "</details>\n<details id='summary'><summary>summary.csv: every column (per configuration: the runs, "
         "how they ended, and mean, std, min, q05, q25, median, q75, q95, max of every metric)</summary>\n";
  std::vector<std::size_t> all(r.summary.header.size());
  for (std::size_t c = 0; c < all.size(); ++c) all[c] = c;
  out << folded_table(r.summary, all, {}) << "</details>\n";
}

void figure(std::ostringstream& out, const PageImage& image) {
  out << "<figure id='" << html_escape(image.id) << "'><h3>" << html_escape(image.title) << "</h3>"
      << png_img(image.png, image.title) << "<figcaption>" << html_escape(image.caption)
      << "</figcaption></figure>\n";
}

void trajectories_section(std::ostringstream& out, const ReportPage& page,
                          const std::vector<PageImage>& images) {
  out << "<h2 id='trajectories'>Trajectories</h2>\n";
  if (page.trajectories.empty()) {
    out << "<p>" << html_escape(page.trajectories_note.empty() ? "No runs to show." : page.trajectories_note)
        << "</p>\n";
    return;
  }
  out << "<p>Runs are pure functions of their configuration and seed, so <code>fsweep report</code> "
         "re-simulated "
         "these runs from the sweep recorded in manifest.json (the run of the same run_index, checked by its "
         "run_key; for a weight search, its first instance with the behaviour's weights) and drew them: the "
         "best and the worst of the ranking, to show what separates them. Explored free cells white, "
         "explored obstacles black, unexplored grey; the path from blue (start) to red (end); the dock and "
         "recharges green; frontier cells left magenta.</p>\n";
  for (const PageTrajectory& t : page.trajectories) {
    if (!t.replay) {
      out << "<div class='warn'>" << html_escape(t.run.role) << ": not re-simulated: " << html_escape(t.error)
          << "</div>\n";
    }
  }
  out << "<div class='gallery'>\n";
  for (const PageImage& image : images) figure(out, image);
  out << "</div>\n";
}

/// The trajectories' figures: title, caption and anchor of each re-simulated run.
std::vector<PageImage> trajectory_images(const ReportPage& page) {
  std::vector<PageImage> images;
  for (const PageTrajectory& t : page.trajectories) {
    if (!t.replay) continue;
    const Replay& rp = *t.replay;
    PageImage image;
    image.id = "trajectory-" + std::to_string(images.size() + 1);
    image.title = t.run.role;
    image.caption = t.run.run_index
                        ? "run_index " + std::to_string(*t.run.run_index) + ", run_key " + t.run.run_key
                        : "search " + std::to_string(*t.run.search_id) + ", behaviour " + t.run.behaviour_id;
    image.caption += ", map " + rp.map + ". ";
    if (rp.differences.empty()) {
      image.caption +=
          "Re-simulated: the " + std::to_string(rp.compared) +
          " recorded outcome cells (end reason and every metric but timings and search counters) are equal.";
    } else {
      image.caption +=
          "Re-simulated, but " + std::to_string(rp.differences.size()) + " of " +
          std::to_string(rp.compared) +
          " recorded outcome cells differ (a planner that is not deterministic, or another build): ";
      for (std::size_t i = 0; i < rp.differences.size(); ++i)
        image.caption += (i ? "; " : "") + rp.differences[i];
    }
    image.png = rp.png;
    images.push_back(std::move(image));
  }
  return images;
}

}  // namespace

PageImage plot_image(const std::string& name, std::string png) {
  PageImage image;
  const std::string stem = name.substr(0, name.rfind('.'));
  image.id = "plot-" + stem;
  image.png = std::move(png);
  if (stem == "progress") {
    image.title = "Explored area over distance";
    image.caption =
        "A panel per map class: for its best configurations by best.csv, the mean explored area over the "
        "distance travelled, and the band from q05 to q95 over their runs.";
  } else if (stem == "metrics") {
    image.title = "Metrics per configuration";
    image.caption =
        "For the best configurations of each map class by best.csv (coloured by class), the median of "
        "distance, energy, coverage and distance to the final coverage, with bars from q05 to q95.";
  } else if (stem.starts_with("heatmap_")) {
    image.title = "Weight heat map " + stem.substr(8);
    image.caption =
        "The objective's median over each pair of values of two weights (the best over the other "
        "weights and config columns); the best cell framed.";
  } else if (stem.starts_with("search") && stem.ends_with("_gap")) {
    image.title = "Exact weight search " + stem.substr(6, stem.size() - 10) + ": best and bound over time";
    image.caption =
        "Mode best (search_anytime.csv): the best objective found so far and the certified bound of the "
        "optimum over the search's time, the gap between them shaded; crosses where it was stopped and "
        "resumed.";
  } else if (stem.starts_with("search")) {
    image.title = "Exact weight search " + stem.substr(6);
    image.caption =
        "Exact search: the best objective of any weight vector with each pair of values of two weights "
        "(search_heatmaps.csv); the best cell framed.";
  } else {
    image.title = name;
    image.caption = "A figure of fsweep plot.";
  }
  return image;
}

std::vector<std::string> reproduce_commands(const ResultDir& r) {
  const nlohmann::json& m = r.manifest;
  std::string sweep_file = field(m, "/sweep_file");
  if (sweep_file.empty()) sweep_file = "sweep.json";
  const std::string rerun = shell_word(r.dir + "-rerun");
  std::vector<std::string> lines;
  const std::string revision = field(m, "/git_revision");
  if (!revision.empty() && revision != "unknown") lines.push_back("git checkout " + shell_word(revision));
  const std::string threads =
      field(m, "/threads").empty() ? "" : " --threads " + shell_word(field(m, "/threads"));
  const std::string shards = field(m, "/shard/merged_from");
  if (!shards.empty()) {
    lines.push_back("for i in $(seq 0 $((" + shell_word(shards) + " - 1))); do fsweep run " +
                    shell_word(sweep_file) + " --shard \"$i/" + shell_word(shards) + "\"" + threads +
                    " --out " + rerun + "; done");
    lines.push_back("fsweep merge " + rerun);
  } else {
    lines.push_back("fsweep run " + shell_word(sweep_file) + threads + " --out " + rerun);
  }
  lines.push_back("fsweep compare " + rerun + " " + shell_word(r.dir));
  lines.push_back("fsweep report " + shell_word(r.dir));
  return lines;
}

std::string report_html(const ReportPage& page) {
  const ResultDir& r = page.result;
  const std::string name = field(r.manifest, "/sweep/name");
  const std::vector<PageImage> trajectories = trajectory_images(page);
  const std::string optimum = optimum_html(r.dir + "/runs.csv");
  std::ostringstream out;
  out << html_page_start(
      "fsweep report: " + name,
      "figure{margin:1em 0}figcaption{font-size:13px;color:#333;max-width:1100px}"
      ".scroll{overflow-x:auto}.same{font-size:13px;color:#333}pre{background:#f4f4f4;padding:6px}"
      "figure img{max-width:100%;border:1px solid #ddd}.gallery{display:flex;flex-wrap:wrap;gap:0 2em}"
      ".gallery figure{flex:1 1 420px;max-width:640px}.gallery h3{font-size:15px}"
      "table.readable td.num{text-align:right;white-space:nowrap}table.readable "
      "td:nth-child(2){white-space:nowrap}tr.copies td{background:#fff3cd}"
      "details{margin:0.6em 0}summary{cursor:pointer}",
      kReportGenerator);
  out << "<h1>fsweep report: " << html_escape(name) << "</h1>\n";
  if (const std::string d = field(r.manifest, "/sweep/description"); !d.empty())
    out << "<p>" << html_escape(d) << "</p>\n";
  out << "<p>" << r.runs << " runs in <code>" << html_escape(r.dir) << "</code>.</p>\n";

  // Contents: the sections and every figure the page holds.
  out << "<ul class='contents'><li><a href='#what-ran'>What ran</a></li><li><a href='#ranking'>Ranking per "
         "map "
         "class</a></li>";
  if (!optimum.empty()) out << "<li><a href='#optimum'>The offline optimum</a></li>";
  if (page.paired || !page.paired_note.empty()) out << "<li><a href='#paired'>Paired comparisons</a></li>";
  if (r.search_best) out << "<li><a href='#searches'>Exact weight searches</a></li>";
  out << "<li><a href='#plots'>Plots</a><ul>";
  for (const auto& p : page.plots) {
    out << "<li><a class='figure-link' href='#" << html_escape(p.id) << "'>" << html_escape(p.title)
        << "</a></li>";
  }
  out << "</ul></li><li><a href='#trajectories'>Trajectories</a><ul>";
  for (const auto& t : trajectories) {
    out << "<li><a class='figure-link' href='#" << html_escape(t.id) << "'>" << html_escape(t.title)
        << "</a></li>";
  }
  out << "</ul></li><li><a href='#files'>The files in full</a></li><li><a "
         "href='#reproduce'>Reproduce</a></li></ul>\n";

  what_ran(out, r);
  out << "<h2 id='ranking'>Ranking per map class</h2>\n<p>Per map class, the configurations ranked by the "
         "median of the objective over their runs (the map instances of the class and the repetitions "
         "pooled), "
         "best first; numbers rounded for reading.</p>\n"
      << ranking_html(r);
  if (!optimum.empty()) out << "<h2 id='optimum'>The offline optimum</h2>\n" << optimum;
  if (page.paired) {
    out << "<h2 id='paired'>Paired comparisons</h2>\n" << paired_html(*page.paired, page.paired_note);
  } else if (!page.paired_note.empty()) {
    out << "<h2 id='paired'>Paired comparisons</h2>\n<p>" << html_escape(page.paired_note) << "</p>\n";
  }
  if (r.search_best) {
    out << "<h2 id='searches'>Exact weight searches (search_best.csv)</h2>\n<p>Per search, its behaviours "
           "ranked by "
           "the objective (the class mean); the representative is the smallest weight vector of each.</p>\n"
        << folded_table(readable_excerpt(*r.search_best),
                        [&] {
                          std::vector<std::size_t> all(r.search_best->header.size());
                          for (std::size_t c = 0; c < all.size(); ++c) all[c] = c;
                          return all;
                        }(),
                        {})
        << "<p>Rounded for reading; <code>search_best.csv</code> has every digit.</p>\n";
  }
  out << "<h2 id='plots'>Plots</h2>\n<p>Drawn by <code>fsweep plot</code> (tools/plot.py) from the summary "
         "files.</p>\n";
  for (const auto& p : page.plots) figure(out, p);
  trajectories_section(out, page, trajectories);
  files_section(out, r);

  out << "<h2 id='reproduce'>Reproduce</h2>\n<p>From the source tree, with <code>fsweep</code> built at the "
         "revision above and on your PATH (build/release/bin, or installed): rerun the sweep into a new "
         "directory, check it against this one (runs of deterministic "
         "planners "
         "equal cell for cell), and make this page again. If the sweep file is no longer there, save the "
         "sweep "
         "shown under What ran as that file.</p>\n<pre>";
  for (const auto& line : reproduce_commands(r)) out << html_escape(line) << "\n";
  out << "</pre>\n</body></html>\n";
  return out.str();
}

}  // namespace report
}  // namespace fsweep
