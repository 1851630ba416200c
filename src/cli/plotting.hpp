#pragma once
/// @file plotting.hpp
/// The figures of an aggregated sweep directory, drawn by tools/plot.py with Debian's python3
/// and matplotlib: `fsweep plot` writes them, `fsweep report` embeds them.

#include <string>

namespace fsweep::cli {

/// Which of a child process's output streams go to the terminal.
enum class ChildOutput {
  All,         ///< stdout and stderr
  ErrorsOnly,  ///< stderr; stdout to /dev/null
  None,        ///< both to /dev/null
};

/// Draws the figures of `dir` (summary.csv, progress_summary.csv and best.csv must be there)
/// into `out` (created when missing): progress.png, metrics.png and the heat maps of weight
/// searches, the best `top` configurations. Returns 0, else the exit code for the CLI after
/// saying why on stderr: 2 when python3 with matplotlib or the script is missing, 1 when the
/// script fails.
[[nodiscard]] int draw_plots(const std::string& dir, const std::string& out, int top, ChildOutput output);

}  // namespace fsweep::cli
