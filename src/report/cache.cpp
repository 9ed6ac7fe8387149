#include "report/cache.h"

#include <nlohmann/json.hpp>

#include <cctype>
#include <cstdio>
#include <filesystem>

#include "base/atomic_file.h"
#include "base/error.h"
#include "gl_engine/kernel_program.h"
#include "image/image_io.h"

namespace sg {
namespace fs = std::filesystem;

namespace {
// The revision of the methods computed outside the shading kernel (lean, taa, microspec,
// specaa, bruneton, the exact footprint's host finish, the cascades' fields of
// shading/cascade_fields.h) and the methods' default options (methods/options.h): raise it
// when a change alters their pictures, so that the frame cache renders them again.
// 6: point, supersample and staa-temporal intersect displaced water with every wave by
// default (methods/options.h, intersect_tolerance_for).
// 7: staa's RDF takes three kernels by default with a footprint term (methods/options.h,
// rdf_kernels).
constexpr int kHostMethodsRevision = 7;
}  // namespace

std::string canonical_label(const std::string& label) {
  std::string out;
  bool space = false;
  for (char c : label) {
    if (std::isspace(static_cast<unsigned char>(c))) {
      space = !out.empty();
      continue;
    }
    if (space) out += ' ';
    space = false;
    out += c;
  }
  return out;
}

std::string file_slug(const std::string& label) {
  std::string out;
  for (char c : label) {
    const unsigned char u = static_cast<unsigned char>(c);
    if (std::isalnum(u)) {
      out += static_cast<char>(std::tolower(u));
    } else if (!out.empty() && out.back() != '-') {
      out += '-';
    }
  }
  if (out.size() > 48) out.resize(48);
  while (!out.empty() && out.back() == '-')
    out.pop_back();
  return out.empty() ? "method" : out;
}

std::string renderer_version(int reference_revision) {
  return gl_engine::kernel_fingerprint() + "/" + std::to_string(kHostMethodsRevision) +
         "/reference-" + std::to_string(reference_revision);
}

std::string frame_key(const Scene& scene, const std::string& label, int frame, int history_from,
                      const std::string& renderer) {
  // The renderer: the shading kernel's sources (both engines), the revision of the
  // host-side methods (bumped when their pictures change) and the reference's.
  std::string key =
      "sunglint-frame/1\nrenderer=" + (renderer.empty() ? renderer_version() : renderer) +
      "\nsize=" + std::to_string(scene.width) + "x" + std::to_string(scene.height) +
      "\nframe=" + std::to_string(frame) + "\nmethod=" + canonical_label(label) + "\n";
  if (history_from >= 0) key += "history_from=" + std::to_string(history_from) + "\n";
  key += "scene=" + scene_to_json(scene) + "\n";
  // A cascade's sidecar by its contents (the scene names only the file).
  for (const CascadeDesc& c : scene.surface.cascades) {
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx",
                  static_cast<unsigned long long>(c.data ? c.data->fingerprint : 0));
    key += "lattice=" + c.file + " " + hex + "\n";
  }
  return key;
}

std::string variance_key(const std::string& frame_key) {
  return frame_key + "\nvariance of the estimate";
}

std::string reference_batch_key(const std::string& frame_key, int batch) {
  return frame_key + "batch=" + std::to_string(batch) + "\n";
}

FrameCache::FrameCache(std::string dir) : dir_(std::move(dir)) {
  std::error_code ec;
  fs::create_directories(dir_, ec);
  if (!fs::is_directory(dir_)) throw Error(dir_ + ": cannot create the cache folder");
}

std::string FrameCache::path(const std::string& label, const std::string& key) const {
  char hash[17];
  std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(fnv1a64(key)));
  return (fs::path(dir_) / (file_slug(label) + "-" + hash + ".exr")).string();
}

namespace {

// The sidecar's render time when it holds `key`.
std::optional<double> read_sidecar(const std::string& image_path, const std::string& key) {
  std::error_code ec;
  if (!fs::exists(image_path, ec) || !fs::exists(image_path + ".json", ec)) return std::nullopt;
  try {
    auto j = nlohmann::json::parse(read_file(image_path + ".json"));
    if (j.at("key").get<std::string>() != key) return std::nullopt;
    return j.at("ms").get<double>();
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

}  // namespace

bool FrameCache::has(const std::string& label, const std::string& key) const {
  return read_sidecar(path(label, key), key).has_value();
}

std::optional<CachedFrame> FrameCache::load(const std::string& label,
                                            const std::string& key) const {
  const std::string p = path(label, key);
  auto ms = read_sidecar(p, key);
  if (!ms) return std::nullopt;
  try {
    return CachedFrame{read_image(p), *ms};
  } catch (const Error&) {
    return std::nullopt;
  }
}

void FrameCache::store(const std::string& label, const std::string& key, const Image& image,
                       double ms) const {
  const std::string p = path(label, key);
  std::error_code ec;
  fs::remove(p + ".json", ec);  // the old sidecar must not vouch for the new image
  write_image(p, image);
  write_file_atomic(p + ".json", nlohmann::json{{"key", key}, {"ms", ms}}.dump(1) + "\n");
}

}  // namespace sg
