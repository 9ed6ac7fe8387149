// The subcommands of `sunglint`; each file cmd_*.cpp adds one to the app.
#pragma once

#include <CLI/CLI.hpp>

#include "methods/options.h"

namespace sg {

void add_render_command(CLI::App& app);
void add_diff_command(CLI::App& app);
void add_info_command(CLI::App& app);
void add_bench_command(CLI::App& app);
void add_compare_command(CLI::App& app);
void add_report_command(CLI::App& app);
void add_ocean_command(CLI::App& app);
void add_view_command(CLI::App& app);
void add_web_command(CLI::App& app);

}  // namespace sg
