// A file built into the program at build time (cmake/embed_files.cmake writes the table):
// the report page's assets, the GLSL sources of the GL engine. Nothing is read from disk at
// run time, so the binary runs from any folder and on a machine without the source tree.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "base/error.h"

namespace sg {

struct EmbeddedFile {
  std::string_view name;   // the name the program knows it by (e.g. "kernel/waves.glsl")
  std::string_view bytes;  // contents
};

// The file called `name` in `table`; an sg::Error naming it when it is not there.
inline const EmbeddedFile& find_embedded(const std::vector<EmbeddedFile>& table,
                                         std::string_view name) {
  for (const EmbeddedFile& f : table)
    if (f.name == name) return f;
  throw Error(std::string(name) + ": no such embedded file");
}

}  // namespace sg
