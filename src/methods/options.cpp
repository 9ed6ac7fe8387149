#include "methods/options.h"

#include <charconv>
#include <cmath>
#include <vector>

#include "base/error.h"

namespace sg {

SampleCounts parse_sample_counts(const std::string& text, const std::string& flag) {
  std::vector<int> v;
  size_t start = 0;
  while (start <= text.size()) {
    size_t x = text.find('x', start);
    std::string part = text.substr(start, x == std::string::npos ? std::string::npos : x - start);
    int n = 0;
    auto [ptr, ec] = std::from_chars(part.data(), part.data() + part.size(), n);
    if (part.empty() || ec != std::errc() || ptr != part.data() + part.size() || n < 1 ||
        n > 4096) {
      throw Error(flag + ": expected SxSxT with positive integers, e.g. 8x8x8 (got '" + text +
                  "')");
    }
    v.push_back(n);
    if (x == std::string::npos) break;
    start = x + 1;
  }
  if (v.size() != 3) {
    throw Error(flag + ": expected SxSxT with positive integers, e.g. 8x8x8 (got '" + text + "')");
  }
  SampleCounts s{v[0], v[1], v[2]};
  if (s.total() > (1L << 22)) throw Error(flag + ": at most 4194304 samples per pixel");
  return s;
}

std::string to_string(const SampleCounts& s) {
  return std::to_string(s.sx) + "x" + std::to_string(s.sy) + "x" + std::to_string(s.st);
}

double intersect_tolerance_for(const MethodOptions& o, const std::string& method) {
  if (o.intersect_tolerance_given) return o.intersect_tolerance;
  return method == "staa" ? MethodOptions{}.intersect_tolerance : 0.0;
}

void validate(const MethodOptions& o) {
  auto require = [](bool ok, const std::string& flag, const std::string& rule) {
    if (!ok) throw Error(flag + ": " + rule);
  };
  require(o.samples.st <= 64, "--samples", "at most 64 time samples (T) per pixel");
  require(o.batches >= 2 && o.batches <= 8, "--batches", "must be in [2, 8]");
  require(o.only_batch >= -1 && o.only_batch < o.batches, "--batches",
          "the batch rendered alone must be one of them");
  require(o.quiet_samples >= 1 && o.quiet_samples <= 64, "--quiet-samples", "must be in [1, 64]");
  require(o.staa.segments >= 1 && o.staa.segments <= 32, "--segments", "must be in [1, 32]");
  require(std::isfinite(o.intersect_tolerance) && o.intersect_tolerance >= 0 &&
              o.intersect_tolerance <= 16,
          "--intersect-tolerance", "must be in [0, 16] pixels");
  const SpecaaOptions& sa = o.specaa;
  require(std::isfinite(sa.sigma2) && sa.sigma2 > 0, "--specaa-sigma2", "must be > 0");
  require(std::isfinite(sa.kappa) && sa.kappa >= 0, "--specaa-kappa", "must be >= 0");
  const BrunetonOptions& b = o.bruneton;
  require(std::isfinite(b.n_min) && b.n_min > 0, "--bruneton-nmin", "must be > 0");
  require(std::isfinite(b.n_max) && b.n_max > b.n_min, "--bruneton-nmax",
          "must be > --bruneton-nmin");
  require(std::isfinite(b.min_variance) && b.min_variance > 0, "--bruneton-min-variance",
          "must be > 0");
}

}  // namespace sg
