#include "verify/certificate_check.hpp"

#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

#include "core/config_error.hpp"
#include "core/csv_format.hpp"
#include "core/json_text.hpp"
#include "core/random.hpp"
#include "report/search_objective.hpp"
#include "report/search_schema.hpp"
#include "sim/simulation.hpp"
#include "strategies/registry.hpp"
#include "strategies/strategy.hpp"

namespace fsweep {
inline namespace verify {
namespace {

using nlohmann::json;

/// `j` as a count or index: a JSON integer (not a boolean, not 6.0) in [0, max]; throws naming
/// `what` otherwise.
std::uint64_t whole(const json& j, std::string_view what, std::uint64_t max = UINT64_MAX) {
  if (!j.is_number_integer() || (!j.is_number_unsigned() && j.get<std::int64_t>() < 0) ||
      j.get<std::uint64_t>() > max) {
    throw std::runtime_error(std::string(what) + " " + j.dump() + "; allowed: an integer from 0 to " +
                             std::to_string(max));
  }
  return j.get<std::uint64_t>();
}

/// `j` as a number (not a boolean); throws naming `what` otherwise.
double number(const json& j, std::string_view what) {
  if (!j.is_number()) throw std::runtime_error(std::string(what) + " " + j.dump() + "; allowed: a number");
  return j.get<double>();
}

/// `j` as an array; throws naming `what` otherwise.
const json& array(const json& j, std::string_view what) {
  if (!j.is_array()) throw std::runtime_error(std::string(what) + " is not an array");
  return j;
}

/// A region's trace: exactly 16 hexadecimal digits.
std::uint64_t trace_of(const json& j) {
  const std::string text = j.get<std::string>();
  if (text.size() != 16 || text.find_first_not_of("0123456789abcdefABCDEF") != std::string::npos)
    throw std::runtime_error("trace '" + text + "'; allowed: 16 hexadecimal digits");
  return std::stoull(text, nullptr, 16);
}

/// `path` opened for reading, refused unless it is a regular file (a FIFO would block).
std::ifstream open_certificate(const std::string& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error))
    throw ConfigError(path, std::filesystem::exists(path, error) ? "not a regular file" : "missing");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ConfigError(path, "cannot be read");
  return in;
}

constexpr double kUnit = 0x1.0p-53;
/// Boxes the corners do not decide are checked point by point up to this many points.
constexpr std::uint64_t kPointLimit = std::uint64_t{1} << 20;
/// The box's bitmap for the overlap check, up to this many vectors (1 GiB).
constexpr std::uint64_t kBitmapLimit = std::uint64_t{1} << 33;

/// A box of grid indices, lo[k] <= index_k <= hi[k] (k < the header's weight count).
struct Box {
  std::array<int, 4> lo{};
  std::array<int, 4> hi{};
};

struct Region {
  std::size_t line = 0;
  bool pruned = false;
  double value = 0.0;  ///< NaN: none (finished only)
  std::vector<Box> boxes;
  std::vector<std::uint64_t> steps;
  std::uint64_t trace = 0;
  std::uint64_t vectors = 0;
};

std::string describe(const Region& r) {
  std::string s =
      "line " + std::to_string(r.line) + " (" + (r.pruned ? "pruned" : "finished") + " region, box [";
  const Box& b = r.boxes.front();
  for (std::size_t k = 0; k < 4; ++k)
    s += (k > 0 ? ", " : "") + std::to_string(b.lo[k]) + ".." + std::to_string(b.hi[k]);
  return s + "]" + (r.boxes.size() > 1 ? " and " + std::to_string(r.boxes.size() - 1) + " more" : "") + ")";
}

/// The lines after the header, checked against it.
std::vector<Region> read_regions(const std::string& path, const CertificateHeader& header) {
  std::ifstream in = open_certificate(path);
  std::string text;
  std::getline(in, text);  // the header
  const std::size_t n = header.weights.size();
  std::vector<Region> out;
  for (std::size_t line = 2; std::getline(in, text); ++line) {
    const std::string where = path + ":" + std::to_string(line);
    try {
      const json j = parse_json_unique_keys(text, where);
      Region r;
      r.line = line;
      const std::string kind = j.at("kind").get<std::string>();
      if (kind != "finished" && kind != "pruned")
        throw std::runtime_error("kind is neither finished nor pruned");
      r.pruned = kind == "pruned";
      const json& value = j.at("value");
      if (value.is_null() && r.pruned) throw std::runtime_error("a pruned region without a bound");
      r.value = value.is_null() ? std::numeric_limits<double>::quiet_NaN() : number(value, "value");
      if (r.pruned) {
        for (const json& steps : array(j.at("steps"), "steps")) r.steps.push_back(whole(steps, "steps"));
        if (r.steps.size() != header.instances.size())
          throw std::runtime_error("steps for another number of instances");
      } else {
        r.trace = trace_of(j.at("trace"));
      }
      // Its path in the region tree: read for its form only, since the re-simulation proves
      // every decision over the whole region.
      for (const json& choice : array(j.at("choices"), "choices")) (void)whole(choice, "a choice");
      for (const json& b : array(j.at("boxes"), "boxes")) {
        if (array(b, "a box").size() != 2 * n)
          throw std::runtime_error("a box of " + std::to_string(b.size()) + " numbers; allowed: 2 x " +
                                   std::to_string(n));
        Box box;
        std::uint64_t count = 1;
        for (std::size_t k = 0; k < n; ++k) {
          const auto size = static_cast<std::int64_t>(header.values[k].size());
          const std::string allowed = "; allowed: an integer from 0 to " + std::to_string(size - 1) +
                                      " (the search's box along " + header.weights[k] + ")";
          const auto index = [&](const json& v) {
            if (!v.is_number_integer() || v.get<std::int64_t>() < 0 || v.get<std::int64_t>() >= size)
              throw std::runtime_error("a box index " + v.dump() + " along " + header.weights[k] + allowed);
            return static_cast<int>(v.get<std::int64_t>());
          };
          box.lo[k] = index(b.at(k));
          box.hi[k] = index(b.at(n + k));
          if (box.lo[k] > box.hi[k]) {
            throw std::runtime_error("an empty box: from " + std::to_string(box.lo[k]) + " to " +
                                     std::to_string(box.hi[k]) + " along " + header.weights[k]);
          }
          count *= static_cast<std::uint64_t>(box.hi[k] - box.lo[k] + 1);
        }
        if (__builtin_add_overflow(r.vectors, count, &r.vectors))
          throw std::runtime_error("a region of more than 2^64 vectors");
        r.boxes.push_back(box);
      }
      if (r.boxes.empty()) throw std::runtime_error("a region without a box");
      out.push_back(std::move(r));
    } catch (const ConfigError&) {
      throw;
    } catch (const std::exception& e) {
      throw ConfigError(where, e.what());
    }
  }
  return out;
}

/// The index of a vector of the box in lexicographic order.
std::uint64_t index_of(const CertificateHeader& h, const std::array<int, 4>& at) {
  std::uint64_t i = 0;
  for (std::size_t k = 0; k < h.weights.size(); ++k)
    i = i * h.values[k].size() + static_cast<std::uint64_t>(at[k]);
  return i;
}

/// Calls f(first, last) for the lexicographic index range of each row of `box` along the last weight.
template <typename F>
void for_each_row(const CertificateHeader& h, const Box& box, F&& f) {
  const std::size_t n = h.weights.size();
  std::array<int, 4> at = box.lo;
  for (;;) {
    at[n - 1] = box.lo[n - 1];
    const std::uint64_t first = index_of(h, at);
    f(first, first + static_cast<std::uint64_t>(box.hi[n - 1] - box.lo[n - 1]));
    std::size_t k = n - 1;
    while (k > 0) {
      --k;
      if (++at[k] <= box.hi[k]) break;
      at[k] = box.lo[k];
      if (k == 0) return;
    }
    if (n == 1) return;
  }
}

/// The region holding a vector of index `index`, first in file order.
const Region* holder(const CertificateHeader& h, const std::vector<Region>& regions, std::uint64_t index,
                     const Region* other_than) {
  for (const Region& r : regions) {
    if (&r == other_than) continue;
    for (const Box& b : r.boxes) {
      bool in = false;
      for_each_row(h, b, [&](std::uint64_t first, std::uint64_t last) {
        in = in || (index >= first && index <= last);
      });
      if (in) return &r;
    }
  }
  return nullptr;
}

/// "(w1 = 3, w2 = 0, ...)": the weights of the vector of lexicographic index `index`.
std::string describe_vector(const CertificateHeader& h, std::uint64_t index) {
  std::vector<std::size_t> at(h.weights.size());
  for (std::size_t d = h.weights.size(); d-- > 0;) {
    at[d] = static_cast<std::size_t>(index % h.values[d].size());
    index /= h.values[d].size();
  }
  std::string s = "(";
  for (std::size_t d = 0; d < at.size(); ++d)
    s += (d > 0 ? ", " : "") + h.weights[d] + " = " + format_number(h.values[d][at[d]]);
  return s + ")";
}

/// Checks that the regions cover the box exactly.
void check_cover(const CertificateHeader& h, const std::vector<Region>& regions, CertificateCheck& out) {
  std::uint64_t total = 0;
  for (const Region& r : regions) {
    if (__builtin_add_overflow(total, r.vectors, &total)) total = UINT64_MAX;  // more than the box
  }
  out.counts_match = total == h.vectors;
  if (!out.counts_match) {
    out.problems.push_back("the regions hold " + std::to_string(total) + " vectors, the box " +
                           std::to_string(h.vectors) + ": they do not cover it exactly");
  }
  if (h.vectors > kBitmapLimit) return;
  out.overlap_checked = true;
  std::vector<std::uint64_t> bits((h.vectors + 63) / 64, 0);
  for (const Region& r : regions) {
    for (const Box& b : r.boxes) {
      std::uint64_t overlap = UINT64_MAX;
      for_each_row(h, b, [&](std::uint64_t first, std::uint64_t last) {
        for (std::uint64_t i = first; i <= last; ++i) {
          std::uint64_t& word = bits[i / 64];
          const std::uint64_t bit = std::uint64_t{1} << (i % 64);
          if ((word & bit) != 0 && overlap == UINT64_MAX) overlap = i;
          word |= bit;
        }
      });
      if (overlap != UINT64_MAX) {
        out.overlap_found = true;
        const Region* first = holder(h, regions, overlap, &r);
        out.problems.push_back(describe(r) + ": overlaps " +
                               (first != nullptr ? describe(*first) : "another region") +
                               " at vector index " + std::to_string(overlap));
        return;
      }
    }
  }
  for (std::uint64_t word = 0; word < bits.size(); ++word) {
    const std::uint64_t missing = ~bits[word];
    if (missing == 0) continue;
    const std::uint64_t index = word * 64 + static_cast<std::uint64_t>(std::countr_zero(missing));
    if (index >= h.vectors) break;
    out.problems.push_back("the vector of index " + std::to_string(index) + " " + describe_vector(h, index) +
                           " is in no region");
    return;
  }
}

/// Checks the regions' values against the optimum.
void check_values(const CertificateHeader& h, const std::vector<Region>& regions, CertificateCheck& out) {
  const auto worse = [&](double v) { return h.minimize ? v > h.optimum : v < h.optimum; };
  if (std::isnan(h.optimum)) {
    // No vector's runs have a value: every region must be a behaviour without one (nothing can
    // be pruned against an optimum that does not exist).
    for (const Region& r : regions) {
      (r.pruned ? out.pruned : out.finished) += 1;
      if (r.pruned || !std::isnan(r.value)) {
        out.problems.push_back(describe(r) + ": " +
                               (r.pruned ? "pruned, but no vector has a value to prune against"
                                         : "its objective " + format_number(r.value) +
                                               ", but the optimum is none (no vector has a value)"));
      }
    }
    return;
  }
  for (const Region& r : regions) {
    (r.pruned ? out.pruned : out.finished) += 1;
    if (std::isnan(r.value)) continue;
    if (!r.pruned && r.value == h.optimum) {
      ++out.optimal_regions;
      out.optimal_vectors += r.vectors;
    } else if (!worse(r.value)) {
      out.problems.push_back(describe(r) + ": its " + (r.pruned ? "bound " : "objective ") +
                             format_number(r.value) + " is " + (r.pruned ? "not worse than" : "better than") +
                             " the optimum " + format_number(h.optimum));
    }
  }
  if (out.optimal_regions == 0) out.problems.push_back("no finished region has the optimum's objective");
}

/// The weights of the vector of indices `at`.
std::vector<double> weights_at(const CertificateHeader& h, const std::array<int, 4>& at) {
  std::vector<double> w;
  for (std::size_t k = 0; k < h.weights.size(); ++k)
    w.push_back(h.values[k][static_cast<std::size_t>(at[k])]);
  return w;
}

/// True when candidate `c` costs no more than `j` (less, when `strict`) at every vector of `box`,
/// proven at its corners with the rounding allowance of the file comment; false when not proven.
bool beats_at_corners(const CertificateHeader& h, const Box& box, std::span<const double> fc,
                      std::span<const double> fj, bool strict) {
  const std::size_t n = h.weights.size();
  const double gamma = static_cast<double>(n + 8) * kUnit;
  std::array<double, 4> g{};
  for (std::size_t k = 0; k < n; ++k) {
    if (!std::isfinite(fc[k]) || !std::isfinite(fj[k])) return false;
    g[k] = (fj[k] - fc[k]) - gamma * (std::abs(fj[k]) + std::abs(fc[k]));
  }
  for (unsigned corner = 0; corner < (1U << n); ++corner) {
    double sum = 0.0;
    double magnitude = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
      const int index = ((corner >> k) & 1U) != 0 ? box.hi[k] : box.lo[k];
      const double w = h.values[k][static_cast<std::size_t>(index)];
      sum += w * g[k];
      magnitude += std::abs(w * g[k]);
    }
    const double allowance = static_cast<double>(n + 3) * kUnit * magnitude;
    if (strict ? !(sum > allowance) : !(sum >= allowance)) return false;
  }
  return true;
}

/// Checks that every vector of `region` chooses `chosen` among `candidates`; "" or the problem.
std::string check_choice(const CertificateHeader& h, const Region& region, const Candidates& candidates,
                         int chosen, std::atomic<std::uint64_t>& by_corners,
                         std::atomic<std::uint64_t>& by_points) {
  const auto k = static_cast<std::size_t>(candidates.feature_count);
  if (k != h.weights.size())
    return "the strategy scores " + std::to_string(k) + " features, the box has " +
           std::to_string(h.weights.size()) + " weights";
  const auto features = [&](std::size_t i) { return std::span(candidates.features).subspan(i * k, k); };
  const auto c = static_cast<std::size_t>(chosen);
  for (const Box& box : region.boxes) {
    bool proven = true;
    for (std::size_t j = 0; j < candidates.cells.size() && proven; ++j) {
      if (j != c) proven = beats_at_corners(h, box, features(c), features(j), j < c);
    }
    if (proven) {
      by_corners.fetch_add(1, std::memory_order_relaxed);
      continue;
    }
    std::uint64_t points = 1;
    for (std::size_t d = 0; d < k; ++d) points *= static_cast<std::uint64_t>(box.hi[d] - box.lo[d] + 1);
    if (points > kPointLimit) {
      return "a box of " + std::to_string(points) +
             " vectors that its corners do not prove chooses candidate " + std::to_string(chosen) +
             " (more than " + std::to_string(kPointLimit) + " to check one by one)";
    }
    by_points.fetch_add(1, std::memory_order_relaxed);
    std::string problem;
    for_each_row(h, box, [&](std::uint64_t first, std::uint64_t last) {
      for (std::uint64_t i = first; i <= last && problem.empty(); ++i) {
        std::array<int, 4> at{};
        std::uint64_t rest = i;
        for (std::size_t d = k; d-- > 0;) {
          at[d] = static_cast<int>(rest % h.values[d].size());
          rest /= h.values[d].size();
        }
        const std::vector<double> w = weights_at(h, at);
        const int made = argmin_linear(candidates, w);
        if (made != chosen) {
          problem = "the vector (";
          for (std::size_t d = 0; d < k; ++d) problem += (d > 0 ? ", " : "") + format_number(w[d]);
          problem += ") chooses candidate " + std::to_string(made) + ", the representative " +
                     std::to_string(chosen);
        }
      }
    });
    if (!problem.empty()) return problem;
  }
  return {};
}

/// The lexicographically smallest vector of the region.
std::array<int, 4> representative(const Region& r) {
  std::array<int, 4> best = r.boxes.front().lo;
  for (const Box& b : r.boxes) best = std::min(best, b.lo);
  return best;
}

/// `spec` with the strategy's weights `w`.
RunSpec with_weights(const RunSpec& spec, const CertificateHeader& h, const std::vector<double>& w) {
  json params = spec.strategy.params;
  for (std::size_t k = 0; k < h.weights.size(); ++k) params[h.weights[k]] = w[k];
  RunSpec out = spec;
  out.strategy = configure_strategy(spec.strategy.name, params);
  return out;
}

/// Re-simulates one region (point 4 of the file comment); "" or the problem.
std::string resimulate(const CertificateHeader& h, const Objective& objective, const Region& r,
                       std::span<const RunSpec> specs, std::atomic<std::uint64_t>& decisions,
                       std::atomic<std::uint64_t>& by_corners, std::atomic<std::uint64_t>& by_points) {
  const std::vector<double> w = weights_at(h, representative(r));
  const std::size_t n = h.weights.size();
  std::vector<double> lo(n);
  std::vector<double> hi(n);
  for (std::size_t k = 0; k < n; ++k) {
    int a = r.boxes.front().lo[k];
    int b = r.boxes.front().hi[k];
    for (const Box& box : r.boxes) {
      a = std::min(a, box.lo[k]);
      b = std::max(b, box.hi[k]);
    }
    lo[k] = h.values[k][static_cast<std::size_t>(a)];
    hi[k] = h.values[k][static_cast<std::size_t>(b)];
  }
  std::vector<Simulation> plain;
  std::vector<RunResult> results;
  std::uint64_t trace = 0;
  for (std::size_t i = 0; i < specs.size(); ++i) {
    const RunSpec spec = with_weights(specs[i], h, w);
    Simulation checked(spec);
    Simulation& ordinary = plain.emplace_back(spec);
    const std::uint64_t limit = r.pruned ? r.steps[i] : std::numeric_limits<std::uint64_t>::max();
    while (!checked.ended() && checked.steps_taken() < limit) {
      const Candidates* candidates = checked.choice(WeightBounds{lo, hi, WeightDirections{}});
      if (candidates == nullptr) {
        (void)checked.step();
      } else {
        const int chosen = argmin_linear(*candidates, w);
        if (candidates->cells.size() > 1) {
          decisions.fetch_add(1, std::memory_order_relaxed);
          const std::string problem = check_choice(h, r, *candidates, chosen, by_corners, by_points);
          if (!problem.empty()) {
            return "instance " + std::to_string(i) + ", step " + std::to_string(checked.steps_taken() + 1) +
                   ": " + problem;
          }
        }
        (void)checked.step_choosing(chosen);
      }
      (void)ordinary.step();
    }
    if (r.pruned && checked.steps_taken() != limit) {
      return "instance " + std::to_string(i) + ": the run ended after " +
             std::to_string(checked.steps_taken()) + " steps, before the " + std::to_string(limit) +
             " the region was pruned at";
    }
    if (checked.decision_trace() != ordinary.decision_trace() || ordinary.ended() != checked.ended()) {
      return "instance " + std::to_string(i) +
             ": the representative's ordinary run decides otherwise than its run checked decision by "
             "decision";
    }
    if (!r.pruned) {
      trace = mix64(trace ^ ordinary.decision_trace());
      results.push_back(ordinary.result());
    }
  }
  if (r.pruned) {
    // The bound its runs give there bounds every vector of the region; a recorded value at most
    // that (a search whose bound was weaker when it wrote the region) is proven as well.
    const double bound = class_lower_bound(plain, objective);
    if (bound >= r.value) return {};
    return "the bound of its representative's runs is " + format_number(bound) + ", below its value " +
           format_number(r.value);
  }
  const double value = class_objective(results, objective);
  if (trace != r.trace)
    return "its runs' decisions hash to " + hex64(trace) + ", not its trace " + hex64(r.trace);
  if (value == r.value || (std::isnan(value) && std::isnan(r.value))) return {};
  return "the objective of its representative's runs is " + format_number(value) + ", not its value " +
         format_number(r.value);
}

}  // namespace

CertificateHeader read_certificate_header(const std::string& path) {
  std::ifstream in = open_certificate(path);
  std::string line;
  std::getline(in, line);
  CertificateHeader h;
  try {
    const json j = parse_json_unique_keys(line, path + ":1");
    if (j.at("format").get<std::string>() != kCertificateFormat) {
      throw std::runtime_error("format '" + j.at("format").get<std::string>() + "'; allowed: '" +
                               kCertificateFormat + "'");
    }
    h.search_id = whole(j.at("search_id"), "search_id");
    h.strategy_label = j.at("strategy_label").get<std::string>();
    h.map_class = j.at("map_class").get<std::string>();
    h.weights = j.at("weights").get<std::vector<std::string>>();
    for (const json& values : array(j.at("values"), "values")) {
      std::vector<double>& v = h.values.emplace_back();
      for (const json& value : array(values, "a weight's values"))
        v.push_back(number(value, "a weight's value"));
    }
    h.objective = j.at("objective").get<std::string>();
    h.objective_column = j.at("objective_column").get<std::string>();
    const std::string direction = j.at("direction").get<std::string>();
    if (direction != "minimize" && direction != "maximize")
      throw std::runtime_error("direction '" + direction + "'");
    h.minimize = direction == "minimize";
    const json& optimum = j.at("optimum");
    h.optimum = optimum.is_null() ? std::numeric_limits<double>::quiet_NaN() : number(optimum, "optimum");
    h.vectors = whole(j.at("vectors"), "vectors");
    h.instances = j.at("instances");
    if (!h.instances.is_array() || h.instances.empty()) throw std::runtime_error("no instances");
    if (h.weights.empty() || h.weights.size() > 4 || h.values.size() != h.weights.size()) {
      throw std::runtime_error("1 to 4 weights, each with its values");
    }
    std::uint64_t size = 1;
    for (const std::vector<double>& v : h.values) {
      if (v.empty() || !std::is_sorted(v.begin(), v.end()) ||
          std::adjacent_find(v.begin(), v.end()) != v.end() || v.front() < 0 || !std::isfinite(v.back())) {
        throw std::runtime_error("a weight's values must be finite, >= 0 and strictly ascending");
      }
      if (__builtin_mul_overflow(size, std::uint64_t{v.size()}, &size))
        throw std::runtime_error("a box of more than 2^64 vectors");
    }
    if (size != h.vectors)
      throw std::runtime_error("vectors " + std::to_string(h.vectors) + ", the values' product " +
                               std::to_string(size));
  } catch (const ConfigError&) {
    throw;
  } catch (const std::exception& e) {
    throw ConfigError(path + ":1", std::string("not a weight search certificate's header: ") + e.what());
  }
  return h;
}

CertificateCheck check_certificate(const std::string& path, const CertificateHeader& header,
                                   std::span<const RunSpec> specs, const VerifyOptions& options) {
  CertificateCheck out;
  const Objective* objective = find_objective(header.objective);
  if (objective == nullptr || objective->column != header.objective_column) {
    throw ConfigError(path + ":1", "objective '" + header.objective + "' of column '" +
                                       header.objective_column +
                                       "'; allowed: " + join_names(objective_names()));
  }
  if (specs.size() != header.instances.size())
    throw std::invalid_argument("check_certificate: a spec per instance");
  const std::vector<Region> regions = read_regions(path, header);
  out.regions = regions.size();
  if (regions.empty()) {
    out.problems.push_back("no region");
    return out;
  }
  check_cover(header, regions, out);
  check_values(header, regions, out);
  // The regions to re-simulate: all, or the optimal ones and a seeded sample of the others.
  std::vector<std::size_t> chosen(regions.size());
  std::iota(chosen.begin(), chosen.end(), 0);
  if (header.vectors > options.full_limit) {
    std::vector<std::size_t> optimal;
    std::vector<std::size_t> others;
    for (std::size_t i = 0; i < regions.size(); ++i) {
      (!regions[i].pruned && regions[i].value == header.optimum ? optimal : others).push_back(i);
    }
    Rng rng = make_rng(options.seed, "verify sample");
    const std::size_t take = std::min(options.sample, others.size());
    for (std::size_t i = 0; i < take; ++i) {
      std::swap(others[i], others[i + static_cast<std::size_t>(rng() % (others.size() - i))]);
    }
    others.resize(take);
    chosen = optimal;
    chosen.insert(chosen.end(), others.begin(), others.end());
    std::sort(chosen.begin(), chosen.end());
    out.sampled = take < regions.size() - optimal.size();
  }
  out.resimulated = chosen.size();
  std::vector<std::string> problems(chosen.size());
  std::atomic<std::uint64_t> decisions{0};
  std::atomic<std::uint64_t> by_corners{0};
  std::atomic<std::uint64_t> by_points{0};
  tbb::task_arena arena(std::max(1, options.threads));
  arena.execute([&] {
    tbb::parallel_for(std::size_t{0}, chosen.size(), [&](std::size_t i) {
      const Region& r = regions[chosen[i]];
      try {
        const std::string problem =
            resimulate(header, *objective, r, specs, decisions, by_corners, by_points);
        if (!problem.empty()) problems[i] = describe(r) + ": " + problem;
      } catch (const std::exception& e) {
        problems[i] = describe(r) + ": " + e.what();
      }
    });
  });
  for (std::string& p : problems) {
    if (!p.empty()) out.problems.push_back(std::move(p));
  }
  out.decisions_checked = decisions.load();
  out.boxes_by_corners = by_corners.load();
  out.boxes_by_points = by_points.load();
  return out;
}

}  // namespace verify
}  // namespace fsweep
