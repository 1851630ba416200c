// compare.html of `fsweep compare` (compare.hpp): inline SVG charts, tables, embedded PNGs.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <set>
#include <sstream>
#include <system_error>

#include "core/files.hpp"
#include "report/compare.hpp"
#include "report/html.hpp"

namespace fsweep {
inline namespace report {
namespace {

constexpr const char* kBaselineColour = "#4c72b0";
constexpr const char* kNewColour = "#dd8452";
constexpr int kLabelWidth = 300;  // px left of each chart for the labels
constexpr int kPlotWidth = 560;   // px of the chart's data area
constexpr int kChartWidth = kLabelWidth + kPlotWidth + 20;

std::string num(double v, const char* format = "%.4g") {
  char buf[48];
  std::snprintf(buf, sizeof(buf), format, v);
  return buf;
}

std::string label_text(const std::string& s, std::size_t max_chars = 46) {
  return s.size() <= max_chars ? s : s.substr(0, max_chars - 3) + "...";
}

/// One horizontal box (whiskers q05..q95, box q25..q75, median line) at rows y..y+h.
void box(std::ostringstream& out, const BoxStats& b, double lo, double hi, int y, int h, const char* colour) {
  auto x = [&](double v) { return kLabelWidth + (v - lo) / (hi - lo) * kPlotWidth; };
  const double mid = y + h / 2.0;
  out << "<line x1='" << num(x(b.q05)) << "' x2='" << num(x(b.q95)) << "' y1='" << mid << "' y2='" << mid
      << "' stroke='" << colour << "'/>";
  for (const double v : {b.q05, b.q95}) {
    out << "<line x1='" << num(x(v)) << "' x2='" << num(x(v)) << "' y1='" << y + 2 << "' y2='" << y + h - 2
        << "' stroke='" << colour << "'/>";
  }
  out << "<rect x='" << num(x(b.q25)) << "' y='" << y << "' width='"
      << num(std::max(1.0, x(b.q75) - x(b.q25))) << "' height='" << h << "' fill='" << colour
      << "' fill-opacity='0.5' stroke='" << colour << "'/>";
  out << "<line x1='" << num(x(b.median)) << "' x2='" << num(x(b.median)) << "' y1='" << y << "' y2='"
      << y + h << "' stroke='black' stroke-width='2'/>";
}

/// x axis with 5 ticks from lo to hi under a chart of `height` px.
void axis(std::ostringstream& out, double lo, double hi, int height, const std::string& title) {
  out << "<line x1='" << kLabelWidth << "' x2='" << kLabelWidth + kPlotWidth << "' y1='" << height << "' y2='"
      << height << "' stroke='#444'/>";
  for (int i = 0; i <= 4; ++i) {
    const double v = lo + (hi - lo) * i / 4.0;
    const double x = kLabelWidth + kPlotWidth * i / 4.0;
    out << "<line x1='" << num(x) << "' x2='" << num(x) << "' y1='0' y2='" << height << "' stroke='#ddd'/>"
        << "<text x='" << num(x) << "' y='" << height + 14 << "' text-anchor='middle' font-size='11'>"
        << html_escape(num(v)) << "</text>";
  }
  out << "<text x='" << kLabelWidth + kPlotWidth / 2 << "' y='" << height + 30
      << "' text-anchor='middle' font-size='12'>" << html_escape(title) << "</text>";
}

/// Box plots of metric `m` (index into box_metrics): baseline above NEW per configuration.
void box_chart(std::ostringstream& out, const CompareReport& r, std::size_t m) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  std::vector<const ConfigComparison*> shown;
  for (const auto& c : r.configs) {
    bool any = false;
    for (const auto* side : {&c.baseline_box, &c.new_box}) {
      if (m < side->size() && (*side)[m]) {
        lo = std::min(lo, (*side)[m]->q05);
        hi = std::max(hi, (*side)[m]->q95);
        any = true;
      }
    }
    if (any) shown.push_back(&c);
  }
  out << "<h3>" << html_escape(r.box_metrics[m]) << "</h3>\n";
  if (shown.empty()) {
    out << "<p>No values in either summary.csv.</p>\n";
    return;
  }
  if (!(hi > lo)) {
    const double pad = std::max(1e-9, std::abs(lo) * 0.05 + (lo == 0.0 ? 1.0 : 0.0));
    lo -= pad;
    hi += pad;
  }
  constexpr int kRow = 30;
  const int height = static_cast<int>(shown.size()) * kRow + 4;
  out << "<svg xmlns='http://www.w3.org/2000/svg' width='" << kChartWidth << "' height='" << height + 40
      << "' font-family='sans-serif'>";
  axis(out, lo, hi, height, r.box_metrics[m] + " (whiskers q05-q95, box q25-q75, line median)");
  for (std::size_t i = 0; i < shown.size(); ++i) {
    const ConfigComparison& c = *shown[i];
    const int y = static_cast<int>(i) * kRow + 2;
    out << "<text x='" << kLabelWidth - 6 << "' y='" << y + kRow / 2 + 4
        << "' text-anchor='end' font-size='11'><title>" << html_escape(c.name) << "</title>"
        << html_escape(label_text(c.name)) << "</text>";
    if (m < c.baseline_box.size() && c.baseline_box[m])
      box(out, *c.baseline_box[m], lo, hi, y + 2, 11, kBaselineColour);
    if (m < c.new_box.size() && c.new_box[m]) box(out, *c.new_box[m], lo, hi, y + 15, 11, kNewColour);
  }
  out << "</svg>\n";
}

/// Bars of the time ratios (log scale) of the sweep and the micro-benchmarks, tolerance band
/// shaded.
void speed_chart(std::ostringstream& out, const CompareReport& r) {
  std::vector<const CompareCheck*> shown;
  for (const auto& k : r.checks) {
    if (((k.kind == "speed" && k.name == "sweep") || k.kind == "bench") && k.ratio) shown.push_back(&k);
  }
  out << "<h2>Speed ratios (new / baseline time)</h2>\n";
  if (shown.empty()) {
    out << "<p>No speed ratios (no throughput in the manifests, no bench.json on both sides).</p>\n";
    return;
  }
  double lo = 0.25, hi = 4.0;
  for (const auto* k : shown) {
    lo = std::max(1.0 / 64, std::min(lo, *k->ratio));
    hi = std::min(64.0, std::max(hi, *k->ratio));
  }
  const double llo = std::log2(lo), lhi = std::log2(hi);
  auto x = [&](double ratio) {
    const double l = std::clamp(std::log2(ratio), llo, lhi);
    return kLabelWidth + (l - llo) / (lhi - llo) * kPlotWidth;
  };
  constexpr int kRow = 18;
  const int height = static_cast<int>(shown.size()) * kRow + 4;
  out << "<svg xmlns='http://www.w3.org/2000/svg' width='" << kChartWidth << "' height='" << height + 40
      << "' font-family='sans-serif'>";
  const double band_lo = x(1.0 / (1.0 + r.speed_tolerance)), band_hi = x(1.0 + r.speed_tolerance);
  out << "<rect x='" << num(band_lo) << "' y='0' width='" << num(band_hi - band_lo) << "' height='" << height
      << "' fill='#2ca02c' fill-opacity='0.12'/>";
  for (const double t : {0.25, 0.5, 1.0, 2.0, 4.0}) {
    if (t < lo || t > hi) continue;
    out << "<line x1='" << num(x(t)) << "' x2='" << num(x(t)) << "' y1='0' y2='" << height << "' stroke='"
        << (t == 1.0 ? "#444" : "#ddd") << "'/>"
        << "<text x='" << num(x(t)) << "' y='" << height + 14 << "' text-anchor='middle' font-size='11'>x"
        << num(t, "%g") << "</text>";
  }
  out << "<text x='" << kLabelWidth + kPlotWidth / 2 << "' y='" << height + 30
      << "' text-anchor='middle' font-size='12'>time ratio (log scale); shaded: within the tolerance</text>";
  for (std::size_t i = 0; i < shown.size(); ++i) {
    const CompareCheck& k = *shown[i];
    const int y = static_cast<int>(i) * kRow + 2;
    const char* colour = k.status == CheckStatus::Slower   ? "#d62728"
                         : k.status == CheckStatus::Faster ? "#2ca02c"
                                                           : "#7f7f7f";
    const double a = std::min(x(1.0), x(*k.ratio)), b = std::max(x(1.0), x(*k.ratio));
    const std::string name = k.kind == "speed" ? "sweep seconds per run" : k.name;
    out << "<text x='" << kLabelWidth - 6 << "' y='" << y + 12 << "' text-anchor='end' font-size='11'><title>"
        << html_escape(name) << "</title>" << html_escape(label_text(name)) << "</text>"
        << "<rect x='" << num(a) << "' y='" << y + 2 << "' width='" << num(std::max(1.0, b - a))
        << "' height='12' fill='" << colour << "'><title>" << html_escape(name) << " x"
        << num(*k.ratio, "%.3f") << "</title></rect>";
  }
  out << "</svg>\n";
}

void check_table(std::ostringstream& out, const CompareReport& r, bool quality) {
  out << "<table><tr><th>kind</th><th>name</th><th>metric</th><th>baseline</th><th>new</th><th>delta</th>"
         "<th>ratio</th><th>tolerance</th><th>status</th></tr>\n";
  for (const auto& k : r.checks) {
    const bool is_quality = k.kind == "run" || k.kind == "config";
    if (is_quality != quality) continue;
    out << "<tr class='" << (k.failure ? "fail" : "") << "'><td>" << k.kind << "</td><td>"
        << html_escape(k.name) << "</td><td>" << html_escape(k.metric) << "</td><td>"
        << html_escape(k.baseline) << "</td><td>" << html_escape(k.current) << "</td><td>"
        << (k.delta ? num(*k.delta) : "") << "</td><td>" << (k.ratio ? num(*k.ratio, "%.3f") : "")
        << "</td><td>" << (k.tolerance ? num(*k.tolerance) : "") << "</td><td>"
        << html_escape(to_string(k.status)) << (k.failure ? " (fail)" : "") << "</td></tr>\n";
  }
  out << "</table>\n";
}

std::set<std::string> png_names(const std::string& dir) {
  std::set<std::string> names;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(dir + "/plots", ec)) {
    if (e.path().extension() == ".png") names.insert(e.path().filename().string());
  }
  return names;
}

std::string png_cell(const std::string& path) {
  const auto bytes = read_file(path);
  return bytes ? "<td>" + png_img(*bytes, path) + "</td>" : "<td>(none)</td>";
}

}  // namespace

std::string compare_html(const CompareReport& r) {
  std::ostringstream out;
  out << html_page_start("fsweep compare",
                         "tr.fail{background:#fdd}.verdict{font-size:1.3em;font-weight:bold}",
                         "fsweep compare");
  out << "<h1>fsweep compare</h1>\n<p>new: <code>" << html_escape(r.new_dir) << "</code><br>baseline: <code>"
      << html_escape(r.baseline_dir) << "</code></p>\n";
  out << "<p class='verdict' style='color:" << (r.regressions ? "#c00" : "#080") << "'>"
      << (r.regressions
              ? std::to_string(r.regressions) + (r.regressions == 1 ? " regression" : " regressions")
              : std::string("no regressions"))
      << "</p>\n";
  for (const auto& w : r.warnings) out << "<div class='warn'>" << html_escape(w) << "</div>\n";
  for (const auto& n : r.notes) out << "<p>" << html_escape(n) << "</p>\n";

  // 1. Status per configuration.
  out << "<h2>Configurations</h2>\n<table><tr>";
  for (const auto& c : r.label_columns) out << "<th>" << html_escape(c) << "</th>";
  out << "<th>kind</th><th>runs baseline/new</th><th>status</th><th>worst difference</th></tr>\n";
  for (const auto& c : r.configs) {
    out << "<tr class='" << (c.failure ? "fail" : "") << "'>";
    for (const auto& v : c.label) out << "<td>" << html_escape(v) << "</td>";
    out << "<td>" << (c.reproducible ? "exact" : "quantiles") << "</td><td>" << c.baseline_runs << "/"
        << c.new_runs << "</td><td>" << html_escape(to_string(c.status)) << "</td><td>"
        << html_escape(c.worst) << "</td></tr>\n";
  }
  out << "</table>\n";

  // 2. Quality distributions, baseline (blue, upper) and new (orange, lower).
  out << "<h2>Quality (summary.csv quantiles)</h2>\n<p><span style='color:" << kBaselineColour
      << "'>&#9632; baseline</span> (upper box) &nbsp; <span style='color:" << kNewColour
      << "'>&#9632; new</span> (lower box)</p>\n";
  for (std::size_t m = 0; m < r.box_metrics.size(); ++m) box_chart(out, r, m);

  // 3. Speed.
  speed_chart(out, r);
  out << "<h3>Speed checks</h3>\n";
  check_table(out, r, false);
  out << "<h2>Quality checks</h2>\n";
  check_table(out, r, true);

  // 4. The figures of `fsweep plot`, side by side.
  std::set<std::string> pngs = png_names(r.baseline_dir);
  const auto new_pngs = png_names(r.new_dir);
  pngs.insert(new_pngs.begin(), new_pngs.end());
  if (!pngs.empty()) {
    out << "<h2>Plots</h2>\n<table><tr><th>baseline</th><th>new</th></tr>\n";
    for (const auto& name : pngs) {
      out << "<tr><th colspan='2'>" << html_escape(name) << "</th></tr><tr>"
          << png_cell(r.baseline_dir + "/plots/" + name) << png_cell(r.new_dir + "/plots/" + name)
          << "</tr>\n";
    }
    out << "</table>\n";
  }
  out << "</body></html>\n";
  return out.str();
}

}  // namespace report
}  // namespace fsweep
