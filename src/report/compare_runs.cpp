#include "report/compare_runs.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <utility>

#include "core/config_error.hpp"
#include "core/csv_reader.hpp"
#include "report/runs_schema.hpp"

namespace fsweep {
inline namespace report {

RunsFile read_runs_file(const std::string& path) {
  if (!std::filesystem::exists(path)) throw ConfigError(path, "missing (not a sweep output directory?)");
  RunsFile t;
  t.path = path;
  CsvReader in(path);
  const RunsHeader header(in.header(), path);
  t.header = header.names();
  t.run_key = header.run_key();
  t.config_names = header.names_of(header.config());
  t.quality_names = header.names_of(header.quality());
  while (in.next()) {
    const auto& f = in.fields();
    for (const std::size_t m : header.metrics()) (void)metric_value(f[m], t.header[m], in);
    if (!t.row_of_key.try_emplace(f[t.run_key], t.rows.size()).second) {
      throw ConfigError(in.where(), "run_key " + f[t.run_key] + " appears twice");
    }
    t.rows.push_back(f);
  }
  return t;
}

Grouping group(const RunsFile& t, const std::vector<int>& columns) {
  Grouping g;
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    const std::string key = config_key(t.rows[r], columns);
    auto [it, added] = g.rows.try_emplace(key);
    if (added) g.keys.push_back(key);
    it->second.push_back(r);
  }
  return g;
}

std::vector<int> columns_of(const RunsFile& t, const std::vector<std::string>& names) {
  std::vector<int> out;
  out.reserve(names.size());
  for (const auto& n : names) out.push_back(t.column(n));
  return out;
}

std::vector<double> sorted_values(const RunsFile& t, const std::vector<std::size_t>& rows,
                                  const std::string& name) {
  std::vector<double> v;
  const int c = t.column(name);
  if (c < 0) return v;
  for (const std::size_t r : rows) {
    const auto x = parse_number(t.rows[r][static_cast<std::size_t>(c)]);
    if (x && !std::isnan(*x)) v.push_back(*x);
  }
  std::sort(v.begin(), v.end());
  return v;
}

double mann_whitney_greater_p(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.empty() || b.empty()) return 1.0;
  // Ranks of the pooled sample, ties given their mean rank; b's rank sum gives U.
  std::vector<std::pair<double, bool>> pooled;  // (value, from b)
  pooled.reserve(a.size() + b.size());
  for (const double x : a) pooled.emplace_back(x, false);
  for (const double y : b) pooled.emplace_back(y, true);
  std::sort(pooled.begin(), pooled.end(), [](const auto& l, const auto& r) { return l.first < r.first; });
  const auto n = static_cast<double>(pooled.size());
  double rank_sum_b = 0.0;
  double tie_term = 0.0;  // sum of t^3 - t over groups of t tied values
  for (std::size_t i = 0; i < pooled.size();) {
    std::size_t j = i;
    while (j < pooled.size() && pooled[j].first == pooled[i].first) ++j;
    const double t = static_cast<double>(j - i);
    const double mean_rank = (static_cast<double>(i + 1) + static_cast<double>(j)) / 2.0;
    for (std::size_t k = i; k < j; ++k) rank_sum_b += pooled[k].second ? mean_rank : 0.0;
    tie_term += t * t * t - t;
    i = j;
  }
  const auto na = static_cast<double>(a.size());
  const auto nb = static_cast<double>(b.size());
  const double u = rank_sum_b - nb * (nb + 1.0) / 2.0;
  const double variance = na * nb / 12.0 * ((n + 1.0) - tie_term / (n * (n - 1.0)));
  if (!(variance > 0.0)) return 1.0;
  const double z = (u - na * nb / 2.0 - 0.5) / std::sqrt(variance);
  return 0.5 * std::erfc(z / std::sqrt(2.0));
}

double success_share(const RunsFile& t, const std::vector<std::size_t>& rows) {
  const auto c = static_cast<std::size_t>(t.column(kEndReasonColumn));
  std::size_t ok = 0;
  for (const std::size_t r : rows) ok += successful_end(t.rows[r][c]);
  return rows.empty() ? 0.0 : static_cast<double>(ok) / static_cast<double>(rows.size());
}

bool cells_equal(const std::string& a, const std::string& b) {
  const auto x = parse_number(a);
  const auto y = parse_number(b);
  if (x && y) return *x == *y || (std::isnan(*x) && std::isnan(*y));
  return a == b;
}

std::map<std::string, std::vector<std::optional<BoxStats>>> read_boxes(
    const std::string& path, const std::vector<std::string>& key_names,
    const std::vector<std::string>& metrics) {
  std::map<std::string, std::vector<std::optional<BoxStats>>> out;
  if (!std::filesystem::exists(path)) return out;
  CsvReader in(path);
  std::vector<int> key_cols;
  key_cols.reserve(key_names.size());
  for (const auto& n : key_names) key_cols.push_back(in.column(n));
  while (in.next()) {
    const auto& f = in.fields();
    auto& boxes = out[config_key(f, key_cols)];
    for (const auto& m : metrics) {
      std::array<double, 5> q{};
      bool ok = true;
      const char* names[] = {".q05", ".q25", ".median", ".q75", ".q95"};
      for (std::size_t i = 0; i < 5 && ok; ++i) {
        const int c = in.column(m + names[i]);
        const auto v = c >= 0 ? parse_number(f[static_cast<std::size_t>(c)]) : std::nullopt;
        ok = v && std::isfinite(*v);
        if (ok) q[i] = *v;
      }
      boxes.push_back(ok ? std::optional<BoxStats>(BoxStats{q[0], q[1], q[2], q[3], q[4]}) : std::nullopt);
    }
  }
  return out;
}

std::vector<std::size_t> label_positions(const std::vector<std::string>& key_names,
                                         const std::vector<std::vector<std::string>>& values) {
  std::vector<std::size_t> out;
  for (const char* always : {kMapClassColumn, kStrategyLabelColumn, kPlannerColumn}) {
    const auto it = std::find(key_names.begin(), key_names.end(), always);
    if (it != key_names.end()) out.push_back(static_cast<std::size_t>(it - key_names.begin()));
  }
  auto label_of = [&](const std::vector<std::string>& v, const std::vector<std::size_t>& cols) {
    return config_key(v, std::vector<int>(cols.begin(), cols.end()));
  };
  for (std::size_t i = 0; i < key_names.size(); ++i) {
    if (std::find(out.begin(), out.end(), i) != out.end()) continue;
    // Column i is needed if two configurations with the same label so far differ in it.
    std::map<std::string, std::string> value_of_label;
    for (const auto& v : values) {
      const auto [it, added] = value_of_label.try_emplace(label_of(v, out), v[i]);
      if (!added && it->second != v[i]) {
        out.push_back(i);
        break;
      }
    }
  }
  return out;
}

int RunsFile::column(const std::string& name) const {
  const auto it = std::find(header.begin(), header.end(), name);
  return it == header.end() ? -1 : static_cast<int>(it - header.begin());
}

}  // namespace report
}  // namespace fsweep
