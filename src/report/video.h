// Videos of a study: 8-bit grey frames encoded as H.264 in MP4 by ffmpeg (Debian package
// `ffmpeg`), run as a subprocess that reads raw frames on its standard input. Flags are
// fixed for the same bytes from the same frames: libx264 preset "medium", CRF 18,
// one thread, yuv420p, -bitexact, no metadata, +faststart (plays while loading).
// Odd sizes are padded to even ones (yuv420p needs them).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace sg {

// Writes `path` (through a temporary file and a rename). Throws sg::Error when ffmpeg is
// missing ("ffmpeg: not found ...") or fails.
void encode_h264(const std::string& path, int width, int height, double fps,
                 const std::vector<std::vector<uint8_t>>& grey_frames,
                 const std::string& ffmpeg = "ffmpeg");

}  // namespace sg
