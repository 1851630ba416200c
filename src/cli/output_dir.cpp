#include "cli/output_dir.hpp"

#include <filesystem>
#include <system_error>

#include "core/config_error.hpp"

namespace fsweep {

void create_output_dir(const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw ConfigError(dir, "cannot create the output directory: " + ec.message());
}

}  // namespace fsweep
