#include "viewer/viewer.h"

#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <deque>
#include <memory>
#include <numeric>
#include <optional>
#include <thread>

#include "base/atomic_file.h"
#include "base/error.h"
#include "base/output_path.h"
#include "gl_engine/gl_engine.h"
#include "image/image_io.h"
#include "methods/method.h"
#include "scene/camera_path.h"
#include "viewer/camera_record.h"
#include "viewer/gpu_display.h"
#include "viewer/texture_view.h"
#include "viewer/view_camera.h"
#include "viewer/view_image.h"
#include "viewer/view_reference.h"
#include "viewer/window.h"

namespace sg::viewer {

const std::vector<std::string>& gl_method_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const MethodInfo& m : method_catalog()) {
      try {
        gl_engine::gl_variant(m.name, MethodOptions{});
        n.push_back(m.name);
      } catch (const Error&) {
      }
    }
    return n;
  }();
  return names;
}

namespace {

using Clock = std::chrono::steady_clock;

// One side of the view: a method on the GL engine and its last frame.
struct Side {
  std::string method;
  MethodOptions options;
  std::unique_ptr<gl_engine::GlEngine> engine;
  Image linear;
  Picture picture;
  std::deque<double> gpu_ms;  // the last frames' GPU times
  double sum_gpu_ms = 0;      // over every frame rendered (scripted runs' mean)
  long frames = 0;
};

// The mean of the last frames' GPU times.
double recent_mean(const Side& s) {
  if (s.gpu_ms.empty()) return 0;
  return std::accumulate(s.gpu_ms.begin(), s.gpu_ms.end(), 0.0) / double(s.gpu_ms.size());
}

class Viewer {
 public:
  explicit Viewer(const ViewerOptions& o)
      : o_(o),
        base_(o.scene),
        edits_(o.edits ? *o.edits : edits_of(o.scene)),
        scene_(edited_scene(base_, edits_)),
        model_(std::make_unique<SceneModel>(scene_)),
        window_({scene_.width, scene_.height,
                 "sunglint view: " + scene_.name + (o.frames > 0 ? " (scripted)" : "")}) {
    if (window_.width() != scene_.width || window_.height() != scene_.height) {
      throw Error("view: the window's framebuffer is " + std::to_string(window_.width()) + " x " +
                  std::to_string(window_.height()) + ", not the image's " +
                  std::to_string(scene_.width) + " x " + std::to_string(scene_.height));
    }
    view_ = std::make_unique<TextureView>();
    shown_ = gl::Texture::image_2d(scene_.width, scene_.height);
    const std::string& renderer = window_.info().gl_renderer;
    const bool software = renderer.find("llvmpipe") != std::string::npos ||
                          renderer.find("softpipe") != std::string::npos;
    if (o.display_on == "gpu" || (o.display_on == "auto" && !software)) {
      gpu_display_ = std::make_unique<GpuDisplay>();
      display_on_gpu_ = true;
    }
    display_.exposure = o.exposure;
    display_.glare = o.glare;
    divider_ = scene_.width / 2;
    sides_[0].method = o.method;
    sides_[0].options = o.options;
    build(sides_[0]);
    split_ = !o.split.empty();
    sides_[1].method = split_ ? o.split : o.method;
    sides_[1].options = o.options;
    if (split_) build(sides_[1]);
    // Keys at most four a frame interval apart: a shutter (at most one interval) then holds
    // at most six keys, within the kernel's eight.
    if (!o.record.empty())
      recorder_ = std::make_unique<CameraRecorder>(0.25 / scene_.animation.fps);
    clock_ = view_time(scene_, 0).end;
  }

  // The recorded path as a scene file (ViewerOptions::record).
  void write_record() {
    if (!recorder_) return;
    write_recording(o_.record, recorder_->scene(scene_));
    std::printf("view: the camera's path, %zu keys -> %s\n", recorder_->keys().size(),
                o_.record.c_str());
  }

  void scripted() {
    std::vector<std::uint8_t> shot;
    const auto t0 = Clock::now();
    const CameraDesc start = edits_.camera;
    const vec3 target = orbit_target(start);
    for (int f = 0; f < o_.frames; ++f) {
      window_.begin_frame();
      clock_ = frame_time(scene_, f).end;
      if (o_.orbit_rate_deg != 0) {  // a scripted flight: the orbit at the frame's time
        constexpr double kDeg = 3.14159265358979323846 / 180;
        ViewEdits e = edits_;
        e.camera =
            orbit(start, target, o_.orbit_rate_deg * kDeg * (clock_ - scene_.animation.t0), 0);
        bool dirty = false;
        set_edits(e, dirty);
        if (!status_.empty()) throw Error("view: --orbit-rate: " + status_);
      }
      render(f);
      if (f == o_.frames - 1 && o_.reference_batches > 0) {
        playing_ = false;
        reference_ = true;
        ref_difference_ = o_.reference_difference > 0;
        if (ref_difference_) diff_scale_ = static_cast<float>(o_.reference_difference);
        for (int b = 0; b < o_.reference_batches; ++b)
          reference_batch(f);
        if (!status_.empty()) throw Error("view: " + status_);
      }
      view_->draw(shown_, 0, 0, scene_.width, scene_.height);
      if (o_.show_controls) {
        bool dirty = false;
        playing_ = false;
        position_ = f;
        divider_and_labels();
        controls(dirty);
      }
      window_.end_frame(f == o_.frames - 1 ? &shot : nullptr);
    }
    const double wall = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    if (!o_.screenshot.empty()) {
      std::vector<std::uint8_t> rgb(shot.size() / 4 * 3);
      for (size_t k = 0; k < shot.size() / 4; ++k)
        for (int c = 0; c < 3; ++c)
          rgb[3 * k + c] = shot[4 * k + c];
      write_png_rgb8(o_.screenshot, scene_.width, scene_.height, rgb);
    }
    if (!o_.save_scene.empty()) write_scene(o_.save_scene, scene_);
    std::string gpu = sides_[0].method + " " + fmt_ms(sides_[0].sum_gpu_ms / o_.frames);
    if (ref_ && ref_->batches() > 0) {
      gpu += ", reference " + std::to_string(ref_->batches()) + " batches (" +
             std::to_string(ref_->busy_samples()) + " samples per busy pixel)";
    }
    if (split_) gpu += ", " + sides_[1].method + " " + fmt_ms(sides_[1].sum_gpu_ms / o_.frames);
    std::string written = o_.screenshot;
    if (!o_.save_scene.empty()) written += (written.empty() ? "" : " and ") + o_.save_scene;
    std::printf(
        "view: %s, %dx%d, frames 0-%d on %s: GPU time per frame (mean of %d) %s; %.1f ms "
        "per frame in all%s%s\n",
        scene_.name.c_str(), scene_.width, scene_.height, o_.frames - 1,
        window_.info().gl_renderer.c_str(), o_.frames, gpu.c_str(), wall / o_.frames,
        written.empty() ? "" : " -> ", written.c_str());
  }

  void interactive() {
    auto last = Clock::now();
    bool dirty = true;
    while (!window_.should_close()) {
      window_.begin_frame();
      const auto now = Clock::now();
      const double dt = std::chrono::duration<double>(now - last).count();
      last = now;
      keys(dirty);
      camera_input(dt, dirty);
      if (playing_) {
        position_ += speed_ * scene_.animation.fps * dt;
        clock_ += speed_ * dt;
        wrap_position();
        dirty = true;
      }
      // A frame rendered in motion while paused: once the camera stands, render it still.
      if (!dirty && !playing_ && last_moved_) dirty = true;
      if (dirty) {
        render(position_);
        dirty = false;
      } else if (reference_ && !playing_ && (!ref_ || ref_->batches() < kMaxReferenceBatches)) {
        reference_batch(position_);
      } else {
        // Paused and unchanged: the image stands; the loop only serves the controls.
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
      }
      view_->draw(shown_, 0, 0, scene_.width, scene_.height);
      divider_and_labels();
      lens();
      controls(dirty);
      window_.end_frame();
      wall_ms_ = 1000 * dt;
    }
  }

 private:
  static std::string fmt_ms(double ms) {
    char b[32];
    std::snprintf(b, sizeof b, "%.2f ms", ms);
    return b;
  }

  static constexpr int kMaxReferenceBatches = 1 << 16;

  // One more batch of the still-frame reference at `position`, shown.
  void reference_batch(double position) {
    try {
      if (!ref_) ref_ = std::make_unique<ReferenceView>(o_.options);
      ref_->add_batch(FrameContext{*model_, view_time(scene_, position), 0});
    } catch (const Error& e) {
      status_ = std::string("reference: ") + e.what();
      reference_ = false;
    }
    redisplay();
  }
  bool showing_reference() const { return reference_ && !playing_ && ref_ && ref_->batches() > 0; }

  void build(Side& s) {
    s.engine = std::make_unique<gl_engine::GlEngine>(s.method, s.options);
    s.gpu_ms.clear();
  }

  int frame_count() const { return std::max(1, scene_.animation.frames); }
  void wrap_position() {
    const double n = frame_count();
    position_ = std::fmod(position_, n);
    if (position_ < 0) position_ += n;
  }

  // Every side's frame at `position`, displayed, split, uploaded. A camera that moved since
  // the frame before is keyed over the shutter (viewer/camera_record.h); the path recorded.
  void render(double position) {
    const FrameTime ft = view_time(scene_, position);
    const Scene frame_scene = moving_view_scene(scene_, cut_ ? scene_.camera : last_camera_, ft);
    std::optional<SceneModel> moved;
    if (frame_scene.camera.moving()) moved.emplace(frame_model(frame_scene, ft));
    last_moved_ = frame_scene.camera.moving() && !scene_.camera.moving();
    last_camera_ = camera_at(scene_.camera, ft.end);
    last_camera_.keyframes.clear();
    cut_ = false;
    if (recorder_) recorder_->add(clock_, last_camera_);
    const FrameContext base{moved ? *moved : *model_, ft, 0};
    for (int k = 0; k < (split_ ? 2 : 1); ++k) {
      Side& s = sides_[k];
      const FrameContext ctx{base.model, base.time, s.options.seed};
      s.linear = render_linear(*s.engine, ctx);
      const double ms = s.engine->last_gpu_ms();
      s.gpu_ms.push_back(ms);
      if (s.gpu_ms.size() > 30) s.gpu_ms.pop_front();
      s.sum_gpu_ms += ms;
      ++s.frames;
    }
    if (ref_) ref_->restart();  // a new frame, camera, edit or method
    redisplay();
  }

  // `img` through the display pipeline, on the GPU or the CPU.
  Picture show(const Image& img, const DisplaySettings& d) {
    if (!display_on_gpu_) return display_picture(img, d);
    if (!gpu_display_) gpu_display_ = std::make_unique<GpuDisplay>();
    return gpu_display_->picture(img, d);
  }

  // The display pipeline and the split again, on the images already rendered.
  void redisplay() {
    for (int k = 0; k < (split_ ? 2 : 1); ++k)
      sides_[k].picture = show(sides_[k].linear, display_);
    recompose();
  }
  void recompose() {
    if (showing_reference()) {
      if (ref_difference_) {
        DisplaySettings d = display_;
        d.glare = false;
        shown_picture_ = show(difference_image(ref_->mean(), sides_[0].linear, diff_scale_), d);
      } else {
        shown_picture_ = show(ref_->mean(), display_);
      }
    } else {
      shown_picture_ = split_ ? split_picture(sides_[0].picture, sides_[1].picture, divider_)
                              : sides_[0].picture;
    }
    shown_.upload(picture_texels(shown_picture_));
  }

  void keys(bool& dirty) {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantCaptureKeyboard) return;
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false)) window_.request_close();
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Space), false)) playing_ = !playing_;
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_RightArrow))) step(1, dirty);
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_LeftArrow))) step(-1, dirty);
    if (ImGui::IsKeyPressed('Z', false)) lens_ = !lens_;
    if (ImGui::IsKeyPressed('R', false)) set_reference(!reference_);
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Tab), false))
      show_controls_ = !show_controls_;
    if (ImGui::IsKeyPressed('H', false)) home(dirty);
    if (ImGui::IsKeyPressed('V', false)) {
      split_ = !split_;
      set_split(dirty);
    }
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_UpArrow)))
      speed_ = std::min(4.0f, speed_ * 2);
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_DownArrow)))
      speed_ = std::max(1.0f / 32, speed_ / 2);
  }

  // The camera's moves (viewer/view_camera.h) from the mouse and keys: left drag orbits
  // about the point the view meets the water (fixed when the drag starts), right drag
  // looks around, the wheel dollies towards that point, W A S D Q E fly.
  void camera_input(double dt, bool& dirty) {
    const ImGuiIO& io = ImGui::GetIO();
    CameraDesc c = edits_.camera;
    if (c.moving()) {  // a keyed camera (format /3): a move takes it over where it stands
      c = camera_at(c, view_time(scene_, position_).end);
      c.keyframes.clear();
    }
    const CameraDesc before = c;
    const bool near_divider = split_ && std::abs(io.MousePos.x - divider_) < 6;
    if (!io.WantCaptureMouse && !dragging_ && !near_divider) {
      if (ImGui::IsMouseClicked(0)) {
        orbiting_ = true;
        orbit_target_ = orbit_target(c);
      }
      if (ImGui::IsMouseClicked(1)) looking_ = true;
      if (io.MouseWheel != 0) c = dolly(c, orbit_target(c), std::pow(0.85, double(io.MouseWheel)));
    }
    if (!io.MouseDown[0]) orbiting_ = false;
    if (!io.MouseDown[1]) looking_ = false;
    const double dx = io.MouseDelta.x, dy = io.MouseDelta.y;
    if (orbiting_ && (dx != 0 || dy != 0)) c = orbit(c, orbit_target_, -0.005 * dx, 0.005 * dy);
    if (looking_ && (dx != 0 || dy != 0)) {
      const double per_pixel = c.vfov_deg * 3.14159265358979323846 / 180 / scene_.height;
      c = look(c, -per_pixel * dx, -per_pixel * dy);
    }
    if (!io.WantCaptureKeyboard) {
      auto key = [](int k) { return ImGui::IsKeyDown(k) ? 1.0 : 0.0; };
      const double right = key('D') - key('A'), up = key('E') - key('Q');
      const double forward = key('W') - key('S');
      if (right != 0 || up != 0 || forward != 0) {
        // Metres per second: twice the camera's height (at least 2), five times with Shift.
        const double v = 2 * std::max(1.0, c.position.y) * (io.KeyShift ? 5 : 1) * dt;
        c = fly(c, v * right, v * up, v * forward);
      }
    }
    if (c.position != before.position || c.look_at != before.look_at) {
      ViewEdits e = edits_;
      e.camera = c;
      set_edits(e, dirty);
    }
  }

  void set_reference(bool on) {
    reference_ = on;
    if (on) playing_ = false;
    recompose();
  }

  // The scene's camera again (a cut: no motion from the camera before).
  void home(bool& dirty) {
    ViewEdits e = edits_;
    e.camera = base_.camera;
    set_edits(e, dirty);
    cut_ = true;
  }

  void step(int by, bool& dirty) {
    playing_ = false;
    if (by > 0) clock_ += by / scene_.animation.fps;
    position_ = std::floor(position_) + by;
    wrap_position();
    dirty = true;
  }

  void set_split(bool& dirty) {
    if (split_ && !sides_[1].engine && !rebuild(sides_[1])) split_ = false;
    dirty = true;
  }

  // Rebuilds a side's engine after a change of method or option; on a refusal the side
  // keeps its engine and the message shows.
  bool rebuild(Side& s) {
    try {
      build(s);
      status_.clear();
      return true;
    } catch (const Error& e) {
      status_ = e.what();
      return false;
    }
  }

  void divider_and_labels() {
    ImDrawList* dl = ImGui::GetBackgroundDrawList();
    const ImGuiIO& io = ImGui::GetIO();
    if (split_) {
      const bool near = std::abs(io.MousePos.x - divider_) < 6;
      if (!io.WantCaptureMouse && !orbiting_ && io.MouseDown[0] && (dragging_ || near))
        dragging_ = true;
      if (!io.MouseDown[0]) dragging_ = false;
      if (dragging_) {
        const int d = std::clamp(static_cast<int>(std::lround(io.MousePos.x)), 0, scene_.width);
        if (d != divider_) {
          divider_ = d;
          recompose();
        }
      }
      dl->AddLine(ImVec2(float(divider_), 0), ImVec2(float(divider_), float(scene_.height)),
                  IM_COL32(255, 255, 255, near || dragging_ ? 220 : 110), 1.0f);
      dl->AddText(ImVec2(float(divider_) + 6, float(scene_.height) - 20),
                  IM_COL32(255, 255, 255, 200), sides_[1].method.c_str());
      const float w = ImGui::CalcTextSize(sides_[0].method.c_str()).x;
      dl->AddText(ImVec2(float(divider_) - 6 - w, float(scene_.height) - 20),
                  IM_COL32(255, 255, 255, 200), sides_[0].method.c_str());
    }
  }

  // A magnified crop of the displayed image under the cursor, nearest texels.
  void lens() {
    const ImGuiIO& io = ImGui::GetIO();
    if (!lens_ || io.WantCaptureMouse || dragging_ || orbiting_ || looking_) return;
    const float mx = io.MousePos.x, my = io.MousePos.y;
    if (mx < 0 || my < 0 || mx >= scene_.width || my >= scene_.height) return;
    const float side = 192, half = side / 2 / float(zoom_);
    const float w = float(scene_.width), h = float(scene_.height);
    const ImVec2 uv0((mx - half) / w, (my - half) / h), uv1((mx + half) / w, (my + half) / h);
    ImGui::BeginTooltip();
    ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(shown_.id())),
                 ImVec2(side, side), uv0, uv1);
    ImGui::Text("(%d, %d) x%d", int(mx), int(my), zoom_);
    ImGui::EndTooltip();
  }

  bool method_combo(const char* label, Side& s) {
    bool changed = false;
    if (ImGui::BeginCombo(label, s.method.c_str())) {
      for (const std::string& m : gl_method_names()) {
        if (ImGui::Selectable(m.c_str(), m == s.method) && m != s.method) {
          const std::string old = s.method;
          s.method = m;
          if (rebuild(s)) {
            changed = true;
          } else {
            s.method = old;
          }
        }
      }
      ImGui::EndCombo();
    }
    return changed;
  }

  // The options of the catalogue that matter to the side's method.
  bool method_options(const char* id, Side& s) {
    ImGui::PushID(id);
    const MethodOptions old = s.options;
    bool changed = false;
    if (s.method == "supersample" || s.method == "reference") {
      int n[3] = {s.options.samples.sx, s.options.samples.sy, s.options.samples.st};
      if (ImGui::InputInt3("samples SxSxT", n)) {
        s.options.samples.sx = std::clamp(n[0], 1, 64);
        s.options.samples.sy = std::clamp(n[1], 1, 64);
        s.options.samples.st = std::clamp(n[2], 1, 64);
        changed = true;
      }
    }
    if (s.method == "staa" || s.method == "staa-temporal") {
      changed |= ImGui::SliderInt("segments", &s.options.staa.segments, 1, 8);
    }
    if (s.method == "staa") {
      bool per_pixel = per_pixel_ndf(s.options.staa);
      if (ImGui::Checkbox("per-pixel NDF", &per_pixel)) {
        s.options.staa.ndf = per_pixel ? NdfMode::per_pixel : NdfMode::uniform;
        changed = true;
      }
      bool none = s.options.staa.footprint == FootprintMode::none;
      if (ImGui::Checkbox("no footprint term", &none)) {
        s.options.staa.footprint = none ? FootprintMode::none : FootprintMode::gaussian;
        changed = true;
      }
      // docs/method.md, "The RDF linearised at the light".
      bool centre = !rdf_at_light(s.options.staa);
      if (ImGui::Checkbox("RDF linearised at the NDF's centre", &centre)) {
        s.options.staa.rdf_at = centre ? RdfAnchor::centre : RdfAnchor::light;
        changed = true;
      }
    }
    ImGui::PopID();
    if (changed && !rebuild(s)) {
      s.options = old;
      rebuild(s);
      return false;
    }
    return changed;
  }

  void set_edits(const ViewEdits& e, bool& dirty) {
    try {
      scene_ = edited_scene(base_, e);
      edits_ = e;
      model_ = std::make_unique<SceneModel>(scene_);
      status_.clear();
      dirty = true;
    } catch (const Error& err) {
      status_ = err.what();
    }
  }

  void save(const std::string& path, int what) {
    try {
      check_output_file(path, false);
      if (what == 0) {
        write_scene(path, scene_);
      } else if (what == 1) {
        const ImageFormat f = image_format_of(path);
        if (f == ImageFormat::png)
          throw Error(path + ": the linear image is saved as .exr or .pfm");
        write_image(path, split_ ? split_image(sides_[0].linear, sides_[1].linear, divider_)
                                 : sides_[0].linear);
      } else {
        if (image_format_of(path) != ImageFormat::png) throw Error(path + ": must be a .png");
        write_png_rgb8(path, shown_picture_.width, shown_picture_.height, shown_picture_.rgb);
      }
      status_ = "saved " + path;
    } catch (const Error& e) {
      status_ = e.what();
    }
  }

  void controls(bool& dirty) {
    if (!show_controls_) return;
    ImGui::SetNextWindowPos(ImVec2(6, 6), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(300, std::min(560.0f, float(scene_.height) - 12)),
                             ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowBgAlpha(0.75f);
    ImGui::Begin("sunglint view (Tab hides)", nullptr);
    ImGui::PushItemWidth(150);
    ImGui::Text("%s, %d x %d, %d frames at %.0f fps", scene_.name.c_str(), scene_.width,
                scene_.height, scene_.animation.frames, scene_.animation.fps);
    // Time.
    if (ImGui::Button(playing_ ? "pause" : "play")) playing_ = !playing_;
    ImGui::SameLine();
    if (ImGui::Button("<")) step(-1, dirty);
    ImGui::SameLine();
    if (ImGui::Button(">")) step(1, dirty);
    float pos = static_cast<float>(position_);
    if (ImGui::SliderFloat("frame", &pos, 0.0f, float(frame_count()) - 0.001f, "%.2f")) {
      position_ = pos;
      wrap_position();
      dirty = true;
    }
    ImGui::SliderFloat("speed", &speed_, 1.0f / 32, 4.0f, "%.3fx", ImGuiSliderFlags_Logarithmic);
    // Methods.
    ImGui::Separator();
    dirty |= method_combo(split_ ? "left" : "method", sides_[0]);
    dirty |= method_options("a", sides_[0]);
    if (ImGui::Checkbox("split view", &split_)) set_split(dirty);
    if (split_) {
      dirty |= method_combo("right", sides_[1]);
      dirty |= method_options("b", sides_[1]);
      if (ImGui::SliderInt("divider", &divider_, 0, scene_.width)) recompose();
    }
    // Display.
    ImGui::Separator();
    float exposure = static_cast<float>(display_.exposure);
    if (ImGui::SliderFloat("exposure", &exposure, -10, 10, "%.2f stops")) {
      display_.exposure = exposure;
      redisplay();
    }
    ImGui::SameLine();
    if (ImGui::Checkbox("glare", &display_.glare)) redisplay();
    if (ImGui::Checkbox("display on the GPU", &display_on_gpu_)) redisplay();
    ImGui::Checkbox("zoom lens (Z)", &lens_);
    ImGui::SameLine();
    ImGui::SliderInt("zoom", &zoom_, 2, 16);
    // The still-frame reference.
    bool ref = reference_;
    if (ImGui::Checkbox("reference (R)", &ref)) set_reference(ref);
    if (reference_) {
      ImGui::SameLine();
      if (ImGui::Checkbox("difference", &ref_difference_)) recompose();
      if (ref_difference_ && ImGui::SliderFloat("x scale", &diff_scale_, 1, 1000, "%.1f",
                                                ImGuiSliderFlags_Logarithmic)) {
        recompose();
      }
      if (ref_ && ref_->batches() > 0) {
        ImGui::TextWrapped("%d batches: %ld samples per pixel (quiet pixels %ld), %.1f ms a batch",
                           ref_->batches(), ref_->busy_samples(), ref_->quiet_samples(),
                           ref_->last_gpu_ms());
      } else {
        ImGui::TextUnformatted("(shown while paused)");
      }
    }
    // The scene.
    ImGui::Separator();
    ViewEdits e = edits_;
    float el = float(e.sun_elevation_deg), az = float(e.sun_azimuth_deg);
    float radius = float(e.sun_radius_deg), amp = float(e.amplitude_scale);
    bool edited = false;
    if (ImGui::SliderFloat("sun elevation", &el, 0.1f, 89.0f, "%.2f deg")) {
      e.sun_elevation_deg = el;
      edited = true;
    }
    if (ImGui::SliderFloat("sun azimuth", &az, -180.0f, 180.0f, "%.2f deg")) {
      e.sun_azimuth_deg = az;
      edited = true;
    }
    if (ImGui::SliderFloat("sun radius", &radius, 0.01f, 10.0f, "%.3f deg",
                           ImGuiSliderFlags_Logarithmic)) {
      e.sun_radius_deg = radius;
      edited = true;
    }
    if (ImGui::SliderFloat("wave amplitude", &amp, 0.0f, 3.0f, "x %.2f")) {
      e.amplitude_scale = amp;
      edited = true;
    }
    // The sea from a wind spectrum, regenerated as the sliders move (explicit waves, or the
    // scene's number of cascades).
    bool sea = e.sea;
    if (ImGui::Checkbox("sea from a wind spectrum", &sea)) {
      e.sea = sea;
      edited = true;
    }
    if (e.sea) {
      float wind = float(e.sea_params.wind_speed), dir = float(e.sea_params.wind_direction_deg);
      float fetch = float(e.sea_params.fetch_km);
      if (ImGui::SliderFloat("wind speed", &wind, 1.0f, 30.0f, "%.1f m/s")) {
        e.sea_params.wind_speed = wind;
        edited = true;
      }
      if (ImGui::SliderFloat("wind direction", &dir, -180.0f, 180.0f, "%.0f deg")) {
        e.sea_params.wind_direction_deg = dir;
        edited = true;
      }
      if (ImGui::SliderFloat("fetch", &fetch, 1.0f, 10000.0f, "%.0f km",
                             ImGuiSliderFlags_Logarithmic)) {
        e.sea_params.fetch_km = fetch;
        edited = true;
      }
      if (base_.surface.cascades.empty()) {
        ImGui::TextWrapped("JONSWAP, %d waves (the scene's, 16 to 4096), seed %llu",
                           e.sea_params.waves, static_cast<unsigned long long>(e.sea_params.seed));
      } else {
        ImGui::TextWrapped("JONSWAP, %zu cascades of %d x %d (the scene's), seed %llu",
                           base_.surface.cascades.size(), base_.surface.cascades[0].lattice,
                           base_.surface.cascades[0].lattice,
                           static_cast<unsigned long long>(e.sea_params.seed));
      }
    }
    if (edited) set_edits(e, dirty);
    if (ImGui::Button("scene as loaded")) {
      set_edits(edits_of(base_), dirty);
      cut_ = true;
    }
    ImGui::SameLine();
    if (ImGui::Button("Home (H)")) home(dirty);
    const CameraDesc& cam = edits_.camera;
    if (cam.moving()) {
      ImGui::TextWrapped("camera: the scene's keyframes (a move takes it over)");
    } else {
      ImGui::TextWrapped("camera (%.2f, %.2f, %.2f) looks at (%.1f, %.1f, %.1f)", cam.position.x,
                         cam.position.y, cam.position.z, cam.look_at.x, cam.look_at.y,
                         cam.look_at.z);
    }
    if (recorder_) {
      ImGui::TextWrapped("recording the path: %zu keys, %.2f s (written to %s at the end)",
                         recorder_->keys().size(),
                         recorder_->keys().empty()
                             ? 0.0
                             : recorder_->keys().back().time - recorder_->keys().front().time,
                         o_.record.c_str());
    }
    // Saving.
    ImGui::Separator();
    ImGui::InputText("file", path_, sizeof path_);
    if (ImGui::Button("save scene (.json)")) save(path_, 0);
    ImGui::SameLine();
    if (ImGui::Button("save linear (.exr)")) save(path_, 1);
    ImGui::SameLine();
    if (ImGui::Button("save picture (.png)")) save(path_, 2);
    if (!status_.empty()) ImGui::TextWrapped("%s", status_.c_str());
    // Timing.
    ImGui::Separator();
    ImGui::Text("GPU: %s %.2f ms", sides_[0].method.c_str(), recent_mean(sides_[0]));
    if (split_) {
      ImGui::SameLine();
      ImGui::Text("| %s %.2f ms", sides_[1].method.c_str(), recent_mean(sides_[1]));
    }
    ImGui::TextWrapped("frame %.1f ms in all (%s)", wall_ms_, window_.info().gl_renderer.c_str());
    ImGui::PopItemWidth();
    ImGui::End();
  }

  ViewerOptions o_;
  Scene base_;
  ViewEdits edits_;
  Scene scene_;
  std::unique_ptr<SceneModel> model_;
  Window window_;
  std::unique_ptr<TextureView> view_;
  gl::Texture shown_;
  Picture shown_picture_;
  DisplaySettings display_;
  Side sides_[2];
  bool split_ = false, playing_ = true, lens_ = false, dragging_ = false, show_controls_ = true;
  bool orbiting_ = false, looking_ = false, reference_ = false, ref_difference_ = false;
  float diff_scale_ = 10;
  std::unique_ptr<ReferenceView> ref_;
  std::unique_ptr<GpuDisplay> gpu_display_;
  bool display_on_gpu_ = false;
  vec3 orbit_target_{0};
  int divider_ = 0, zoom_ = 4;
  double position_ = 0, wall_ms_ = 0;
  float speed_ = 1;
  char path_[512] = "view.json";
  std::string status_;
  // The camera in motion: the last frame's camera (at its display time), whether that frame
  // was keyed over its shutter, a jump (home) that the next frame must not blur, and the
  // recorded path on its clock (ViewerOptions::record).
  CameraDesc last_camera_;
  bool last_moved_ = false, cut_ = true;
  std::unique_ptr<CameraRecorder> recorder_;
  double clock_ = 0;
};

}  // namespace

void run_viewer(const ViewerOptions& o) {
  // What can be refused without a window: the methods and the edits.
  gl_engine::gl_variant(o.method, o.options);
  if (!o.split.empty()) gl_engine::gl_variant(o.split, o.options);
  if (o.edits) edited_scene(o.scene, *o.edits);
  Viewer v(o);
  if (o.frames > 0) {
    v.scripted();
  } else {
    v.interactive();
  }
  v.write_record();
}

}  // namespace sg::viewer
