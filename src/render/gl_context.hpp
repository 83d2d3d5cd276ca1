// OpenGL without a display: an EGL surfaceless context (Mesa llvmpipe works with no GPU) and a
// framebuffer object with multisampling, resolved into a single-sample one for readback.
#pragma once
#include <string>

#include "io/image.hpp"

namespace s4d {

// An OpenGL 3.3 core context made current on the constructing thread, with no window or surface.
// Throws s4d::Error saying what failed when EGL or the context is unavailable.
class OffscreenContext {
 public:
  OffscreenContext();
  ~OffscreenContext();
  OffscreenContext(const OffscreenContext&) = delete;
  OffscreenContext& operator=(const OffscreenContext&) = delete;

  // GL_RENDERER and GL_VERSION strings, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)", "4.5 (Core ...)".
  std::string renderer() const;
  std::string version() const;

 private:
  void release();
  void* display_ = nullptr;  // EGLDisplay
  void* context_ = nullptr;  // EGLContext
};

// A colour + depth framebuffer of a given size drawn with `samples` (clamped to GL_MAX_SAMPLES;
// 1 = no multisampling) and resolved into a single-sample framebuffer for reading. Works in any
// current GL 3.3 context (offscreen or the GUI's window, e.g. for screenshots).
class RenderTarget {
 public:
  RenderTarget(int width, int height, int samples = 4);
  ~RenderTarget();
  RenderTarget(const RenderTarget&) = delete;
  RenderTarget& operator=(const RenderTarget&) = delete;

  // Binds the (multisampled) framebuffer for drawing and sets the viewport.
  void bind() const;
  // Resolves the samples and reads the image back (top row first). Leaves the resolve
  // framebuffer bound for reading.
  Image resolve_and_read() const;

  int width() const { return width_; }
  int height() const { return height_; }
  int samples() const { return samples_; }  // actual sample count used

 private:
  void release();
  int width_, height_, samples_;
  unsigned draw_fbo_ = 0, draw_colour_ = 0, draw_depth_ = 0;
  unsigned resolve_fbo_ = 0, resolve_colour_ = 0;
};

// Throws s4d::Error naming `where` if glGetError reports an error (drains all pending errors).
void check_gl(const char* where);

// Reads the framebuffer bound for reading into an RGBA image, top row first: the rectangle of
// `width` x `height` whose lower-left corner is (x, y) in OpenGL's pixels (y up).
Image read_framebuffer(int width, int height, int x = 0, int y = 0);

}  // namespace s4d
