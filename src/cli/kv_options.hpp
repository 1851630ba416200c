#pragma once
/// @file kv_options.hpp
/// `--param key=value` options to JSON: dotted keys nest (`sensor.range_m=30`), values are
/// read as JSON when they parse (`3`, `true`, `[1,2]`) and as strings otherwise.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace fsweep {

/// Builds a JSON object from `key=value` items. Throws ConfigError naming `option` for an
/// item without '='. Returns null for no items.
[[nodiscard]] nlohmann::json kv_to_json(const std::vector<std::string>& items, const std::string& option);

}  // namespace fsweep
