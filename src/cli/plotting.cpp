#include "cli/plotting.hpp"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <iostream>
#include <vector>

namespace fsweep::cli {
namespace {

constexpr const char* kPython = "/usr/bin/python3";

/// Runs `args` (args[0] an absolute path) and returns its exit code (-1 if it could not run or
/// was killed).
int run_process(const std::vector<std::string>& args, ChildOutput output) {
  std::vector<char*> argv;
  argv.reserve(args.size() + 1);
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  std::cout.flush();
  const pid_t pid = fork();
  if (pid < 0) return -1;
  if (pid == 0) {
    if (output != ChildOutput::All) {
      const int null = open("/dev/null", O_WRONLY);
      if (null >= 0) {
        dup2(null, STDOUT_FILENO);
        if (output == ChildOutput::None) dup2(null, STDERR_FILENO);
      }
    }
    execv(argv[0], argv.data());
    _exit(127);
  }
  int status = 0;
  if (waitpid(pid, &status, 0) < 0) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

int draw_plots(const std::string& dir, const std::string& out, int top, ChildOutput output) {
  const std::string script = std::string(FSWEEP_SOURCE_DIR) + "/tools/plot.py";
  if (!std::filesystem::exists(kPython) ||
      run_process({kPython, "-c", "import matplotlib"}, ChildOutput::None) != 0) {
    std::cerr << "fsweep: error: plotting needs " << kPython
              << " with matplotlib (Debian: apt install python3-matplotlib)\n";
    return 2;
  }
  if (!std::filesystem::exists(script)) {
    std::cerr << "fsweep: error: " << script << ": plotting script not found\n";
    return 2;
  }
  const int code = run_process({kPython, script, dir, "--out", out, "--top", std::to_string(top)}, output);
  if (code != 0) {
    std::cerr << "fsweep: error: " << script << " failed (exit code " << code << ")\n";
    return 1;
  }
  return 0;
}

}  // namespace fsweep::cli
