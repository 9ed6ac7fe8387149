#include "cli/path_tables.h"

#include <cstdio>

namespace sg {

namespace {

// The path-integral tables (used by `staa`) are generated once and cached in an 8 MiB file;
// say so when that happens, and where.
void announce_path_table_cache(const PathTableCacheResult& r) {
  if (r.written) {
    std::fprintf(stderr,
                 "sunglint: generated the path-integral tables and cached them in %s (8 MiB, "
                 "reused by later runs; --cache-dir or SUNGLINT_CACHE_DIR choose the folder)\n",
                 r.path.c_str());
  } else {
    std::fprintf(stderr, "sunglint: generated the path-integral tables in memory (%s)\n",
                 r.note.c_str());
  }
}

}  // namespace

PathTableStore& cli_path_tables() {
  static PathTableStore store(path_table_cache_file(path_table_cache_dir_from_environment()),
                              announce_path_table_cache);
  return store;
}

void set_cli_cache_dir(const std::string& dir) {
  cli_path_tables().set_cache_file(path_table_cache_file(dir));
}

}  // namespace sg
