// `sunglint web`'s page (web_page.h): the data the host computes, the sources, the assets.
#include "web/web_page.h"

#include <nlohmann/json.hpp>

#include <bit>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <set>

#include "base/atomic_file.h"
#include "base/error.h"
#include "base/output_path.h"
#include "embedded/web_sources.h"
#include "gl_engine/gl_engine.h"
#include "gl_engine/kernel_program.h"
#include "image/tonemap.h"
#include "methods/options.h"
#include "scene/scene.h"
#include "scene/scene_limits.h"
#include "shading/kernel_table.h"
#include "shading/path_table.h"

namespace sg::web {
namespace {

using json = nlohmann::json;

// Little-endian float32, as base64 (RFC 4648).
std::string base64_floats(const std::vector<float>& v) {
  static const char* kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string bytes(v.size() * 4, '\0');
  for (size_t i = 0; i < v.size(); ++i) {
    const uint32_t w = std::bit_cast<uint32_t>(v[i]);
    for (int k = 0; k < 4; ++k)
      bytes[4 * i + k] = static_cast<char>((w >> (8 * k)) & 0xff);
  }
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (size_t i = 0; i < bytes.size(); i += 3) {
    uint32_t n = uint32_t(static_cast<unsigned char>(bytes[i])) << 16;
    if (i + 1 < bytes.size()) n |= uint32_t(static_cast<unsigned char>(bytes[i + 1])) << 8;
    if (i + 2 < bytes.size()) n |= uint32_t(static_cast<unsigned char>(bytes[i + 2]));
    out += kAlphabet[(n >> 18) & 63];
    out += kAlphabet[(n >> 12) & 63];
    out += i + 1 < bytes.size() ? kAlphabet[(n >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? kAlphabet[n & 63] : '=';
  }
  return out;
}

// A method of the page: the GL engine's settings (gl_variant) of `name` with `options`.
struct PageMethod {
  std::string id, label, name;
  MethodOptions options;
};

std::vector<PageMethod> page_methods() {
  auto with_samples = [](int s) {
    MethodOptions o;
    o.samples = {s, s, 1};
    o.samples_given = true;
    return o;
  };
  return {
      {"point", "point", "point", MethodOptions{}},
      {"supersample-2x2x1", "supersample 2x2x1", "supersample", with_samples(2)},
      {"supersample-4x4x1", "supersample 4x4x1", "supersample", with_samples(4)},
      {"staa-temporal", "staa-temporal", "staa-temporal", MethodOptions{}},
      {"staa", "staa", "staa", MethodOptions{}},
  };
}

// The uniforms of the kernel's structs as gl_engine/uniforms.cpp writes them, by field.
json staa_params(const kf::StaaParams& p) {
  return {{"per_pixel_ndf", p.per_pixel_ndf},
          {"ndf_mean_shift", p.ndf_mean_shift},
          {"kernels", p.kernels},
          {"elongation_threshold", p.elongation_threshold},
          {"fallback_riemann", p.fallback_riemann},
          {"fallback_along_path", p.fallback_along_path},
          {"riemann_cells", p.riemann_cells},
          {"alias_start", p.alias_start},
          {"alias_end", p.alias_end},
          {"nyquist_max", p.nyquist_max},
          {"footprint", p.footprint},
          {"curvature_limit", p.curvature_limit},
          {"fold_cells", p.fold_cells},
          {"wave_remainder", p.wave_remainder},
          {"smooth_cells", p.smooth_cells},
          {"rdf_at_light", p.rdf_at_light}};
}
json table_info(const kf::PathTableInfo& t) {
  return {{"n_distance", t.n_distance},
          {"n_u", t.n_u},
          {"n_v", t.n_v},
          {"n_sigma", t.n_sigma},
          {"sigma_min", t.sigma_min},
          {"sigma_max", t.sigma_max},
          {"log_q", t.log_q},
          {"extent_k", t.extent_k}};
}
json fit_info(const kf::KernelFitInfo& t) {
  return {{"intervals", t.intervals},
          {"max_ratio", t.max_ratio},
          {"first_solved3", t.first_solved3},
          {"first_solved5", t.first_solved5},
          {"first_solved9", t.first_solved9}};
}

json methods_json(const kf::PathTableInfo& tinfo, const kf::KernelFitInfo& finfo) {
  json out = json::array();
  for (const PageMethod& m : page_methods()) {
    const gl_engine::GlVariant v = gl_engine::gl_variant(m.name, m.options);
    json uniforms = json::object();
    if (v.entry == gl_engine::KernelEntry::stratified) {
      uniforms["counts"] = {{"sx", v.counts.sx},
                            {"sy", v.counts.sy},
                            {"nt", v.counts.nt},
                            {"time_at_frame", v.counts.time_at_frame}};
    }
    if (v.entry == gl_engine::KernelEntry::staa) {
      uniforms["params"] = staa_params(v.params);
      uniforms["tinfo"] = table_info(tinfo);
      uniforms["finfo"] = fit_info(finfo);
    }
    const uint64_t seed = m.options.seed;
    out.push_back(
        {{"id", m.id},
         {"label", m.label},
         {"define", gl_engine::entry_define(v.entry)},
         {"header", gl_engine::kernel_program_header(v.entry, gl_engine::program_options(v))},
         {"segments", v.segments},
         {"intersect_tolerance", v.intersect_tolerance},
         {"seed", {uint32_t(seed), uint32_t(seed >> 32)}},
         {"uniforms", uniforms}});
  }
  return out;
}

// F, the fine grids of F per slice (PathTables::fine_grid) and the kernel fits.
json tables_json(const PathTables& t) {
  const PathTableParams& p = t.params();
  const kernel_tables::R32Texture2D f = t.f_texture();
  std::vector<float> fine;
  json slices = json::array();
  for (int k = 0; k < p.n_sigma; ++k) {
    const double sigma = t.slice_sigma(k), R = t.extent(k);
    json s = {{"sigma", sigma}, {"extent", float(R)}};
    if (sigma > 0) {
      const PathTables::FineGrid g = PathTables::fine_grid(sigma, R);
      s["offset"] = fine.size();
      s["count"] = g.values.size();
      s["step"] = g.step;
      s["panels"] = PathTables::cell_panels(t.u_cell(k), sigma);
      for (double x : g.values)
        fine.push_back(float(x));
    }
    slices.push_back(s);
  }
  const KernelFitTexture& fits = kernel_fit_texture();
  return {{"info", table_info(t.kernel_info_float())},
          {"fits_info", fit_info(fits.info_float)},
          {"f", base64_floats(std::vector<float>(f.data, f.data + size_t(f.width) * f.height))},
          {"fits", base64_floats(fits.texels)},
          {"fits_rows", fits.texels.size() / 15},
          {"fine", base64_floats(fine)},
          {"slices", slices}};
}

json display_json() {
  const DisplaySettings d;
  const GlareSettings& g = d.glare_settings;
  json blurs = json::array();
  for (const GlareBlur& b : g.blurs)
    blurs.push_back({b.sigma, b.weight});
  return {{"exposure", d.exposure},
          {"glare_on", d.glare},
          {"glare",
           {{"threshold", g.threshold},
            {"blurs", blurs},
            {"star_points", g.star_points},
            {"star_length", g.star_length},
            {"star_weight", g.star_weight},
            {"star_angle_deg", g.star_angle_deg}}}};
}

// `window.NAME = VALUE;` with the JSON's "</" escaped, so that a scene's text cannot close
// a script element.
std::string script_assigning(const std::string& name, const json& value) {
  std::string text = value.dump();
  std::string out = "// Written by `sunglint web` (docs/web.md); data for host.js and page.js.\n";
  out += "window." + name + " = ";
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '<' && i + 1 < text.size() && text[i + 1] == '/') {
      out += "<\\/";
      ++i;
    } else {
      out += text[i];
    }
  }
  return out + ";\n";
}

}  // namespace

std::vector<std::string> web_method_ids() {
  std::vector<std::string> ids;
  for (const PageMethod& m : page_methods())
    ids.push_back(m.id);
  return ids;
}

WebPage write_web_page(const WebPageOptions& o, const PathTables& tables) {
  if (o.scenes.empty()) throw Error("give at least one scene file");
  // The scenes, checked by the loader, kept as their files' text for the page's own checks.
  WebPage page;
  json scenes = json::array();
  std::set<std::string> names;
  for (const WebScene& w : o.scenes) {
    const std::string& path = w.path;
    Scene s = load_scene(path);
    // The page's kernel takes a fixed camera (kernel/glsl_es_prelude.glsl: SG_FIXED_CAMERA).
    if (s.camera.moving()) {
      throw Error(path +
                  ": camera.keyframes: the page renders a fixed camera (a moving one: "
                  "sunglint render)");
    }
    if (!s.surface.cascades.empty()) {
      throw Error(path +
                  ": surface.cascades: the page reads explicit waves only (`sunglint ocean "
                  "--cascades C --lattice N --expand` writes the same sea as explicit waves)");
    }
    set_image_size(s, w.width > 0 ? w.width : s.width, w.height > 0 ? w.height : s.height);
    if (!names.insert(s.name).second) {
      throw Error(path + ": a second scene named '" + s.name +
                  "' (the page's scene parameter takes names)");
    }
    page.scene_names.push_back(s.name);
    const std::string file = std::filesystem::path(path).filename().string();
    scenes.push_back({{"file", file},
                      {"name", s.name},
                      {"width", s.width},
                      {"height", s.height},
                      {"text", read_file(path, limits::kMaxSceneFileBytes)}});
  }
  prepare_output_folder(o.out_dir, "--out");

  json data = {
      {"kernel", gl_engine::kernel_fingerprint()},
      {"scenes", scenes},
      {"methods", methods_json(tables.kernel_info_float(), kernel_fit_texture().info_float)},
      {"default_method", "staa"},
      {"default_split", "point"},
      {"tables", tables_json(tables)},
      {"display", display_json()}};

  // The GLSL the page compiles, by the names host.js includes them by.
  json shaders = json::object();
  for (const EmbeddedFile& f : web_sources()) {
    const std::string name(f.name);
    if (name.ends_with(".glsl")) shaders[name] = std::string(f.bytes);
  }
  std::vector<std::pair<std::string, std::string>> files = {
      {"data.js", script_assigning("SUNGLINT_DATA", data)},
      {"shaders.js", script_assigning("SUNGLINT_SHADERS", shaders)},
  };
  for (const char* asset : {"index.html", "page.js", "host.js", "scene_check.js"}) {
    files.emplace_back(
        asset, std::string(find_embedded(web_sources(), std::string("web/assets/") + asset).bytes));
  }
  for (const auto& [name, text] : files) {
    write_file_atomic((std::filesystem::path(o.out_dir) / name).string(), text);
    page.files.push_back({name, text.size()});
    page.total_bytes += text.size();
  }
  return page;
}

}  // namespace sg::web
