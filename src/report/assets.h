// Files built into the program for the report page: the vendored chart library and its
// licence, the page's script and style. Generated at build time from the files by
// cmake/embed_files.cmake (src/CMakeLists.txt lists them).
#pragma once

#include <string_view>
#include <vector>

namespace sg {

struct EmbeddedFile {
  std::string_view name;   // file name in the study folder
  std::string_view bytes;  // contents
};

const std::vector<EmbeddedFile>& report_assets();

}  // namespace sg
