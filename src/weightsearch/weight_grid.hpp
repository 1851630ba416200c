#pragma once
/// @file weight_grid.hpp
/// Sets of weight vectors for the exact weight search (docs/dev/architecture.md, "The exact weight
/// search"): a WeightGrid is the product of one sorted list of values per weight (e.g. the
/// integers 0..250 four times), a WeightRegion any subset of its points, and
/// WeightGrid::split() divides a region by which candidate argmin_linear() chooses at each of
/// its points.
///
/// Exact by construction: a point goes to the candidate that argmin_linear() itself chooses for
/// those weights, the same function on the same doubles as a run with those weights alone.
/// Points are stored in blocks of 8 values per weight (8^4 = 4,096 points for four weights);
/// a block is decided whole, without looking at its points, when one candidate provably wins at
/// all of them: with finite features, each product w_k * F_k rounds monotonically in w_k
/// (increasing for F_k >= 0, decreasing for F_k < 0) and so does each sum, so linear_cost() over a
/// block lies between its values at two corners of the block (chosen per feature by its sign),
/// bit for bit. Candidates that provably cost more than another over a block or a partial
/// block's span (costs_more_at_every_weight(), the box form of the proofs by direction) are
/// left out of it. A block that no candidate wins whole is decided point by point.

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "strategies/strategy.hpp"

namespace fsweep {
inline namespace weightsearch {

/// Points of one block of a WeightGrid, as bits (bit = local index, see WeightGrid).
using BlockBits = std::array<std::uint64_t, 64>;

/// True when point `bit` of a block is in `bits`.
[[nodiscard]] inline bool has_point(const BlockBits& bits, int bit) {
  return ((bits[static_cast<std::size_t>(bit) / 64] >> (static_cast<unsigned>(bit) % 64)) & 1U) != 0;
}

/// The points of `bits` as run lengths in bit order, alternating points out and points in,
/// starting with points out (that first run may be 0) and ending with the last run of points in
/// (no runs: no point). A behaviour's share of a block is the block cut by half-spaces, so it
/// takes a few runs where the 64 words take 1,024 hexadecimal digits: journal lines keep parts so.
[[nodiscard]] std::vector<std::uint32_t> point_runs(const BlockBits& bits);
/// The points of runs written by point_runs(). Throws std::invalid_argument when `runs` is not
/// such a list (a run but the first of 0, an odd count, or more than 4,096 points).
[[nodiscard]] BlockBits bits_of_runs(std::span<const std::uint32_t> runs);

/// A set of points of a WeightGrid: boxes of blocks it holds whole (every grid point of every
/// block of the box) and blocks it holds in part, the latter in ascending block order. A box
/// keeps a large uniform share (the whole [0, 250]^4 is one box of 32^4 blocks) in one entry,
/// so a split costs what the boundaries between its shares cost, not the region's volume.
struct WeightRegion {
  /// Blocks with block coordinates lo[k] <= c < hi[k] along each weight (unused weights: 0, 1).
  struct Box {
    std::array<std::uint32_t, 4> lo{};
    std::array<std::uint32_t, 4> hi{};
  };
  struct Part {
    std::uint32_t block = 0;
    BlockBits bits{};
  };
  std::vector<Box> whole;
  std::vector<Part> parts;
  [[nodiscard]] bool empty() const { return whole.empty() && parts.empty(); }
};

/// The product of sorted value lists, one per weight (1 to 4 weights).
class WeightGrid {
 public:
  static constexpr int kMaxWeights = 4;
  /// Values per weight along one edge of a block.
  static constexpr int kBlockEdge = 8;
  /// Most blocks of a grid (a block's number is 32 bits wide).
  static constexpr std::uint64_t kMaxBlocks = std::uint64_t{1} << 31;
  /// Most blocks one process searches (4 times the full [0, 250]^4's 32^4; a shard searches its
  /// part of them): a decision over a whole box splits it into parts block by block, and holds
  /// memory in proportion to its blocks before a search can stop.
  static constexpr std::uint64_t kMaxSearchBlocks = std::uint64_t{1} << 22;
  /// The blocks of shard `index` of `count` (shard()), of a grid of `blocks` blocks.
  [[nodiscard]] static std::uint64_t shard_blocks(std::uint64_t blocks, std::uint64_t index,
                                                  std::uint64_t count);

  /// The blocks of the grid of `values` (each weight's count of values), saturating at 2^64 - 1.
  [[nodiscard]] static std::uint64_t blocks_of(const std::vector<std::vector<double>>& values);

  /// `values[k]`: the values of weight k, strictly ascending, finite and >= 0, at least one.
  /// Throws std::invalid_argument otherwise.
  explicit WeightGrid(std::vector<std::vector<double>> values);

  [[nodiscard]] int weights() const { return static_cast<int>(values_.size()); }
  [[nodiscard]] std::span<const double> values(int k) const { return values_[static_cast<std::size_t>(k)]; }
  /// Points of the grid (the product of the list sizes).
  [[nodiscard]] std::uint64_t size() const { return size_; }
  /// Blocks of kBlockEdge values per weight (fewer at the grid's end): what shard() divides.
  [[nodiscard]] std::uint64_t block_count() const { return block_count_; }

  /// The region of every point.
  [[nodiscard]] WeightRegion everything() const;
  /// Points in `region`.
  [[nodiscard]] std::uint64_t count(const WeightRegion& region) const;
  /// The lexicographically smallest point of a non-empty region (by weight 0, then 1, ...), as
  /// indices into the value lists.
  [[nodiscard]] std::array<int, kMaxWeights> lexmin(const WeightRegion& region) const;
  /// Per weight, the smallest and largest index of the region's points (non-empty region).
  [[nodiscard]] std::array<std::array<int, 2>, kMaxWeights> bounds(const WeightRegion& region) const;
  /// True when `region` is a region of this grid: every box non-empty and within its blocks,
  /// parts in strictly ascending block order, each with points only on grid points of its
  /// block, and at least one. (Not checked: that boxes and parts share no block.) A journal line
  /// read back is checked so before its region is used.
  [[nodiscard]] bool holds(const WeightRegion& region) const;
  /// A box of grid points by their indices into the value lists, `lo[k]` to `hi[k]` inclusive
  /// along each weight (unused weights: 0 to 0).
  struct IndexBox {
    std::array<int, kMaxWeights> lo{};
    std::array<int, kMaxWeights> hi{};
  };
  /// `region` as disjoint boxes of grid indices: each box of whole blocks as one, each part as
  /// its runs of consecutive points along the last weight, joined into larger boxes where runs
  /// differ only along one weight and touch there (the weight search's certificate lists
  /// regions so, for a reader who knows nothing of blocks).
  [[nodiscard]] std::vector<IndexBox> index_boxes(const WeightRegion& region) const;
  /// True when the point of indices `at` is in `region`.
  [[nodiscard]] bool contains(const WeightRegion& region, const std::array<int, kMaxWeights>& at) const;
  /// Calls `f(indices)` for every point of `region` once: the blocks of its boxes, then its
  /// parts; within a block lexicographically.
  template <typename F>
  void for_each_point(const WeightRegion& region, F&& f) const;
  /// Calls `f(index_a, index_b)` for the indices of weights a and b of every point of `region`
  /// (a pair may come more than once): a box of whole blocks as the rectangle of its span,
  /// without visiting its points (heat maps over weight pairs of the full box).
  template <typename F>
  void for_each_projection(const WeightRegion& region, int a, int b, F&& f) const;
  /// Shard `index` of `count` (0 <= index < count): the blocks whose block number (weight 0's
  /// block coordinate most significant) lies in [index * B / count, (index + 1) * B / count), B
  /// the grid's block count, as a few boxes. The shards of one count are disjoint block by block
  /// and together are everything(); a shard may be empty when count > B. Throws
  /// std::invalid_argument for an index outside [0, count).
  [[nodiscard]] WeightRegion shard(std::uint64_t index, std::uint64_t count) const;
  /// The union of regions that share no block (e.g. of different shards); their boxes, then
  /// their parts in block order.
  [[nodiscard]] static WeightRegion united(const WeightRegion& a, const WeightRegion& b);
  /// The weight vector of the point of indices `at`.
  [[nodiscard]] std::vector<double> weights_at(const std::array<int, kMaxWeights>& at) const;

  /// The directions of a region's points (WeightDirections), their bounds widened outward by
  /// 1e-14 so that they hold the exact ratios, which rounding may miss by a few units in the
  /// last place.
  [[nodiscard]] WeightDirections directions(const WeightRegion& region) const;
  /// The candidate argmin_linear() chooses at every point of a region whose directions are
  /// `directions`, when that can be proven without visiting its points: each other candidate
  /// costs more at every direction (costs_more_at_every_direction()) or has exactly its
  /// features and comes later (an exact tie, which the first wins); at the zero vector every
  /// cost is 0 and the first candidate wins. -1 otherwise (the region may still have one
  /// choice: split() tells). `candidates` must have at least one candidate and weights()
  /// features.
  [[nodiscard]] int sole_choice(const WeightDirections& directions, const Candidates& candidates) const;

  /// Tied features. When every candidate's third feature is s times its second (s = -1 or +1,
  /// as the energy-aware strategy's d_gbe = -d_gb above half charge and +d_gb below), a cost is
  /// w1 f1 + (w2 + s w3) f2 + w4 f4: it depends on w2 + s w3, not on w2 and w3 apart, and a
  /// region is a slab along (0, 1, -s, 0) whose directions w / sum(w) no box follows. In the
  /// coordinates v = (w1, max(w2 - w3, 0), max(w3 - w2, 0), w4) (s = -1) or (w1, w2 + w3, 0, w4)
  /// (s = +1), v . f = w . f for such candidates, and a region's directions v / sum(v) are narrow.
  /// The sign s of `candidates` (4 features), or 0 when they are not tied so.
  [[nodiscard]] static int tied_sign(const Candidates& candidates);
  /// The directions v / sum(v) of the region's points in the coordinates of tied sign `sign`
  /// (widened by 1e-14, as directions()); `zero`: some point has v = 0, where every tied
  /// candidate's cost is exactly 0 (for s = -1: w1 = w4 = 0 and w2 = w3, where w2 f2 and
  /// w3 (-f2) cancel exactly). Needs 4 weights.
  [[nodiscard]] WeightDirections tied_directions(const WeightRegion& region, int sign) const;
  /// sole_choice() for candidates of tied_sign() `sign` != 0, by the region's
  /// tied_directions(): each other candidate costs more at every direction of v, by
  /// costs_more_at_every_direction() with an extra margin for the rounding that v does not
  /// carry (for s = -1 the costs' rounding grows with w2 + w3 = |w2 - w3| + 2 min(w2, w3), and
  /// min(w2, w3) / sum(v) is at most tied_ratio()). -1 when not proven.
  [[nodiscard]] int sole_choice_tied(const WeightDirections& tied, int sign,
                                     const Candidates& candidates) const;
  /// An upper bound of min(w2, w3) / (w1 + |w2 - w3| + w4) over the grid's points where the
  /// denominator is not 0 (the largest w2 or w3 over the smallest positive value it can take).
  [[nodiscard]] double tied_ratio() const { return tied_ratio_; }
  /// The extra margin (costs_more_at_every_direction()) of a claim about candidates f_j, f_i of
  /// tied sign `sign` over directions of v: 2e-12 tied_ratio() (|f_j2| + |f_i2|) for s = -1, else 0.
  [[nodiscard]] double tied_extra(int sign, std::span<const double> f_j, std::span<const double> f_i) const;

  /// One part of a split: the points where candidate `candidate` is argmin_linear's choice.
  struct Share {
    int candidate = 0;
    WeightRegion region;
  };
  /// `region` divided by argmin_linear(candidates, w) at each of its points w: the non-empty
  /// shares in ascending candidate order. `candidates` must have at least one candidate and
  /// weights() features.
  /// `tied`, when given, must be the region's tied_directions() for the candidates'
  /// tied_sign(): a block then also rules out candidates in those coordinates (over the
  /// directions of v within both the region's and the block's span), which decides most blocks
  /// on the boundary of a slab-shaped region without visiting their points.
  [[nodiscard]] std::vector<Share> split(const WeightRegion& region, const Candidates& candidates,
                                         const WeightDirections* tied = nullptr) const;

 private:
  /// split()'s steps (weight_grid.cpp).
  class Splitter;
  /// The first grid index of a block or box along each weight, and the number of grid values it
  /// spans there (kBlockEdge per block, fewer at the grid's end).
  struct BlockSpan {
    std::array<int, kMaxWeights> first{};
    std::array<int, kMaxWeights> extent{};
  };
  [[nodiscard]] BlockSpan span_of(std::uint32_t block) const;
  /// Joins boxes of `boxes` that differ only along weight `k` and touch there (index_boxes()).
  static void join_along(std::vector<IndexBox>& boxes, std::size_t k);
  /// The directions of `region`'s points in n coordinates (w itself, or the tied coordinates):
  /// `box_of(lo, hi, low, high)` puts the extreme ratios of a box of weights lo..hi into
  /// low..high and returns whether some point of it may have every coordinate 0;
  /// `point_of(w)` gives a point's coordinates. Widened as directions() says.
  template <typename BoxOf, typename PointOf>
  [[nodiscard]] WeightDirections directions_in(const WeightRegion& region, std::size_t n, const BoxOf& box_of,
                                               const PointOf& point_of) const;
  /// The lowest and highest value of each weight over `span`.
  void span_values(const BlockSpan& span, std::array<double, kMaxWeights>& lo,
                   std::array<double, kMaxWeights>& hi) const;
  [[nodiscard]] BlockSpan span_of(const WeightRegion::Box& box) const;
  /// The smallest span holding the points `bits` (at least one) of block `block`, from the
  /// bits' words without visiting the points.
  [[nodiscard]] BlockSpan span_of(std::uint32_t block, const BlockBits& bits) const;
  /// The block of block coordinates `c`.
  [[nodiscard]] std::uint32_t block_at(const std::array<std::uint32_t, kMaxWeights>& c) const;
  /// Calls `f(block)` for every block of `box`.
  template <typename F>
  void for_each_block(const WeightRegion::Box& box, F&& f) const;
  [[nodiscard]] std::uint32_t block_of(const std::array<int, kMaxWeights>& at) const;
  /// The bit of local coordinates `local` (each below kBlockEdge) within a block.
  [[nodiscard]] static int bit_of(const std::array<int, kMaxWeights>& local);
  /// Calls `f(bit, indices)` for every grid point of block `span`, lexicographically.
  template <typename F>
  void for_each_in_block(const BlockSpan& span, F&& f) const;
  /// Calls `f(bit, indices)` for every point of `bits` in block `span`, in bit order (which is
  /// lexicographic), visiting only those points.
  template <typename F>
  void for_each_member(const BlockSpan& span, const BlockBits& bits, F&& f) const;
  /// The bits of every grid point of a block.
  [[nodiscard]] BlockBits all_bits(const BlockSpan& span) const;

  std::vector<std::vector<double>> values_;
  double tied_ratio_ = 0.0;
  std::array<std::uint32_t, kMaxWeights> blocks_{1, 1, 1, 1};
  std::uint32_t block_count_ = 1;
  std::uint64_t size_ = 1;
};

template <typename F>
void WeightGrid::for_each_in_block(const BlockSpan& span, F&& f) const {
  std::array<int, kMaxWeights> local{};
  std::array<int, kMaxWeights> at{};
  const int n = weights();
  for (local[0] = 0; local[0] < span.extent[0]; ++local[0]) {
    for (local[1] = 0; local[1] < span.extent[1]; ++local[1]) {
      for (local[2] = 0; local[2] < span.extent[2]; ++local[2]) {
        for (local[3] = 0; local[3] < span.extent[3]; ++local[3]) {
          for (int k = 0; k < n; ++k)
            at[static_cast<std::size_t>(k)] =
                span.first[static_cast<std::size_t>(k)] + local[static_cast<std::size_t>(k)];
          f(bit_of(local), at);
        }
      }
    }
  }
}

template <typename F>
void WeightGrid::for_each_member(const BlockSpan& span, const BlockBits& bits, F&& f) const {
  std::array<int, kMaxWeights> at{};
  const auto n = static_cast<std::size_t>(weights());
  for (std::size_t word = 0; word < bits.size(); ++word) {
    for (std::uint64_t rest = bits[word]; rest != 0; rest &= rest - 1) {
      const int bit = static_cast<int>(word * 64) + std::countr_zero(rest);
      // bit_of()'s inverse: kBlockEdge = 8, three bits per weight, weight 0 most significant.
      const std::array<int, kMaxWeights> local{bit >> 9, (bit >> 6) & 7, (bit >> 3) & 7, bit & 7};
      for (std::size_t k = 0; k < n; ++k) at[k] = span.first[k] + local[k];
      f(bit, at);
    }
  }
}

template <typename F>
void WeightGrid::for_each_block(const WeightRegion::Box& box, F&& f) const {
  std::array<std::uint32_t, kMaxWeights> c{};
  for (c[0] = box.lo[0]; c[0] < box.hi[0]; ++c[0]) {
    for (c[1] = box.lo[1]; c[1] < box.hi[1]; ++c[1]) {
      for (c[2] = box.lo[2]; c[2] < box.hi[2]; ++c[2]) {
        for (c[3] = box.lo[3]; c[3] < box.hi[3]; ++c[3]) f(block_at(c));
      }
    }
  }
}

template <typename F>
void WeightGrid::for_each_point(const WeightRegion& region, F&& f) const {
  for (const WeightRegion::Box& box : region.whole) {
    for_each_block(box, [&](std::uint32_t block) {
      for_each_in_block(span_of(block), [&](int /*bit*/, const std::array<int, kMaxWeights>& at) { f(at); });
    });
  }
  for (const WeightRegion::Part& part : region.parts) {
    for_each_member(span_of(part.block), part.bits,
                    [&](int /*bit*/, const std::array<int, kMaxWeights>& at) { f(at); });
  }
}

template <typename F>
void WeightGrid::for_each_projection(const WeightRegion& region, int a, int b, F&& f) const {
  const auto ua = static_cast<std::size_t>(a);
  const auto ub = static_cast<std::size_t>(b);
  for (const WeightRegion::Box& box : region.whole) {
    const BlockSpan span = span_of(box);
    for (int i = 0; i < span.extent[ua]; ++i) {
      for (int j = 0; j < span.extent[ub]; ++j) f(span.first[ua] + i, span.first[ub] + j);
    }
  }
  for (const WeightRegion::Part& part : region.parts) {
    for_each_member(span_of(part.block), part.bits,
                    [&](int /*bit*/, const std::array<int, kMaxWeights>& at) { f(at[ua], at[ub]); });
  }
}

}  // namespace weightsearch
}  // namespace fsweep
