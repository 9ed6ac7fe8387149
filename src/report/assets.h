// Files built into the program for the report page: the vendored chart library and its
// licence, the page's script and style. Generated at build time from the files by
// cmake/embed_files.cmake (src/CMakeLists.txt lists them).
#pragma once

#include <vector>

#include "base/embedded_file.h"

namespace sg {

const std::vector<EmbeddedFile>& report_assets();

}  // namespace sg
