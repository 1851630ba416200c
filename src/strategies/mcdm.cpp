#include "strategies/mcdm.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <nlohmann/json.hpp>
#include <string_view>

#include "core/config_error.hpp"
#include "core/json_excerpt.hpp"
#include "strategies/choquet.hpp"

namespace fsweep {
inline namespace strategies {
namespace {

/// Criterion letters in bit order (kMcdmL, kMcdmI, kMcdmO).
constexpr const char* kLetters = "LIO";

/// The six JSON keys, i.e. subset names, of the proper non-empty subsets, by bitmask.
const std::array<const char*, 8> kKeys{"", "L", "I", "LI", "O", "LO", "IO", ""};

/// Equation 5 and its analogues: the linear map of `v` onto [0, 1] over [lo, hi]; `maximise`
/// false turns it around (the paper's u_L). hi == lo: 1 (see Mcdm).
double normalise(double v, double lo, double hi, bool maximise) {
  if (!(hi > lo)) return 1.0;
  const double t = (v - lo) / (hi - lo);
  return maximise ? t : 1.0 - t;
}

}  // namespace

namespace {

/// The problems of a JSON fuzzy measure (see mcdm_params()); on success `out` holds it.
std::vector<std::string> measure_problems(const nlohmann::json& m, std::array<double, 8>* out) {
  std::vector<std::string> problems;
  if (!m.is_object())
    return {
        "expected an object {\"L\": ..., \"I\": ..., \"O\": ..., \"LI\": ..., "
        "\"LO\": ..., \"IO\": ...}, got " +
        json_excerpt(m)};
  for (const auto& [key, value] : m.items()) {
    if (std::find(kKeys.begin() + 1, kKeys.end() - 1, key) == kKeys.end() - 1) {
      problems.push_back(key + ": unknown subset; allowed: L, I, O, LI, LO, IO");
    }
  }
  std::array<double, 8> measure{0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0};
  for (unsigned s = 1; s < 7; ++s) {
    const std::string key = kKeys[s];
    if (!m.contains(key)) {
      problems.push_back(key + ": missing; the measure needs all of L, I, O, LI, LO, IO");
      continue;
    }
    const auto& v = m.at(key);
    if (!v.is_number() || !(v.get<double>() >= 0.0 && v.get<double>() <= 1.0)) {
      problems.push_back(key + ": value " + json_excerpt(v) + " not allowed; allowed: a number in [0, 1]");
      continue;
    }
    measure[s] = v.get<double>();
  }
  if (!problems.empty()) return problems;
  // Every value is in [0, 1] and the ends are fixed, so only monotonicity can fail here.
  for (const MeasureViolation& v : fuzzy_measure_violations(measure)) {
    const std::string a = subset_name(v.subset, kLetters);
    const std::string b = subset_name(v.superset, kLetters);
    // Names the user's value that is part of the pair (the larger set unless it is the fixed
    // full set).
    const std::string key = v.superset == 7U ? a : b;
    // NOLINTBEGIN(performance-inefficient-string-concatenation): one message per refused value
    problems.push_back(key + ": mu(" + a + ") = " + nlohmann::json(measure[v.subset]).dump() + " > mu(" + b +
                       ") = " + nlohmann::json(measure[v.superset]).dump() +
                       "; a fuzzy measure must not decrease when a criterion is added (" + a +
                       " is a subset of " + b + ")");
    // NOLINTEND(performance-inefficient-string-concatenation)
  }
  if (problems.empty() && out != nullptr) *out = measure;
  return problems;
}

}  // namespace

ParamDecl<McdmParams> mcdm_params() {
  ParamDecl<McdmParams> d;
  ParamSpec spec;
  spec.name = "measure";
  spec.type = ParamType::Custom;
  spec.doc =
      "fuzzy measure of the Choquet integral over the criteria L (travel), I (gain), O (overlap); "
      "default Holz 2010 Table I";
  spec.allowed_text = "an object of the subsets L, I, O, LI, LO, IO, each a number in [0, 1], monotone";
  spec.custom_check = [](const nlohmann::json& v) { return measure_problems(v, nullptr); };
  d.custom(
      std::move(spec), [](McdmParams& p, const nlohmann::json& v) { (void)measure_problems(v, &p.measure); },
      [](const McdmParams& p) {
        nlohmann::json m = nlohmann::json::object();
        for (unsigned s = 1; s < 7; ++s) m[kKeys[s]] = p.measure[s];
        return m;
      });
  return d;
}

std::vector<McdmCandidate> Mcdm::evaluate(const Observation& obs) {
  // 1. Reachable cluster representatives.
  std::vector<int> reps;
  reps.reserve(obs.clusters.size());
  for (const auto& c : obs.clusters) reps.push_back(c.representative);
  if (reps.empty()) return {};
  const std::vector<double> length = obs.distances.from_robot(reps, std::numeric_limits<double>::infinity());
  // 2. One simulated scan per candidate.
  const double cell_area_m2 = obs.known.resolution_m() * obs.known.resolution_m();
  std::vector<McdmCandidate> out;
  for (std::size_t k = 0; k < reps.size(); ++k) {
    if (!std::isfinite(length[k])) continue;
    McdmCandidate c;
    c.cell = obs.known.cell(reps[k]);
    c.length_m = length[k];
    const ScanCounts counts = scanner_.at(obs, c.cell);
    c.gain_m2 = counts.unknown * cell_area_m2;
    c.overlap_m2 = counts.known * cell_area_m2;
    out.push_back(c);
  }
  if (out.empty()) return out;
  // 3. Normalisation over this decision's candidates.
  const auto range = [&](double McdmCandidate::*field) {
    const auto [lo, hi] = std::minmax_element(
        out.begin(), out.end(),
        [&](const McdmCandidate& a, const McdmCandidate& b) { return a.*field < b.*field; });
    return std::pair<double, double>{(*lo).*field, (*hi).*field};
  };
  const auto [l_lo, l_hi] = range(&McdmCandidate::length_m);
  const auto [i_lo, i_hi] = range(&McdmCandidate::gain_m2);
  const auto [o_lo, o_hi] = range(&McdmCandidate::overlap_m2);
  // 4. Choquet integral (criteria in bit order L, I, O).
  for (McdmCandidate& c : out) {
    c.utility = {normalise(c.length_m, l_lo, l_hi, false), normalise(c.gain_m2, i_lo, i_hi, true),
                 normalise(c.overlap_m2, o_lo, o_hi, true)};
    c.global = choquet_integral(c.utility, params_.measure);
  }
  return out;
}

Decision Mcdm::decide(const Observation& obs) {
  const std::vector<McdmCandidate> c = evaluate(obs);
  if (c.empty()) return Decision::finish();
  std::size_t best = 0;
  for (std::size_t k = 1; k < c.size(); ++k) {
    if (c[k].global > c[best].global) best = k;  // strict: ties keep the lowest cluster
  }
  return Decision::go_to(c[best].cell);
}

}  // namespace strategies
}  // namespace fsweep
