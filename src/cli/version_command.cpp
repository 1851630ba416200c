/// @file version_command.cpp
/// `fsweep version` (and `fsweep --version`): this build's version and its libraries'.

#include <iostream>

#include "cli/commands.hpp"
#include "sweep/manifest.hpp"

namespace fsweep::cli {

Command add_version_command(CLI::App& app) {
  app.add_subcommand("version",
                     "Print fsweep's version, the compiler and the libraries' versions (as --version)");
  return [] {
    std::cout << version_text();
    return 0;
  };
}

}  // namespace fsweep::cli
