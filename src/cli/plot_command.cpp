/// @file plot_command.cpp
/// `fsweep plot DIR`: the sweep's figures, drawn by tools/plot.py with Debian's python3 and
/// matplotlib (progress.png, metrics.png, and heatmap_<wi>_<wj>.png for weight searches).

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "report/aggregate.hpp"

namespace fsweep::cli {
namespace {

constexpr const char* kPython = "/usr/bin/python3";

struct PlotOptions {
  std::string dir;
  std::string out;  // empty: DIR/plots
  int top = 10;     // configurations drawn, best first
};

/// Runs `args` (args[0] an absolute path) and returns its exit code (-1 if it could not run or
/// was killed). `quiet` sends its output to /dev/null.
int run_process(const std::vector<std::string>& args, bool quiet) {
  std::vector<char*> argv;
  argv.reserve(args.size() + 1);
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  std::cout.flush();
  const pid_t pid = fork();
  if (pid < 0) return -1;
  if (pid == 0) {
    if (quiet) {
      const int null = open("/dev/null", O_WRONLY);
      if (null >= 0) {
        dup2(null, STDOUT_FILENO);
        dup2(null, STDERR_FILENO);
      }
    }
    execv(argv[0], argv.data());
    _exit(127);
  }
  int status = 0;
  if (waitpid(pid, &status, 0) < 0) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

int run_plot(const PlotOptions& o) {
  const std::string script = std::string(FSWEEP_SOURCE_DIR) + "/tools/plot.py";
  if (!std::filesystem::exists(kPython) || run_process({kPython, "-c", "import matplotlib"}, true) != 0) {
    std::cerr << "fsweep: error: plotting needs " << kPython
              << " with matplotlib (Debian: apt install python3-matplotlib)\n";
    return 2;
  }
  if (!std::filesystem::exists(script)) {
    std::cerr << "fsweep: error: " << script << ": plotting script not found\n";
    return 2;
  }
  for (const char* name : {"summary.csv", "progress_summary.csv", "best.csv"}) {
    if (!std::filesystem::exists(o.dir + "/" + name)) {
      std::cout << o.dir << " has no " << name << ": aggregating first\n";
      aggregate(o.dir, AggregateOptions{});
      break;
    }
  }
  const std::string out = o.out.empty() ? o.dir + "/plots" : o.out;
  const int code = run_process({kPython, script, o.dir, "--out", out, "--top", std::to_string(o.top)}, false);
  if (code != 0) {
    std::cerr << "fsweep: error: " << script << " failed (exit code " << code << ")\n";
    return 1;
  }
  return 0;
}

}  // namespace

Command add_plot_command(CLI::App& app) {
  auto o = std::make_shared<PlotOptions>();
  CLI::App* sub = app.add_subcommand(
      "plot",
      "Draw a sweep's figures (progress bands, metric bars, weight heat maps) with python3-matplotlib");
  sub->add_option("DIR", o->dir, "Sweep output directory (aggregated first if summary files are missing)")
      ->required();
  sub->add_option("--out", o->out, "Directory for the PNGs (default: DIR/plots)");
  sub->add_option("--top", o->top, "Draw the best N configurations (by best.csv)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  return [o] { return run_plot(*o); };
}

}  // namespace fsweep::cli
