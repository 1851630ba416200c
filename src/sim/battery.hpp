#pragma once
/// @file battery.hpp
/// Battery with a remaining-range estimate (Rappaport 2016 eq. 5).

#include <limits>

namespace fsweep {
inline namespace sim {

/// Charge bookkeeping. Unlimited when the capacity is +infinity.
class Battery {
 public:
  /// `straight_rate` is the energy per metre of straight travel (the estimate before any
  /// motion).
  Battery(double capacity, double straight_rate)
      : capacity_(capacity), level_(capacity), straight_rate_(straight_rate) {}

  [[nodiscard]] bool unlimited() const { return capacity_ == std::numeric_limits<double>::infinity(); }
  [[nodiscard]] double capacity() const { return capacity_; }
  [[nodiscard]] double level() const { return level_; }
  [[nodiscard]] bool full() const { return level_ >= capacity_; }

  /// Draws `energy` for `metres` of travel. Returns false (and draws nothing) if the charge
  /// does not cover it.
  bool draw(double energy, double metres) {
    if (!unlimited() && energy > level_ + 1e-9 * capacity_) return false;
    if (!unlimited()) level_ = level_ > energy ? level_ - energy : 0.0;
    used_energy_ += energy;
    used_metres_ += metres;
    return true;
  }

  void recharge() { level_ = capacity_; }

  /// Remaining range d_l (metres). Rappaport eq. 5 divides the charge by the moving power and
  /// multiplies by the average speed so far, i.e. divides by the average energy per metre so
  /// far; that is what this returns (straight-travel rate before any motion).
  [[nodiscard]] double remaining_range_m() const {
    if (unlimited()) return std::numeric_limits<double>::infinity();
    const double rate = used_metres_ > 0.0 ? used_energy_ / used_metres_ : straight_rate_;
    return level_ / rate;
  }

 private:
  double capacity_;
  double level_;
  double straight_rate_;
  double used_energy_ = 0.0;
  double used_metres_ = 0.0;
};

}  // namespace sim
}  // namespace fsweep
