// Videos of a study and of `render --video`: 8-bit grey or RGB frames encoded as H.264 in
// MP4 by ffmpeg (Debian package `ffmpeg`), run as a subprocess that reads raw frames on
// its standard input. RGB frames are converted to yuv420p with the Rec. 709 matrix and
// tagged as such (the frames' primaries are Rec. 709 / sRGB). Flags are
// fixed for the same bytes from the same frames: libx264 preset "medium", CRF 18,
// one thread, yuv420p, -bitexact, no metadata, +faststart (plays while loading).
// Odd sizes are padded to even ones (yuv420p needs them).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace sg {

// The frame rate a study's video plays at: the scene's, or slower so that `frames` last at
// least `min_seconds` (a 10-frame study at 30 fps would loop in a third of a second, too
// fast to see a pixel flicker): min(fps, frames / min_seconds).
double playback_fps(double scene_fps, int frames, double min_seconds = 3.0);

// Writes `path` (through a temporary file and a rename). Throws sg::Error when ffmpeg is
// missing ("ffmpeg: not found ...") or fails.
void encode_h264(const std::string& path, int width, int height, double fps,
                 const std::vector<std::vector<uint8_t>>& grey_frames,
                 const std::string& ffmpeg = "ffmpeg");
// Throws the error encode_h264 would when `ffmpeg` cannot be started (checked before a
// long render whose frames go to a video).
void check_ffmpeg(const std::string& ffmpeg = "ffmpeg");

// The same for RGB frames (3 bytes per pixel, rows top to bottom).
void encode_h264_rgb(const std::string& path, int width, int height, double fps,
                     const std::vector<std::vector<uint8_t>>& rgb_frames,
                     const std::string& ffmpeg = "ffmpeg");

}  // namespace sg
