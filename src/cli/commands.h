// The subcommands of `sunglint`; each file cmd_*.cpp adds one to the app.
#pragma once

#include <CLI/CLI.hpp>

#include "methods/options.h"

namespace sg {

// The flags of the methods' own options (--lean-*, --taa-*), shared by render and bench;
// defined in cmd_render.cpp. They write into `o`, which must outlive the parse.
void add_method_flags(CLI::App* c, MethodOptions& o);

void add_render_command(CLI::App& app);
void add_diff_command(CLI::App& app);
void add_info_command(CLI::App& app);
void add_bench_command(CLI::App& app);

}  // namespace sg
