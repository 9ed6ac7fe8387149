// The path tables of one `sunglint` run (shading/path_table_store.h): the CLI is the
// caller that creates them, in the cache folder of --cache-dir or else the environment's
// ($SUNGLINT_CACHE_DIR, $XDG_CACHE_HOME/sunglint, ~/.cache/sunglint), and hands them to
// every method it makes (MethodFlags::finish sets MethodOptions::path_tables) and to the
// web page. Generated tables are announced on stderr, with the file they were written to.
#pragma once

#include <string>

#include "shading/path_table_store.h"

namespace sg {

PathTableStore& cli_path_tables();
// --cache-dir: the folder of the cache file (before the tables are first read).
void set_cli_cache_dir(const std::string& dir);

}  // namespace sg
