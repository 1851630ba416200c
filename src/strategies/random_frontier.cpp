#include "strategies/random_frontier.hpp"

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <vector>

#include "core/config_error.hpp"

namespace fsweep {
inline namespace strategies {

Decision RandomFrontier::decide(const Observation& obs) {
  std::vector<int> reps;
  reps.reserve(obs.clusters.size());
  for (const auto& c : obs.clusters) reps.push_back(c.representative);
  if (reps.empty()) return Decision::finish();
  const std::vector<double> d = obs.distances.from_robot(reps, std::numeric_limits<double>::infinity());
  std::vector<int> reachable;
  reachable.reserve(reps.size());
  for (std::size_t k = 0; k < reps.size(); ++k) {
    if (std::isfinite(d[k])) reachable.push_back(reps[k]);
  }
  if (reachable.empty()) return Decision::finish();
  const auto pick = static_cast<std::size_t>(uniform_below(rng_, reachable.size()));
  return Decision::go_to(obs.known.cell(reachable[pick]));
}

}  // namespace strategies
}  // namespace fsweep
