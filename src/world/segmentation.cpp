#include "world/segmentation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>

#include "core/files.hpp"
#include "world/png_image.hpp"

namespace fsweep {
inline namespace world {
namespace {

/// Larger than any squared distance on a grid of at most 65536 cells a side (plus the frame),
/// small enough that the parabola arithmetic below stays exact in doubles.
constexpr double kFar = 1e15;

/// One-dimensional squared distance transform (Felzenszwalb & Huttenlocher 2012, "Distance
/// Transforms of Sampled Functions", algorithm DT): d[q] = min_p (q - p)^2 + f[p] over the
/// lower envelope of the parabolas rooted at p. `v` and `z` are scratch of n and n + 1.
void transform_1d(const std::vector<double>& f, std::vector<double>& d, std::vector<int>& v,
                  std::vector<double>& z) {
  const int n = static_cast<int>(f.size());
  const auto at = [](auto& vec, int i) -> auto& { return vec[static_cast<std::size_t>(i)]; };
  int k = 0;
  at(v, 0) = 0;
  at(z, 0) = -kFar * 4.0;
  at(z, 1) = kFar * 4.0;
  for (int q = 1; q < n; ++q) {
    double s = 0.0;
    for (;;) {
      const int p = at(v, k);
      s = ((at(f, q) + static_cast<double>(q) * q) - (at(f, p) + static_cast<double>(p) * p)) /
          (2.0 * (q - p));
      if (s > at(z, k) || k == 0) break;
      --k;
    }
    if (s <= at(z, k)) {  // k == 0 and the new parabola is below everywhere to the left
      at(v, 0) = q;
      at(z, 1) = kFar * 4.0;
      continue;
    }
    ++k;
    at(v, k) = q;
    at(z, k) = s;
    at(z, k + 1) = kFar * 4.0;
  }
  k = 0;
  for (int q = 0; q < n; ++q) {
    while (at(z, k + 1) < q) ++k;
    const double dq = q - at(v, k);
    at(d, q) = dq * dq + at(f, at(v, k));
  }
}

/// Union-find over cell indices, with the peak (largest squared clearance) of each set.
class Sets {
 public:
  explicit Sets(std::size_t n) : parent_(n), peak_(n, 0) { std::iota(parent_.begin(), parent_.end(), 0); }
  int find(int i) {
    while (parent_[static_cast<std::size_t>(i)] != i) {
      auto& p = parent_[static_cast<std::size_t>(i)];
      p = parent_[static_cast<std::size_t>(p)];
      i = p;
    }
    return i;
  }
  void make(int i, long long peak) { peak_[static_cast<std::size_t>(i)] = peak; }
  /// Joins the sets of a and b; returns the surviving root.
  int join(int a, int b) {
    a = find(a);
    b = find(b);
    if (a == b) return a;
    if (peak_[static_cast<std::size_t>(b)] > peak_[static_cast<std::size_t>(a)]) std::swap(a, b);
    parent_[static_cast<std::size_t>(b)] = a;
    return a;
  }
  [[nodiscard]] long long peak(int root) const { return peak_[static_cast<std::size_t>(root)]; }

 private:
  std::vector<int> parent_;
  std::vector<long long> peak_;
};

/// The connectivity of step 2 as one bit per heading for each known free cell: bit h is set
/// when the neighbour in heading h (grid.hpp) is known free and, for a diagonal, neither cell
/// beside the diagonal is occupied.
class Links {
 public:
  /// Links of the cells `free` (known free cells of `known`; others get none).
  Links(const KnownMap& known, const std::vector<int>& free)
      : width_(known.width()), bits_(static_cast<std::size_t>(known.size()), 0) {
    for (std::size_t k = 0; k < 8; ++k) offset_[k] = kDirections[k].y * width_ + kDirections[k].x;
    const CellState* cells = known.cells().data().data();
    const auto state = [cells](int j) { return cells[j]; };
    for (const int i : free) {
      const Cell c = known.cell(i);
      std::uint8_t b = 0;
      if (c.x > 0 && c.y > 0 && c.x + 1 < known.width() && c.y + 1 < known.height()) {
        // Inside the frame: plain offsets, no bounds checks.
        for (std::size_t h = 0; h < 8; ++h) {
          if (state(i + offset_[h]) != CellState::Free) continue;
          if ((h & 1U) != 0 && (state(i + kDirections[h].x) == CellState::Occupied ||
                                state(i + kDirections[h].y * width_) == CellState::Occupied)) {
            continue;
          }
          b = static_cast<std::uint8_t>(b | (1U << h));
        }
        bits_[static_cast<std::size_t>(i)] = b;
        continue;
      }
      for (int h = 0; h < 8; ++h) {
        const Cell d = kDirections[static_cast<std::size_t>(h)];
        if (!known.is_free(Cell{c.x + d.x, c.y + d.y})) continue;
        if ((h & 1) != 0 && (known.state(Cell{c.x + d.x, c.y}) == CellState::Occupied ||
                             known.state(Cell{c.x, c.y + d.y}) == CellState::Occupied)) {
          continue;
        }
        b = static_cast<std::uint8_t>(b | (1U << h));
      }
      bits_[static_cast<std::size_t>(i)] = b;
    }
  }
  /// Calls f(neighbour index) for every linked neighbour of cell i.
  template <typename F>
  void for_each(int i, F&& f) const {
    const unsigned b = bits_[static_cast<std::size_t>(i)];
    for (std::size_t h = 0; h < 8; ++h) {
      if ((b >> h) & 1U) f(i + offset_[h]);
    }
  }

 private:
  int width_ = 0;
  std::array<int, 8> offset_{};
  std::vector<std::uint8_t> bits_;
};

/// A room core's peak must exceed 1.5 t: peak^2 > 2.25 t^2, i.e. 4 peak^2 > 9 t^2.
bool is_room_peak(long long peak2, long long t) { return 4 * peak2 > 9 * t * t; }

/// Squared clearance (step 1) of the cells in the rectangle [x0, x1] x [y0, y1] of `known`,
/// written into `out` (one entry per cell of `known`; others untouched). Exact for those
/// cells when every occupied cell of `known` that can be nearest lies in the rectangle, i.e.
/// when the rectangle holds every known cell (the others are unknown, never occupied); the
/// frame outside the grid is added in closed form: min(x + 1, y + 1, w - x, h - y)^2.
void clearance_in(const KnownMap& known, int x0, int y0, int x1, int y1, std::vector<long long>& out) {
  const int w = x1 - x0 + 1;
  const int h = y1 - y0 + 1;
  // Pass 1, along each row: squared distance to the nearest occupied cell of the row (kFar
  // when none), by two scans; stored transposed (column after column) for pass 2.
  std::vector<double> cols(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), kFar);
  const CellState* cells = known.cells().data().data();
  for (int y = 0; y < h; ++y) {
    const CellState* row = cells + static_cast<std::ptrdiff_t>(y0 + y) * known.width() + x0;
    const auto put = [&](int x, double v) {
      auto& c = cols[static_cast<std::size_t>(x) * static_cast<std::size_t>(h) + static_cast<std::size_t>(y)];
      c = std::min(c, v);
    };
    int last = -1;  // the last occupied x seen, -1: none
    for (int x = 0; x < w; ++x) {
      if (row[x] == CellState::Occupied) last = x;
      if (last >= 0) put(x, static_cast<double>(x - last) * (x - last));
    }
    last = -1;
    for (int x = w - 1; x >= 0; --x) {
      if (row[x] == CellState::Occupied) last = x;
      if (last >= 0) put(x, static_cast<double>(last - x) * (last - x));
    }
  }
  // Pass 2, along each column: the lower envelope of the row results.
  std::vector<double> f(static_cast<std::size_t>(h));
  std::vector<double> d(static_cast<std::size_t>(h));
  std::vector<int> v(static_cast<std::size_t>(h));
  std::vector<double> z(static_cast<std::size_t>(h) + 1);
  for (int x = 0; x < w; ++x) {
    const auto first = cols.begin() + static_cast<std::ptrdiff_t>(x) * h;
    std::copy(first, first + h, f.begin());
    transform_1d(f, d, v, z);
    for (int y = 0; y < h; ++y) {
      const Cell c{x0 + x, y0 + y};
      const long long frame = std::min({c.x + 1, c.y + 1, known.width() - c.x, known.height() - c.y});
      const double inner = d[static_cast<std::size_t>(y)];
      out[static_cast<std::size_t>(known.index(c))] =
          inner < static_cast<double>(frame * frame) ? std::llround(inner) : frame * frame;
    }
  }
}

}  // namespace

std::vector<long long> squared_clearance(const KnownMap& known) {
  std::vector<long long> out(static_cast<std::size_t>(known.size()), 0);
  if (known.size() > 0) clearance_in(known, 0, 0, known.width() - 1, known.height() - 1, out);
  return out;
}

namespace {

/// segment_free_space()'s steps over one known map, writing `s`.
class Segmenter {
 public:
  /// `order`: the known free cells, ascending; `d2`: their squared clearances.
  Segmenter(const KnownMap& known, std::vector<int> order, std::vector<long long> d2, Segmentation& s)
      : known_(known), s_(s), order_(std::move(order)), d2_(std::move(d2)), links_(known, order_) {}

  void run() {
    rank_by_clearance();
    const long long best_t = best_threshold();
    s_.threshold_cells = static_cast<int>(best_t);
    grow_cores(best_t);
    label_from_neighbours();
    const std::vector<int> small = label_left_overs(best_t);
    join_small(small);
  }

 private:
  static constexpr int kLeftOver = -2;
  static constexpr int kSmall = -3;

  [[nodiscard]] long long clear2(int i) const { return d2_[static_cast<std::size_t>(i)]; }
  int& label(int i) { return s_.label[static_cast<std::size_t>(i)]; }

  /// Known free cells by decreasing clearance, ties by index (a counting sort when the keys are
  /// few); rank = position in that order.
  void rank_by_clearance() {
    long long max_key = 0;
    for (const int i : order_) max_key = std::max(max_key, clear2(i));
    if (max_key <= 4 * static_cast<long long>(order_.size())) {
      std::vector<int> start(static_cast<std::size_t>(max_key) + 2, 0);
      for (const int i : order_) ++start[static_cast<std::size_t>(max_key - clear2(i)) + 1];
      for (std::size_t k = 1; k < start.size(); ++k) start[k] += start[k - 1];
      std::vector<int> sorted(order_.size());
      for (const int i : order_)
        sorted[static_cast<std::size_t>(start[static_cast<std::size_t>(max_key - clear2(i))]++)] = i;
      order_ = std::move(sorted);
    } else {
      std::sort(order_.begin(), order_.end(),
                [&](int a, int b) { return clear2(a) != clear2(b) ? clear2(a) > clear2(b) : a < b; });
    }
    rank_.assign(s_.label.size(), kUnranked);
    for (std::size_t r = 0; r < order_.size(); ++r)
      rank_[static_cast<std::size_t>(order_[r])] = static_cast<int>(r);
  }

  /// Step 3: room cores at every integer threshold, in one sweep from the top; the threshold
  /// with the most (ties: the smaller), 0 when none has a room.
  long long best_threshold() {
    const auto t_max =
        static_cast<long long>(std::floor(std::sqrt(static_cast<double>(clear2(order_.front())))));
    Sets sets(s_.label.size());
    std::vector<int> roots;  // the live components (dead ones are dropped at every level)
    std::size_t next = 0;
    int best_count = 0;
    long long best_t = 0;
    for (long long t = t_max; t >= 1; --t) {
      for (; next < order_.size() && clear2(order_[next]) > t * t; ++next) {
        const int c = order_[next];
        sets.make(c, clear2(c));
        links_.for_each(c, [&](int nb) {
          if (rank_[static_cast<std::size_t>(nb)] < static_cast<int>(next)) (void)sets.join(c, nb);
        });
        if (sets.find(c) == c) roots.push_back(c);  // a new component, or the survivor of a tie
      }
      std::erase_if(roots, [&](int r) { return sets.find(r) != r; });
      int count = 0;
      for (const int r : roots) {
        if (is_room_peak(sets.peak(r), t)) ++count;
      }
      if (count >= best_count && count > 0) {  // ties: the smaller t (visited later)
        best_count = count;
        best_t = t;
      }
    }
    return best_t;
  }

  /// Labels `id` the cells breadth-first from `start` (labelled already) through links to
  /// cells `joins(cell)` accepts; the cells reached are in queue_.
  template <typename Joins>
  void flood(int start, int id, const Joins& joins) {
    queue_.assign(1, start);
    for (std::size_t head = 0; head < queue_.size(); ++head) {
      links_.for_each(queue_[head], [&](int nb) {
        if (joins(nb)) {
          label(nb) = id;
          queue_.push_back(nb);
        }
      });
    }
  }

  /// Step 4a: the cores at t* (cells above it, connected), each a room when its peak (its first
  /// cell in this order) is, else left over.
  void grow_cores(long long best_t) {
    if (best_t == 0) return;
    const long long t2 = best_t * best_t;
    for (const int c : order_) {
      if (clear2(c) <= t2) break;
      if (label(c) != -1) continue;
      const bool room = is_room_peak(clear2(c), best_t);
      const int id = room ? s_.count++ : kLeftOver;
      if (room) s_.room.push_back(1);
      label(c) = id;
      flood(c, id, [&](int nb) { return clear2(nb) > t2 && label(nb) == -1; });
    }
  }

  /// Step 4b: every other cell from its highest earlier neighbour (ties: a labelled one, then
  /// the lowest index); left over when that has no segment.
  void label_from_neighbours() {
    for (const int c : order_) {
      if (label(c) != -1) continue;
      int best = -1;
      links_.for_each(c, [&](int nb) {
        if (rank_[static_cast<std::size_t>(nb)] > rank_[static_cast<std::size_t>(c)]) return;
        if (best < 0) {
          best = nb;
          return;
        }
        const bool labelled = label(nb) >= 0;
        const bool best_labelled = label(best) >= 0;
        if (clear2(nb) != clear2(best) ? clear2(nb) > clear2(best)
                                       : (labelled != best_labelled ? labelled : nb < best))
          best = nb;
      });
      const int id = best >= 0 ? label(best) : kLeftOver;
      label(c) = id >= 0 ? id : kLeftOver;
    }
  }

  /// Step 5: left-over components, in index order of their lowest cell: one of at least
  /// (2 t* + 1)^2 cells is a segment (not a room); the cells of smaller ones are returned.
  std::vector<int> label_left_overs(long long best_t) {
    const long long big = (2 * best_t + 1) * (2 * best_t + 1);
    std::vector<int> small;
    for (int i = 0; i < known_.size(); ++i) {
      if (label(i) != kLeftOver) continue;
      label(i) = kSmall;
      flood(i, kSmall, [&](int nb) { return label(nb) == kLeftOver; });
      if (static_cast<long long>(queue_.size()) >= big) {
        const int id = s_.count++;
        s_.room.push_back(0);
        for (const int c : queue_) label(c) = id;
      } else {
        small.insert(small.end(), queue_.begin(), queue_.end());
      }
    }
    return small;
  }

  /// Small components join their neighbours: breadth-first from every labelled cell that touches
  /// one, in index order. Those that touch no segment are segments of their own.
  void join_small(std::vector<int> small) {
    queue_.clear();
    for (const int i : small) {
      links_.for_each(i, [&](int nb) {
        if (label(nb) >= 0) queue_.push_back(nb);
      });
    }
    std::sort(queue_.begin(), queue_.end());
    queue_.erase(std::unique(queue_.begin(), queue_.end()), queue_.end());
    for (std::size_t head = 0; head < queue_.size(); ++head) {
      const int id = label(queue_[head]);
      links_.for_each(queue_[head], [&](int nb) {
        if (label(nb) == kSmall) {
          label(nb) = id;
          queue_.push_back(nb);
        }
      });
    }
    std::sort(small.begin(), small.end());
    for (const int i : small) {
      if (label(i) != kSmall) continue;
      const int id = s_.count++;
      s_.room.push_back(0);
      label(i) = id;
      flood(i, id, [&](int nb) { return label(nb) == kSmall; });
    }
  }

  static constexpr int kUnranked = -1;
  const KnownMap& known_;
  Segmentation& s_;
  std::vector<int> order_;
  std::vector<long long> d2_;
  const Links links_;
  std::vector<int> rank_;
  std::vector<int> queue_;
};

}  // namespace

Segmentation segment_free_space(const KnownMap& known) {
  Segmentation s;
  const auto n = static_cast<std::size_t>(known.size());
  s.label.assign(n, -1);
  if (n == 0) return s;
  // Clearance over the bounding box of the known cells only (outside it all is unknown).
  std::vector<int> order;  // known free cells, ascending
  int x0 = known.width();
  int y0 = known.height();
  int x1 = -1;
  int y1 = -1;
  for (int i = 0; i < known.size(); ++i) {
    if (known.is_unknown(i)) continue;
    const Cell c = known.cell(i);
    x0 = std::min(x0, c.x);
    y0 = std::min(y0, c.y);
    x1 = std::max(x1, c.x);
    y1 = std::max(y1, c.y);
    if (known.is_free(i)) order.push_back(i);
  }
  if (order.empty()) return s;
  std::vector<long long> d2(n, 0);
  clearance_in(known, x0, y0, x1, y1, d2);
  Segmenter(known, std::move(order), std::move(d2), s).run();
  return s;
}

void write_segments_png(const std::string& path, const KnownMap& known, const Segmentation& s, int scale) {
  scale = std::max(scale, 1);
  const int w = known.width() * scale;
  const int h = known.height() * scale;
  std::vector<std::uint8_t> px(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 3, 0);
  for (int i = 0; i < known.size(); ++i) {
    std::array<std::uint8_t, 3> rgb{60, 60, 60};
    if (known.state(i) == CellState::Occupied) rgb = {0, 0, 0};
    const int id = s.label[static_cast<std::size_t>(i)];
    if (id >= 0) {
      // A multiplicative hash of the id spreads neighbouring ids over the colour cube.
      const std::uint32_t hsh = static_cast<std::uint32_t>(id + 1) * 2654435761U;
      const bool room =
          static_cast<std::size_t>(id) < s.room.size() && s.room[static_cast<std::size_t>(id)] != 0;
      const auto channel = [&](int shift) {
        const auto v = static_cast<std::uint8_t>((hsh >> shift) & 0xFFU);
        return room ? static_cast<std::uint8_t>(64 + v / 2 + v / 4) : static_cast<std::uint8_t>(200 + v / 8);
      };
      rgb = {channel(8), channel(16), channel(24)};
    }
    const Cell c = known.cell(i);
    for (int y = c.y * scale; y < (c.y + 1) * scale; ++y) {
      for (int x = c.x * scale; x < (c.x + 1) * scale; ++x) {
        const auto at =
            (static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x)) * 3;
        std::copy(rgb.begin(), rgb.end(), px.begin() + static_cast<std::ptrdiff_t>(at));
      }
    }
  }
  write_file_atomically(path, encode_png(w, h, px));
}

}  // namespace world
}  // namespace fsweep
