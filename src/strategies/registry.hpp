#pragma once
/// @file registry.hpp
/// Strategy names to factories, filled explicitly in src/strategies/register_all.cpp. The same
/// registry serves JSON, the command line and the tests.

#include <cstdint>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "strategies/strategy.hpp"

namespace fsweep {
inline namespace strategies {

/// Makes strategy `name` with `params` (JSON object or null for defaults; unknown keys are
/// errors) and the run seed (for strategies with random parts). Throws ConfigError at `where`
/// for an unknown name, listing the known ones.
[[nodiscard]] std::unique_ptr<Strategy> make_strategy(const std::string& name, const nlohmann::json& params,
                                                      std::uint64_t seed,
                                                      const std::string& where = "strategy");

/// Every registered strategy name, sorted.
[[nodiscard]] std::vector<std::string> strategy_names();

/// The resolved parameters of a strategy (defaults filled in), for outputs.
[[nodiscard]] nlohmann::json resolved_strategy_params(const std::string& name, const nlohmann::json& params);

}  // namespace strategies
}  // namespace fsweep
