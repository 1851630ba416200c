#include "weightsearch/weight_grid.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace fsweep {
inline namespace weightsearch {
namespace {

constexpr std::size_t kWeights = WeightGrid::kMaxWeights;

void set_bit(BlockBits& bits, int bit) {
  bits[static_cast<std::size_t>(bit) / 64] |= std::uint64_t{1} << (static_cast<unsigned>(bit) % 64);
}

/// The first bit at or after `from` (below 4,096) whose value is `value`, or 4,096.
std::size_t next_bit(const BlockBits& bits, std::size_t from, bool value) {
  constexpr std::size_t kBits = std::tuple_size_v<BlockBits> * 64;
  for (std::size_t at = from; at < kBits;) {
    const std::uint64_t word = value ? bits[at / 64] : ~bits[at / 64];
    const std::uint64_t rest = word >> (at % 64);
    if (rest != 0) return at + static_cast<std::size_t>(std::countr_zero(rest));
    at = (at / 64 + 1) * 64;
  }
  return kBits;
}

/// Adds the direction v / sum(v) of a point's weights (or coordinates) `v` to `d`, or marks
/// `d.zero` when they sum to 0. One division, then products: within two units in the last place
/// of the ratios, well inside widen()'s margin.
void take_direction(WeightDirections& d, std::span<const double> v) {
  double sum = 0.0;
  for (const double x : v) sum += x;
  if (sum == 0.0) {
    d.zero = true;
    return;
  }
  d.nonzero = true;
  const double inverse = 1.0 / sum;
  for (std::size_t k = 0; k < v.size(); ++k) {
    const double ratio = v[k] * inverse;
    d.lo[k] = std::min(d.lo[k], ratio);
    d.hi[k] = std::max(d.hi[k], ratio);
  }
}

/// Widens the first n bounds of `d` outward by 1e-14 (within [0, 1]), so that they hold the exact
/// ratios that rounding may miss by a few units in the last place.
void widen(WeightDirections& d, std::size_t n) {
  for (std::size_t k = 0; k < n; ++k) {
    d.lo[k] = std::max(0.0, d.lo[k] - 1e-14);
    d.hi[k] = std::min(1.0, d.hi[k] + 1e-14);
  }
}

/// The candidate that wins at every direction of `d` (candidates of k features), proven without
/// visiting points: the one cheapest at the middle of `d` (the only one that can), when every
/// other costs more at every direction (costs_more_at_every_direction() with the margin
/// `extra(f_j, f_i)`) or has exactly its features and comes later (an exact tie, which the first
/// wins). Where every cost is 0 (d.zero) the first candidate wins. -1 otherwise.
template <typename Extra>
int sole_over(const WeightDirections& d, const Candidates& candidates, std::size_t k, const Extra& extra) {
  if (!d.nonzero) return d.zero ? 0 : -1;
  std::array<double, WeightDirections::kMaxWeights> middle{};
  for (std::size_t j = 0; j < k; ++j) middle[j] = 0.5 * (d.lo[j] + d.hi[j]);
  const int winner = argmin_linear(candidates, std::span(middle).first(k));
  if (d.zero && winner != 0) return -1;
  const std::span<const double> features(candidates.features);
  const std::span<const double> fi = features.subspan(static_cast<std::size_t>(winner) * k, k);
  for (std::size_t other = 0; other < candidates.cells.size(); ++other) {
    if (other == static_cast<std::size_t>(winner)) continue;
    const std::span<const double> fj = features.subspan(other * k, k);
    if (std::equal(fj.begin(), fj.end(), fi.begin())) {
      if (other < static_cast<std::size_t>(winner)) return -1;  // it would win every tie
      continue;
    }
    if (!costs_more_at_every_direction(fj, fi, d, extra(fj, fi))) return -1;
  }
  return winner;
}

/// The extreme directions w_k / sum(w) of the box of weights lo..hi (0 <= lo <= hi): w_k / (w_k +
/// rest) grows with w_k and falls with each other weight, so they are at corners. Each within a
/// few units in the last place of the exact ratio.
void box_ratios(std::span<const double> lo, std::span<const double> hi,
                std::array<double, WeightDirections::kMaxWeights>& low,
                std::array<double, WeightDirections::kMaxWeights>& high) {
  const std::size_t n = lo.size();
  for (std::size_t k = 0; k < n; ++k) {
    // The other weights' sums, added directly (a difference of sums could cancel).
    double others_lo = 0.0;
    double others_hi = 0.0;
    for (std::size_t j = 0; j < n; ++j) {
      if (j == k) continue;
      others_lo += lo[j];
      others_hi += hi[j];
    }
    low[k] = lo[k] == 0.0 ? 0.0 : lo[k] / (lo[k] + others_hi);
    high[k] = hi[k] == 0.0 ? 0.0 : hi[k] / (hi[k] + others_lo);
  }
}

/// The extreme directions v / sum(v) (box_ratios()) of the tied coordinates v of
/// WeightGrid::tied_directions() over the box of weights lo..hi (4 weights), from the box of
/// v's values. True when that box holds v = 0 (then some point of it may have v = 0).
bool tied_box_ratios(std::span<const double> lo, std::span<const double> hi, int sign,
                     std::array<double, WeightDirections::kMaxWeights>& low,
                     std::array<double, WeightDirections::kMaxWeights>& high) {
  std::array<double, WeightDirections::kMaxWeights> v_lo{lo[0], 0.0, 0.0, lo[3]};
  std::array<double, WeightDirections::kMaxWeights> v_hi{hi[0], 0.0, 0.0, hi[3]};
  if (sign < 0) {
    const double u_lo = lo[1] - hi[2];
    const double u_hi = hi[1] - lo[2];
    v_lo[1] = std::max(u_lo, 0.0);
    v_hi[1] = std::max(u_hi, 0.0);
    v_lo[2] = std::max(-u_hi, 0.0);
    v_hi[2] = std::max(-u_lo, 0.0);
  } else {
    v_lo[1] = lo[1] + lo[2];
    v_hi[1] = hi[1] + hi[2];
  }
  box_ratios(v_lo, v_hi, low, high);
  return std::all_of(v_lo.begin(), v_lo.end(), [](double x) { return x == 0.0; });
}

}  // namespace

std::uint64_t WeightGrid::blocks_of(const std::vector<std::vector<double>>& values) {
  std::uint64_t blocks = 1;
  for (const std::vector<double>& v : values) {
    const std::uint64_t edge = (v.size() + kBlockEdge - 1) / kBlockEdge;
    if (__builtin_mul_overflow(blocks, edge, &blocks)) return UINT64_MAX;
  }
  return blocks;
}

std::uint64_t WeightGrid::shard_blocks(std::uint64_t blocks, std::uint64_t index, std::uint64_t count) {
  const auto edge = [&](std::uint64_t i) { return i * blocks / count; };
  return edge(index + 1) - edge(index);
}

WeightGrid::WeightGrid(std::vector<std::vector<double>> values) : values_(std::move(values)) {
  if (values_.empty() || values_.size() > kWeights) {
    throw std::invalid_argument("a weight grid has 1 to 4 weights, not " + std::to_string(values_.size()));
  }
  for (std::size_t k = 0; k < values_.size(); ++k) {
    const std::vector<double>& v = values_[k];
    if (v.empty()) throw std::invalid_argument("weight " + std::to_string(k + 1) + " has no value");
    for (std::size_t i = 0; i < v.size(); ++i) {
      if (!std::isfinite(v[i]) || v[i] < 0.0 || (i > 0 && !(v[i - 1] < v[i]))) {
        throw std::invalid_argument("the values of weight " + std::to_string(k + 1) +
                                    " must be finite, >= 0 and strictly ascending");
      }
    }
    blocks_[k] = static_cast<std::uint32_t>((v.size() + kBlockEdge - 1) / kBlockEdge);
    size_ *= v.size();
  }
  const std::uint64_t blocks = blocks_of(values_);
  if (blocks > kMaxBlocks) throw std::invalid_argument("a weight grid of more than 2^31 blocks");
  block_count_ = static_cast<std::uint32_t>(blocks);
  if (values_.size() == kWeights) {
    // The smallest positive w1 + |w2 - w3| + w4: the smallest positive w1 or w4, or |w2 - w3| (by
    // a merge of the two sorted lists: the closest pair of different values is adjacent in it).
    double smallest = std::numeric_limits<double>::infinity();
    for (const std::size_t k : {std::size_t{0}, std::size_t{3}}) {
      const auto positive = std::upper_bound(values_[k].begin(), values_[k].end(), 0.0);
      if (positive != values_[k].end()) smallest = std::min(smallest, *positive);
    }
    std::vector<double> merged;
    std::merge(values_[1].begin(), values_[1].end(), values_[2].begin(), values_[2].end(),
               std::back_inserter(merged));
    for (std::size_t i = 1; i < merged.size(); ++i) {
      // The difference of two doubles, rounded down a little for its own rounding.
      if (merged[i] > merged[i - 1])
        smallest = std::min(smallest, (merged[i] - merged[i - 1]) * (1.0 - 1e-15));
    }
    const double largest = std::min(values_[1].back(), values_[2].back());
    tied_ratio_ = std::isfinite(smallest) ? largest / smallest * (1.0 + 1e-15) : 0.0;
  }
}

void WeightGrid::span_values(const BlockSpan& span, std::array<double, kMaxWeights>& lo,
                             std::array<double, kMaxWeights>& hi) const {
  for (std::size_t k = 0; k < values_.size(); ++k) {
    lo[k] = values_[k][static_cast<std::size_t>(span.first[k])];
    hi[k] = values_[k][static_cast<std::size_t>(span.first[k] + span.extent[k] - 1)];
  }
}

WeightGrid::BlockSpan WeightGrid::span_of(std::uint32_t block) const {
  BlockSpan span;
  span.extent.fill(1);
  for (std::size_t k = kWeights; k-- > 0;) {
    const std::uint32_t coordinate = block % blocks_[k];
    block /= blocks_[k];
    if (k >= values_.size()) continue;
    span.first[k] = static_cast<int>(coordinate) * kBlockEdge;
    span.extent[k] = std::min(kBlockEdge, static_cast<int>(values_[k].size()) - span.first[k]);
  }
  return span;
}

WeightGrid::BlockSpan WeightGrid::span_of(const WeightRegion::Box& box) const {
  BlockSpan span;
  span.extent.fill(1);
  for (std::size_t k = 0; k < values_.size(); ++k) {
    span.first[k] = static_cast<int>(box.lo[k]) * kBlockEdge;
    span.extent[k] = std::min(static_cast<int>(box.hi[k]) * kBlockEdge, static_cast<int>(values_[k].size())) -
                     span.first[k];
  }
  return span;
}

WeightGrid::BlockSpan WeightGrid::span_of(std::uint32_t block, const BlockBits& bits) const {
  // bit_of(): a word holds the 64 points of one (l0, l1) = (word / 8, word % 8), bit 8 l2 + l3.
  int lo0 = kBlockEdge;
  int hi0 = -1;
  int lo1 = kBlockEdge;
  int hi1 = -1;
  std::uint64_t any = 0;
  for (std::size_t word = 0; word < bits.size(); ++word) {
    if (bits[word] == 0) continue;
    const auto l0 = static_cast<int>(word / kBlockEdge);
    const auto l1 = static_cast<int>(word % kBlockEdge);
    lo0 = std::min(lo0, l0);
    hi0 = std::max(hi0, l0);
    lo1 = std::min(lo1, l1);
    hi1 = std::max(hi1, l1);
    any |= bits[word];
  }
  if (any == 0) throw std::invalid_argument("the span of an empty part of a weight region");
  std::uint64_t bytes = 0;    // bit l2: some point has that l2
  std::uint64_t columns = 0;  // bit l3: some point has that l3
  for (int l2 = 0; l2 < kBlockEdge; ++l2) {
    const std::uint64_t row = (any >> (kBlockEdge * l2)) & 0xFFU;
    if (row != 0) bytes |= std::uint64_t{1} << l2;
    columns |= row;
  }
  const std::array<int, kMaxWeights> lo{lo0, lo1, std::countr_zero(bytes), std::countr_zero(columns)};
  const std::array<int, kMaxWeights> hi{hi0, hi1, 63 - std::countl_zero(bytes),
                                        63 - std::countl_zero(columns)};
  BlockSpan span = span_of(block);
  for (std::size_t k = 0; k < kWeights; ++k) {
    span.first[k] += lo[k];
    span.extent[k] = hi[k] - lo[k] + 1;
  }
  return span;
}

std::uint32_t WeightGrid::block_at(const std::array<std::uint32_t, kMaxWeights>& c) const {
  std::uint32_t block = 0;
  for (std::size_t k = 0; k < kWeights; ++k) block = block * blocks_[k] + c[k];
  return block;
}

std::uint32_t WeightGrid::block_of(const std::array<int, kMaxWeights>& at) const {
  std::uint32_t block = 0;
  for (std::size_t k = 0; k < kWeights; ++k) {
    block = block * blocks_[k] + static_cast<std::uint32_t>(k < values_.size() ? at[k] / kBlockEdge : 0);
  }
  return block;
}

std::vector<std::uint32_t> point_runs(const BlockBits& bits) {
  std::vector<std::uint32_t> runs;
  std::size_t at = 0;
  for (bool in = false;; in = !in) {
    const std::size_t end = next_bit(bits, at, !in);
    if (!in && end == std::tuple_size_v<BlockBits> * 64) return runs;  // no point after `at`
    runs.push_back(static_cast<std::uint32_t>(end - at));
    at = end;
  }
}

BlockBits bits_of_runs(std::span<const std::uint32_t> runs) {
  constexpr std::size_t kBits = std::tuple_size_v<BlockBits> * 64;
  if (runs.size() % 2 != 0) {
    throw std::invalid_argument("an odd number of runs (the last must be of points in)");
  }
  BlockBits bits{};
  std::size_t at = 0;
  for (std::size_t r = 0; r < runs.size(); ++r) {
    if (r > 0 && runs[r] == 0) throw std::invalid_argument("a run of 0 points after the first");
    if (runs[r] > kBits - at) throw std::invalid_argument("runs of more than 4096 points");
    if (r % 2 == 1) {
      for (std::size_t b = at; b < at + runs[r]; ++b) set_bit(bits, static_cast<int>(b));
    }
    at += runs[r];
  }
  return bits;
}

int WeightGrid::bit_of(const std::array<int, kMaxWeights>& local) {
  return ((local[0] * kBlockEdge + local[1]) * kBlockEdge + local[2]) * kBlockEdge + local[3];
}

BlockBits WeightGrid::all_bits(const BlockSpan& span) const {
  // A word holds the 64 points of one (local[0], local[1]): 8 per local[2], one per local[3].
  static_assert(kBlockEdge == 8);
  std::uint64_t word = 0;
  const std::uint64_t row = (std::uint64_t{1} << static_cast<unsigned>(span.extent[3])) - 1;
  for (int l2 = 0; l2 < span.extent[2]; ++l2) word |= row << static_cast<unsigned>(8 * l2);
  BlockBits bits{};
  const auto edge = static_cast<std::size_t>(kBlockEdge);
  for (std::size_t l0 = 0; l0 < static_cast<std::size_t>(span.extent[0]); ++l0) {
    for (std::size_t l1 = 0; l1 < static_cast<std::size_t>(span.extent[1]); ++l1) bits[l0 * edge + l1] = word;
  }
  return bits;
}

std::vector<double> WeightGrid::weights_at(const std::array<int, kMaxWeights>& at) const {
  std::vector<double> w(values_.size());
  for (std::size_t k = 0; k < values_.size(); ++k) w[k] = values_[k][static_cast<std::size_t>(at[k])];
  return w;
}

WeightRegion WeightGrid::everything() const {
  WeightRegion region;
  region.whole.push_back({{0, 0, 0, 0}, blocks_});
  return region;
}

std::uint64_t WeightGrid::count(const WeightRegion& region) const {
  std::uint64_t n = 0;
  for (const WeightRegion::Box& box : region.whole) {
    const BlockSpan span = span_of(box);
    std::uint64_t points = 1;
    for (const int e : span.extent) points *= static_cast<std::uint64_t>(e);
    n += points;
  }
  for (const WeightRegion::Part& part : region.parts) {
    for (const std::uint64_t word : part.bits) n += static_cast<std::uint64_t>(std::popcount(word));
  }
  return n;
}

std::array<int, WeightGrid::kMaxWeights> WeightGrid::lexmin(const WeightRegion& region) const {
  if (region.empty()) throw std::invalid_argument("lexmin of an empty weight region");
  std::array<int, kMaxWeights> best{};
  bool found = false;
  // Within a block the first point in bit order is its smallest; across blocks compare them.
  const auto offer = [&](const std::array<int, kMaxWeights>& at) {
    if (!found || at < best) best = at;
    found = true;
  };
  for (const WeightRegion::Box& box : region.whole) offer(span_of(box).first);
  for (const WeightRegion::Part& part : region.parts) {
    const auto word =
        std::find_if(part.bits.begin(), part.bits.end(), [](std::uint64_t w) { return w != 0; });
    if (word == part.bits.end()) continue;
    BlockBits first{};
    first[static_cast<std::size_t>(word - part.bits.begin())] = *word & (~*word + 1);  // its lowest bit
    for_each_member(span_of(part.block), first,
                    [&](int /*bit*/, const std::array<int, kMaxWeights>& at) { offer(at); });
  }
  return best;
}

std::vector<WeightGrid::IndexBox> WeightGrid::index_boxes(const WeightRegion& region) const {
  std::vector<IndexBox> out;
  for (const WeightRegion::Box& box : region.whole) {
    const BlockSpan span = span_of(box);
    IndexBox& b = out.emplace_back();
    for (std::size_t k = 0; k < kMaxWeights; ++k) {
      b.lo[k] = span.first[k];
      b.hi[k] = span.first[k] + span.extent[k] - 1;
    }
  }
  const std::size_t last = static_cast<std::size_t>(weights()) - 1;
  std::vector<IndexBox> runs;
  for (const WeightRegion::Part& part : region.parts) {
    runs.clear();
    for_each_member(span_of(part.block), part.bits, [&](int /*bit*/, const std::array<int, kMaxWeights>& at) {
      if (!runs.empty()) {
        IndexBox& run = runs.back();
        bool extends = at[last] == run.hi[last] + 1;
        for (std::size_t k = 0; k < last && extends; ++k) extends = at[k] == run.lo[k];
        if (extends) {
          run.hi[last] = at[last];
          return;
        }
      }
      runs.push_back({at, at});
    });
    // Runs that differ only along one weight, where they touch, are one box: a share of a block
    // cut by a few planes takes a few boxes instead of a run per row.
    for (std::size_t k = last; k-- > 0;) join_along(runs, k);
    out.insert(out.end(), runs.begin(), runs.end());
  }
  return out;
}

void WeightGrid::join_along(std::vector<IndexBox>& boxes, std::size_t k) {
  const auto others = [k](const IndexBox& b) {
    std::array<int, std::size_t{2} * kMaxWeights> key{};
    for (std::size_t d = 0; d < kMaxWeights; ++d) {
      key[2 * d] = d == k ? 0 : b.lo[d];
      key[2 * d + 1] = d == k ? 0 : b.hi[d];
    }
    return key;
  };
  std::sort(boxes.begin(), boxes.end(), [&](const IndexBox& a, const IndexBox& b) {
    const auto ka = others(a);
    const auto kb = others(b);
    return ka != kb ? ka < kb : a.lo[k] < b.lo[k];
  });
  std::size_t kept = 0;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    if (kept > 0 && boxes[kept - 1].hi[k] + 1 == boxes[i].lo[k] &&
        others(boxes[kept - 1]) == others(boxes[i])) {
      boxes[kept - 1].hi[k] = boxes[i].hi[k];
    } else {
      boxes[kept++] = boxes[i];
    }
  }
  boxes.resize(kept);
}

std::array<std::array<int, 2>, WeightGrid::kMaxWeights> WeightGrid::bounds(const WeightRegion& region) const {
  if (region.empty()) throw std::invalid_argument("bounds of an empty weight region");
  std::array<std::array<int, 2>, kMaxWeights> box{};
  bool found = false;
  const auto offer = [&](const std::array<int, kMaxWeights>& lo, const std::array<int, kMaxWeights>& hi) {
    for (std::size_t k = 0; k < kWeights; ++k) {
      box[k][0] = found ? std::min(box[k][0], lo[k]) : lo[k];
      box[k][1] = found ? std::max(box[k][1], hi[k]) : hi[k];
    }
    found = true;
  };
  for (const WeightRegion::Box& box : region.whole) {
    const BlockSpan span = span_of(box);
    std::array<int, kMaxWeights> hi{};
    for (std::size_t k = 0; k < kWeights; ++k) hi[k] = span.first[k] + span.extent[k] - 1;
    offer(span.first, hi);
  }
  for (const WeightRegion::Part& part : region.parts) {
    const BlockSpan span = span_of(part.block, part.bits);
    std::array<int, kMaxWeights> hi{};
    for (std::size_t k = 0; k < kWeights; ++k) hi[k] = span.first[k] + span.extent[k] - 1;
    offer(span.first, hi);
  }
  return box;
}

bool WeightGrid::holds(const WeightRegion& region) const {
  for (const WeightRegion::Box& box : region.whole) {
    for (std::size_t k = 0; k < kWeights; ++k) {
      if (box.lo[k] >= box.hi[k] || box.hi[k] > blocks_[k]) return false;
    }
  }
  for (std::size_t i = 0; i < region.parts.size(); ++i) {
    const WeightRegion::Part& part = region.parts[i];
    if (part.block >= block_count_ || (i > 0 && part.block <= region.parts[i - 1].block)) return false;
    const BlockBits grid_points = all_bits(span_of(part.block));
    bool any = false;
    for (std::size_t w = 0; w < part.bits.size(); ++w) {
      if ((part.bits[w] & ~grid_points[w]) != 0) return false;
      any = any || part.bits[w] != 0;
    }
    if (!any) return false;
  }
  return true;
}

bool WeightGrid::contains(const WeightRegion& region, const std::array<int, kMaxWeights>& at) const {
  for (std::size_t k = 0; k < kWeights; ++k) {
    const int size = k < values_.size() ? static_cast<int>(values_[k].size()) : 1;
    if (at[k] < 0 || at[k] >= size) return false;
  }
  for (const WeightRegion::Box& box : region.whole) {
    bool inside = true;
    for (std::size_t k = 0; k < kWeights; ++k) {
      const auto c = static_cast<std::uint32_t>(k < values_.size() ? at[k] / kBlockEdge : 0);
      inside = inside && box.lo[k] <= c && c < box.hi[k];
    }
    if (inside) return true;
  }
  const std::uint32_t block = block_of(at);
  const auto part =
      std::lower_bound(region.parts.begin(), region.parts.end(), block,
                       [](const WeightRegion::Part& p, std::uint32_t b) { return p.block < b; });
  if (part == region.parts.end() || part->block != block) return false;
  std::array<int, kMaxWeights> local{};
  for (std::size_t k = 0; k < kWeights; ++k) local[k] = at[k] % kBlockEdge;
  return has_point(part->bits, bit_of(local));
}

WeightRegion WeightGrid::shard(std::uint64_t index, std::uint64_t count) const {
  if (count == 0 || index >= count) {
    throw std::invalid_argument("WeightGrid::shard: shard " + std::to_string(index) + " of " +
                                std::to_string(count));
  }
  const std::uint64_t blocks = block_count_;
  std::uint64_t at = index * blocks / count;  // as shard_blocks() counts them
  const std::uint64_t end = at + shard_blocks(blocks, index, count);
  // Block numbers are mixed-radix digits (weight 0 most significant): from `at`, take the
  // longest run of whole sub-boxes that fits, along the most significant weight whose less
  // significant digits are all 0 at `at`.
  std::array<std::uint64_t, kWeights> stride{};
  std::uint64_t s = 1;
  for (std::size_t k = kWeights; k-- > 0;) {
    stride[k] = s;
    s *= blocks_[k];
  }
  WeightRegion out;
  while (at < end) {
    std::size_t level = kWeights - 1;
    while (level > 0 && at % stride[level - 1] == 0 && at + stride[level - 1] <= end) --level;
    WeightRegion::Box box;
    std::uint64_t rest = at;
    for (std::size_t k = 0; k < kWeights; ++k) {
      const auto digit = static_cast<std::uint32_t>((rest / stride[k]) % blocks_[k]);
      box.lo[k] = k <= level ? digit : 0;
      box.hi[k] = k < level ? digit + 1 : blocks_[k];
    }
    const std::uint64_t run =
        std::min<std::uint64_t>(blocks_[level] - box.lo[level], (end - at) / stride[level]);
    box.hi[level] = box.lo[level] + static_cast<std::uint32_t>(run);
    out.whole.push_back(box);
    at += run * stride[level];
  }
  return out;
}

WeightRegion WeightGrid::united(const WeightRegion& a, const WeightRegion& b) {
  WeightRegion out = a;
  out.whole.insert(out.whole.end(), b.whole.begin(), b.whole.end());
  out.parts.insert(out.parts.end(), b.parts.begin(), b.parts.end());
  std::inplace_merge(
      out.parts.begin(), out.parts.begin() + static_cast<std::ptrdiff_t>(a.parts.size()), out.parts.end(),
      [](const WeightRegion::Part& x, const WeightRegion::Part& y) { return x.block < y.block; });
  return out;
}

template <typename BoxOf, typename PointOf>
WeightDirections WeightGrid::directions_in(const WeightRegion& region, std::size_t n, const BoxOf& box_of,
                                           const PointOf& point_of) const {
  WeightDirections d;
  d.lo.fill(1.0);
  d.hi.fill(0.0);
  d.zero = false;
  d.nonzero = false;
  std::array<double, kMaxWeights> lo{};
  std::array<double, kMaxWeights> hi{};
  std::array<double, kMaxWeights> low{};
  std::array<double, kMaxWeights> high{};
  for (const WeightRegion::Box& box : region.whole) {
    span_values(span_of(box), lo, hi);
    const bool zero = box_of(lo, hi, low, high);
    d.zero = d.zero || zero;
    // Every ratio's highest is 0 only where every coordinate is: the zero point alone.
    if (zero && std::all_of(high.begin(), high.begin() + static_cast<std::ptrdiff_t>(n),
                            [](double x) { return x == 0.0; })) {
      continue;
    }
    d.nonzero = true;
    for (std::size_t k = 0; k < n; ++k) {
      d.lo[k] = std::min(d.lo[k], low[k]);
      d.hi[k] = std::max(d.hi[k], high[k]);
    }
  }
  // A part whose members' span has its directions (and its zero point, if any) within those
  // found so far cannot widen them: its points are not visited. In a large region, its boxes'
  // directions hold most of its parts'.
  const auto within_so_far = [&](const WeightRegion::Part& part) {
    if (!d.nonzero) return false;
    span_values(span_of(part.block, part.bits), lo, hi);
    if (box_of(lo, hi, low, high) && !d.zero) return false;
    for (std::size_t k = 0; k < n; ++k) {
      if (low[k] < d.lo[k] || high[k] > d.hi[k]) return false;
    }
    return true;
  };
  for (const WeightRegion::Part& part : region.parts) {
    if (within_so_far(part)) continue;
    for_each_member(span_of(part.block), part.bits, [&](int /*bit*/, const std::array<int, kMaxWeights>& at) {
      for (std::size_t k = 0; k < values_.size(); ++k) lo[k] = values_[k][static_cast<std::size_t>(at[k])];
      const std::array<double, kMaxWeights> point = point_of(lo);
      take_direction(d, std::span(point).first(n));
    });
  }
  widen(d, n);
  return d;
}

WeightDirections WeightGrid::directions(const WeightRegion& region) const {
  const std::size_t n = values_.size();
  return directions_in(
      region, n,
      [n](const std::array<double, kMaxWeights>& lo, const std::array<double, kMaxWeights>& hi,
          std::array<double, kMaxWeights>& low, std::array<double, kMaxWeights>& high) {
        box_ratios(std::span(lo).first(n), std::span(hi).first(n), low, high);
        return std::all_of(lo.begin(), lo.begin() + static_cast<std::ptrdiff_t>(n),
                           [](double v) { return v == 0.0; });
      },
      [](const std::array<double, kMaxWeights>& w) { return w; });
}

int WeightGrid::sole_choice(const WeightDirections& directions, const Candidates& candidates) const {
  const auto k = static_cast<std::size_t>(candidates.feature_count);
  const std::size_t n = candidates.cells.size();
  if (n == 0 || candidates.feature_count != weights() || candidates.features.size() != n * k) {
    throw std::invalid_argument("weight grid sole_choice: candidates do not match the grid's weights");
  }
  return sole_over(directions, candidates, k,
                   [](std::span<const double>, std::span<const double>) { return 0.0; });
}

int WeightGrid::tied_sign(const Candidates& candidates) {
  if (candidates.feature_count != static_cast<int>(kWeights) || candidates.cells.empty()) return 0;
  bool minus = true;
  bool plus = true;
  for (std::size_t i = 0; i < candidates.cells.size(); ++i) {
    const double f2 = candidates.features[i * kWeights + 1];
    const double f3 = candidates.features[i * kWeights + 2];
    if (!std::isfinite(f2)) return 0;
    minus = minus && f3 == -f2;
    plus = plus && f3 == f2;
  }
  return minus ? -1 : (plus ? 1 : 0);
}

WeightDirections WeightGrid::tied_directions(const WeightRegion& region, int sign) const {
  if (weights() != static_cast<int>(kWeights) || (sign != -1 && sign != 1)) {
    throw std::invalid_argument("weight grid tied_directions: needs 4 weights and a sign of -1 or +1");
  }
  // v of the weights w (each of v's coordinates is exact for integer weights; the widening
  // holds the rounding of others).
  return directions_in(
      region, kWeights,
      [sign](const std::array<double, kWeights>& lo, const std::array<double, kWeights>& hi,
             std::array<double, kWeights>& low,
             std::array<double, kWeights>& high) { return tied_box_ratios(lo, hi, sign, low, high); },
      [sign](const std::array<double, kWeights>& w) {
        const double u = w[1] - w[2];
        return sign < 0 ? std::array<double, kWeights>{w[0], std::max(u, 0.0), std::max(-u, 0.0), w[3]}
                        : std::array<double, kWeights>{w[0], w[1] + w[2], 0.0, w[3]};
      });
}

double WeightGrid::tied_extra(int sign, std::span<const double> f_j, std::span<const double> f_i) const {
  // costs_more_at_every_direction() bounds the rounding by 1e-12 sum_k v_k (|f_jk| + |f_ik|); the
  // costs' own bound is 1e-12 sum_k w_k (|f_jk| + |f_ik|), larger by 2e-12 min(w2, w3)
  // (|f_j2| + |f_i2|) for s = -1 (|f_3| = |f_2|), which per unit of sum(v) is at most this.
  return sign < 0 ? 2e-12 * tied_ratio_ * (std::abs(f_j[1]) + std::abs(f_i[1])) : 0.0;
}

int WeightGrid::sole_choice_tied(const WeightDirections& tied, int sign, const Candidates& candidates) const {
  const std::size_t n = candidates.cells.size();
  if (n == 0 || tied_sign(candidates) != sign || sign == 0) return -1;
  // v . f is w . f for these candidates: the same proof over the directions of v, with the
  // margin for the rounding v does not carry.
  return sole_over(tied, candidates, kWeights, [&](std::span<const double> f_j, std::span<const double> f_i) {
    return tied_extra(sign, f_j, f_i);
  });
}

/// split() for one set of candidates, as named steps. A box of whole blocks (decide_box()) goes
/// whole to one candidate when sole_winner() proves one wins everywhere in it, else its halves
/// are decided, down to single blocks decided point by point (decide_points()); a block held in
/// part is decided the same way over its members' span. The candidates that cannot win in a box
/// cannot win in its halves, so each step narrows the pool it hands on. The buffers live here so
/// that one split allocates them once.
class WeightGrid::Splitter {
 public:
  /// `candidates` checked by split(): at least one, the grid's weight count of features.
  Splitter(const WeightGrid& grid, const Candidates& candidates, const WeightDirections* tied)
      : grid_(grid),
        values_(grid.values_),
        features_(candidates.features),
        k_(static_cast<std::size_t>(candidates.feature_count)),
        n_(static_cast<int>(candidates.cells.size())),
        bounded_(std::all_of(features_.begin(), features_.end(), [](double f) { return std::isfinite(f); })),
        tied_(tied),
        sign_(tied != nullptr && tied->nonzero ? tied_sign(candidates) : 0),
        won_(static_cast<std::size_t>(n_)),
        lo_cost_(static_cast<std::size_t>(n_)),
        hi_cost_(static_cast<std::size_t>(n_)),
        w_lo_(k_),
        w_hi_(k_),
        w_mid_(k_),
        shares_(static_cast<std::size_t>(n_)),
        touched_(static_cast<std::size_t>(n_)) {}

  /// The non-empty shares of `region`, in ascending candidate order.
  std::vector<Share> run(const WeightRegion& region) {
    std::vector<int> everyone(static_cast<std::size_t>(n_));
    for (int i = 0; i < n_; ++i) everyone[static_cast<std::size_t>(i)] = i;
    for (const WeightRegion::Box& box : region.whole) decide_box(box, everyone);
    std::vector<int> among;
    for (const WeightRegion::Part& part : region.parts) {
      const int winner = sole_winner(grid_.span_of(part.block, part.bits), everyone, among);
      if (winner >= 0) {
        won_[static_cast<std::size_t>(winner)].parts.push_back(part);
      } else {
        decide_points(part.block, &part.bits, nullptr, among);
      }
    }
    std::vector<Share> result;
    for (int i = 0; i < n_; ++i) {
      WeightRegion& r = won_[static_cast<std::size_t>(i)];
      if (r.empty()) continue;
      std::sort(r.parts.begin(), r.parts.end(),
                [](const WeightRegion::Part& a, const WeightRegion::Part& b) { return a.block < b.block; });
      result.push_back({i, std::move(r)});
    }
    return result;
  }

 private:
  /// Candidate i's features.
  [[nodiscard]] std::span<const double> features_of(int i) const {
    return features_.subspan(static_cast<std::size_t>(i) * k_, k_);
  }

  /// The candidates of `pool` (ascending) that can win somewhere in `span`, into `among`
  /// (ascending), after corner_test() and prune(); returns the one that wins at every point of
  /// it, or -1.
  int sole_winner(const BlockSpan& span, const std::vector<int>& pool, std::vector<int>& among) {
    int winner = corner_test(span, pool, among);
    if (winner < 0) {
      prune(span, among);
      if (among.size() == 1) winner = among.front();
    }
    return winner;
  }

  /// The candidates of `pool` (ascending) that can win somewhere in `span`, into `among`
  /// (ascending); returns the one that wins at every point of it, or -1. Only the candidate of
  /// the smallest highest cost (lowest index on a tie) can win everywhere; it does when every
  /// other candidate's lowest cost is above its highest, or equal to it and the other comes
  /// later (the tie rule). A candidate whose lowest cost is above that highest cost loses at
  /// every point.
  int corner_test(const BlockSpan& span, const std::vector<int>& pool, std::vector<int>& among) {
    among.clear();
    if (!bounded_) {
      among = pool;
      return -1;
    }
    int first = pool.front();
    for (const int i : pool) {
      const std::span<const double> f = features_of(i);
      for (std::size_t j = 0; j < k_; ++j) {
        const double lo = values_[j][static_cast<std::size_t>(span.first[j])];
        const double hi = values_[j][static_cast<std::size_t>(span.first[j] + span.extent[j] - 1)];
        w_lo_[j] = f[j] >= 0.0 ? lo : hi;
        w_hi_[j] = f[j] >= 0.0 ? hi : lo;
      }
      lo_cost_[static_cast<std::size_t>(i)] = linear_cost(w_lo_, f);
      hi_cost_[static_cast<std::size_t>(i)] = linear_cost(w_hi_, f);
      if (hi_cost_[static_cast<std::size_t>(i)] < hi_cost_[static_cast<std::size_t>(first)]) first = i;
    }
    const double ceiling = hi_cost_[static_cast<std::size_t>(first)];
    bool whole = true;
    for (const int i : pool) {
      if (i == first) {
        among.push_back(i);
        continue;
      }
      const double other = lo_cost_[static_cast<std::size_t>(i)];
      if (other < ceiling || (other == ceiling && i < first)) whole = false;
      if (other <= ceiling) among.push_back(i);
    }
    return whole ? first : -1;
  }

  /// Drops from `among` (ascending) every candidate that `costs_more(f_j, f_i)` proves costs more
  /// than one cheaper at `middle`, or that has exactly the features of an earlier one.
  /// argmin_linear() chooses none of them there: at each point the dropped candidate's cost is
  /// above, or equal to and after, another's, which holds along chains, so argmin_linear() over
  /// the rest chooses what it chooses over all. Each candidate is compared with those cheaper at
  /// the middle, cheapest first: only they can cost less all over the span, and the cheapest
  /// mostly does. (Which pairs are compared only decides how many candidates go; each one that
  /// goes is proven.)
  template <typename CostsMore>
  void prune_by(std::span<const double> middle, const CostsMore& costs_more, std::vector<int>& among) {
    by_middle_.clear();
    for (const int i : among) by_middle_.emplace_back(linear_cost(middle, features_of(i)), i);
    std::sort(by_middle_.begin(), by_middle_.end());
    std::vector<int> kept;
    for (std::size_t at = 0; at < by_middle_.size(); ++at) {
      const int j = by_middle_[at].second;
      const std::span<const double> fj = features_of(j);
      const bool beaten =
          std::any_of(by_middle_.begin(), by_middle_.begin() + static_cast<std::ptrdiff_t>(at),
                      [&](const std::pair<double, int>& cheaper) {
                        const int i = cheaper.second;
                        const std::span<const double> fi = features_of(i);
                        if (std::equal(fj.begin(), fj.end(), fi.begin())) return i < j;
                        return costs_more(fj, fi);
                      });
      if (!beaten) kept.push_back(j);
    }
    std::sort(kept.begin(), kept.end());
    among = std::move(kept);
  }

  /// Drops from `among` the candidates that provably cost more than another of `among` at every
  /// weight vector of `span` (costs_more_at_every_weight()): unlike corner_test(), which compares
  /// each candidate's whole range of costs over the span, this compares the difference of two
  /// costs, which stays positive along a narrow cone. With tied candidates (tied_sign()) and the
  /// region's tied directions, the span is also proven in their coordinates, over the
  /// directions of v within both the region's and the span's.
  void prune(const BlockSpan& span, std::vector<int>& among) {
    if (!bounded_ || among.size() < 2) return;
    for (std::size_t j = 0; j < k_; ++j) {
      w_lo_[j] = values_[j][static_cast<std::size_t>(span.first[j])];
      w_hi_[j] = values_[j][static_cast<std::size_t>(span.first[j] + span.extent[j] - 1)];
      w_mid_[j] = 0.5 * (w_lo_[j] + w_hi_[j]);
    }
    prune_by(
        w_mid_,
        [&](std::span<const double> fj, std::span<const double> fi) {
          return costs_more_at_every_weight(fj, fi, w_lo_, w_hi_);
        },
        among);
    if (among.size() < 2 || sign_ == 0) return;
    WeightDirections within;
    within.zero = false;
    if (tied_box_ratios(w_lo_, w_hi_, sign_, within.lo, within.hi)) return;  // v may be 0 here
    for (std::size_t j = 0; j < k_; ++j) {
      within.lo[j] = std::max(within.lo[j] - 1e-14, tied_->lo[j]);
      within.hi[j] = std::min(within.hi[j] + 1e-14, tied_->hi[j]);
      w_mid_[j] = 0.5 * (within.lo[j] + within.hi[j]);
    }
    prune_by(
        w_mid_,
        [&](std::span<const double> fj, std::span<const double> fi) {
          return costs_more_at_every_direction(fj, fi, within, grid_.tied_extra(sign_, fj, fi));
        },
        among);
  }

  /// A box of whole blocks: whole to one candidate if one wins everywhere in it, else its two
  /// halves (along its widest side), down to single blocks decided point by point.
  void decide_box(const WeightRegion::Box& box, const std::vector<int>& pool) {
    std::vector<int> among;
    const int winner = sole_winner(grid_.span_of(box), pool, among);
    if (winner >= 0) {
      won_[static_cast<std::size_t>(winner)].whole.push_back(box);
      return;
    }
    std::size_t widest = 0;
    for (std::size_t j = 1; j < kWeights; ++j) {
      if (box.hi[j] - box.lo[j] > box.hi[widest] - box.lo[widest]) widest = j;
    }
    const std::uint32_t width = box.hi[widest] - box.lo[widest];
    if (width == 1) return decide_points(grid_.block_at(box.lo), nullptr, &box, among);
    WeightRegion::Box low = box;
    WeightRegion::Box high = box;
    low.hi[widest] = box.lo[widest] + width / 2;
    high.lo[widest] = low.hi[widest];
    decide_box(low, among);
    decide_box(high, among);
  }

  /// Block `block` (its member points `member`, all when null, and then `box` is the block as a
  /// box), point by point by argmin_linear's own rule over the candidates `among`. (Deciding its
  /// cubes of 4^4 and 2^4 points by corner tests first took twice as long on the free-space
  /// search: with many candidates a corner test costs more than the points it saves.) The costs
  /// are argmin_linear()'s own: linear_cost() adds w_j * F_j to 0.0 in feature order, so the
  /// partial sums over the first weights are computed once per value of them (add_term()) and
  /// the last term is added per point: the same operations on the same doubles, in the same
  /// order. Only the rows (points along the last weight: one byte of the bits) that hold members
  /// are visited, so a block with few members costs what they cost.
  void decide_points(std::uint32_t block, const BlockBits* member, const WeightRegion::Box* box,
                     const std::vector<int>& among) {
    const BlockSpan span = grid_.span_of(block);
    const BlockBits points = member == nullptr ? grid_.all_bits(span) : *member;
    start_points(among);
    int summed_l0 = -1;
    static_assert(kBlockEdge == 8);
    for (std::size_t word = 0; word < points.size(); ++word) {
      const std::uint64_t rows = points[word];
      if (rows == 0) continue;
      // A word holds the 64 points of one (local[0], local[1]) (bit_of()).
      const int l0 = static_cast<int>(word >> 3);
      const int l1 = static_cast<int>(word & 7);
      if (l0 != summed_l0) add_term(0, span.first[0] + l0);
      summed_l0 = l0;
      add_term(1, span.first[1] + l1);
      for (int l2 = 0; l2 < kBlockEdge; ++l2) {
        const auto row = static_cast<unsigned>(rows >> static_cast<unsigned>(8 * l2)) & 0xFFU;
        if (row == 0) continue;
        add_term(2, span.first[2] + l2);
        decide_row(span, static_cast<int>(word * 64) + 8 * l2, row, among);
      }
    }
    emit(block, points, box, among);
  }

  /// Clears the shares of `among` and lays out their features by feature (among_features_[j *
  /// m + c]) for the sums over every point, with partial sums of 0.
  void start_points(const std::vector<int>& among) {
    const std::size_t m = among.size();
    for (const int i : among) {
      shares_[static_cast<std::size_t>(i)] = BlockBits{};
      touched_[static_cast<std::size_t>(i)] = 0;
    }
    among_features_.resize(m * kWeights);
    for (std::size_t c = 0; c < m; ++c) {
      for (std::size_t j = 0; j < k_; ++j) {
        among_features_[j * m + c] = features_[static_cast<std::size_t>(among[c]) * k_ + j];
      }
    }
    for (auto& p : partial_) p.assign(m, 0.0);
  }

  /// partial_[j + 1] = partial_[j] + w * F_j for each candidate, w weight j's value `index`
  /// (feature j unused: unchanged). partial_[j]: the sum of the first j terms.
  void add_term(std::size_t j, int index) {
    if (j >= k_) {
      partial_[j + 1] = partial_[j];
      return;
    }
    const std::size_t m = partial_[j].size();
    const double wj = values_[j][static_cast<std::size_t>(index)];
    const double* f = &among_features_[j * m];
    for (std::size_t c = 0; c < m; ++c) partial_[j + 1][c] = partial_[j][c] + wj * f[c];
  }

  /// The points of one row (its bits `row`, of bits first_bit..first_bit + 7, along the last
  /// weight), the first three terms summed in partial_[3].
  void decide_row(const BlockSpan& span, int first_bit, unsigned row, const std::vector<int>& among) {
    const std::size_t m = among.size();
    const double* base = partial_[3].data();
    if (k_ < kWeights) {
      // No fourth weight: the row is its one point, and partial_[3] its costs.
      std::size_t best = 0;
      for (std::size_t c = 1; c < m; ++c) {
        if (base[c] < base[best]) best = c;  // argmin_linear's strict '<'
      }
      decided(first_bit, among[best]);
      return;
    }
    if (std::popcount(row) >= 3) return decide_full_row(span, first_bit, row, among);
    const double* f3 = &among_features_[3 * m];
    const std::span<const double> last(values_[3]);
    for (unsigned rest = row; rest != 0; rest &= rest - 1) {
      const int l3 = std::countr_zero(rest);
      const double w = last[static_cast<std::size_t>(span.first[3]) + static_cast<std::size_t>(l3)];
      std::size_t best = 0;
      double best_cost = base[0] + w * f3[0];
      for (std::size_t c = 1; c < m; ++c) {
        const double cost = base[c] + w * f3[c];
        if (cost < best_cost) {  // argmin_linear's strict '<': a tie keeps the earlier one
          best = c;
          best_cost = cost;
        }
      }
      decided(first_bit + l3, among[best]);
    }
  }

  /// A row of three or more members: its (up to) 8 points at once, candidate by candidate, each
  /// point's running best, with decide_row()'s sums and comparisons, in an order the compiler can
  /// vectorise.
  void decide_full_row(const BlockSpan& span, int first_bit, unsigned row, const std::vector<int>& among) {
    const std::size_t m = among.size();
    const double* base = partial_[3].data();
    const double* f3 = &among_features_[3 * m];
    std::array<double, kBlockEdge> w{};
    const std::span<const double> values =
        std::span<const double>(values_[3])
            .subspan(static_cast<std::size_t>(span.first[3]), static_cast<std::size_t>(span.extent[3]));
    std::copy(values.begin(), values.end(), w.begin());
    std::array<double, kBlockEdge> best_cost{};
    std::array<double, kBlockEdge> best_at{};  // candidate positions, exact as doubles
    for (std::size_t p = 0; p < kBlockEdge; ++p) best_cost[p] = base[0] + w[p] * f3[0];
    for (std::size_t c = 1; c < m; ++c) {
      const double at = static_cast<double>(c);
      for (std::size_t p = 0; p < kBlockEdge; ++p) {
        const double cost = base[c] + w[p] * f3[c];
        const bool better = cost < best_cost[p];  // strict: a tie keeps the earlier one
        best_cost[p] = better ? cost : best_cost[p];
        best_at[p] = better ? at : best_at[p];
      }
    }
    for (unsigned rest = row; rest != 0; rest &= rest - 1) {
      const auto l3 = static_cast<std::size_t>(std::countr_zero(rest));
      decided(first_bit + static_cast<int>(l3), among[static_cast<std::size_t>(best_at[l3])]);
    }
  }

  /// Point `bit` of the block being decided goes to `candidate`.
  void decided(int bit, int candidate) {
    const auto winner = static_cast<std::size_t>(candidate);
    set_bit(shares_[winner], bit);
    touched_[winner] = 1;
  }

  /// The shares of a block decided point by point (its points `full`; `box`: the block as a box
  /// when it was held whole), to the candidates' regions.
  void emit(std::uint32_t block, const BlockBits& full, const WeightRegion::Box* box,
            const std::vector<int>& among) {
    for (const int i : among) {
      if (touched_[static_cast<std::size_t>(i)] == 0) continue;
      WeightRegion& to = won_[static_cast<std::size_t>(i)];
      if (shares_[static_cast<std::size_t>(i)] == full && box != nullptr) {
        to.whole.push_back(*box);
      } else {
        to.parts.push_back({block, shares_[static_cast<std::size_t>(i)]});
      }
    }
  }

  const WeightGrid& grid_;
  const std::vector<std::vector<double>>& values_;
  const std::span<const double> features_;
  const std::size_t k_;
  const int n_;
  const bool bounded_;
  const WeightDirections* tied_;
  const int sign_;
  /// Per candidate, the region it wins.
  std::vector<WeightRegion> won_;
  std::vector<double> lo_cost_;
  std::vector<double> hi_cost_;
  std::vector<double> w_lo_;
  std::vector<double> w_hi_;
  std::vector<double> w_mid_;
  std::vector<std::pair<double, int>> by_middle_;
  /// The block being decided point by point: each candidate's points, and whether it has any.
  std::vector<BlockBits> shares_;
  std::vector<std::uint8_t> touched_;
  std::array<std::vector<double>, kWeights + 1> partial_;
  std::vector<double> among_features_;
};

std::vector<WeightGrid::Share> WeightGrid::split(const WeightRegion& region, const Candidates& candidates,
                                                 const WeightDirections* tied) const {
  const auto n = candidates.cells.size();
  const auto k = static_cast<std::size_t>(candidates.feature_count);
  if (n == 0 || candidates.feature_count != weights() || candidates.features.size() != n * k) {
    throw std::invalid_argument("weight grid split: candidates do not match the grid's weights");
  }
  return Splitter(*this, candidates, tied).run(region);
}

}  // namespace weightsearch
}  // namespace fsweep
