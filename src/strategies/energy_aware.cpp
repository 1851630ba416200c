#include "strategies/energy_aware.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/config_error.hpp"
#include "core/csv_format.hpp"
#include "strategies/sensing_region.hpp"

namespace fsweep {
inline namespace strategies {
namespace {

double direction(Cell from, Cell to) {
  return std::atan2(static_cast<double>(to.y - from.y), static_cast<double>(to.x - from.x));
}

/// Rappaport 2016 eq. 10: relative orientation in [0, 1].
double theta_rel(double theta_r, double theta_g) {
  return (M_PI - std::abs(std::abs(theta_r - theta_g) - M_PI)) / M_PI;
}

}  // namespace

namespace {

const std::vector<std::string> kDistanceModes{"path", "octile", "euclidean"};
constexpr const char* kDistanceDoc =
    "how d_g and d_gb are measured: shortest path over known free space (the paper's A*), "
    "octile length without obstacles, or straight line between cell centres";

}  // namespace

ParamDecl<EnergyAwareParams> energy_aware_params() {
  ParamDecl<EnergyAwareParams> d;
  const double max = EnergyAwareParams::kMaxWeight;
  d.number("w1", &EnergyAwareParams::w1, "weight of d_g, robot to frontier distance (Rappaport 2016 eq. 8)")
      .range(0, max);
  d.number("w2", &EnergyAwareParams::w2, "weight of d_gb, frontier to dock distance (eq. 8)").range(0, max);
  d.number("w3", &EnergyAwareParams::w3, "weight of d_gbe, -d_gb above half charge, +d_gb below (eq. 9)")
      .range(0, max);
  d.number("w4", &EnergyAwareParams::w4, "weight of theta_rel in [0, 1], the turn toward the goal (eq. 10)")
      .range(0, max);
  d.choice("distance", &EnergyAwareParams::distance, kDistanceModes, kDistanceDoc);
  d.choice("unit", &EnergyAwareParams::unit, {"m", "cell"},
           "unit of d_g, d_gb and d_gbe in the cost (eq. 8): metres, or cells of the map (the paper does "
           "not say; theta_rel is in [0, 1] either way)")
      .omitted_at_default();
  return d;
}

ParamDecl<ClosestFrontierParams> closest_frontier_params() {
  ParamDecl<ClosestFrontierParams> d;
  d.choice("distance", &ClosestFrontierParams::distance, kDistanceModes, kDistanceDoc);
  d.choice(
       "goal", &ClosestFrontierParams::goal, {"cluster", "cell"},
       "the representative of the nearest frontier cluster, or the nearest frontier cell (Holz 2010 eq. 2)")
      .omitted_at_default();
  return d;
}

namespace {

/// Every frontier cell of obs.clusters as a cluster of its own (ascending index; with the `seg`
/// heuristic's mask, only the cells of the robot's segment).
std::vector<FrontierCluster> cell_clusters(const Observation& obs) {
  std::vector<int> cells = open_frontier_cells(obs);
  if (obs.segment_mask != nullptr) {
    std::erase_if(cells, [&](int i) { return (*obs.segment_mask)[static_cast<std::size_t>(i)] == 0; });
  }
  std::vector<FrontierCluster> out(cells.size());
  for (std::size_t k = 0; k < cells.size(); ++k) {
    out[k].cells = {cells[k]};
    out[k].representative = cells[k];
  }
  return out;
}

/// `obs` with `clusters` in place of its own.
Observation with_clusters(const Observation& obs, const std::vector<FrontierCluster>& clusters) {
  return Observation{obs.known,         obs.frontiers, clusters,    obs.distances,
                     obs.sensor,        obs.robot,     obs.heading, obs.previous_position,
                     obs.previous_goal, obs.dock,      obs.battery, obs.decision_index,
                     obs.segment_mask};
}

}  // namespace

Decision EnergyAware::decide(const Observation& obs) {
  if (params_.goal != "cell") return decide_among(obs);
  const std::vector<FrontierCluster> cells = cell_clusters(obs);
  return decide_among(with_clusters(obs, cells));
}

Candidates EnergyAware::candidates(const Observation& obs) {
  if (params_.goal != "cell") return candidates_among(obs);
  const std::vector<FrontierCluster> cells = cell_clusters(obs);
  return candidates_among(with_clusters(obs, cells));
}

Candidates EnergyAware::candidates_within(const Observation& obs, const WeightBounds& bounds) {
  if (params_.goal != "cell") return candidates_within_among(obs, bounds);
  const std::vector<FrontierCluster> cells = cell_clusters(obs);
  return candidates_within_among(with_clusters(obs, cells), bounds);
}

EnergyAware::EnergyAware(std::string name, const EnergyAwareParams& params)
    : name_(std::move(name)), params_(params), weights_{params.w1, params.w2, params.w3, params.w4} {}

/// What one decision knows besides d_g: per cluster representative its dock distance d_gb
/// and its turn theta_rel (computed when first asked for: a decision may never need most of
/// them), and the battery's reach d_l (eq. 5) and state (eq. 9).
struct EnergyAware::Terms {
  std::vector<int> reps;
  std::vector<double> d_gb;
  double d_l = 0.0;
  bool above_half = true;
  /// Theta_rel's inputs: the robot's cell and direction of travel theta_r (radians).
  Cell robot;
  double theta_r = 0.0;
  int width = 1;
  /// Metres per distance unit of the features (EnergyAwareParams::unit): 1, or the resolution.
  double unit_m = 1.0;

  /// Eq. 10 for representative i (the same value every time it is asked for).
  [[nodiscard]] double theta(std::size_t i) const {
    double& t = theta_[i];
    if (std::isnan(t)) {
      const int r = reps[i];
      t = theta_rel(theta_r, direction(robot, Cell{r % width, r / width}));
    }
    return t;
  }

  /// Eq. 7 (strict) on finite lengths: can the robot reach representative i at d_g and still
  /// get back to the dock?
  [[nodiscard]] bool feasible(std::size_t i, double d_g) const {
    return std::isfinite(d_g) && std::isfinite(d_gb[i]) && d_l > d_g + d_gb[i];
  }
  /// The feature row of representative i at robot distance d_g (kFeatures order).
  [[nodiscard]] std::array<double, kFeatures> features(std::size_t i, double d_g) const {
    auto row = features_without_theta(i, d_g);
    row[3] = theta(i);
    return row;
  }
  /// The same row with theta_rel at its lower bound 0. Its cost with weights >= 0 is a lower
  /// bound of the row's: linear_cost adds the theta term last, and adding w4 theta >= 0 never
  /// rounds below the sum before it.
  /// Distances are divided by unit_m (x / 1 is x exactly: metres are the lengths themselves);
  /// the division keeps the row non-decreasing in d_g.
  [[nodiscard]] std::array<double, kFeatures> features_without_theta(std::size_t i, double d_g) const {
    const double g = d_g / unit_m;
    const double gb = d_gb[i] / unit_m;
    return {g, gb, above_half ? -gb : gb, 0.0};
  }

  /// Theta_rel per representative, NaN until computed.
  mutable std::vector<double> theta_;
};

EnergyAware::Terms EnergyAware::own_terms(const Observation& obs) const {
  return terms(obs, weights_[1] != 0.0 || weights_[2] != 0.0);
}

EnergyAware::Terms EnergyAware::terms(const Observation& obs, bool dock_weighted) const {
  Terms t;
  t.reps.reserve(obs.clusters.size());
  for (const auto& c : obs.clusters) t.reps.push_back(c.representative);
  t.d_l = obs.battery.remaining_range_m;
  // Eq. 9: the sign of d_gbe flips at half charge. An unlimited battery is always "full".
  t.above_half = obs.battery.unlimited() || obs.battery.level > 0.5 * obs.battery.capacity;
  const double res = obs.known.resolution_m();
  if (params_.distance == "path") {
    // The leg to the dock must be shorter than d_l, so d_l bounds its search (docs/dev/architecture.md,
    // "Plugins and their parameters"). With an unlimited battery d_gb matters only through its
    // weights: skip that search if both are zero (the features then read 0, which those weights
    // ignore).
    const bool need_dock = !obs.battery.unlimited() || dock_weighted;
    t.d_gb = need_dock ? obs.distances.from_dock(t.reps, t.d_l) : std::vector<double>(t.reps.size(), 0.0);
  } else {
    const auto metric = params_.distance == "euclidean" ? &euclidean_distance : &octile_distance;
    for (const int r : t.reps) t.d_gb.push_back(metric(obs.known.cell(r), obs.dock) * res);
  }
  t.unit_m = params_.unit == "cell" ? res : 1.0;
  t.robot = obs.robot;
  t.theta_r = direction(obs.previous_position, obs.robot);
  t.width = obs.known.width();
  t.theta_.assign(t.reps.size(), std::numeric_limits<double>::quiet_NaN());
  return t;
}

void EnergyAware::set_weights(std::span<const double> weights) {
  if (weights.size() != weights_.size()) {
    throw std::invalid_argument(name_ + ": set_weights needs " + std::to_string(weights_.size()) +
                                " weights");
  }
  for (std::size_t k = 0; k < weights.size(); ++k) {
    if (!(weights[k] >= 0.0 && weights[k] <= EnergyAwareParams::kMaxWeight)) {
      throw std::invalid_argument(name_ + ": w" + std::to_string(k + 1) + " = " + format_number(weights[k]) +
                                  " is out of range; allowed: 0..250");
    }
  }
  std::copy(weights.begin(), weights.end(), weights_.begin());
  params_.w1 = weights_[0];
  params_.w2 = weights_[1];
  params_.w3 = weights_[2];
  params_.w4 = weights_[3];
}

Candidates EnergyAware::candidates_among(const Observation& obs) {
  Candidates out;
  out.feature_count = kFeatures;
  if (obs.clusters.empty()) return out;
  const Terms t = own_terms(obs);
  std::vector<double> d_g;
  if (params_.distance == "path") {
    // The leg to the frontier must be shorter than d_l too.
    d_g = obs.distances.from_robot(t.reps, t.d_l);
  } else {
    const auto metric = params_.distance == "euclidean" ? &euclidean_distance : &octile_distance;
    for (const int r : t.reps) d_g.push_back(metric(obs.robot, obs.known.cell(r)) * obs.known.resolution_m());
  }
  out.cells.reserve(t.reps.size());
  out.features.reserve(t.reps.size() * kFeatures);
  for (std::size_t i = 0; i < t.reps.size(); ++i) {
    if (!t.feasible(i, d_g[i])) continue;
    out.cells.push_back(obs.known.cell(t.reps[i]));
    const auto row = t.features(i, d_g[i]);
    out.features.insert(out.features.end(), row.begin(), row.end());
  }
  return out;
}

namespace {

/// What the watchers of a decision's search from the robot keep: the decision's terms, each
/// representative's lower bound of d_g, and which representatives are still open (not reached,
/// and not rejected).
class RepresentativeWatch : public SettleWatcher {
 public:
  /// True while representative i is not reached and passes eq. 7 at its lower bound.
  [[nodiscard]] bool open(std::size_t i) const { return open_[i] != 0; }

 protected:
  RepresentativeWatch(const EnergyAware::Terms& terms, std::vector<double> lower_bound_m)
      : terms_(terms), lower_bound_m_(std::move(lower_bound_m)), open_(terms.reps.size(), 1) {
    for (std::size_t i = 0; i < open_.size(); ++i) {
      if (!terms_.feasible(i, lower_bound_m_[i])) open_[i] = 0;
    }
  }
  /// Representative i is reached at `d_g`: closes it, and returns true when it was open and
  /// passes eq. 7 there (from_robot() reads a length beyond its bound d_l as unreachable).
  bool reach(std::size_t i, double d_g) {
    if (open_[i] == 0) return false;
    open_[i] = 0;
    return d_g <= terms_.d_l && terms_.feasible(i, d_g);
  }

  const EnergyAware::Terms& terms_;
  std::vector<double> lower_bound_m_;
  std::vector<std::uint8_t> open_;  // 1: not yet reached, and might still win
};

/// The energy-aware choice made while the search from the robot grows (SettleWatcher): the
/// same argmin as argmin_linear over candidates() (ties to the lowest representative), with the
/// search stopped as soon as no representative not yet reached can beat or tie the best one.
/// A representative not yet reached is at least max(radius, its static lower bound) away, and
/// its cost at that distance (linear_cost, which never decreases as d_g grows) bounds its real
/// cost; eq. 7 rejects by the same bound. Only exact lengths make a representative the best.
class WatchedChoice final : public RepresentativeWatch {
 public:
  WatchedChoice(const EnergyAware::Terms& terms, std::span<const double> weights,
                std::vector<double> lower_bound_m)
      : RepresentativeWatch(terms, std::move(lower_bound_m)), weights_(weights) {}

  void settled(std::size_t i, double d_g) override {
    if (!reach(i, d_g)) return;
    const double cost = cost_at(i, d_g);
    if (best_ < 0 || cost < best_cost_ || (cost == best_cost_ && i < static_cast<std::size_t>(best_))) {
      best_ = static_cast<int>(i);
      best_cost_ = cost;
    }
  }

  double go_on_until(double radius_m) override {
    // Close every representative that can no longer win, and find the smallest radius at which
    // another one might close: the search asks again only there.
    double next = std::numeric_limits<double>::infinity();
    bool any_open = false;
    for (std::size_t i = 0; i < open_.size(); ++i) {
      if (open_[i] == 0) continue;
      const double d_g = std::max(radius_m, lower_bound_m_[i]);
      if (!terms_.feasible(i, d_g) || loses(i, cost_without_theta(i, d_g)) || loses(i, cost_at(i, d_g))) {
        open_[i] = 0;
        continue;
      }
      any_open = true;
      next = std::min(next, closing_radius(i));
    }
    if (!any_open) return -std::numeric_limits<double>::infinity();
    return std::max(next, radius_m);
  }

  /// The chosen representative (index into terms.reps), or -1.
  [[nodiscard]] int best() const { return best_; }
  /// Representative i's cost at its lower bound with theta_rel at 0 (a lower bound of its
  /// cost that needs no theta_rel).
  [[nodiscard]] double bound_cost(std::size_t i) const { return cost_without_theta(i, lower_bound_m_[i]); }
  /// True when representative i, by bound_cost(), can no longer beat or tie the best to win.
  [[nodiscard]] bool beaten(std::size_t i) const { return loses(i, bound_cost(i)); }
  /// True when representative i, by its cost at its lower bound, can no longer win.
  [[nodiscard]] bool beaten_with_theta(std::size_t i) const {
    return loses(i, cost_at(i, lower_bound_m_[i]));
  }

 private:
  /// Representative i's cost at robot distance d_g (its theta_rel only when w4 counts).
  [[nodiscard]] double cost_at(std::size_t i, double d_g) const {
    if (weights_[3] == 0.0) return cost_without_theta(i, d_g);  // w4 * theta_rel adds 0
    const auto row = terms_.features(i, d_g);
    return linear_cost(weights_, row);
  }
  [[nodiscard]] double cost_without_theta(std::size_t i, double d_g) const {
    const auto row = terms_.features_without_theta(i, d_g);
    return linear_cost(weights_, row);
  }
  /// True when cost `bound` of representative i cannot beat or tie the best so far to win.
  [[nodiscard]] bool loses(std::size_t i, double bound) const {
    return best_ >= 0 && (bound > best_cost_ || (bound == best_cost_ && i > static_cast<std::size_t>(best_)));
  }
  /// About where representative i closes (eq. 7, or its cost passing the best): where to ask
  /// again. An estimate; go_on_until() decides on the exact bounds.
  [[nodiscard]] double closing_radius(std::size_t i) const {
    double r = terms_.d_l - terms_.d_gb[i];
    if (best_ >= 0 && weights_[0] > 0.0) {
      r = std::min(r, (best_cost_ - cost_at(i, 0.0)) / weights_[0] * terms_.unit_m);
    }
    return r;
  }

  std::span<const double> weights_;
  int best_ = -1;
  double best_cost_ = 0.0;
};

}  // namespace

namespace {

/// The energy-aware choice for every weight vector of a region (WeightBounds), made while the
/// search from the robot grows (SettleWatcher): WatchedChoice for a box. A reached
/// representative that passes eq. 7 is kept with its exact length; one not yet reached closes
/// once it loses at every vector of the region by either of two proofs, both at
/// max(radius, its lower bound) with theta_rel at 0 (its cost only grows with either):
/// - the box: its lowest cost in the box is above the highest cost in the box of a kept one (or
///   equal, and it comes later). The costs at the box's corners bound the costs inside
///   (linear_cost rounds monotonically in each weight, by the sign of its feature).
/// - the directions: it costs more than the kept one that is cheapest at the middle of the
///   region's directions, at every direction of them (costs_more_at_every_direction()). A
///   narrow region of a wide box (a cone through the origin) closes much sooner so.
class BoxWatch final : public RepresentativeWatch {
 public:
  BoxWatch(const EnergyAware::Terms& terms, const WeightBounds& bounds, std::vector<double> lower_bound_m)
      : RepresentativeWatch(terms, std::move(lower_bound_m)),
        w_lo_(bounds.lo),
        w_hi_(bounds.hi),
        directions_(bounds.directions),
        // At the zero vector every cost ties; the directions say nothing of who wins there.
        by_direction_(!bounds.directions.zero && bounds.directions.nonzero),
        d_g_(terms.reps.size(), std::numeric_limits<double>::infinity()),
        estimate_(terms.reps.size(), 0.0),
        estimated_in_(terms.reps.size(), 0) {
    for (std::size_t k = 0; k < middle_.size(); ++k)
      middle_[k] = 0.5 * (directions_.lo[k] + directions_.hi[k]);
    open_list_.reserve(open_.size());
    for (std::size_t i = 0; i < open_.size(); ++i) {
      if (open_[i] != 0) open_list_.push_back(static_cast<std::uint32_t>(i));
    }
  }

  void settled(std::size_t i, double d_g) override {
    if (!reach(i, d_g)) return;
    d_g_[i] = d_g;
    const auto row = terms_.features(i, d_g);
    const double ceiling = corner_cost(row, true);
    if (best_ < 0 || ceiling < ceiling_ || (ceiling == ceiling_ && i < static_cast<std::size_t>(best_))) {
      best_ = static_cast<int>(i);
      ceiling_ = ceiling;
      bests_changed();
    }
    const double middle = linear_cost(middle_, row);
    if (by_direction_ && (middle_best_ < 0 || middle < middle_cost_)) {
      middle_best_ = static_cast<int>(i);
      middle_cost_ = middle;
      middle_row_ = row;
      bests_changed();
    }
  }

  double go_on_until(double radius_m) override {
    // Asked after every settled representative: look again only where one may close.
    if (radius_m < next_) return next_;
    // Every open representative is looked at (the closed ones leave open_list_). One whose
    // lower bound is still beyond the radius has the same row as when it was last looked at;
    // if the bests did not change since, it is still open with the same estimate.
    double next = std::numeric_limits<double>::infinity();
    std::size_t kept = 0;
    for (std::size_t k = 0; k < open_list_.size(); ++k) {
      const std::uint32_t i = open_list_[k];
      if (open_[i] == 0) continue;  // reached
      if (estimated_in_[i] != bests_ || lower_bound_m_[i] < radius_m) {
        const std::optional<double> estimate = estimate_at(i, radius_m);
        if (!estimate) {
          open_[i] = 0;
          continue;
        }
        estimate_[i] = *estimate;
        estimated_in_[i] = bests_;
      } else {
        check_kept_estimate(i, radius_m);
      }
      open_list_[kept++] = i;
      next = std::min(next, estimate_[i]);
    }
    open_list_.resize(kept);
    if (kept == 0) return -std::numeric_limits<double>::infinity();
    next_ = std::max(next, radius_m);
    return next_;
  }

  /// The exact length of representative i if it was reached and passes eq. 7, else +infinity.
  [[nodiscard]] double d_g(std::size_t i) const { return d_g_[i]; }

  /// Closes representative i, not yet reached, when it already loses by either proof at its
  /// lower bound (or fails eq. 7 there); true when it is closed.
  bool close_at_bound(std::size_t i) {
    if (open_[i] == 0) return true;
    const double d_g = lower_bound_m_[i];
    const auto row = terms_.features_without_theta(i, d_g);
    if (!closes(i, d_g, row, corner_cost(row, false))) return false;
    open_[i] = 0;
    return true;
  }
  /// The order in which probes measure the representatives: cost at its lower bound (theta_rel
  /// at 0) at the middle direction, where the proof by direction compares, else at the box's
  /// lowest corner. Only an order: which representatives it settles first, not what is chosen.
  [[nodiscard]] double probe_key(std::size_t i) const {
    const auto row = terms_.features_without_theta(i, lower_bound_m_[i]);
    return by_direction_ ? linear_cost(middle_, row) : corner_cost(row, false);
  }

 private:
  /// True when representative i, at distance d_g (not below its length) with row `row` (theta_rel
  /// at 0) and lowest cost `lowest` in the box, fails eq. 7 or loses at every vector by either proof.
  [[nodiscard]] bool closes(std::size_t i, double d_g, const std::array<double, EnergyAware::kFeatures>& row,
                            double lowest) const {
    return !terms_.feasible(i, d_g) || loses(i, lowest) ||
           (middle_best_ >= 0 && costs_more_at_every_direction(row, middle_row_, directions_));
  }

  /// The kept representatives changed: every open one is looked at again, and may close sooner.
  void bests_changed() {
    next_ = -std::numeric_limits<double>::infinity();
    ++bests_;
  }

  /// Open representative i at distance max(radius_m, its lower bound): nullopt when it closes(),
  /// else about where it closes (eq. 7, or its lowest cost passing the ceiling, or its cost
  /// passing the middle's best at every direction): an estimate, as go_on_until decides on the
  /// exact bounds when asked there. A function of i, that distance and the bests.
  [[nodiscard]] std::optional<double> estimate_at(std::size_t i, double radius_m) const {
    const double d_g = std::max(radius_m, lower_bound_m_[i]);
    const auto row = terms_.features_without_theta(i, d_g);
    const double lowest = corner_cost(row, false);
    if (closes(i, d_g, row, lowest)) return std::nullopt;
    double r = terms_.d_l - terms_.d_gb[i];
    const double w1 = w_lo_[0];
    if (best_ >= 0 && w1 > 0.0) r = std::min(r, d_g + (ceiling_ - lowest) / w1 * terms_.unit_m);
    if (middle_best_ >= 0 && directions_.lo[0] > 0.0) {
      // The difference at the middle grows by at least lo[0] per unit of d_g.
      r = std::min(r, d_g + (middle_cost_ - linear_cost(middle_, row)) / directions_.lo[0] * terms_.unit_m);
    }
    return r;
  }

  /// Debug builds (the sanitizer tree runs every test so): the estimate go_on_until() kept for
  /// representative i is, bit for bit, the one estimate_at() makes now. It reuses it when the
  /// bests are unchanged and i's lower bound is still beyond the radius, where both give the
  /// same distance and row; a stale one could keep a loser open, which no choice would show.
  void check_kept_estimate([[maybe_unused]] std::size_t i, [[maybe_unused]] double radius_m) const {
#ifndef NDEBUG
    const std::optional<double> now = estimate_at(i, radius_m);
    if (!now || std::bit_cast<std::uint64_t>(*now) != std::bit_cast<std::uint64_t>(estimate_[i])) {
      throw std::logic_error("BoxWatch: the estimate kept for representative " + std::to_string(i) +
                             " is not the one made now");
    }
#endif
  }

  /// linear_cost of `row` at the box's corner where it is highest (`highest`) or lowest.
  [[nodiscard]] double corner_cost(const std::array<double, EnergyAware::kFeatures>& row,
                                   bool highest) const {
    std::array<double, EnergyAware::kFeatures> w{};
    for (std::size_t k = 0; k < w.size(); ++k) w[k] = (row[k] >= 0.0) == highest ? w_hi_[k] : w_lo_[k];
    return linear_cost(w, row);
  }
  [[nodiscard]] bool loses(std::size_t i, double lowest) const {
    return best_ >= 0 && (lowest > ceiling_ || (lowest == ceiling_ && i > static_cast<std::size_t>(best_)));
  }

  std::span<const double> w_lo_;
  std::span<const double> w_hi_;
  const WeightDirections& directions_;
  bool by_direction_;
  std::array<double, EnergyAware::kFeatures> middle_{};
  std::vector<double> d_g_;
  int best_ = -1;
  double ceiling_ = 0.0;
  /// The kept representative cheapest at the middle direction, its cost there and its features.
  int middle_best_ = -1;
  double middle_cost_ = 0.0;
  std::array<double, EnergyAware::kFeatures> middle_row_{};
  /// The radius below which no representative closes (until a best changes).
  double next_ = -std::numeric_limits<double>::infinity();
  /// The representatives open when last looked at, and for each its estimate_at() and the count of
  /// changes of the bests (bests_) it was made in (0: never made).
  std::vector<std::uint32_t> open_list_;
  std::vector<double> estimate_;
  std::vector<std::uint32_t> estimated_in_;
  std::uint32_t bests_ = 1;
};

}  // namespace

bool octile_path_known_free(const KnownMap& known, Cell from, Cell to) {
  const int sx = sign_of(to.x - from.x);
  const int sy = sign_of(to.y - from.y);
  const int ax = std::abs(to.x - from.x);
  const int ay = std::abs(to.y - from.y);
  const int diagonal_steps = std::min(ax, ay);
  const int straight_steps = std::max(ax, ay) - diagonal_steps;
  const Cell straight = ax > ay ? Cell{sx, 0} : Cell{0, sy};
  const auto clear = [&](bool diagonal_first) {
    Cell c = from;
    if (!known.is_free(c)) return false;
    for (const bool diagonal : {diagonal_first, !diagonal_first}) {
      for (int k = diagonal ? diagonal_steps : straight_steps; k > 0; --k) {
        if (diagonal && !(known.is_free(Cell{c.x + sx, c.y}) && known.is_free(Cell{c.x, c.y + sy})))
          return false;
        c = diagonal ? Cell{c.x + sx, c.y + sy} : Cell{c.x + straight.x, c.y + straight.y};
        if (!known.is_free(c)) return false;
      }
    }
    return true;
  };
  return clear(true) || (diagonal_steps > 0 && straight_steps > 0 && clear(false));
}

namespace {

/// Point searches (A*) a decision may try before it searches from the robot outward: at most
/// this many, each settling at most kProbeCellsPerStep cells per cell of octile length plus
/// kProbeCellsExtra (in open space A* settles about one cell per cell of length).
constexpr int kMaxProbes = 8;
constexpr long kProbeCellsPerStep = 16;
constexpr long kProbeCellsExtra = 64;

/// The exact length of representative i from the robot without a search from it (+infinity
/// beyond d_l, as from_robot() reads it): its octile length when a known free path of that length
/// shows it exact (octile_path_known_free), else a point search, while `probes` stays below
/// `max_probes`. nullopt when the probes ran out or the point search hit its budget.
std::optional<double> probe_length(const Observation& obs, const EnergyAware::Terms& t, std::size_t i,
                                   int& probes, int max_probes) {
  const Cell goal = obs.known.cell(t.reps[i]);
  const double octile = octile_distance(obs.robot, goal);
  if (octile_path_known_free(obs.known, obs.robot, goal)) {
    // The octile length is exact: the value a point search returns (its length is computed the
    // same way from the same step counts), read against the bound d_l as it reads it.
    const double d = octile * obs.known.resolution_m();
    return d <= t.d_l ? d : std::numeric_limits<double>::infinity();
  }
  if (probes++ == max_probes) return std::nullopt;
  const auto steps = static_cast<long>(std::ceil(octile));
  return obs.distances.probe_from_robot(t.reps[i], t.d_l, kProbeCellsExtra + kProbeCellsPerStep * steps);
}

/// Exact lengths for the representatives with the lowest cost bounds, best bound first, by
/// point searches (or without one where a known free path of octile length shows that length
/// exact, octile_path_known_free), until the best one found is certified (every other bound loses; in open
/// space, where lengths equal their octile bounds, the first probe does it). False when the
/// probes ran out first: then `choice` holds what they found and a search from the robot must
/// finish the choice.
bool choose_by_probes(const Observation& obs, const EnergyAware::Terms& t, WatchedChoice& choice) {
  // The open representatives (the others are rejected by eq. 7 on their bound) by cost bound
  // without theta_rel, then index: a heap, as a decision mostly looks at the first few.
  struct Entry {
    double key;
    std::size_t i;
  };
  const auto later = [](const Entry& a, const Entry& b) {
    return a.key > b.key || (a.key == b.key && a.i > b.i);
  };
  std::vector<Entry> heap;
  heap.reserve(t.reps.size());
  for (std::size_t i = 0; i < t.reps.size(); ++i) {
    if (choice.open(i)) heap.push_back({choice.bound_cost(i), i});
  }
  std::make_heap(heap.begin(), heap.end(), later);
  int probes = 0;
  while (!heap.empty()) {
    std::pop_heap(heap.begin(), heap.end(), later);
    const std::size_t i = heap.back().i;
    heap.pop_back();
    // In bound order: once one is beaten, so is every later one (ties: by index, too).
    if (choice.beaten(i)) return true;
    if (choice.beaten_with_theta(i)) continue;  // its turn makes it lose: no need to measure it
    const std::optional<double> d = probe_length(obs, t, i, probes, kMaxProbes);
    if (!d) return false;
    choice.settled(i, *d);
  }
  return true;
}

/// choose_by_probes() for a weight box: exact lengths, best probe_key() first, for every
/// representative that does not already lose at its lower bound (BoxWatch::close_at_bound()),
/// until none is left open. False when the probes ran out first: `watch` holds what they found
/// and a search from the robot must finish it.
bool settle_by_probes(const Observation& obs, const EnergyAware::Terms& t, BoxWatch& watch) {
  std::vector<std::pair<double, std::size_t>> order;
  order.reserve(t.reps.size());
  for (std::size_t i = 0; i < t.reps.size(); ++i) {
    if (watch.open(i)) order.emplace_back(watch.probe_key(i), i);
  }
  std::sort(order.begin(), order.end());
  int probes = 0;
  for (const auto& [key, i] : order) {
    if (watch.close_at_bound(i)) continue;
    const std::optional<double> d = probe_length(obs, t, i, probes, 0);
    if (!d) return false;
    watch.settled(i, *d);
  }
  return true;
}

}  // namespace

Candidates EnergyAware::candidates_within_among(const Observation& obs, const WeightBounds& bounds) {
  if (params_.distance != "path" || obs.clusters.empty()) return candidates_among(obs);
  const std::span<const double> w_lo = bounds.lo;
  const std::span<const double> w_hi = bounds.hi;
  if (w_lo.size() != kFeatures || w_hi.size() != kFeatures) {
    throw std::invalid_argument(name_ + ": candidates_within needs " + std::to_string(kFeatures) +
                                " weights");
  }
  // The dock terms count if any vector of the box weighs them.
  const Terms t = terms(obs, w_hi[1] != 0.0 || w_hi[2] != 0.0);
  BoxWatch watch(t, bounds, obs.distances.lower_bounds_from_robot(t.reps));
  if (!settle_by_probes(obs, t, watch)) obs.distances.watch_from_robot(t.reps, t.d_l, watch);
  Candidates out;
  out.feature_count = kFeatures;
  for (std::size_t i = 0; i < t.reps.size(); ++i) {
    const double d_g = watch.d_g(i);
    if (!std::isfinite(d_g)) continue;
    out.cells.push_back(obs.known.cell(t.reps[i]));
    const auto row = t.features(i, d_g);
    out.features.insert(out.features.end(), row.begin(), row.end());
  }
  return out;
}

Decision EnergyAware::decide_among(const Observation& obs) {
  if (params_.distance != "path") return LinearScoredStrategy::decide(obs);
  if (obs.clusters.empty()) return on_no_candidate(obs);
  // Pure closest frontier without a battery limit: the nearest representative by path (ties to
  // the lowest cluster index), by one search from the robot that stops at the first one. Among
  // walls this beats probing (an A* to a representative behind a wall settles most of what
  // that search would).
  const bool pure_distance =
      weights_[1] == 0.0 && weights_[2] == 0.0 && weights_[3] == 0.0 && weights_[0] > 0.0;
  if (pure_distance && obs.battery.unlimited()) {
    std::vector<int> reps;
    reps.reserve(obs.clusters.size());
    for (const auto& c : obs.clusters) reps.push_back(c.representative);
    const int best = obs.distances.nearest_from_robot(reps);
    if (best < 0) return on_no_candidate(obs);
    return Decision::go_to(obs.known.cell(reps[static_cast<std::size_t>(best)]));
  }
  // The argmin of candidates(), computing d_g only as far as it can matter: first by point
  // searches for the best bounds, then, if they do not settle it, by a search from the robot
  // that stops once no representative it has not reached can win.
  const Terms t = own_terms(obs);
  WatchedChoice choice(t, weights_, obs.distances.lower_bounds_from_robot(t.reps));
  if (!choose_by_probes(obs, t, choice)) obs.distances.watch_from_robot(t.reps, t.d_l, choice);
  if (choice.best() < 0) return on_no_candidate(obs);
  return Decision::go_to(obs.known.cell(t.reps[static_cast<std::size_t>(choice.best())]));
}

Decision EnergyAware::on_no_candidate(const Observation& obs) {
  if (obs.battery.unlimited() || obs.robot == obs.dock) return Decision::finish();
  return Decision::return_to_dock();
}

}  // namespace strategies
}  // namespace fsweep
