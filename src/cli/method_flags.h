// The flags that configure methods, defined once: `render` and `bench` add them to their
// command lines, and `compare` parses each method variant it is given ("staa --ndf
// per-pixel") with the same definitions, so a flag means the same thing everywhere.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "gl_engine/engines.h"
#include "methods/options.h"

namespace sg {

// Storage for the flags' values; `finish` checks them and converts the few that need it.
struct MethodFlags {
  std::string samples;                                      // empty: the method's default
  std::string engine_name = "cpu";                          // --engine
  const CLI::Option* intersect_tolerance_option = nullptr;  // --intersect-tolerance
  Engine engine = Engine::cpu;                              // set by finish()
  MethodOptions options;
  // The flags that configure some methods only, with those methods (add_method_flags
  // fills it; --engine configures every method and is not listed).
  struct Scoped {
    const CLI::Option* option;
    std::vector<std::string> methods;
  };
  std::vector<Scoped> scoped;
  // Method flags that add_method_flags does not know the methods of (taken by every method):
  // a new flag belongs in its table (method_flags_test checks that none is left here).
  std::vector<std::string> unscoped;
  // `context` prefixes error messages (e.g. the method variant being parsed).
  void finish(const std::string& context = "");
  // Refuses a flag given on the command line that none of `methods` takes: "--samples: not
  // a flag of method point (it configures supersample, reference)" (throws sg::Error, a
  // usage error to the caller).
  void check_taken_by(const std::vector<std::string>& methods,
                      const std::string& context = "") const;
};

void add_method_flags(CLI::App& app, MethodFlags& flags);

// A method variant as `compare` takes it: "NAME [FLAGS...]", e.g.
// "supersample --samples 6x6x1". Returns the method name and its options; throws
// sg::Error naming `flag` (the option that gave it) and the variant on a bad flag.
struct MethodVariant {
  std::string label;  // the text as given, used in tables and file names
  std::string name;
  MethodOptions options;
  Engine engine = Engine::cpu;  // its --engine
};

// Checks that `engine` runs `name` with `options` (the GL engine runs the kernel methods
// only), without starting it; throws sg::Error naming the method or flag, after `context`.
void check_engine_runs(Engine engine, const std::string& name, const MethodOptions& options,
                       const std::string& context = "");
MethodVariant parse_method_variant(const std::string& text, const std::string& flag = "--methods");

}  // namespace sg
