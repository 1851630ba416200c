#include "core/config_error.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "core/json_excerpt.hpp"

namespace fsweep {
inline namespace core {

std::string join_names(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) {
    if (!out.empty()) out += ", ";
    out += n;
  }
  return out;
}

void require_known_keys(const nlohmann::json& object, std::initializer_list<std::string_view> allowed,
                        const std::string& where) {
  if (!object.is_object()) {
    throw ConfigError(where, "expected a JSON object, got " + json_excerpt(object));
  }
  for (const auto& [key, value] : object.items()) {
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
      std::vector<std::string> names(allowed.begin(), allowed.end());
      // NOLINTNEXTLINE(performance-inefficient-string-concatenation): runs once, then throws
      throw ConfigError(where + "/" + key, "unknown key '" + key + "'; allowed: " + join_names(names));
    }
  }
}

}  // namespace core
}  // namespace fsweep
