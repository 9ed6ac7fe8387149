#include "scene/lattice.h"

#include <cmath>
#include <cstring>
#include <sstream>

#include "base/atomic_file.h"
#include "base/error.h"
#include "base/fnv1a.h"
#include "scene/scene.h"
#include "scene/scene_limits.h"

namespace sg {
namespace {

constexpr char kMagic[] = "\x93NUMPY";
constexpr size_t kMagicSize = 6;

std::string num(double v) {
  std::ostringstream o;
  o.precision(6);
  o << v;
  return o.str();
}

// The header dictionary's value of `key` ('descr': '<f8' -> <f8; 'shape': (4, 4, 2) ->
// (4, 4, 2)); empty when absent.
std::string header_value(const std::string& h, const std::string& key) {
  const std::string k = "'" + key + "':";
  const size_t at = h.find(k);
  if (at == std::string::npos) return "";
  size_t p = at + k.size();
  while (p < h.size() && h[p] == ' ')
    ++p;
  size_t end = p;
  if (p < h.size() && h[p] == '(') {
    end = h.find(')', p);
    return end == std::string::npos ? "" : h.substr(p, end - p + 1);
  }
  if (p < h.size() && h[p] == '\'') {
    end = h.find('\'', p + 1);
    return end == std::string::npos ? "" : h.substr(p + 1, end - p - 1);
  }
  while (end < h.size() && h[end] != ',' && h[end] != '}')
    ++end;
  return h.substr(p, end - p);
}

std::string without_spaces(std::string s) {
  std::string out;
  for (char c : s)
    if (c != ' ') out += c;
  return out;
}

}  // namespace

vec2 lattice_wave_vector(double patch_size, int n, int i, int j) {
  const double dk = kTwoPi / patch_size;
  return vec2(dk * lattice_frequency(i, n), dk * lattice_frequency(j, n));
}

std::shared_ptr<const LatticeData> read_lattice(const std::string& path, const CascadeDesc& c,
                                                const std::string& key) {
  const std::string where = key + " (" + path + ")";
  auto fail = [&](const std::string& rule) { throw Error(where + ": " + rule); };
  const int n = c.lattice;
  // Header (at most 64 KiB) plus float64 data: anything larger is not this lattice.
  const std::uintmax_t data_bytes = static_cast<std::uintmax_t>(n) * n * 2 * 8;
  std::string bytes;
  try {
    bytes = read_file(path, data_bytes + 65536 + 10);
  } catch (const Error& e) {
    fail(std::string("cannot read the lattice file: ") + e.what());
  }
  if (bytes.size() < 10 || std::memcmp(bytes.data(), kMagic, kMagicSize) != 0)
    fail("not a NumPy .npy file (the magic string \\x93NUMPY is missing)");
  const int major = static_cast<unsigned char>(bytes[6]);
  size_t header_len = 0, header_start = 0;
  if (major == 1) {
    header_len = static_cast<unsigned char>(bytes[8]) |
                 (static_cast<size_t>(static_cast<unsigned char>(bytes[9])) << 8);
    header_start = 10;
  } else if (major == 2 || major == 3) {
    if (bytes.size() < 12) fail("truncated .npy header");
    header_len = 0;
    for (int b = 0; b < 4; ++b)
      header_len |= static_cast<size_t>(static_cast<unsigned char>(bytes[8 + b])) << (8 * b);
    header_start = 12;
  } else {
    fail("unsupported .npy format version " + std::to_string(major));
  }
  if (bytes.size() < header_start + header_len) fail("truncated .npy header");
  const std::string header = bytes.substr(header_start, header_len);
  const std::string descr = header_value(header, "descr");
  const std::string order = without_spaces(header_value(header, "fortran_order"));
  const std::string shape = without_spaces(header_value(header, "shape"));
  size_t item = 0;
  if (descr == "<f8") {
    item = 8;
  } else if (descr == "<f4") {
    item = 4;
  } else {
    fail("values must be little-endian float64 ('<f8') or float32 ('<f4') (got '" + descr + "')");
  }
  if (order != "False") fail("values must be in C order (fortran_order False)");
  std::string want = "(";
  want += std::to_string(n);
  want += ',';
  want += std::to_string(n);
  want += ",2)";
  if (shape != want) {
    fail("shape " + shape + " does not match the cascade's lattice " + std::to_string(n) +
         ": expected " + want + " (amplitude, phase per lattice point)");
  }
  const size_t start = header_start + header_len;
  const size_t need = static_cast<size_t>(n) * n * 2 * item;
  if (bytes.size() - start < need) {
    fail("truncated: " + std::to_string(need) + " bytes of values expected, " +
         std::to_string(bytes.size() - start) + " found");
  }
  if (bytes.size() - start > need) {
    fail(std::to_string(bytes.size() - start - need) + " bytes past the " + std::to_string(need) +
         " of the values");
  }

  auto data = std::make_shared<LatticeData>();
  data->n = n;
  data->amplitude.resize(static_cast<size_t>(n) * n);
  data->phase.resize(static_cast<size_t>(n) * n);
  data->fingerprint = fnv1a64(bytes);
  const char* p = bytes.data() + start;
  auto value = [&](size_t idx) {
    if (item == 8) {
      double v;
      std::memcpy(&v, p + idx * 8, 8);
      return v;
    }
    float v;
    std::memcpy(&v, p + idx * 4, 4);
    return static_cast<double>(v);
  };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const size_t e = static_cast<size_t>(j) * n + i;
      const double a = value(2 * e), phi = value(2 * e + 1);
      const std::string entry = "entry [" + std::to_string(j) + "][" + std::to_string(i) + "]";
      if (!std::isfinite(a)) fail(entry + ": the amplitude is not finite");
      if (!std::isfinite(phi)) fail(entry + ": the phase is not finite");
      if (a < 0) fail(entry + ": the amplitude must be >= 0 (got " + num(a) + ")");
      if (std::fabs(phi) > limits::kMaxPhase)
        fail(entry + ": the phase must be in [-1e+06, 1e+06] rad (got " + num(phi) + ")");
      if (a > 0) {
        const double k = length(lattice_wave_vector(c.patch_size, n, i, j));
        if (k == 0) fail(entry + ": the amplitude at k = 0 (the mean level) must be 0");
        if (!(k >= c.band_min && k < c.band_max)) {
          fail(entry + ": amplitude " + num(a) + " at |k| = " + num(k) +
               " rad/m, outside the cascade's band [" + num(c.band_min) + ", " + num(c.band_max) +
               ")");
        }
        if (!(a * k <= limits::kMaxSteepness)) {
          fail(entry + ": the steepness amplitude * |k| must be at most " +
               num(limits::kMaxSteepness) + " (Stokes' limit of breaking), got " + num(a * k));
        }
      }
      data->amplitude[e] = a;
      data->phase[e] = phi;
    }
  }
  return data;
}

std::string lattice_npy_bytes(const LatticeData& d) {
  const int n = d.n;
  std::string header = "{'descr': '<f8', 'fortran_order': False, 'shape': (" + std::to_string(n) +
                       ", " + std::to_string(n) + ", 2), }";
  // Padded with spaces and a newline so that the values start at a multiple of 64 bytes.
  const size_t total = 10 + header.size() + 1;
  header.append((64 - total % 64) % 64, ' ');
  header += '\n';
  const size_t count = static_cast<size_t>(n) * n;
  std::string out;
  out.reserve(10 + header.size() + count * 16);
  out.append(kMagic, kMagicSize);
  const char version_and_length[4] = {1, 0, static_cast<char>(header.size() & 0xff),
                                      static_cast<char>(header.size() >> 8)};
  out.append(version_and_length, 4);
  out.append(header);
  char value[16];
  for (size_t e = 0; e < count; ++e) {
    std::memcpy(value, &d.amplitude[e], 8);
    std::memcpy(value + 8, &d.phase[e], 8);
    out.append(value, 16);
  }
  return out;
}

void write_lattice(const std::string& path, const LatticeData& d) {
  write_file_atomic(path, lattice_npy_bytes(d));
}

std::vector<Wave> cascade_waves(const CascadeDesc& c, const Dispersion& water) {
  std::vector<Wave> out;
  if (!c.data) return out;
  const int n = c.data->n;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const size_t e = static_cast<size_t>(j) * n + i;
      const double a = c.data->amplitude[e];
      if (a == 0) continue;
      Wave w;
      w.amplitude = a;
      w.wave_vector = lattice_wave_vector(c.patch_size, n, i, j);
      w.angular_frequency = water.omega(length(w.wave_vector));
      w.phase = c.data->phase[e];
      out.push_back(w);
    }
  }
  return out;
}

std::vector<Wave> surface_waves(const SurfaceDesc& s) {
  std::vector<Wave> out = s.waves;
  const Dispersion water{s.depth};
  for (const CascadeDesc& c : s.cascades) {
    const std::vector<Wave> w = cascade_waves(c, water);
    out.insert(out.end(), w.begin(), w.end());
  }
  return out;
}

double cascade_variance(const CascadeDesc& c) {
  double v = 0;
  if (c.data)
    for (double a : c.data->amplitude)
      v += a * a / 2;
  return v;
}

}  // namespace sg
