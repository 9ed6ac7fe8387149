// `sunglint web`: a self-contained static page that runs the shading kernel in a browser
// (docs/web.md). The kernel's own GLSL files (src/kernel/*.glsl) go into the page as they
// are, compiled there as GLSL ES 3.00 fragment shaders (kernel/glsl_es_prelude.glsl) by a
// short host (web/assets/host.js) that mirrors the GL engine's; the display pipeline runs
// as fragment passes of image/display.glsl. Beside them the page carries what only the host
// computes: each method's GL-engine settings (gl_engine/gl_engine.h, gl_variant), the path
// tables' F and the fine grids of F that S is integrated from in the browser
// (shading/path_table.h), the kernel fits, the display settings, and the scene files as
// given, which the page checks with the loader's rules ported to JavaScript
// (web/assets/scene_check.js).
//
// Files written (all built into the program; nothing is looked up at run time): index.html,
// page.js, host.js, scene_check.js, shaders.js (the GLSL sources), data.js (the data
// above, the tables as base64 float32). Scripts, not fetched files, so that the page opens
// from file:// (browsers refuse fetch() there) as well as from any static server.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace sg {
class PathTables;
}

namespace sg::web {

// A scene of the page: its file and the image size the page renders it at (0: the file's;
// the CLI's --width/--height resolved as `render` resolves them, cli/args.h).
struct WebScene {
  std::string path;
  int width = 0, height = 0;
};

struct WebPageOptions {
  std::vector<WebScene> scenes;  // at least one; the first is shown first
  std::string out_dir;           // created if missing
};

struct WebPageFile {
  std::string name;  // in out_dir
  size_t bytes = 0;
};

struct WebPage {
  std::vector<WebPageFile> files;
  size_t total_bytes = 0;
  std::vector<std::string> scene_names;  // as the page's `scene` parameter takes them
};

// The page's methods: the GL engine's settings of `point`, `supersample` (2x2x1 and 4x4x1),
// `staa-temporal` and `staa`, by the ids the `method` and `split` parameters take.
std::vector<std::string> web_method_ids();

// Checks the scenes (the loader's errors, naming the file) and the sizes, then writes the
// page with `tables` (the caller's path tables, shading/path_table_store.h) in it. Throws
// sg::Error naming the culprit; writes nothing when a scene is bad.
WebPage write_web_page(const WebPageOptions& options, const PathTables& tables);

// The page's size limit (docs/web.md): 2 MiB, path tables included.
inline constexpr size_t kWebPageBudgetBytes = 2u << 20;

}  // namespace sg::web
