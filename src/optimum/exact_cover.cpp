#include "optimum/exact_cover.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <queue>
#include <unordered_map>

#include "search/octile_grid.hpp"

namespace fsweep {
inline namespace optimum {
namespace {

struct State {
  int node = -1;
  std::uint64_t revealed = 0;
  friend bool operator==(const State&, const State&) = default;
};

struct StateHash {
  std::size_t operator()(const State& s) const {
    std::uint64_t h = s.revealed * 0x9E3779B97F4A7C15ULL;
    h ^= static_cast<std::uint64_t>(s.node) + 0x632BE59BD9B4E019ULL + (h << 6U) + (h >> 2U);
    return static_cast<std::size_t>(h);
  }
};

struct Entry {
  double f;
  double g;
  State state;
  /// Smaller f first; on equal f larger g; then node and set, so the order is total.
  friend bool operator<(const Entry& a, const Entry& b) {
    if (a.f != b.f) return a.f > b.f;
    if (a.g != b.g) return a.g < b.g;
    if (a.state.node != b.state.node) return a.state.node > b.state.node;
    return a.state.revealed > b.state.revealed;
  }
};

struct Record {
  double g = kInfinity;
  State parent{};
};

}  // namespace

ExactResult exact_cover(const CoverageInstance& in, const CoverageLowerBound& bound,
                        const ExactOptions& options) {
  ExactResult result;
  // Bits: the explorable targets, by id.
  std::vector<int> bit_of(static_cast<std::size_t>(in.targets()), -1);
  std::vector<int> target_of_bit;
  if (in.explorable_count() > kExactMaxTargets) return result;
  for (int t = 0; t < in.targets(); ++t) {
    if (!in.is_explorable(t)) continue;
    bit_of[static_cast<std::size_t>(t)] = static_cast<int>(target_of_bit.size());
    target_of_bit.push_back(t);
  }
  const int bits = static_cast<int>(target_of_bit.size());
  const std::uint64_t full = bits == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << bits) - 1;
  std::vector<std::uint64_t> sees(static_cast<std::size_t>(in.nodes()), 0);
  for (int n = 0; n < in.nodes(); ++n) {
    for (const int t : in.sees.row(n)) {
      const int b = bit_of[static_cast<std::size_t>(t)];
      if (b >= 0) sees[static_cast<std::size_t>(n)] |= std::uint64_t{1} << b;
    }
  }
  // Per target: the distance from every node to its nearest viewpoint.
  std::vector<std::vector<double>> to_target;
  std::vector<int> cells;
  for (const int t : target_of_bit) {
    cells.clear();
    for (const int n : in.seen_from.row(t)) cells.push_back(in.node_cell[static_cast<std::size_t>(n)]);
    to_target.push_back(node_distances_m(in, cells));
  }
  // Which witness is which bit.
  std::vector<int> witness_bit;
  for (const int w : bound.witnesses()) witness_bit.push_back(bit_of[static_cast<std::size_t>(w)]);
  std::vector<std::uint8_t> open_witness(witness_bit.size());
  const auto heuristic = [&](const State& s) {
    double h = 0.0;
    for (int b = 0; b < bits; ++b) {
      if ((s.revealed >> b & 1U) == 0)
        h = std::max(h, to_target[static_cast<std::size_t>(b)][static_cast<std::size_t>(s.node)]);
    }
    for (std::size_t k = 0; k < witness_bit.size(); ++k) {
      open_witness[k] = witness_bit[k] >= 0 && (s.revealed >> witness_bit[k] & 1U) == 0 ? 1 : 0;
    }
    return std::max(h * (1.0 - kBoundRoundingMargin), bound.from_node(s.node, open_witness));
  };

  std::unordered_map<State, Record, StateHash> records;
  std::priority_queue<Entry> open;
  const State start{in.start_node, sees[static_cast<std::size_t>(in.start_node)]};
  records[start] = Record{0.0, State{}};
  open.push(Entry{heuristic(start), 0.0, start});
  while (!open.empty()) {
    const Entry e = open.top();
    if (e.g > records[e.state].g) {  // stale
      open.pop();
      continue;
    }
    if (e.state.revealed == full) {
      result.solved = true;
      result.optimum_m = e.g;
      result.lower_m = e.g;
      for (State s = e.state; s.node >= 0; s = records[s].parent) {
        result.cells.push_back(in.node_cell[static_cast<std::size_t>(s.node)]);
        if (s == start) break;
      }
      std::reverse(result.cells.begin(), result.cells.end());
      return result;
    }
    if (result.expansions >= options.max_expansions ||
        (options.deadline && (result.expansions & 1023) == 0 &&
         std::chrono::steady_clock::now() > *options.deadline)) {
      result.stopped_by_time = result.expansions < options.max_expansions;
      result.lower_m = e.f;
      return result;
    }
    open.pop();
    ++result.expansions;
    const int cell = in.node_cell[static_cast<std::size_t>(e.state.node)];
    for_each_octile_neighbour<double>(
        in.truth, cell, in.allow_corner_cutting, [&](int next_cell, double step) {
          const int next = in.node_of_cell[static_cast<std::size_t>(next_cell)];
          if (next < 0) return;
          const State s{next, e.state.revealed | sees[static_cast<std::size_t>(next)]};
          const double g = e.g + step * in.resolution_m;
          Record& r = records[s];
          if (g >= r.g) return;
          r = Record{g, e.state};
          open.push(Entry{g + heuristic(s), g, s});
        });
  }
  result.lower_m = kInfinity;  // no goal reachable: no route reveals every target
  return result;
}

}  // namespace optimum
}  // namespace fsweep
