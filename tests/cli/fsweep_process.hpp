#pragma once
/// @file fsweep_process.hpp
/// Runs the built `fsweep` executable for command-line tests.

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace fsweep::testing {

/// Exit code (-1 when the process did not exit normally) and everything it printed.
struct CliOutcome {
  int code = -1;
  std::string output;  // stdout and stderr
};

/// Runs `fsweep ARGS` (a shell command line) from the build tree.
inline CliOutcome run_fsweep(const std::string& args) {
  const std::string cmd = std::string(FSWEEP_BINARY_DIR) + "/bin/fsweep " + args + " 2>&1";
  CliOutcome out;
  FILE* pipe = popen(cmd.c_str(), "r");
  if (pipe == nullptr) return out;
  std::array<char, 4096> buf{};
  while (fgets(buf.data(), static_cast<int>(buf.size()), pipe) != nullptr) out.output += buf.data();
  const int status = pclose(pipe);
  out.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return out;
}

}  // namespace fsweep::testing
