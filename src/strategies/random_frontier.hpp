#pragma once
/// @file random_frontier.hpp
/// The random-frontier baseline of Holz 2010 (section V): a uniformly random frontier goal.

#include <cstdint>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <string>

#include "core/random.hpp"
#include "strategies/strategy.hpp"

namespace fsweep {
inline namespace strategies {

/// Random frontier: the representatives of obs.clusters that the robot can reach
/// (obs.distances), in cluster order; the goal is the one at position uniform_below(count) of
/// the strategy's generator (stream "random_frontier" of the seed given at construction; one
/// draw per decision with at least one candidate). None reachable: finish.
/// State: the generator; clone() copies it, so a clone makes the same choices.
class RandomFrontier final : public Strategy {
 public:
  explicit RandomFrontier(std::uint64_t seed) : rng_(make_rng(seed, "random_frontier")) {}

  [[nodiscard]] std::string name() const override { return "random_frontier"; }
  [[nodiscard]] Decision decide(const Observation& obs) override;
  [[nodiscard]] std::unique_ptr<Strategy> clone() const override {
    return std::make_unique<RandomFrontier>(*this);
  }

  /// Equal generator states.
  friend bool operator==(const RandomFrontier& a, const RandomFrontier& b) { return a.rng_ == b.rng_; }

 private:
  Rng rng_;
};

}  // namespace strategies
}  // namespace fsweep
