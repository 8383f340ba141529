#pragma once
// The subcommands of the blockdem tool, one file each. Each adds itself to the CLI11 app and
// runs through its callback; errors are thrown and reported by main().
#include <string>

#include <CLI/CLI.hpp>

namespace blockdem::cli {

void add_run_command(CLI::App& app);
void add_check_command(CLI::App& app);
void add_motion_command(CLI::App& app);
void add_report_command(CLI::App& app);
void add_bench_command(CLI::App& app);
void add_sweep_command(CLI::App& app);
void add_converge_command(CLI::App& app);
void add_calibrate_command(CLI::App& app);
void add_export_command(CLI::App& app);
void add_limit_command(CLI::App& app);

/// Thrown by a command to end the program with this status, after its own message (an
/// interrupted run: 130 / 143).
struct ExitStatus {
    int code = 0;
};

/// Sets the number of threads of the time step (--threads of run and bench; step_threads.cpp).
/// Results do not depend on it (world/parallel.hpp). Throws CLI::ValidationError for n < 1, or
/// n > 1 in a build without OpenMP.
void set_step_threads(int n);

/// The figure files a report writes by default: the page's PNGs and an SVG copy for papers.
inline constexpr const char* default_figure_formats = "png,svg";
/// Writes out_dir/report.html and out_dir/figures/ through tools/blockdem_report.py (cmd_report.cpp),
/// the figures in formats (comma-separated: png, svg, pdf; png always).
void write_report(const std::string& out_dir, bool animation_file = true,
                  const std::string& formats = default_figure_formats);

}  // namespace blockdem::cli
