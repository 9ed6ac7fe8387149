#include "image/sequence.h"

#include <cctype>
#include <cstdio>

#include "base/error.h"
#include "image/image_io.h"

namespace sg {
namespace {

// Expands the pattern; returns the number of frame conversions found.
int expand(const std::string& p, int frame, std::string* out, const std::string& flag) {
  int conversions = 0;
  for (size_t k = 0; k < p.size(); ++k) {
    if (p[k] != '%') {
      if (out) out->push_back(p[k]);
      continue;
    }
    if (k + 1 < p.size() && p[k + 1] == '%') {
      if (out) out->push_back('%');
      ++k;
      continue;
    }
    size_t q = k + 1;
    bool zero = q < p.size() && p[q] == '0';
    if (zero) ++q;
    int width = 0;
    while (q < p.size() && std::isdigit(static_cast<unsigned char>(p[q]))) {
      width = width * 10 + (p[q] - '0');
      if (width > 32) throw Error(flag + ": field width too large in '" + p + "'");
      ++q;
    }
    if (q >= p.size() || p[q] != 'd') {
      throw Error(flag + ": only %d, %Nd or %0Nd may follow '%' in '" + p + "'");
    }
    ++conversions;
    if (out) {
      char buf[64];
      std::snprintf(buf, sizeof buf, zero ? "%0*d" : "%*d", width, frame);
      out->append(buf);
    }
    k = q;
  }
  return conversions;
}

}  // namespace

bool is_frame_pattern(const std::string& text) {
  try {
    return expand(text, 0, nullptr, "pattern") > 0;
  } catch (const Error&) {
    return false;
  }
}

std::string format_frame_path(const std::string& pattern, int frame, const std::string& flag) {
  std::string out;
  int n = expand(pattern, frame, &out, flag);
  if (n != 1) {
    throw Error(flag + ": a sequence needs exactly one frame number conversion such as %04d in '" +
                pattern + "'");
  }
  return out;
}

std::vector<Image> read_sequence(const std::string& pattern, int first, int last) {
  std::vector<Image> frames;
  for (int f = first; f <= last; ++f)
    frames.push_back(read_image(format_frame_path(pattern, f)));
  return frames;
}

}  // namespace sg
