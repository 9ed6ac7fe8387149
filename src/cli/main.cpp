// sunglint: renders the reflection of the sun or moon on moving water without aliasing or
// flicker, and the methods it is compared with; measures them against a ground truth.
//
// Exit codes: 0 success, 1 failed work, 2 a usage error (cli/args.h).
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <new>

#include "base/error.h"
#include "cli/args.h"
#include "cli/commands.h"
#include "cli/slurm.h"
#include "shading/path_table.h"

namespace {

// The path-integral tables (used by `staa`) are generated once and cached in a 64 MiB file;
// say so when that happens, and where.
void announce_path_table_cache(const sg::PathTableCacheResult& r) {
  if (r.written) {
    std::fprintf(stderr,
                 "sunglint: generated the path-integral tables and cached them in %s (64 MiB, "
                 "reused by later runs; --cache-dir or SUNGLINT_CACHE_DIR choose the folder)\n",
                 r.path.c_str());
  } else {
    std::fprintf(stderr, "sunglint: generated the path-integral tables in memory (%s)\n",
                 r.note.c_str());
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "sunglint: anti-aliased, flicker-free reflections of the sun and moon on moving water\n"
      "Exit codes: 0 success, 1 failed work (unreadable or invalid input, unwritable output),\n"
      "2 usage error (unknown or missing flag, bad flag value)"};
  sg::set_program_arguments(argc, argv);
  app.require_subcommand(1);
  app.fallthrough();  // --cache-dir may follow the subcommand
  app.set_version_flag("--version", "sunglint 0.1.0");
  app.add_option_function<std::string>(
      "--cache-dir", [](const std::string& dir) { sg::PathTables::set_cache_dir(dir); },
      "Folder of sunglint's cache file, the path-integral tables of staa (path_tables.bin, "
      "64 MiB; default $SUNGLINT_CACHE_DIR, else $XDG_CACHE_HOME/sunglint, else "
      "~/.cache/sunglint)");
  sg::PathTables::set_cache_notice(announce_path_table_cache);
  sg::add_render_command(app);
  sg::add_diff_command(app);
  sg::add_info_command(app);
  sg::add_bench_command(app);
  sg::add_compare_command(app);
  sg::add_report_command(app);
  sg::add_ocean_command(app);
  sg::add_view_command(app);
  sg::add_web_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version exit 0; every other parse error is a usage error.
    return app.exit(e) == 0 ? 0 : 2;
  } catch (const sg::UsageError& e) {
    std::fprintf(stderr, "sunglint: %s\nRun with --help for more information.\n", e.what());
    return 2;
  } catch (const sg::Error& e) {
    std::fprintf(stderr, "sunglint: %s\n", e.what());
    return 1;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "sunglint: out of memory\n");
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sunglint: %s\n", e.what());
    return 1;
  }
  return 0;
}
