// The path tables of a test process (shading/path_table_store.h): one store in the
// environment's cache folder, as the CLI's default, shared by the process's tests, and
// MethodOptions that carry it (a test is the caller that creates the tables).
#pragma once

#include <string>

#include "methods/options.h"
#include "shading/path_table_store.h"

namespace sg::testing {

inline const PathTableStore& path_table_store() {
  static const PathTableStore store(path_table_cache_file(path_table_cache_dir_from_environment()));
  return store;
}

inline const PathTables& path_tables() {
  return path_table_store().tables();
}

// `o` with the test process's path tables.
inline MethodOptions with_tables(MethodOptions o = {}) {
  o.path_tables = &path_table_store();
  return o;
}

}  // namespace sg::testing
