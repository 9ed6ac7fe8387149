// The path-integral tables (Podee et al. 2021, Sec. 3.5, Eqs. 17-19, and Sec. 4); every
// choice is documented in path_table.h.
#include "shading/path_table.h"

#include <zlib.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <thread>

#include "base/atomic_file.h"
#include "base/embedded_file.h"
#include "base/error.h"
#include "base/fnv1a.h"
#include "embedded/path_table_sources.h"
#include "kernel/kernel_double.h"
#include "shading/disk_gaussian.h"

namespace sg {

double PathTables::distance_node(int i, int k) const {
  return kd::table_radial_node(extent_[k], double(i) / (p_.n_distance - 1));
}
double PathTables::v_node(int j, int k) const {
  return kd::table_radial_node(extent_[k], double(j) / (p_.n_v - 1));
}
namespace {

namespace fs = std::filesystem;

constexpr char kMagic[8] = {'S', 'G', 'P', 'A', 'T', 'H', 'T', 'B'};
constexpr size_t kHeaderBytes = 64;

[[noreturn]] void bad(const std::string& what, double got) {
  std::ostringstream msg;
  msg << what << " (got " << got << ")";
  throw Error(msg.str());
}

void validate(const PathTableParams& p) {
  if (p.n_distance < 2) bad("path tables: n_distance must be >= 2", p.n_distance);
  if (p.n_u < 2) bad("path tables: n_u must be >= 2", p.n_u);
  if (p.n_v < 2) bad("path tables: n_v must be >= 2", p.n_v);
  if (p.n_sigma < 3) bad("path tables: n_sigma must be >= 3", p.n_sigma);
  if (!(p.sigma_min > 0 && std::isfinite(p.sigma_min)))
    bad("path tables: sigma_min must be finite and > 0", p.sigma_min);
  if (!(p.sigma_max > p.sigma_min && std::isfinite(p.sigma_max)))
    bad("path tables: sigma_max must be finite and > sigma_min", p.sigma_max);
  if (!(p.extent_k > 0 && std::isfinite(p.extent_k)))
    bad("path tables: extent_k must be finite and > 0", p.extent_k);
}

// ---------------------------------------------------------------- generation

}  // namespace

PathTables::PathTables(const PathTableParams& p) : p_(p) {
  validate(p);
  sigma_.resize(p.n_sigma);
  extent_.resize(p.n_sigma);
  log_q_ = std::log(p.sigma_max / p.sigma_min) / (p.n_sigma - 2);
  sigma_[0] = 0;
  for (int k = 1; k < p.n_sigma; ++k)
    sigma_[k] = p.sigma_min * std::exp((k - 1) * log_q_);
  sigma_[p.n_sigma - 1] = p.sigma_max;
  for (int k = 0; k < p.n_sigma; ++k)
    extent_[k] = 1 + p.extent_k * sigma_[k];
}

PathTables::FineGrid PathTables::fine_grid(double sigma, double R) {
  FineGrid g;
  g.step = std::min(sigma / 16, R / 1024);
  const int n = static_cast<int>(std::ceil(std::sqrt(2.0) * R / g.step)) + 4;
  g.values.resize(n);
  for (int j = 0; j < n; ++j)
    g.values[j] = disk_gaussian(j * g.step, sigma);
  return g;
}

int PathTables::cell_panels(double hu, double sigma) {
  return std::max(1, static_cast<int>(std::ceil(hu / sigma)));
}

PathTables PathTables::generate(const PathTableParams& params, int threads) {
  PathTables t(params);
  const PathTableParams& p = t.p_;
  t.f_.assign(size_t(p.n_sigma) * p.n_distance, 0.0f);
  t.s_.assign(size_t(p.n_sigma) * p.n_v * p.n_u, 0.0f);

  auto make_slice = [&t, &p](int k) {
    const double sigma = t.sigma_[k], R = t.extent_[k];
    float* f = &t.f_[size_t(k) * p.n_distance];
    for (int i = 0; i < p.n_distance; ++i)
      f[i] = float(disk_gaussian(t.distance_node(i, k), sigma));
    const double hu = t.u_cell(k);
    if (sigma == 0) {
      for (int j = 0; j < p.n_v; ++j) {
        const double v = t.v_node(j, k);
        float* row = &t.s_[(size_t(k) * p.n_v + j) * p.n_u];
        for (int i = 0; i < p.n_u; ++i)
          row[i] = float(kd::path_table_chord(t.u_node(i, k), v));
      }
      return;
    }
    // F on the fine grid, integrated by the kernel's functions (kernel/path_table_gen.glsl).
    const FineGrid fine = fine_grid(sigma, R);
    const kd::TableLine line{fine.values.data(), static_cast<int>(fine.values.size())};
    const int count = line.size;
    const double step = fine.step;
    const int panels = cell_panels(hu, sigma);
    const double w = hu / panels;
    // Where F is exactly 1 or 0 (|d - 1| >= 40 sigma, disk_gaussian.h) the cell's integral
    // is its width or 0; the fine grid holds those exact values, so skipping is exact.
    const double d_one = 1 - 40 * sigma, d_zero = 1 + 40 * sigma;
    for (int j = 0; j < p.n_v; ++j) {
      const double v = t.v_node(j, k), v2 = v * v;
      float* row = &t.s_[(size_t(k) * p.n_v + j) * p.n_u];
      double sum = 0;
      row[0] = 0.0f;
      for (int i = 0; i + 1 < p.n_u; ++i) {
        // The cell [u_i, u_i + hu] lies left of u = 0: its nearest point to the centre is
        // its right end.
        const double u0 = t.u_node(i, k), u1 = u0 + hu;
        const double d_far = std::hypot(u0, v), d_near = std::hypot(std::min(u1, 0.0), v);
        if (d_near >= d_zero) {
          // nothing to add
        } else if (d_far <= d_one) {
          sum += hu;
        } else {
          for (int m = 0; m < panels; ++m) {
            const double c = u0 + (m + 0.5) * w, r = 0.5 * w;
            sum += kd::path_cell_panel(line, 0, count, step, c, r, v2);
          }
        }
        row[i + 1] = float(sum);
      }
    }
  };

  int n = threads > 0 ? threads : static_cast<int>(std::thread::hardware_concurrency());
  n = std::clamp(n, 1, p.n_sigma);
  std::atomic<int> next{0};
  auto worker = [&] {
    for (int k; (k = next.fetch_add(1)) < p.n_sigma;)
      make_slice(k);
  };
  std::vector<std::thread> pool;
  for (int i = 1; i < n; ++i)
    pool.emplace_back(worker);
  worker();
  for (auto& th : pool)
    th.join();
  return t;
}

// ---------------------------------------------------------------- lookups

kd::PathTableInfo PathTables::kernel_info() const {
  kd::PathTableInfo t;
  t.n_distance = p_.n_distance;
  t.n_u = p_.n_u;
  t.n_v = p_.n_v;
  t.n_sigma = p_.n_sigma;
  t.sigma_min = p_.sigma_min;
  t.sigma_max = p_.sigma_max;
  t.log_q = log_q_;
  t.extent_k = p_.extent_k;
  return t;
}

kf::PathTableInfo PathTables::kernel_info_float() const {
  kf::PathTableInfo t;
  t.n_distance = p_.n_distance;
  t.n_u = p_.n_u;
  t.n_v = p_.n_v;
  t.n_sigma = p_.n_sigma;
  t.sigma_min = float(p_.sigma_min);
  t.sigma_max = float(p_.sigma_max);
  t.log_q = float(log_q_);
  t.extent_k = float(p_.extent_k);
  return t;
}

namespace {

void check_finite(double x, const char* name) {
  if (!std::isfinite(x)) bad(std::string("path tables: ") + name + " must be finite", x);
}
void check_sigma(double sigma) {
  if (!(std::isfinite(sigma) && sigma >= 0))
    bad("path tables: sigma must be finite and >= 0", sigma);
}

}  // namespace

double PathTables::disk_gaussian_table(double d, double sigma) const {
  check_sigma(sigma);
  if (!(std::isfinite(d) && d >= 0)) bad("path tables: d must be finite and >= 0", d);
  return kd::disk_gaussian_table(f_texture(), kernel_info(), d, sigma);
}

double PathTables::path_table_S(double u, double v, double sigma) const {
  check_sigma(sigma);
  check_finite(u, "u");
  check_finite(v, "v");
  return kd::path_table_S(s_texture(), kernel_info(), u, v, sigma);
}

double PathTables::path_integral(double u0, double u1, double v, double sigma) const {
  check_sigma(sigma);
  check_finite(u0, "u0");
  check_finite(u1, "u1");
  check_finite(v, "v");
  return kd::path_integral(f_texture(), s_texture(), kernel_info(), u0, u1, v, sigma);
}

double PathTables::path_average(vec2 p0, vec2 p1, double sigma, double disk_radius) const {
  if (!(std::isfinite(disk_radius) && disk_radius > 0))
    bad("path tables: disk_radius must be finite and > 0", disk_radius);
  check_sigma(sigma);
  check_finite(p0.x, "p0.x");
  check_finite(p0.y, "p0.y");
  check_finite(p1.x, "p1.x");
  check_finite(p1.y, "p1.y");
  return kd::path_average(f_texture(), s_texture(), kernel_info(), p0, p1, sigma, disk_radius);
}

// ---------------------------------------------------------------- cache

namespace {

void put_u32(std::string& out, uint32_t x) {
  for (int i = 0; i < 4; ++i)
    out.push_back(static_cast<char>((x >> (8 * i)) & 0xff));
}
void put_u64(std::string& out, uint64_t x) {
  for (int i = 0; i < 8; ++i)
    out.push_back(static_cast<char>((x >> (8 * i)) & 0xff));
}
void put_f64(std::string& out, double x) {
  put_u64(out, std::bit_cast<uint64_t>(x));
}
uint32_t get_u32(std::string_view in, size_t at) {
  uint32_t x = 0;
  for (int i = 0; i < 4; ++i)
    x |= uint32_t(static_cast<unsigned char>(in[at + i])) << (8 * i);
  return x;
}
uint64_t get_u64(std::string_view in, size_t at) {
  uint64_t x = 0;
  for (int i = 0; i < 8; ++i)
    x |= uint64_t(static_cast<unsigned char>(in[at + i])) << (8 * i);
  return x;
}
double get_f64(std::string_view in, size_t at) {
  return std::bit_cast<double>(get_u64(in, at));
}

uint32_t crc_of(std::string_view bytes) {
  uLong crc = crc32_z(0L, Z_NULL, 0);
  return static_cast<uint32_t>(
      crc32_z(crc, reinterpret_cast<const Bytef*>(bytes.data()), bytes.size()));
}

size_t payload_floats(const PathTableParams& p) {
  return size_t(p.n_sigma) * p.n_distance + size_t(p.n_sigma) * p.n_v * p.n_u;
}

}  // namespace

uint32_t PathTables::source_fingerprint() {
  static const uint32_t h = [] {
    uint64_t x = kFnv1aBasis;
    for (const EmbeddedFile& f : path_table_sources()) {
      x = fnv1a64(f.name, x);
      x = fnv1a64(std::string_view("\0", 1), x);
      x = fnv1a64(f.bytes, x);
    }
    return uint32_t(x ^ (x >> 32));
  }();
  return h;
}

namespace {

std::optional<PathTables> reject(std::string* why, const std::string& reason) {
  if (why) *why = reason;
  return std::nullopt;
}

}  // namespace

std::string PathTables::serialize() const {
  std::string out;
  out.reserve(kHeaderBytes + bytes() + 4);
  out.append(kMagic, sizeof kMagic);
  put_u32(out, kFormatVersion);
  put_u32(out, uint32_t(p_.n_distance));
  put_u32(out, uint32_t(p_.n_u));
  put_u32(out, uint32_t(p_.n_v));
  put_u32(out, uint32_t(p_.n_sigma));
  put_u32(out, source_fingerprint());
  put_f64(out, p_.sigma_min);
  put_f64(out, p_.sigma_max);
  put_f64(out, p_.extent_k);
  put_u64(out, uint64_t(bytes()));
  for (const std::vector<float>* v : {&f_, &s_}) {
    for (float x : *v)
      put_u32(out, std::bit_cast<uint32_t>(x));
  }
  put_u32(out, crc_of(out));
  return out;
}

std::optional<PathTables> PathTables::deserialize(std::string_view in,
                                                  const PathTableParams& expected,
                                                  std::string* why) {
  if (in.size() < kHeaderBytes + 4) return reject(why, "truncated header");
  if (std::memcmp(in.data(), kMagic, sizeof kMagic) != 0) return reject(why, "bad magic");
  const uint32_t version = get_u32(in, 8);
  if (version != kFormatVersion) {
    return reject(why, "format version " + std::to_string(version) + ", expected " +
                           std::to_string(kFormatVersion));
  }
  PathTableParams p;
  p.n_distance = int(get_u32(in, 12));
  p.n_u = int(get_u32(in, 16));
  p.n_v = int(get_u32(in, 20));
  p.n_sigma = int(get_u32(in, 24));
  p.sigma_min = get_f64(in, 32);
  p.sigma_max = get_f64(in, 40);
  p.extent_k = get_f64(in, 48);
  if (!(p == expected)) return reject(why, "parameters differ");
  if (get_u32(in, 28) != source_fingerprint()) {
    return reject(why,
                  "made by other grid or generation sources (kernel/path_table_grid.glsl, "
                  "kernel/path_table_gen.glsl)");
  }
  const size_t floats = payload_floats(p);
  if (get_u64(in, 56) != floats * 4) return reject(why, "payload size differs");
  if (in.size() != kHeaderBytes + floats * 4 + 4) return reject(why, "truncated or oversized");
  if (crc_of(in.substr(0, in.size() - 4)) != get_u32(in, in.size() - 4)) {
    return reject(why, "checksum mismatch");
  }
  PathTables t(p);
  t.f_.resize(size_t(p.n_sigma) * p.n_distance);
  t.s_.resize(size_t(p.n_sigma) * p.n_v * p.n_u);
  size_t at = kHeaderBytes;
  for (std::vector<float>* v : {&t.f_, &t.s_}) {
    for (float& x : *v) {
      x = std::bit_cast<float>(get_u32(in, at));
      at += 4;
    }
  }
  return t;
}

PathTables PathTables::load_or_generate(const std::string& path, const PathTableParams& params,
                                        PathTableCacheResult* result) {
  PathTableCacheResult r;
  r.path = path;
  if (!path.empty()) {
    std::error_code ec;
    if (fs::exists(path, ec)) {
      try {
        std::string why;
        std::optional<PathTables> t = deserialize(read_file(path), params, &why);
        if (t) {
          r.loaded = true;
          if (result) *result = r;
          return std::move(*t);
        }
        r.note = path + ": stale cache (" + why + "), regenerated";
      } catch (const std::exception& e) {
        r.note = std::string(e.what()) + ", regenerated";
      }
    } else {
      r.note = path + ": no cache, generated";
    }
  } else {
    r.note = "no cache directory, generated in memory";
  }
  PathTables t = generate(params);
  if (!path.empty()) {
    try {
      std::error_code ec;
      fs::create_directories(fs::path(path).parent_path(), ec);
      write_file_atomic(path, t.serialize());
      r.written = true;
    } catch (const std::exception& e) {
      r.note += std::string("; not written: ") + e.what();
    }
  }
  if (result) *result = r;
  return t;
}

}  // namespace sg
