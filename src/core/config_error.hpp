#pragma once
/// @file config_error.hpp
/// Bad configuration is an exception carrying where it is (file, JSON path or map cell),
/// what was found and what is allowed. Expected outcomes (no path, range limited) are values.

#include <initializer_list>
#include <nlohmann/json_fwd.hpp>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace fsweep {
inline namespace core {

/// One configuration problem. `where` is a file, a JSON path (e.g. `/strategies/0/params/w1`)
/// or a map cell; `message` says what is wrong and what is allowed.
class ConfigError : public std::runtime_error {
 public:
  ConfigError(std::string where, const std::string& message)
      : std::runtime_error(where.empty() ? message : where + ": " + message), where_(std::move(where)) {}
  [[nodiscard]] const std::string& where() const { return where_; }

 private:
  std::string where_;
};

/// Throws ConfigError at `where` if `object` is not a JSON object or has a key not in
/// `allowed`; the message lists the allowed keys.
void require_known_keys(const nlohmann::json& object, std::initializer_list<std::string_view> allowed,
                        const std::string& where);

/// "a, b, c": names joined for messages.
[[nodiscard]] std::string join_names(const std::vector<std::string>& names);

}  // namespace core
}  // namespace fsweep
