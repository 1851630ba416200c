#pragma once
/// @file registry.hpp
/// The strategy registry (core/registry.hpp), filled explicitly in
/// src/strategies/register_all.cpp. The same registry serves JSON, the command line
/// (`fsweep describe strategy`) and the tests.

#include <cstdint>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "core/registry.hpp"
#include "strategies/strategy.hpp"

namespace fsweep {
inline namespace strategies {

/// Strategies, made from their typed params and the run seed (for strategies with random parts).
using StrategyRegistry = Registry<std::unique_ptr<Strategy>, std::uint64_t>;
/// A strategy resolved once: name, resolved params (every parameter), maker.
using StrategyConfig = StrategyRegistry::Configured;

/// What a strategy declares of itself beside its parameters (register_all.cpp, beside each
/// registration).
struct StrategyTraits {
  /// Draws random numbers from the seed it is made with (the run seed's "strategy" stream): runs
  /// that differ only in their seed (a sweep's repetitions) choose differently.
  bool seeded = false;
  /// Its strategies are LinearScoredStrategy (Strategy::linear_scored() is not null): they choose
  /// argmin(weights . features), so the exact weight search can search their weights.
  bool linear_scored = false;
};

/// Every registered strategy.
[[nodiscard]] const StrategyRegistry& strategy_registry();

/// The traits of strategy `name` (the defaults for a name not registered).
[[nodiscard]] StrategyTraits strategy_traits(std::string_view name);

/// Resolves strategy `name` with `params` (JSON object or null for defaults). Throws ConfigError
/// at `where` for an unknown name (listing the known ones) and one ConfigError listing every
/// bad parameter at `params_where`/<key> (default `where`/params). A "heuristics" key is refused with a
/// message naming its new place (a sibling of "params" in a sweep's strategy entry; src/sim/heuristics.hpp).
[[nodiscard]] StrategyConfig configure_strategy(const std::string& name, const nlohmann::json& params,
                                                const std::string& where = "strategy",
                                                const std::string& params_where = {});

/// configure_strategy(name, params, where).make(seed).
[[nodiscard]] std::unique_ptr<Strategy> make_strategy(const std::string& name, const nlohmann::json& params,
                                                      std::uint64_t seed,
                                                      const std::string& where = "strategy");

/// Every registered strategy name, sorted.
[[nodiscard]] std::vector<std::string> strategy_names();

}  // namespace strategies
}  // namespace fsweep
