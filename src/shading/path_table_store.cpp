#include "shading/path_table_store.h"

#include <cstdlib>
#include <filesystem>
#include <utility>

#include "base/error.h"

namespace sg {

namespace fs = std::filesystem;

PathTableStore::PathTableStore(std::string cache_file, Notice on_generated)
    : cache_file_(std::move(cache_file)), on_generated_(std::move(on_generated)) {}

void PathTableStore::set_cache_file(std::string cache_file) {
  if (tables_) throw Error("path tables: the cache file is set after the tables were read");
  cache_file_ = std::move(cache_file);
}

const PathTables& PathTableStore::tables() const {
  std::call_once(once_, [this] {
    tables_.emplace(PathTables::load_or_generate(cache_file_, {}, &result_));
    if (!result_.loaded && on_generated_) on_generated_(result_);
  });
  return *tables_;
}

const PathTableCacheResult& PathTableStore::cache_result() const {
  tables();
  return result_;
}

std::string path_table_cache_file(const std::string& dir) {
  return dir.empty() ? std::string() : dir + "/" + PathTables::kCacheFileName;
}

std::string path_table_cache_dir_from_environment() {
  auto env = [](const char* name) {
    const char* v = std::getenv(name);
    return std::string(v ? v : "");
  };
  if (std::string d = env("SUNGLINT_CACHE_DIR"); !d.empty()) return d;
  if (std::string d = env("XDG_CACHE_HOME"); !d.empty()) return d + "/sunglint";
  if (std::string d = env("HOME"); !d.empty()) return d + "/.cache/sunglint";
  std::error_code ec;
  const fs::path tmp = fs::temp_directory_path(ec);
  return ec ? std::string() : (tmp / "sunglint").string();
}

}  // namespace sg
