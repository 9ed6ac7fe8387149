// The path tables (shading/path_table.h) of one program run, as a resource its caller
// creates and passes to what reads them: `staa` on the CPU and the GL engine
// (MethodOptions::path_tables), the counting render, the web page. Nothing below the caller
// holds tables of its own or reads the environment: the CLI makes one store for its run
// (cli/path_tables.h, with --cache-dir or the environment's cache folder), a test makes one
// for its process (testing/path_tables.h), an engine that embeds sunglint makes its own.
//
// The store loads the tables from its cache file, or generates them and writes the file,
// the first time one asks (so that a run of `point` never touches them); the first
// request may come from any thread and the others wait for it.
#pragma once

#include <functional>
#include <mutex>
#include <optional>
#include <string>

#include "shading/path_table.h"

namespace sg {

class PathTableStore {
 public:
  using Notice = std::function<void(const PathTableCacheResult&)>;
  // `cache_file`: the cache file, "" for none (the tables are then generated in memory
  // only). `on_generated`: called once, on the thread that asked first, when the tables
  // were generated rather than loaded (the CLI announces the file).
  explicit PathTableStore(std::string cache_file = "", Notice on_generated = {});
  PathTableStore(const PathTableStore&) = delete;
  PathTableStore& operator=(const PathTableStore&) = delete;

  // Changes the cache file; only before the first tables() (sg::Error after it).
  void set_cache_file(std::string cache_file);
  const std::string& cache_file() const { return cache_file_; }
  // The tables with the default parameters: loaded or generated on the first call
  // (thread-safe).
  const PathTables& tables() const;
  // How tables() obtained them (loads them first).
  const PathTableCacheResult& cache_result() const;

 private:
  std::string cache_file_;
  Notice on_generated_;
  mutable std::once_flag once_;
  mutable std::optional<PathTables> tables_;
  mutable PathTableCacheResult result_;
};

// The cache folder a program takes when it is given none: $SUNGLINT_CACHE_DIR, else
// $XDG_CACHE_HOME/sunglint, else $HOME/.cache/sunglint, else <temp>/sunglint; "" when none
// can be named. The caller decides to read the environment (the CLI, the tests).
std::string path_table_cache_dir_from_environment();
// The cache file in folder `dir` (path_tables.bin), "" for no folder.
std::string path_table_cache_file(const std::string& dir);

}  // namespace sg
