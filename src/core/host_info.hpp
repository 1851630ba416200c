#pragma once
/// @file host_info.hpp
/// What the result files record about the machine they were made on (manifests, benchmark logs).

#include <string>

namespace fsweep {
inline namespace core {

/// This machine's host name (gethostname); "unknown" when it cannot be read.
[[nodiscard]] std::string host_name();

/// The first "model name" of /proc/cpuinfo (Linux); "unknown" elsewhere.
[[nodiscard]] std::string cpu_model();

}  // namespace core
}  // namespace fsweep
