#include "base/atomic_file.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "base/error.h"

namespace sg {
namespace fs = std::filesystem;

namespace {

std::string temp_path_for(const std::string& path) {
  return path + ".tmp." + std::to_string(::getpid());
}

void check_directory(const std::string& path) {
  fs::path dir = fs::path(path).parent_path();
  if (dir.empty()) dir = ".";
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    throw Error(path + ": cannot write: directory '" + dir.string() + "' does not exist");
  }
}

}  // namespace

void write_file_atomic_with(const std::string& path,
                            const std::function<void(const std::string& tmp)>& write) {
  if (path.empty()) throw Error("output path is empty");
  check_directory(path);
  const std::string tmp = temp_path_for(path);
  try {
    write(tmp);
  } catch (const std::exception& e) {
    std::error_code ec;
    fs::remove(tmp, ec);
    throw Error(path + ": cannot write: " + e.what());
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw Error(path + ": cannot write: " + ec.message());
  }
}

void write_file_atomic(const std::string& path, std::string_view bytes) {
  write_file_atomic_with(path, [&](const std::string& tmp) {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw Error(std::strerror(errno));
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.flush();
    if (!out) throw Error(std::strerror(errno));
  });
}

std::uintmax_t check_readable_file(const std::string& path, std::uintmax_t max_bytes) {
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (ec || !fs::exists(st)) {
    throw Error(path + ": cannot read: " + (ec ? ec.message() : "no such file"));
  }
  if (fs::is_directory(st)) throw Error(path + ": cannot read: a folder, not a file");
  if (!fs::is_regular_file(st)) {
    throw Error(path + ": cannot read: not a regular file (a device, fifo or socket)");
  }
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) throw Error(path + ": cannot read: " + ec.message());
  if (size > max_bytes) {
    throw Error(path + ": cannot read: " + std::to_string(size) + " bytes, more than the " +
                std::to_string(max_bytes) + " allowed");
  }
  return size;
}

std::string read_file(const std::string& path, std::uintmax_t max_bytes) {
  const std::uintmax_t size = check_readable_file(path, max_bytes);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path + ": cannot read: " + std::strerror(errno));
  // Read in chunks, never past max_bytes: the file may grow after the size check.
  std::string out;
  out.reserve(static_cast<size_t>(size));
  char buf[1 << 16];
  while (in) {
    in.read(buf, sizeof buf);
    out.append(buf, static_cast<size_t>(in.gcount()));
    if (out.size() > max_bytes) {
      throw Error(path + ": cannot read: more than the " + std::to_string(max_bytes) +
                  " bytes allowed");
    }
  }
  if (in.bad()) throw Error(path + ": cannot read: " + std::strerror(errno));
  return out;
}

}  // namespace sg
