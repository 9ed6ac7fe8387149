// The frame cache of `sunglint compare`: every rendered frame (the reference's and every
// method's) is kept on disk, so a second study reuses the references and a killed study
// resumes where it stopped.
//
// A frame is keyed by the text of everything its pixels depend on: the scene as canonical
// JSON (scene_to_json, at the study's image size), the frame number, the image size, the
// method variant with its flags (samples and seed included, "reference --samples 12x12x8")
// and, for a stateful method, the frame its history starts from. Thread counts, other
// methods and output folders are not part of it. The file is
//     CACHE/<slug of the variant>-<FNV-1a 64 of the key, hex>.exr
// with a sidecar CACHE/...exr.json holding the key text and the frame's render time. Both
// are written whole (temporary file + rename), the sidecar last, so a frame is trusted
// only when its sidecar exists and holds the same key text (which also rules out hash
// collisions); anything else is rendered again.
//
// The key also holds the renderer's version (renderer_version): the shading kernel's
// fingerprint, the host-side methods' revision and the reference estimator's revision
// (methods/reference.h), so that a changed kernel or a fixed estimator never serves frames
// of before. A change of a method outside these still needs its files (CACHE/<slug>-*)
// deleted by hand.
#pragma once

#include "base/fnv1a.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "image/image.h"
#include "methods/reference.h"
#include "scene/scene.h"

namespace sg {

// Whitespace collapsed to single spaces and trimmed, so "supersample  --samples 6x6x1 "
// and "supersample --samples 6x6x1" name one variant.
std::string canonical_label(const std::string& label);

// A file-name-safe form of a label: lower-case letters, digits and single dashes, at most
// 48 characters ("supersample --samples 6x6x1" -> "supersample-samples-6x6x1").
std::string file_slug(const std::string& label);

// The renderer's version as keys hold it: "<kernel fingerprint>/<host methods' revision>/
// reference-<reference revision>"; the current one by default.
std::string renderer_version(int reference_revision = kReferenceRevision);

// The key text of one frame (see the header). history_from < 0: stateless method.
// `renderer`: the renderer_version() to key on (empty: the current one).
std::string frame_key(const Scene& scene, const std::string& label, int frame,
                      int history_from = -1, const std::string& renderer = {});

// The key of a frame's companion image: the per-pixel variance of a reference's estimate
// (methods/reference.h), stored beside the frame as a frame of its own.
std::string variance_key(const std::string& frame_key);

// The key of one batch of a reference frame (methods/reference.h, only_batch): a study
// renders and caches each batch alone, and the frame is their mean.
std::string reference_batch_key(const std::string& frame_key, int batch);

struct CachedFrame {
  Image image;
  double ms = 0;  // render time recorded when the frame was rendered
};

class FrameCache {
 public:
  // Creates `dir` (and its parents) if needed.
  explicit FrameCache(std::string dir);
  const std::string& dir() const { return dir_; }

  // CACHE/<slug(label)>-<hash(key)>.exr
  std::string path(const std::string& label, const std::string& key) const;
  // True when a complete frame with this key is stored.
  bool has(const std::string& label, const std::string& key) const;
  // The stored frame, or nothing when absent, incomplete or unreadable.
  std::optional<CachedFrame> load(const std::string& label, const std::string& key) const;
  void store(const std::string& label, const std::string& key, const Image& image, double ms) const;

 private:
  std::string dir_;
};

}  // namespace sg
