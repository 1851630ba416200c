#pragma once
/// @file config_error_message.hpp
/// The message of a ConfigError in tests that check what bad input is told.

#include <string>

#include "core/config_error.hpp"

namespace fsweep::testing {

/// The message of the ConfigError that `f` throws (empty if none).
template <typename F>
std::string config_error(F f) {
  try {
    f();
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

}  // namespace fsweep::testing
