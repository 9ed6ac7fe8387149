// sunglint: renders the reflection of the sun or moon on moving water without aliasing or
// flicker, and the methods it is compared with; measures them against a ground truth.
//
// Exit codes: 0 success, 1 failed work, 2 a usage error (cli/args.h).
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <new>
#include <string>
#include <vector>

#include "base/error.h"
#include "cli/args.h"
#include "cli/commands.h"
#include "cli/path_tables.h"
#include "cli/slurm.h"
#include "gl_engine/program_notice.h"

namespace {

std::vector<std::string> subcommand_names(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* s : app.get_subcommands([](const CLI::App*) { return true; }))
    names.push_back(s->get_name());
  return names;
}

std::string joined(const std::vector<std::string>& v) {
  std::string t;
  for (const std::string& s : v)
    t += (t.empty() ? "" : ", ") + s;
  return t;
}

// A command-line mistake that CLI11 found, said as sunglint says its own: "sunglint: ",
// the culprit (an unknown subcommand with the list of them, an unknown flag with the one
// it may be a slip of), and where the help is. Exit code 2.
int parse_error(const CLI::App& app, const CLI::ParseError& e) {
  const std::vector<CLI::App*> parsed = app.get_subcommands();
  const CLI::App* sub = parsed.empty() ? nullptr : parsed.front();
  const std::string where = sub ? "sunglint " + sub->get_name() : "sunglint";
  const std::vector<std::string> rest = app.remaining();
  std::string message = e.what();
  if (sub == nullptr && !rest.empty() && rest.front().rfind("-", 0) != 0) {
    // Not a subcommand: CLI11 would say "A subcommand is required".
    const std::vector<std::string> subs = subcommand_names(app);
    const std::string near = sg::closest_name(rest.front(), subs);
    message = "unknown subcommand '" + rest.front() + "'" +
              (near.empty() ? "" : " (did you mean " + near + "?)") + "; the subcommands are " +
              joined(subs);
  } else if (sub == nullptr && dynamic_cast<const CLI::RequiredError*>(&e) != nullptr) {
    message = "give a subcommand: " + joined(subcommand_names(app));
    if (!rest.empty()) {
      const std::string name = rest.front().substr(0, rest.front().find('='));
      const std::string near = sg::closest_name(name, sg::flag_names(&app));
      message = "unknown flag '" + name + "'" +
                (near.empty() ? "" : " (did you mean " + near + "?)") + "; " + message;
    }
  } else if (dynamic_cast<const CLI::ExtrasError*>(&e) != nullptr && !rest.empty()) {
    auto flag = std::find_if(rest.begin(), rest.end(),
                             [](const std::string& a) { return a.size() > 1 && a[0] == '-'; });
    if (flag != rest.end()) {
      const std::string name = flag->substr(0, flag->find('='));
      const std::string near = sg::closest_name(name, sg::flag_names(sub ? sub : &app));
      message =
          "unknown flag '" + name + "'" + (near.empty() ? "" : " (did you mean " + near + "?)");
    } else {
      message = "unexpected argument '" + rest.front() + "'";
    }
    if (sub) message = sub->get_name() + ": " + message;
  }
  std::fprintf(stderr, "sunglint: %s\nRun '%s --help' for more information.\n", message.c_str(),
               where.c_str());
  return 2;
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
      "--cache-dir", [](const std::string& dir) { sg::set_cli_cache_dir(dir); },
      "Folder of sunglint's cache file, the path-integral tables of staa (path_tables.bin, "
      "8 MiB; default $SUNGLINT_CACHE_DIR, else $XDG_CACHE_HOME/sunglint, else "
      "~/.cache/sunglint)");
  // A GL program whose preparation takes a while (its first compile on a driver) is
  // announced, and its time said when it is ready.
  std::chrono::milliseconds notice_after = sg::gl_engine::kAnnounceAfter;
  if (const char* e = std::getenv("SUNGLINT_GL_NOTICE_AFTER"); e != nullptr && *e != 0) {
    const double s = std::strtod(e, nullptr);
    if (s >= 0 && s < 1e6) notice_after = std::chrono::milliseconds(std::lround(1000 * s));
  }
  sg::gl_engine::set_program_notice(
      [](const std::string& line) { std::fprintf(stderr, "sunglint: %s\n", line.c_str()); },
      notice_after);
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
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    return parse_error(app, e);  // a usage error
  } catch (const sg::UsageError& e) {
    const std::vector<CLI::App*> parsed = app.get_subcommands();
    std::fprintf(stderr, "sunglint: %s\nRun 'sunglint%s --help' for more information.\n", e.what(),
                 parsed.empty() ? "" : (" " + parsed.front()->get_name()).c_str());
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
