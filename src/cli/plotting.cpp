#include "cli/plotting.hpp"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>

namespace fsweep::cli {
namespace {

constexpr const char* kSystemPython = "/usr/bin/python3";

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

/// The python3 executables on PATH, in PATH's order, then /usr/bin/python3; each once.
std::vector<std::string> python_candidates() {
  std::vector<std::string> out;
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path == nullptr ? "" : path);
  std::string dir;
  const auto add = [&](const std::string& candidate) {
    std::error_code ec;
    const auto canonical = std::filesystem::weakly_canonical(candidate, ec);
    if (access(candidate.c_str(), X_OK) != 0) return;
    for (const auto& o : out) {
      if (std::filesystem::weakly_canonical(o, ec) == canonical) return;
    }
    out.push_back(candidate);
  };
  while (std::getline(dirs, dir, ':')) {
    if (!dir.empty() && dir.front() == '/') add(dir + "/python3");
  }
  add(kSystemPython);
  return out;
}

}  // namespace

std::string python_with_matplotlib(std::vector<std::string>& tried) {
  for (const std::string& python : python_candidates()) {
    tried.push_back(python);
    if (run_process({python, "-c", "import matplotlib"}, ChildOutput::None) == 0) return python;
  }
  return {};
}

std::string tool_script(const std::string& script) {
  // An installed fsweep (cmake --install: <prefix>/bin/fsweep) finds its scripts in
  // <prefix>/share/fsweep/tools; a build in its source tree's tools/.
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const auto installed = exe.parent_path().parent_path() / "share" / "fsweep" / "tools" / script;
    if (std::filesystem::exists(installed, ec)) return installed.string();
  }
  return std::string(FSWEEP_SOURCE_DIR) + "/tools/" + script;
}

int run_tool_script(const std::string& script, const std::vector<std::string>& args, ChildOutput output) {
  const std::string path = tool_script(script);
  if (!std::filesystem::exists(path)) {
    std::cerr << "fsweep: error: " << path << ": script not found\n";
    return 2;
  }
  std::vector<std::string> tried;
  const std::string python = python_with_matplotlib(tried);
  if (python.empty()) {
    std::cerr << "fsweep: error: " << script << " needs python3 with matplotlib; none of";
    for (const auto& t : tried) std::cerr << ' ' << t;
    if (tried.empty()) std::cerr << " (no python3 on PATH or at " << kSystemPython << ")";
    std::cerr << " imports it (Debian: apt install python3-matplotlib)\n";
    return 2;
  }
  std::vector<std::string> command{python, path};
  command.insert(command.end(), args.begin(), args.end());
  const int code = run_process(command, output);
  if (code != 0) {
    std::cerr << "fsweep: error: " << path << " failed with " << python << " (exit code " << code << ")\n";
    return 1;
  }
  return 0;
}

int draw_plots(const std::string& dir, const std::string& out, int top, ChildOutput output) {
  return run_tool_script("plot.py", {dir, "--out", out, "--top", std::to_string(top)}, output);
}

}  // namespace fsweep::cli
