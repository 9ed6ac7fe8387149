#include "cli/method_flags.h"

#include <sstream>
#include <vector>

#include "base/error.h"
#include "methods/method.h"

namespace sg {

void MethodFlags::finish(const std::string& context) {
  options.samples = parse_sample_counts(samples, context + "--samples");
}

void add_method_flags(CLI::App& app, MethodFlags& f) {
  app.add_option("--samples", f.samples, "Samples SxSxT for reference and supersample")
      ->capture_default_str();
  app.add_option("--seed", f.options.seed, "Seed of the sampling streams")->capture_default_str();
}

MethodVariant parse_method_variant(const std::string& text, const std::string& flag) {
  std::istringstream in(text);
  std::vector<std::string> words;
  for (std::string w; in >> w;)
    words.push_back(w);
  if (words.empty()) throw Error(flag + ": empty method variant");
  MethodVariant v;
  v.label = text;
  v.name = words[0];
  CLI::App app{"method variant"};
  MethodFlags flags;
  add_method_flags(app, flags);
  std::vector<std::string> args(words.rbegin(), words.rend() - 1);  // CLI11 wants them reversed
  try {
    app.parse(args);
  } catch (const CLI::ParseError& e) {
    throw Error(flag + ": '" + text + "': " + e.what());
  }
  flags.finish(flag + ": '" + text + "': ");
  v.options = flags.options;
  make_method(v.name, v.options);  // validates the name
  return v;
}

}  // namespace sg
