#include "cli/slurm.h"

#include <fcntl.h>
#include <pwd.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "base/error.h"
#include "embedded/slurm_templates.h"

extern char** environ;

namespace sg {
namespace fs = std::filesystem;

const std::string& slurm_template(const std::string& name) {
  static std::map<std::string, std::string> texts;
  auto it = texts.find(name);
  if (it == texts.end()) {
    it = texts.emplace(name, std::string(find_embedded(slurm_templates(), name).bytes)).first;
  }
  return it->second;
}

std::string fill_template(const std::string& text, const std::map<std::string, std::string>& values,
                          const std::string& name) {
  static const std::regex placeholder("@([A-Z_]+)@");
  std::string out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    std::string filled;
    bool empty = false;
    auto begin = std::sregex_iterator(line.begin(), line.end(), placeholder);
    size_t at = 0;
    for (auto m = begin; m != std::sregex_iterator(); ++m) {
      const std::string key = (*m)[1].str();
      auto v = values.find(key);
      if (v == values.end()) throw Error(name + ": no value for @" + key + "@");
      empty = empty || v->second.empty();
      filled += line.substr(at, m->position() - at) + v->second;
      at = m->position() + m->length();
    }
    filled += line.substr(at);
    if (!empty) out += filled + "\n";
  }
  return out;
}

std::string shell_quote(const std::string& s) {
  if (!s.empty() && s.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                        "0123456789-_./=,:+%@") == std::string::npos) {
    return s;
  }
  std::string q = "'";
  for (char c : s)
    q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::string shell_join(const std::vector<std::string>& argv) {
  std::string out;
  for (const auto& a : argv) {
    if (!out.empty()) out += ' ';
    out += shell_quote(a);
  }
  return out;
}

namespace {

std::string read_all(int fd) {
  std::string s;
  ::lseek(fd, 0, SEEK_SET);
  char buf[4096];
  for (ssize_t n; (n = ::read(fd, buf, sizeof buf)) > 0;)
    s.append(buf, size_t(n));
  return s;
}

std::string trim(std::string s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back())))
    s.pop_back();
  size_t k = 0;
  while (k < s.size() && std::isspace(static_cast<unsigned char>(s[k])))
    ++k;
  return s.substr(k);
}

}  // namespace

CommandOutput run_program(const std::vector<std::string>& argv) {
  // Standard output and error to unlinked temporary files: no pipe to drain in turn.
  char out_name[] = "/tmp/sunglint-out-XXXXXX", err_name[] = "/tmp/sunglint-err-XXXXXX";
  const int out_fd = ::mkstemp(out_name), err_fd = ::mkstemp(err_name);
  if (out_fd < 0 || err_fd < 0) throw Error("cannot create a temporary file in /tmp");
  ::unlink(out_name);
  ::unlink(err_name);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, out_fd, 1);
  posix_spawn_file_actions_adddup2(&actions, err_fd, 2);
  std::vector<char*> args;
  for (const auto& a : argv)
    args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  const int rc = ::posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  CommandOutput r;
  if (rc != 0) {
    ::close(out_fd);
    ::close(err_fd);
    r.status = 127;
    r.started = false;
    r.err = argv[0] + ": " + std::strerror(rc);
    return r;
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  r.status =
      WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
  r.out = read_all(out_fd);
  r.err = read_all(err_fd);
  ::close(out_fd);
  ::close(err_fd);
  return r;
}

namespace {
[[noreturn]] void not_found(const std::string& name, const std::string& flag) {
  throw Error(flag + ": " + name +
              ": not found on PATH; submit from a machine where Slurm's commands run (a "
              "login node of the cluster), or run without " +
              flag);
}
}  // namespace

void require_program(const std::string& name, const std::string& flag) {
  const char* path = std::getenv("PATH");
  std::stringstream ss(path ? path : "");
  for (std::string d; std::getline(ss, d, ':');) {
    const fs::path p = fs::path(d.empty() ? "." : d) / name;
    std::error_code ec;
    if (::access(p.c_str(), X_OK) == 0 && !fs::is_directory(p, ec)) return;
  }
  not_found(name, flag);
}

std::string run_slurm(const std::vector<std::string>& argv, const std::string& flag) {
  const CommandOutput r = run_program(argv);
  if (!r.started) {
    not_found(argv[0], flag);
  }
  if (r.status != 0) {
    std::string msg = trim(r.err.empty() ? r.out : r.err);
    throw Error(flag + ": `" + shell_join(argv) + "` failed (exit " + std::to_string(r.status) +
                "): " + (msg.empty() ? "no message" : msg));
  }
  return r.out;
}

void check_slurm_time(const std::string& t) {
  static const std::regex ok(
      R"(^(\d+|\d+:\d{1,2}|\d+:\d{1,2}:\d{1,2}|\d+-\d+|\d+-\d+:\d{1,2}|\d+-\d+:\d{1,2}:\d{1,2})$)");
  if (!std::regex_match(t, ok)) {
    throw Error(
        "--time-per-task: expected Slurm's time format: minutes, MM:SS, HH:MM:SS, D-HH, "
        "D-HH:MM or D-HH:MM:SS (got '" +
        t + "')");
  }
}

std::string slurm_time(double seconds) {
  long minutes = std::max(1L, static_cast<long>(std::ceil(seconds / 60.0)));
  char buf[48];
  std::snprintf(buf, sizeof buf, "%ld-%02ld:%02ld:00", minutes / 1440, (minutes / 60) % 24,
                minutes % 60);
  return buf;
}

std::string array_spec(const std::vector<int>& indices, int max_parallel) {
  std::string s;
  for (size_t k = 0; k < indices.size();) {
    size_t e = k;
    while (e + 1 < indices.size() && indices[e + 1] == indices[e] + 1)
      ++e;
    if (!s.empty()) s += ",";
    s += std::to_string(indices[k]);
    if (e > k) s += "-" + std::to_string(indices[e]);
    k = e + 1;
  }
  if (max_parallel > 0) s += "%" + std::to_string(max_parallel);
  return s;
}

std::pair<std::string, std::string> filesystem_of(const std::string& path) {
  std::error_code ec;
  const std::string p = fs::weakly_canonical(fs::absolute(path), ec).string();
  std::ifstream in("/proc/self/mountinfo");
  std::string best_mount, best_type;
  for (std::string line; std::getline(in, line);) {
    // ID PARENT MAJ:MIN ROOT MOUNT OPTIONS [OPTIONAL...] - TYPE SOURCE SUPER
    std::istringstream f(line);
    std::string id, parent, dev, root, mount, field;
    f >> id >> parent >> dev >> root >> mount;
    while (f >> field && field != "-") {
    }
    std::string type;
    f >> type;
    // Octal escapes of spaces etc. in mount points (\040) are rare in shared folders.
    const bool under = p == mount || mount == "/" ||
                       (p.compare(0, mount.size(), mount) == 0 && p.size() > mount.size() &&
                        p[mount.size()] == '/');
    if (under && mount.size() >= best_mount.size()) {
      best_mount = mount;
      best_type = type;
    }
  }
  return {best_type, best_mount};
}

std::string check_shared_folders(const std::vector<std::pair<std::string, std::string>>& paths,
                                 const std::string& partition, bool assume_shared) {
  std::vector<std::string> sinfo{"sinfo", "-h", "-N", "-o", "%N"};
  if (!partition.empty()) {
    sinfo.push_back("-p");
    sinfo.push_back(partition);
  }
  std::set<std::string> nodes;
  std::istringstream in(run_slurm(sinfo, "--slurm"));
  for (std::string n; in >> n;)
    nodes.insert(n);
  if (nodes.empty()) {
    throw Error("--slurm: `" + shell_join(sinfo) + "` lists no node" +
                (partition.empty() ? "" : " in partition '" + partition + "'"));
  }
  char host[256] = {0};
  ::gethostname(host, sizeof host - 1);
  std::string me = host;
  if (const size_t dot = me.find('.'); dot != std::string::npos) me.resize(dot);
  std::string list;
  for (const auto& n : nodes) {
    if (!list.empty()) list += ", ";
    list += n;
  }
  const bool only_here = std::all_of(nodes.begin(), nodes.end(), [&](const std::string& n) {
    return n == me || n == "localhost";
  });
  if (only_here) {
    return "the cluster's only node is this machine (" + list +
           "): the study's folders are shared with it";
  }
  static const std::set<std::string> shared_types{
      "nfs",      "nfs4",      "lustre",       "gpfs",       "beegfs",       "ceph",
      "cephfs",   "fuse.ceph", "cifs",         "smb3",       "glusterfs",    "fuse.glusterfs",
      "panfs",    "wekafs",    "afs",          "fuse.sshfs", "9p",           "virtiofs",
      "orangefs", "pvfs2",     "fuse.juicefs", "fuse.s3fs",  "fuse.gcsfuse", "quobyte"};
  if (assume_shared) return "the nodes (" + list + ") see these folders (--assume-shared)";
  for (const auto& [flag, path] : paths) {
    const auto [type, mount] = filesystem_of(path);
    if (!shared_types.count(type)) {
      throw Error("--slurm: " + flag + " '" + path + "' is on a local filesystem (" +
                  (type.empty() ? "unknown" : type) + ", mounted at " + mount +
                  ") that the cluster's nodes (" + list +
                  ") do not see; put it on a filesystem they share (NFS, Lustre, GPFS, "
                  "BeeGFS, CephFS ...), or give --assume-shared if it is shared");
    }
  }
  return "the study's folders are on filesystems the nodes (" + list + ") share";
}

namespace {
std::vector<std::string>& stored_arguments() {
  static std::vector<std::string> a;
  return a;
}
}  // namespace

std::string program_path() {
  std::error_code ec;
  const fs::path p = fs::read_symlink("/proc/self/exe", ec);
  if (ec) throw Error("cannot find the program's own path (/proc/self/exe)");
  return p.string();
}

void set_program_arguments(int argc, char** argv) {
  stored_arguments().assign(argv, argv + argc);
}

const std::vector<std::string>& program_arguments() {
  return stored_arguments();
}

std::vector<std::string> arguments_without(const std::vector<std::string>& args,
                                           const std::map<std::string, int>& drop) {
  std::vector<std::string> out;
  for (size_t k = 0; k < args.size(); ++k) {
    const std::string& a = args[k];
    const size_t eq = a.find('=');
    const std::string name = a.rfind("--", 0) == 0 && eq != std::string::npos ? a.substr(0, eq) : a;
    auto it = drop.find(name);
    if (it == drop.end()) {
      out.push_back(a);
      continue;
    }
    if (name == a) k += static_cast<size_t>(it->second);  // its values follow
  }
  return out;
}

std::vector<std::string> queued_jobs(const std::vector<std::string>& ids) {
  const passwd* pw = ::getpwuid(::getuid());
  std::vector<std::string> argv{"squeue", "-h", "-o", "%A %F %T %r"};
  if (pw) {
    argv.push_back("-u");
    argv.push_back(pw->pw_name);
  }
  std::istringstream in(run_slurm(argv, "--slurm"));
  std::vector<std::string> out;
  const std::set<std::string> wanted(ids.begin(), ids.end());
  for (std::string line; std::getline(in, line);) {
    std::istringstream f(line);
    std::string job, array;
    f >> job >> array;
    if (wanted.count(job) || wanted.count(array)) out.push_back(trim(line));
  }
  return out;
}

std::string next_submission_dir(const std::string& folder) {
  const fs::path base = fs::absolute(folder);
  fs::create_directories(base);
  int n = 0;
  for (const auto& e : fs::directory_iterator(base)) {
    const std::string name = e.path().filename().string();
    if (e.is_directory() && !name.empty() &&
        name.find_first_not_of("0123456789") == std::string::npos)
      n = std::max(n, std::stoi(name));
  }
  const fs::path dir = base / std::to_string(n + 1);
  fs::create_directories(dir);
  return dir.string();
}

std::string job_id(const std::string& out, const std::vector<std::string>& argv) {
  std::string id = out.substr(0, out.find_first_of(";\n"));
  if (id.empty() || id.find_first_not_of("0123456789") != std::string::npos) {
    throw Error("--slurm: `" + shell_join(argv) + "` printed no job id (got '" + out + "')");
  }
  return id;
}

}  // namespace sg
