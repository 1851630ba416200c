#pragma once
/// @file fsweep_process.hpp
/// Runs the built `fsweep` executable for command-line tests.

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "sweep/sweep_test_files.hpp"

namespace fsweep::testing {

/// Exit code (-1 when the process did not exit normally) and everything it printed.
struct CliOutcome {
  int code = -1;
  std::string output;  // stdout and stderr
};

/// Runs the shell command line `command` (stderr into the output).
inline CliOutcome run_command(const std::string& command) {
  const std::string cmd = command + " 2>&1";
  CliOutcome out;
  FILE* pipe = popen(cmd.c_str(), "r");
  if (pipe == nullptr) return out;
  std::array<char, 4096> buf{};
  while (fgets(buf.data(), static_cast<int>(buf.size()), pipe) != nullptr) out.output += buf.data();
  const int status = pclose(pipe);
  out.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return out;
}

/// Runs `fsweep ARGS` (a shell command line) from the build tree, or from `dir` when given (the
/// README's commands name files relative to the repository).
inline CliOutcome run_fsweep(const std::string& args, const std::string& dir = "") {
  std::string command = dir.empty() ? std::string() : "cd '" + dir + "' && ";
  command += FSWEEP_BINARY_DIR;  // appended, not `+`: GCC 12 warns on the temporaries
  command += "/bin/fsweep ";
  command += args;
  return run_command(command);
}

/// A fresh (removed) directory under the system temp dir, unique per process:
/// <tmp>/fsweep_cli_<tag>_<name>_<pid>; removed after the program's tests if all passed
/// (ScratchDirs).
inline std::string fresh_temp_dir(const std::string& tag, const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("fsweep_cli_" + tag + "_" + name + "_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  ScratchDirs::add(dir);
  return dir.string();
}

/// A sweep of 2 runs (one generated rooms map, closest_frontier, 2 repetitions) named `name`
/// with sweep seed `seed`, written to `dir`/`name`.json (`dir` created); returns its path.
inline std::string write_named_sweep(const std::string& dir, const std::string& name, int seed) {
  std::filesystem::create_directories(dir);
  const std::string path = dir + "/" + name + ".json";
  std::ofstream(path) << R"({"schema_version": 1, "name": ")" << name << R"(",
    "maps": ["rooms:w=24,h=20,door=2,seed=2"], "strategies": [{"name": "closest_frontier"}],
    "repetitions": 2, "seed": )"
                      << seed << "}";
  return path;
}

/// The whole file ("" when it cannot be read).
inline std::string read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Number of lines of a text file (0 when it cannot be read).
inline int count_lines(const std::string& path) {
  std::ifstream f(path);
  int n = 0;
  for (std::string line; std::getline(f, line);) ++n;
  return n;
}

}  // namespace fsweep::testing
