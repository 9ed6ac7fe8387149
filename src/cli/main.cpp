// sunglint: renders the reflection of the sun or moon on moving water without aliasing or
// flicker, and the methods it is compared with; measures them against a ground truth.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <new>

#include "base/error.h"
#include "cli/commands.h"

int main(int argc, char** argv) {
  CLI::App app{
      "sunglint: anti-aliased, flicker-free reflections of the sun and moon on moving water"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "sunglint 0.1.0");
  sg::add_render_command(app);
  sg::add_diff_command(app);
  sg::add_info_command(app);
  sg::add_bench_command(app);
  sg::add_compare_command(app);
  sg::add_report_command(app);
  sg::add_ocean_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
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
