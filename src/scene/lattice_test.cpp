// Lattice cascades (scene/lattice.h): the .npy sidecar written and read back, every bad
// file refused naming the scene's key and the file, the cascades' keys in a /3 scene, and
// the lattice's waves as the explicit sines the format defines.
#include "scene/lattice.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>

#include "base/atomic_file.h"
#include "base/error.h"
#include "math/rng.h"
#include "scene/model.h"
#include "scene/scene.h"
#include "testing/paths.h"

namespace sg {
namespace {

std::string out_dir(const std::string& name) {
  const std::string d = testing::binary_dir() + "/test_out/lattice_test/" + name;
  std::filesystem::create_directories(d);
  return d;
}

// A cascade of side `patch` m, lattice n, band [0.2, 2) rad/m, with random amplitudes inside it.
CascadeDesc random_cascade(int n, uint64_t seed, double patch = 64) {
  CascadeDesc c;
  c.patch_size = patch;
  c.lattice = n;
  c.band_min = 0.2;
  c.band_max = 2.0;
  auto d = std::make_shared<LatticeData>();
  d->n = n;
  d->amplitude.assign(static_cast<size_t>(n) * n, 0.0);
  d->phase.assign(static_cast<size_t>(n) * n, 0.0);
  Pcg32 rng(seed, 3);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const size_t e = static_cast<size_t>(j) * n + i;
      const double k = length(lattice_wave_vector(c.patch_size, n, i, j));
      d->phase[e] = kTwoPi * rng.uniform() - kPi;
      if (k >= c.band_min && k < c.band_max) d->amplitude[e] = 0.02 * rng.uniform() / k;
    }
  }
  c.data = d;
  return c;
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(Lattice, WaveVectorsInFftOrder) {
  EXPECT_EQ(lattice_frequency(0, 8), 0);
  EXPECT_EQ(lattice_frequency(3, 8), 3);
  EXPECT_EQ(lattice_frequency(4, 8), -4);
  EXPECT_EQ(lattice_frequency(7, 8), -1);
  const vec2 k = lattice_wave_vector(100, 8, 7, 2);
  EXPECT_DOUBLE_EQ(k.x, -kTwoPi / 100);
  EXPECT_DOUBLE_EQ(k.y, 2 * kTwoPi / 100);
}

TEST(Lattice, NpyWrittenAndReadBack) {
  const CascadeDesc c = random_cascade(16, 1);
  const std::string path = out_dir("roundtrip") + "/c.npy";
  write_lattice(path, *c.data);
  const std::string bytes = read_file(path);
  // NumPy's format 1.0: magic, version, header length, a dict padded to 64 bytes.
  ASSERT_EQ(bytes.compare(0, 8, std::string("\x93NUMPY\x01\x00", 8)), 0);
  const size_t header =
      static_cast<unsigned char>(bytes[8]) | (static_cast<unsigned char>(bytes[9]) << 8);
  EXPECT_EQ((10 + header) % 64, 0u);
  EXPECT_NE(bytes.find("'descr': '<f8', 'fortran_order': False, 'shape': (16, 16, 2)"),
            std::string::npos);
  EXPECT_EQ(bytes.size(), 10 + header + 16 * 16 * 16);
  const auto back = read_lattice(path, c, "surface.cascades[0].file");
  EXPECT_EQ(back->amplitude, c.data->amplitude);
  EXPECT_EQ(back->phase, c.data->phase);
  EXPECT_NE(back->fingerprint, 0u);
  // Another lattice, another fingerprint.
  const CascadeDesc other = random_cascade(16, 2);
  write_lattice(path, *other.data);
  EXPECT_NE(read_lattice(path, other, "k")->fingerprint, back->fingerprint);
}

TEST(Lattice, Float32FilesRead) {
  const CascadeDesc c = random_cascade(8, 3);
  std::string bytes = lattice_npy_bytes(*c.data);
  const size_t at = bytes.find("<f8");
  bytes[at + 2] = '4';
  const size_t start = bytes.size() - 8 * 8 * 16;
  std::string values;
  for (size_t e = 0; e < 8 * 8 * 2; ++e) {
    double v;
    std::memcpy(&v, &bytes[start + 8 * e], 8);
    const float f = static_cast<float>(v);
    values.append(reinterpret_cast<const char*>(&f), 4);
  }
  const std::string path = out_dir("float32") + "/c.npy";
  write_file_atomic(path, bytes.substr(0, start) + values);
  const auto back = read_lattice(path, c, "k");
  for (size_t e = 0; e < back->amplitude.size(); ++e)
    EXPECT_EQ(back->amplitude[e], static_cast<double>(static_cast<float>(c.data->amplitude[e])));
}

TEST(Lattice, BadFilesRefusedNamingTheKeyAndTheFile) {
  const CascadeDesc c = random_cascade(8, 4);
  const std::string dir = out_dir("bad");
  const std::string good = lattice_npy_bytes(*c.data);
  const std::string key = "surface.cascades[2].file";
  auto refused = [&](const std::string& name, const std::string& bytes) {
    const std::string path = dir + "/" + name + ".npy";
    write_file_atomic(path, bytes);
    return error_of([&] { read_lattice(path, c, key); });
  };
  auto has = [](const std::string& msg, const std::string& part) {
    return msg.find(part) != std::string::npos;
  };
  const std::string prefix = key + " (" + dir + "/";

  std::string m = refused("truncated", good.substr(0, good.size() - 24));
  EXPECT_TRUE(
      has(m, prefix + "truncated.npy): truncated: 1024 bytes of values expected, 1000 found"))
      << m;
  m = refused("extra", good + "x");
  EXPECT_TRUE(has(m, "1 bytes past the 1024 of the values")) << m;
  m = refused("magic", "hello" + good.substr(5));
  EXPECT_TRUE(has(m, prefix + "magic.npy): not a NumPy .npy file")) << m;

  CascadeDesc wrong = c;
  wrong.lattice = 16;
  m = error_of([&] {
    const std::string path = dir + "/mismatch.npy";
    write_file_atomic(path, good);
    read_lattice(path, wrong, key);
  });
  EXPECT_TRUE(has(m, "shape (8,8,2) does not match the cascade's lattice 16: expected (16,16,2)"))
      << m;

  std::string fortran = good;
  fortran.replace(fortran.find("False"), 5, "True ");
  m = refused("fortran", fortran);
  EXPECT_TRUE(has(m, "values must be in C order")) << m;
  std::string big_endian = good;
  big_endian[big_endian.find("<f8")] = '>';
  m = refused("endian", big_endian);
  EXPECT_TRUE(has(m, "little-endian float64 ('<f8') or float32 ('<f4') (got '>f8')")) << m;

  // Values: the entry and the rule.
  const size_t start = good.size() - 8 * 8 * 16;
  auto with_value = [&](int entry, int field, double v) {
    std::string b = good;
    std::memcpy(&b[start + 16 * entry + 8 * field], &v, 8);
    return b;
  };
  m = refused("nan", with_value(9, 0, std::nan("")));
  EXPECT_TRUE(has(m, "entry [1][1]: the amplitude is not finite")) << m;
  m = refused("inf_phase", with_value(9, 1, INFINITY));
  EXPECT_TRUE(has(m, "entry [1][1]: the phase is not finite")) << m;
  m = refused("negative", with_value(10, 0, -0.01));
  EXPECT_TRUE(has(m, "entry [1][2]: the amplitude must be >= 0")) << m;
  m = refused("mean", with_value(0, 0, 0.01));
  EXPECT_TRUE(has(m, "entry [0][0]: the amplitude at k = 0 (the mean level) must be 0")) << m;
  // (i, j) = (1, 0): |k| = 2 pi / 64 = 0.098, below the band's 0.2.
  m = refused("out_of_band", with_value(1, 0, 0.01));
  EXPECT_TRUE(has(m,
                  "entry [0][1]: amplitude 0.01 at |k| = 0.0981748 rad/m, outside the "
                  "cascade's band [0.2, 2)"))
      << m;
  // (i, j) = (3, 0): |k| = 0.295, steepness 2 * 0.295 > 0.45.
  m = refused("steep", with_value(3, 0, 2.0));
  EXPECT_TRUE(has(m, "entry [0][3]: the steepness amplitude * |k| must be at most 0.45")) << m;
  m = error_of([&] { read_lattice(dir + "/absent.npy", c, key); });
  EXPECT_TRUE(has(m, prefix + "absent.npy): cannot read the lattice file")) << m;
}

// A /3 scene with two cascades and an explicit wave, its sidecars beside it.
std::string cascaded_scene(const std::string& dir, const std::string& extra_surface = "",
                           const std::string& format = "sunglint-scene/3",
                           const std::string& band1 = "[2.0, 5.0]") {
  CascadeDesc a = random_cascade(8, 5, 16), b = random_cascade(16, 6);
  write_lattice(dir + "/a.npy", *a.data);
  b.patch_size = 8;
  b.band_min = 2.0;
  b.band_max = 5.0;
  auto d = std::make_shared<LatticeData>(*b.data);
  for (int j = 0; j < 16; ++j) {
    for (int i = 0; i < 16; ++i) {
      const double k = length(lattice_wave_vector(8, 16, i, j));
      d->amplitude[static_cast<size_t>(j) * 16 + i] = k >= 2.0 && k < 5.0 ? 0.01 / k : 0.0;
    }
  }
  write_lattice(dir + "/b.npy", *d);
  const std::string text = R"({"format": ")" + format + R"(", "name": "lattice",
    "image": {"width": 32, "height": 18},
    "camera": {"position": [0, 3, 0], "look_at": [0, 0, -100], "up": [0, 1, 0], "vfov_deg": 40},
    "light": {"direction": [0, 0.17, -1], "angular_radius_deg": 0.27},
    "surface": {"waves": [{"amplitude": 0.05, "wave_vector": [0.3, -1.2], "angular_frequency": 3.4}],
      "depth": 30,
      "cascades": [
        {"file": "a.npy", "patch_size": 16, "lattice": 8, "band": [0.2, 2.0]},
        {"file": "b.npy", "patch_size": 8, "lattice": 16, "band": )" +
                           band1 + R"(})" + extra_surface + R"(]},
    "animation": {"t0": 0, "fps": 30, "frames": 4, "shutter": 1}})";
  write_file_atomic(dir + "/scene.json", text);
  return dir + "/scene.json";
}

TEST(LatticeScene, CascadesLoadAndTheirWavesAreTheSurfaces) {
  const std::string dir = out_dir("scene");
  const Scene s = load_scene(cascaded_scene(dir));
  ASSERT_EQ(s.surface.cascades.size(), 2u);
  EXPECT_EQ(s.format_version(), 3);
  EXPECT_EQ(s.surface.depth, 30);
  const CascadeDesc& b = s.surface.cascades[1];
  EXPECT_EQ(b.file, "b.npy");
  EXPECT_EQ(b.lattice, 16);
  EXPECT_EQ(b.band_min, 2.0);
  // The surface: the explicit wave, then every non-zero lattice point with omega(|k|) at
  // 30 m; a model's wave field holds them all.
  const std::vector<Wave> all = surface_waves(s.surface);
  size_t lattice_waves = 0;
  for (const CascadeDesc& c : s.surface.cascades)
    for (double amp : c.data->amplitude)
      lattice_waves += amp > 0;
  ASSERT_GT(lattice_waves, 20u);
  ASSERT_EQ(all.size(), 1 + lattice_waves);
  EXPECT_EQ(all[0].angular_frequency, 3.4);
  const Dispersion water{30};
  for (size_t k = 1; k < all.size(); ++k)
    EXPECT_DOUBLE_EQ(all[k].angular_frequency, water.omega(length(all[k].wave_vector)));
  EXPECT_EQ(SceneModel(s).waves.size(), all.size());

  // Written and read again: the same keys, the files named as given.
  const std::string text = scene_to_json(s);
  EXPECT_NE(text.find("\"file\": \"b.npy\""), std::string::npos);
  const Scene again = parse_scene(text, "again", dir);
  EXPECT_EQ(scene_to_json(again), text);
  EXPECT_EQ(again.surface.cascades[1].data->amplitude, b.data->amplitude);
}

TEST(LatticeScene, BadCascadeKeysRefused) {
  const std::string dir = out_dir("scene_bad");
  auto msg = [&](const std::string& extra, const std::string& format, const std::string& band) {
    return error_of([&] { load_scene(cascaded_scene(dir, extra, format, band)); });
  };
  const std::string p = dir + "/scene.json: ";
  EXPECT_EQ(msg("", "sunglint-scene/2", "[2.0, 5.0]"),
            p + "surface.depth: needs \"format\": \"sunglint-scene/3\"");
  EXPECT_EQ(msg("", "sunglint-scene/3", "[1.5, 5.0]"),
            p + "surface.cascades[1].band: overlaps the band of surface.cascades[0]: a "
                "wavelength would be counted twice");
  EXPECT_EQ(msg("", "sunglint-scene/3", "[5.0, 2.0]"),
            p + "surface.cascades[1].band: must be [min, max] with 0 <= min < max (got [5, 2])");
  EXPECT_EQ(msg(R"(, {"file": "a.npy", "patch_size": 64, "lattice": 12, "band": [9, 10]})",
                "sunglint-scene/3", "[2.0, 5.0]"),
            p + "surface.cascades[2].lattice: must be a power of two in [4, 1024] (got 12)");
  EXPECT_EQ(msg(R"(, {"file": "a.npy", "patch_size": 64, "lattice": 8, "band": [9, 10]})",
                "sunglint-scene/3", "[2.0, 5.0]"),
            p + "surface.cascades[2].band: max must be at most the lattice's largest |k|, 2 pi "
                "/ patch_size * N / 2 * sqrt 2 = 0.55536 rad/m (got 10)");
  // A sidecar whose lattice disagrees with the scene's: the key and the file.
  const std::string m =
      msg(R"(, {"file": "b.npy", "patch_size": 2, "lattice": 8, "band": [9, 10]})",
          "sunglint-scene/3", "[2.0, 5.0]");
  EXPECT_NE(m.find(p + "surface.cascades[2].file (" + dir +
                   "/b.npy): shape (16,16,2) does not match the cascade's lattice 8"),
            std::string::npos)
      << m;
}

}  // namespace
}  // namespace sg
