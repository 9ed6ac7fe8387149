// GPU time of a stretch of GL commands, from timer queries: two GL_TIMESTAMP queries
// (glQueryCounter) around the commands, each taken when the commands before it have
// completed on the GPU; their difference is the GPU time in between. Not a GL_TIME_ELAPSED
// query: llvmpipe reports 0 ns for compute dispatches inside one (it times only its
// rasteriser), while timestamps measure them on llvmpipe and NVIDIA alike, and they nest.
// milliseconds() waits for the result. For figures: warm up first, time many repeats,
// take the median.
#pragma once

#include <epoxy/gl.h>

namespace sg::gl {

class GpuTimer {
 public:
  GpuTimer();
  ~GpuTimer();
  GpuTimer(const GpuTimer&) = delete;
  GpuTimer& operator=(const GpuTimer&) = delete;

  void begin();
  void end();
  // The GPU time between the last begin and end, in milliseconds; waits until it is known.
  double milliseconds() const;

  // Times `f` (GL commands) once and returns the milliseconds.
  template <class F>
  double time(F&& f) {
    begin();
    f();
    end();
    return milliseconds();
  }

 private:
  GLuint queries_[2] = {0, 0};
  bool running_ = false, done_ = false;
};

}  // namespace sg::gl
