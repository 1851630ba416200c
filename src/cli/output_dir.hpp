#pragma once
/// @file output_dir.hpp
/// The output directory of a subcommand.

#include <string>

namespace fsweep {

/// Creates `dir` and its parents (nothing to do when it exists). Throws ConfigError naming
/// `dir` and the system's reason when it cannot be created (e.g. a file of that name exists).
void create_output_dir(const std::string& dir);

}  // namespace fsweep
