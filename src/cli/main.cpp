/// @file main.cpp
/// `fsweep`: the frontier-sweep command line. Errors in the configuration print one message
/// naming the file, JSON path or map cell and exit with code 2; a file the machine does not let
/// it write (a full disk, a file size limit, a read-only directory) prints one naming the file
/// and the OS error and exits with code 1.

#include <malloc.h>

#include <csignal>
#include <iostream>
#include <map>

#include "cli/commands.hpp"
#include "cli/option_checks.hpp"
#include "core/config_error.hpp"
#include "core/io_error.hpp"
#include "sweep/manifest.hpp"

namespace {

/// The allocator policy of a batch engine. A sweep runs thousands of simulations, each of which
/// allocates and frees map-sized arrays; glibc's default hands the top of the heap back to the
/// system once 128 KB of it are free, and the next run faults the same pages in again
/// (measured: 1-4 thousand page faults instead of 700 on 1/20 of the weight search, 5-8% of its
/// time). Keep up to 512 MB of freed heap for the next run instead. Arrays of 128 KB and more
/// still get their own mappings, returned when freed, so a run's peak stays what it needs.
void keep_freed_memory() {
  constexpr int kTrimThreshold = 512 << 20;
  constexpr int kMmapThreshold = 128 << 10;  // glibc's default, now fixed (no longer adaptive)
  (void)mallopt(M_TRIM_THRESHOLD, kTrimThreshold);
  (void)mallopt(M_MMAP_THRESHOLD, kMmapThreshold);
}

/// A write past the file size limit (`ulimit -f`, RLIMIT_FSIZE) raises SIGXFSZ, whose default
/// action kills the process (exit status 153 in a shell) in the middle of a write, without a word.
/// Ignored, the write fails with EFBIG instead, and the writers report it as any full disk
/// (IoError: the file and the OS error, every file left whole). Set here, once for the process:
/// a signal's disposition is the process's, which a library should not change under its caller.
void fail_writes_past_the_file_size_limit() { (void)std::signal(SIGXFSZ, SIG_IGN); }

}  // namespace

// A function-try-block: whatever escapes the setup or a command ends in the message and exit code
// 2 too, not in std::terminate.
int main(int argc, char** argv) try {
  keep_freed_memory();
  fail_writes_past_the_file_size_limit();
  CLI::App app{"frontier-sweep: experiments on 2D frontier exploration strategies and planners"};
  std::string version = fsweep::version_text();
  version.pop_back();  // CLI11 ends the text with its own newline
  app.set_version_flag("--version", version);
  app.require_subcommand(1);
  std::map<std::string, fsweep::cli::Command> commands;
  commands["sim"] = fsweep::cli::add_sim_command(app);
  commands["optimum"] = fsweep::cli::add_optimum_command(app);
  commands["plan"] = fsweep::cli::add_plan_command(app);
  commands["plan-compare"] = fsweep::cli::add_plan_compare_command(app);
  commands["plan-bench"] = fsweep::cli::add_plan_bench_command(app);
  commands["run"] = fsweep::cli::add_run_command(app);
  commands["expand"] = fsweep::cli::add_expand_command(app);
  commands["aggregate"] = fsweep::cli::add_aggregate_command(app);
  commands["merge"] = fsweep::cli::add_merge_command(app);
  commands["compare"] = fsweep::cli::add_compare_command(app);
  commands["paired"] = fsweep::cli::add_paired_command(app);
  commands["slurm"] = fsweep::cli::add_slurm_command(app);
  commands["plot"] = fsweep::cli::add_plot_command(app);
  commands["report"] = fsweep::cli::add_report_command(app);
  commands["describe"] = fsweep::cli::add_describe_command(app);
  commands["export-sqlite"] = fsweep::cli::add_export_sqlite_command(app);
  commands["verify"] = fsweep::cli::add_verify_command(app);
  commands["version"] = fsweep::cli::add_version_command(app);
  commands["completion"] = fsweep::cli::add_completion_command(app);
  fsweep::cli::check_number_options(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << fsweep::cli::parse_error_message(app, e) << '\n';
    return 2;
  }
  try {
    for (const auto& [name, run] : commands) {
      if (app.got_subcommand(name)) return run();
    }
  } catch (const fsweep::ConfigError& e) {
    std::cerr << "fsweep: error: " << e.what() << '\n';
    return 2;
  } catch (const fsweep::IoError& e) {  // not the user's input: 1, as a run that cannot finish
    std::cerr << "fsweep: error: " << e.what() << '\n';
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "fsweep: error: " << e.what() << '\n';
    return 2;
  }
  return 2;
} catch (const std::exception& e) {
  std::cerr << "fsweep: error: " << e.what() << '\n';
  return 2;
}
