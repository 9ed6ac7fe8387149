#include "base/output_path.h"

#include <fcntl.h>
#include <sys/statfs.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "base/error.h"

namespace sg {
namespace fs = std::filesystem;

namespace {

// The kernel's virtual file systems, which hold no files of ours: creating one there fails
// with an errno that misleads ("No such file or directory" in /proc, whose folder exists).
const char* virtual_file_system(const fs::path& dir) {
  struct statfs st {};
  if (::statfs(dir.c_str(), &st) != 0) return nullptr;
  switch (static_cast<unsigned long>(st.f_type)) {
    case 0x9fa0UL:
      return "proc";
    case 0x62656572UL:
      return "sysfs";
    case 0x1cd1UL:
      return "devpts";
    case 0x64626720UL:
      return "debugfs";
    case 0x74726163UL:
      return "tracefs";
    case 0x27e0ebUL:
      return "cgroup";
    case 0x63677270UL:
      return "cgroup2";
    case 0x73636673UL:
      return "securityfs";
    case 0x6e736673UL:
      return "nsfs";
    case 0xcafe4a11UL:
      return "bpf";
    default:
      return nullptr;
  }
}

// Whether a new file can be created in `dir`: a probe file is created and removed (the
// permission bits alone do not say; a read-only mount or a root user change the answer).
// The reason when it cannot: the system's, or that of a virtual file system.
std::string probe_writable(const fs::path& dir) {
  const fs::path probe = dir / (".sunglint-probe-" + std::to_string(::getpid()));
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0600);
  if (fd < 0) {
    const int err = errno;
    if (const char* type = virtual_file_system(dir)) {
      return std::string("it is on the kernel's virtual ") + type +
             " file system, where no program can create a file (" + std::strerror(err) +
             "); choose a folder on a disk";
    }
    return std::strerror(err);
  }
  ::close(fd);
  ::unlink(probe.c_str());
  return "";
}

}  // namespace

bool check_output_file(const std::string& path, bool create_folder, const std::string& hint) {
  if (path.empty()) throw Error("output path is empty");
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw Error(path + ": cannot write: it is a folder");
  fs::path dir = fs::path(path).parent_path();
  if (dir.empty()) dir = ".";
  bool created = false;
  if (!fs::exists(dir, ec)) {
    if (!create_folder) {
      throw Error(path + ": cannot write: folder '" + dir.string() + "' does not exist" + hint);
    }
    fs::create_directories(dir, ec);
    if (ec) throw Error(path + ": cannot create folder '" + dir.string() + "': " + ec.message());
    created = true;
  }
  if (!fs::is_directory(dir, ec)) {
    throw Error(path + ": cannot write: '" + dir.string() + "' is not a folder");
  }
  if (const std::string why = probe_writable(dir); !why.empty()) {
    throw Error(path + ": cannot write in folder '" + dir.string() + "': " + why);
  }
  return created;
}

void prepare_output_folder(const std::string& dir, const std::string& what) {
  if (dir.empty()) throw Error(what + ": give a folder");
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec)) {
    throw Error(what + ": '" + dir + "' is not a folder");
  }
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir)) {
    throw Error(what + ": cannot create folder '" + dir + "'" + (ec ? ": " + ec.message() : ""));
  }
  if (const std::string why = probe_writable(dir); !why.empty()) {
    throw Error(what + ": cannot write in folder '" + dir + "': " + why);
  }
}

void check_output_folder(const std::string& dir, const std::string& what) {
  if (dir.empty()) throw Error(what + ": give a folder");
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec)) {
    throw Error(what + ": '" + dir + "' is not a folder");
  }
  fs::path p = fs::absolute(dir, ec).lexically_normal();
  while (!p.empty() && !fs::exists(p, ec) && p != p.root_path())
    p = p.parent_path();
  if (!fs::is_directory(p, ec)) {
    throw Error(what + ": cannot create folder '" + dir + "': '" + p.string() +
                "' is not a folder");
  }
  if (const std::string why = probe_writable(p); !why.empty()) {
    throw Error(what + ": cannot write in folder '" + p.string() + "': " + why);
  }
}

}  // namespace sg
