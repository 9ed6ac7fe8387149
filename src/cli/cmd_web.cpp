// `sunglint web SCENE... -o DIR`: the live page (web/web_page.h, docs/web.md): the shading
// kernel in the browser as WebGL 2 fragment shaders, on these scenes. Everything is checked
// before a file is written: the flags (exit 2), the scenes (exit 1, the loader's message),
// the folder (created if missing).
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "base/error.h"
#include "cli/args.h"
#include "cli/commands.h"
#include "cli/path_tables.h"
#include "scene/scene.h"
#include "web/web_page.h"

namespace sg {
namespace {

struct WebArgs {
  std::vector<std::string> scenes;
  std::string out;
  int width = 0, height = 0;
};

void run_web(const WebArgs& a) {
  check_usage([&] {
    if (a.scenes.empty()) throw Error("give at least one scene file");
    if (a.out.empty()) throw Error("--out: give the page's folder");
  });
  web::WebPageOptions o;
  o.out_dir = a.out;
  for (const std::string& path : a.scenes) {
    Scene s = load_scene(path);
    check_usage([&] { apply_image_size(s, a.width, a.height); });
    o.scenes.push_back({path, s.width, s.height});
  }
  const web::WebPage page = web::write_web_page(o, cli_path_tables().tables());
  std::string names;
  for (const std::string& n : page.scene_names)
    names += (names.empty() ? "" : ", ") + n;
  std::printf("web: %s/index.html (%zu files, %.2f MiB; scenes %s)\n", a.out.c_str(),
              page.files.size(), page.total_bytes / 1048576.0, names.c_str());
  if (page.total_bytes > web::kWebPageBudgetBytes) {
    std::fprintf(stderr,
                 "sunglint: note: the page takes %.2f MiB, more than its 2 MiB budget "
                 "(docs/web.md): the scene files make the difference\n",
                 page.total_bytes / 1048576.0);
  }
}

}  // namespace

void add_web_command(CLI::App& app) {
  auto a = std::make_shared<WebArgs>();
  CLI::App* c = app.add_subcommand(
      "web",
      "Write a static web page that runs the method live in a browser (WebGL 2): the scenes "
      "animated, a split view, the sun, the exposure; docs/web.md");
  c->add_option("scenes", a->scenes, "Scene files (sunglint-scene/1 or /2 JSON)");
  c->add_option("--out,-o", a->out, "The page's folder (created): index.html and its files");
  c->add_option("--width", a->width, "Override the image width (height follows the aspect ratio)")
      ->check(integer_in(1, 16384));
  c->add_option("--height", a->height, "Override the image height")->check(integer_in(1, 16384));
  c->callback([a] { run_web(*a); });
}

}  // namespace sg
