#include "cli/kv_options.hpp"

#include "core/config_error.hpp"
#include "core/json_text.hpp"

namespace fsweep {

nlohmann::json kv_to_json(const std::vector<std::string>& items, const std::string& option) {
  if (items.empty()) return nullptr;
  nlohmann::json out = nlohmann::json::object();
  for (const auto& item : items) {
    const auto eq = item.find('=');
    if (eq == std::string::npos || eq == 0) {
      throw ConfigError(option, "expected key=value, got '" + item + "'");
    }
    const std::string key = item.substr(0, eq);
    const std::string text = item.substr(eq + 1);
    nlohmann::json value = parse_json_or_discard(text);
    if (value.is_discarded()) value = text;
    nlohmann::json* node = &out;
    std::size_t start = 0;
    for (auto dot = key.find('.'); dot != std::string::npos; dot = key.find('.', start)) {
      node = &(*node)[key.substr(start, dot - start)];
      start = dot + 1;
    }
    (*node)[key.substr(start)] = value;
  }
  return out;
}

}  // namespace fsweep
