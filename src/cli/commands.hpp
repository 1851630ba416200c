#pragma once
/// @file commands.hpp
/// The subcommands of `fsweep`. Each registers its options on the CLI11 app and returns the
/// function that runs it (exit code).

#include <CLI/CLI.hpp>
#include <functional>

namespace fsweep::cli {

using Command = std::function<int()>;

Command add_sim_command(CLI::App& app);
Command add_optimum_command(CLI::App& app);
Command add_plan_command(CLI::App& app);
Command add_plan_compare_command(CLI::App& app);
Command add_plan_bench_command(CLI::App& app);
Command add_run_command(CLI::App& app);
Command add_expand_command(CLI::App& app);
Command add_aggregate_command(CLI::App& app);
Command add_merge_command(CLI::App& app);
Command add_compare_command(CLI::App& app);
Command add_slurm_command(CLI::App& app);
Command add_plot_command(CLI::App& app);
Command add_report_command(CLI::App& app);
Command add_describe_command(CLI::App& app);
Command add_export_sqlite_command(CLI::App& app);
Command add_paired_command(CLI::App& app);
Command add_verify_command(CLI::App& app);
Command add_version_command(CLI::App& app);
Command add_completion_command(CLI::App& app);

}  // namespace fsweep::cli
