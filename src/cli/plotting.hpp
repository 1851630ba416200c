#pragma once
/// @file plotting.hpp
/// The Python scripts of tools/ run by the CLI: the figures of an aggregated sweep directory
/// (tools/plot.py: `fsweep plot` writes them, `fsweep report` embeds them) and the coverage
/// curves of `fsweep paired --curves` (tools/paired_compare.py), with a Python that has
/// matplotlib.

#include <string>
#include <vector>

namespace fsweep::cli {

/// Which of a child process's output streams go to the terminal.
enum class ChildOutput {
  All,         ///< stdout and stderr
  ErrorsOnly,  ///< stderr; stdout to /dev/null
  None,        ///< both to /dev/null
};

/// The Python the scripts run with: the first `python3` on PATH that imports matplotlib, else
/// /usr/bin/python3 if it does (Debian's python3-matplotlib). Empty when none does; `tried` then
/// lists each interpreter tried, in order.
[[nodiscard]] std::string python_with_matplotlib(std::vector<std::string>& tried);

/// The path of tools/`script`: <prefix>/share/fsweep/tools/`script` when this fsweep is installed
/// (<prefix>/bin/fsweep, cmake --install) and the script is there, else the source tree's.
[[nodiscard]] std::string tool_script(const std::string& script);

/// Runs tool_script(`script`) with `args` under python_with_matplotlib(). Returns 0, else the exit code
/// for the CLI after saying why on stderr (naming the interpreter): 2 when no Python with
/// matplotlib or the script is missing, 1 when the script fails.
[[nodiscard]] int run_tool_script(const std::string& script, const std::vector<std::string>& args,
                                  ChildOutput output);

/// Draws the figures of `dir` (summary.csv, progress_summary.csv and best.csv must be there)
/// into `out` (created when missing): progress.png, metrics.png and the heat maps of weight
/// searches, the best `top` configurations (run_tool_script()'s exit codes).
[[nodiscard]] int draw_plots(const std::string& dir, const std::string& out, int top, ChildOutput output);

}  // namespace fsweep::cli
