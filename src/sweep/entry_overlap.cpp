#include "sweep/entry_overlap.hpp"

#include <algorithm>
#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <numeric>
#include <optional>
#include <set>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "core/csv_format.hpp"
#include "core/json_excerpt.hpp"
#include "strategies/registry.hpp"

namespace fsweep {
inline namespace sweep {
namespace sweep_detail {
namespace {

using nlohmann::json;
using Tuple = std::vector<json>;

/// A parameter value as a run's key sees it: numbers as doubles (1 and 1.0 are one value).
json normalized(const json& v) {
  if (v.is_number()) return json(v.get<double>());
  if (v.is_array()) {
    json out = json::array();
    for (const json& e : v) out.push_back(normalized(e));
    return out;
  }
  if (v.is_object()) {
    json out = json::object();
    for (const auto& [k, e] : v.items()) out[k] = normalized(e);
    return out;
  }
  return v;
}

/// Per strategy, its declared defaults (a parameter an entry does not set takes its default);
/// "heuristics", not a declared parameter, is null when not set.
class Defaults {
 public:
  [[nodiscard]] const std::map<std::string, json>& of(const std::string& name) {
    const auto it = by_name_.find(name);
    if (it != by_name_.end()) return it->second;
    std::map<std::string, json> d;
    if (strategy_registry().contains(name)) {
      for (const ParamSpec& spec : strategy_registry().params(name)) {
        d.emplace(spec.name, normalized(spec.default_value));
      }
    }
    return by_name_.emplace(name, std::move(d)).first->second;
  }

 private:
  std::map<std::string, std::map<std::string, json>> by_name_;
};

/// An entry as value sets: each parameter's group and position in it, the groups' normalized
/// combos.
struct EntryValues {
  std::size_t index = 0;  ///< in the sweep's strategies
  const StrategyEntry* entry = nullptr;
  std::map<std::string, std::pair<std::size_t, std::size_t>> at;  ///< name -> (group, position)
  std::vector<std::vector<Tuple>> combos;                         ///< per group, normalized
  std::vector<std::set<Tuple>> combo_sets;                        ///< per group, for lookups
  const std::map<std::string, json>* defaults = nullptr;          ///< of its strategy

  EntryValues(const StrategyEntry& e, std::size_t i, Defaults& all)
      : index(i), entry(&e), defaults(&all.of(e.name)) {
    for (std::size_t g = 0; g < e.groups.size(); ++g) {
      for (std::size_t p = 0; p < e.groups[g].names.size(); ++p)
        at.emplace(e.groups[g].names[p], std::make_pair(g, p));
      std::vector<Tuple>& out = combos.emplace_back();
      out.reserve(e.groups[g].combos.size());
      for (const Tuple& c : e.groups[g].combos) {
        Tuple t;
        t.reserve(c.size());
        for (const json& v : c) t.push_back(normalized(v));
        out.push_back(std::move(t));
      }
      combo_sets.emplace_back(out.begin(), out.end());
    }
  }

  /// The default of a parameter this entry does not set.
  [[nodiscard]] json fallback(const std::string& name) const {
    const auto it = defaults->find(name);
    return it == defaults->end() ? json(nullptr) : it->second;
  }

  /// Whether the assignment `values` (names of one linked set) is one of this entry's
  /// configurations there: each of its groups' projections is a combo, other names defaults.
  [[nodiscard]] bool holds(const std::map<std::string, json>& values) const {
    std::map<std::size_t, Tuple> projected;
    for (const auto& [name, v] : values) {
      const auto it = at.find(name);
      if (it == at.end()) {
        if (v != fallback(name)) return false;
        continue;
      }
      Tuple& t = projected[it->second.first];
      t.resize(combos[it->second.first].front().size());
      t[it->second.second] = v;
    }
    return std::all_of(projected.begin(), projected.end(),
                       [&](const auto& g) { return combo_sets[g.first].contains(g.second); });
  }

  /// The groups this entry has among `names`, and how many assignments of `names` they make.
  [[nodiscard]] std::pair<std::vector<std::size_t>, std::uint64_t> groups_in(
      const std::vector<std::string>& names) const {
    std::set<std::size_t> groups;
    for (const std::string& n : names) {
      if (const auto it = at.find(n); it != at.end()) groups.insert(it->second.first);
    }
    std::uint64_t count = 1;
    for (const std::size_t g : groups) {
      if (__builtin_mul_overflow(count, static_cast<std::uint64_t>(combos[g].size()), &count)) {
        count = UINT64_MAX;
        break;
      }
    }
    return {std::vector<std::size_t>(groups.begin(), groups.end()), count};
  }

  /// Assignment k (mixed radix over `groups`) of `names`: the groups' combos, defaults elsewhere.
  [[nodiscard]] std::map<std::string, json> assignment(const std::vector<std::string>& names,
                                                       const std::vector<std::size_t>& groups,
                                                       std::uint64_t k) const {
    std::map<std::string, json> out;
    for (const std::string& n : names) {
      if (!at.contains(n)) out.emplace(n, fallback(n));
    }
    for (auto g = groups.rbegin(); g != groups.rend(); ++g) {
      const std::uint64_t size = combos[*g].size();
      const Tuple& combo = combos[*g][static_cast<std::size_t>(k % size)];
      k /= size;
      for (std::size_t p = 0; p < combo.size(); ++p) out[entry->groups[*g].names[p]] = combo[p];
    }
    return out;
  }
};

/// The parameters of `a` and `b` in sets linked by their groups (a zip ties its names).
std::vector<std::vector<std::string>> linked_sets(const EntryValues& a, const EntryValues& b) {
  std::vector<std::string> names;
  for (const EntryValues* e : {&a, &b}) {
    for (const auto& [n, where] : e->at) names.push_back(n);
  }
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  std::vector<std::size_t> parent(names.size());
  std::iota(parent.begin(), parent.end(), 0);
  const auto root = [&](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  const auto index = [&](const std::string& n) {
    return static_cast<std::size_t>(std::lower_bound(names.begin(), names.end(), n) - names.begin());
  };
  for (const EntryValues* e : {&a, &b}) {
    for (const StrategyEntry::Group& g : e->entry->groups) {
      for (const std::string& n : g.names) parent[root(index(n))] = root(index(g.names.front()));
    }
  }
  std::map<std::size_t, std::vector<std::string>> sets;
  for (std::size_t i = 0; i < names.size(); ++i) sets[root(i)].push_back(names[i]);
  std::vector<std::vector<std::string>> out;
  out.reserve(sets.size());
  for (auto& [r, set] : sets) out.push_back(std::move(set));
  return out;
}

/// An assignment of `names` that both entries hold, or nullopt (also when both sides have more
/// than kMaxOverlapTuples: not checked).
std::optional<std::map<std::string, json>> shared_assignment(const EntryValues& a, const EntryValues& b,
                                                             const std::vector<std::string>& names) {
  auto [groups_a, count_a] = a.groups_in(names);
  auto [groups_b, count_b] = b.groups_in(names);
  const bool a_smaller = count_a <= count_b;
  const EntryValues& small = a_smaller ? a : b;
  const EntryValues& other = a_smaller ? b : a;
  const std::vector<std::size_t>& groups = a_smaller ? groups_a : groups_b;
  const std::uint64_t count = std::min(count_a, count_b);
  if (count > kMaxOverlapTuples) return std::nullopt;
  for (std::uint64_t k = 0; k < count; ++k) {
    std::map<std::string, json> values = small.assignment(names, groups, k);
    if (other.holds(values)) return values;
  }
  return std::nullopt;
}

/// One configuration `a` and `b` share (the parameters either sets), or nullopt.
std::optional<std::map<std::string, json>> shared_configuration(const EntryValues& a, const EntryValues& b) {
  std::map<std::string, json> shared;
  for (const std::vector<std::string>& names : linked_sets(a, b)) {
    const std::optional<std::map<std::string, json>> part = shared_assignment(a, b, names);
    if (!part) return std::nullopt;
    shared.insert(part->begin(), part->end());
  }
  return shared;
}

/// A value for a message: a number as format_number() writes it (220, not 220.0).
std::string shown_value(const json& v) {
  return v.is_number() ? format_number(v.get<double>()) : json_excerpt(v);
}

std::string overlap_problem(const EntryValues& earlier, const EntryValues& later,
                            const std::map<std::string, json>& shared) {
  std::string values;
  for (const auto& [name, v] : shared) values += (values.empty() ? "" : ", ") + name + " = " + shown_value(v);
  const std::string& name = later.entry->name;
  return "/strategies/" + std::to_string(later.index) + ": the same configuration as /strategies/" +
         std::to_string(earlier.index) + " (" + name + (values.empty() ? "" : ": " + values) +
         "); a label is not part of a run's identity, so both entries would run it; allowed: each "
         "configuration in one entry";
}

/// The key of an entry of one configuration: its strategy and every parameter (defaults filled
/// in), normalized.
std::string single_key(const StrategyEntry& e, Defaults& defaults) {
  json params = json::object();
  for (const auto& [name, v] : defaults.of(e.name)) params[name] = v;
  params["heuristics"] = nullptr;
  for (const StrategyEntry::Group& g : e.groups) {
    for (std::size_t p = 0; p < g.names.size(); ++p) params[g.names[p]] = normalized(g.combos.front()[p]);
  }
  return e.name + '\n' + params.dump();
}

/// The problem of entry `later`, of one configuration, that entry `earlier` has too.
std::string single_overlap_problem(const std::vector<StrategyEntry>& entries, std::size_t earlier,
                                   std::size_t later, Defaults& defaults) {
  const EntryValues e(entries[later], later, defaults);
  std::map<std::string, json> shared;
  for (const auto& [name, where] : e.at) shared.emplace(name, e.combos[where.first].front()[where.second]);
  return overlap_problem(EntryValues(entries[earlier], earlier, defaults), e, shared);
}

}  // namespace

void check_entry_overlaps(const std::vector<StrategyEntry>& entries, std::vector<std::string>& problems) {
  Defaults defaults;
  std::vector<std::size_t> singles;
  std::vector<EntryValues> multis;
  // Entries of one configuration each, by a hash of it (linear in their number).
  std::unordered_map<std::string, std::size_t> first;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    if (entries[i].search) continue;
    if (entries[i].count() != 1) {
      multis.emplace_back(entries[i], i, defaults);
      continue;
    }
    singles.push_back(i);
    const auto [it, fresh] = first.emplace(single_key(entries[i], defaults), i);
    if (!fresh) problems.push_back(single_overlap_problem(entries, it->second, i, defaults));
  }
  // Entries of several configurations, against every other entry of their strategy.
  for (std::size_t m = 0; m < multis.size(); ++m) {
    const EntryValues& e = multis[m];
    const auto check = [&](const EntryValues& other) {
      const std::optional<std::map<std::string, json>> shared = shared_configuration(other, e);
      if (!shared) return false;
      problems.push_back(other.index < e.index ? overlap_problem(other, e, *shared)
                                               : overlap_problem(e, other, *shared));
      return true;
    };
    bool found = false;
    for (std::size_t o = 0; o < m && !found; ++o) {
      if (multis[o].entry->name == e.entry->name) found = check(multis[o]);
    }
    for (std::size_t k = 0; k < singles.size() && !found; ++k) {
      if (entries[singles[k]].name == e.entry->name)
        found = check(EntryValues(entries[singles[k]], singles[k], defaults));
    }
  }
}

}  // namespace sweep_detail
}  // namespace sweep
}  // namespace fsweep
