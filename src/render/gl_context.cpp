// EGL surfaceless context and multisampled framebuffer objects (see gl_context.hpp).
#include "render/gl_context.hpp"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include "render/gl.hpp"

#include <algorithm>
#include <cstring>
#include <string>

#include "core/error.hpp"

namespace s4d {

namespace {

std::string egl_error_name(EGLint e) {
  switch (e) {
    case EGL_SUCCESS: return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE: return "EGL_BAD_SURFACE";
    default: return "EGL error " + std::to_string(e);
  }
}

[[noreturn]] void fail(const std::string& what) {
  throw Error("cannot create an offscreen OpenGL 3.3 context: " + what + " (" +
              egl_error_name(eglGetError()) +
              "); install Mesa's EGL (libegl-mesa0)");
}

bool has_extension(const char* list, const char* name) {
  if (!list) return false;
  const std::size_t n = std::strlen(name);
  for (const char* p = list; (p = std::strstr(p, name)) != nullptr; p += n)
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  return false;
}

// One EGL display for the process: eglTerminate would invalidate every other context on it,
// so it is initialised once and left to process exit.
EGLDisplay process_display() {
  static const EGLDisplay display = [] {
    const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    EGLDisplay d = EGL_NO_DISPLAY;
    if (has_extension(client, "EGL_MESA_platform_surfaceless")) {
      auto get_platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
          eglGetProcAddress("eglGetPlatformDisplayEXT"));
      if (get_platform_display)
        d = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, nullptr, nullptr);  // EGL_DEFAULT_DISPLAY
    }
    if (d == EGL_NO_DISPLAY) d = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    if (d == EGL_NO_DISPLAY) return d;
    EGLint major = 0, minor = 0;
    if (!eglInitialize(d, &major, &minor)) return EGL_NO_DISPLAY;
    return d;
  }();
  return display;
}

}  // namespace

OffscreenContext::OffscreenContext() {
  EGLDisplay d = process_display();
  if (d == EGL_NO_DISPLAY) fail("no EGL display");
  if (!eglBindAPI(EGL_OPENGL_API)) fail("EGL has no desktop OpenGL API");
  const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                            EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                            EGL_NONE};
  EGLConfig config = EGL_NO_CONFIG_KHR;
  const char* ext = eglQueryString(d, EGL_EXTENSIONS);
  if (!has_extension(ext, "EGL_KHR_no_config_context") &&
      !has_extension(ext, "EGL_MESA_configless_context")) {
    // Older drivers need a config even though we never draw to a surface.
    const EGLint want[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLint count = 0;
    if (!eglChooseConfig(d, want, &config, 1, &count) || count < 1) fail("no OpenGL EGL config");
  }
  EGLContext c = eglCreateContext(d, config, EGL_NO_CONTEXT, attribs);
  if (c == EGL_NO_CONTEXT) fail("eglCreateContext for OpenGL 3.3 core failed");
  if (!eglMakeCurrent(d, EGL_NO_SURFACE, EGL_NO_SURFACE, c)) {
    eglDestroyContext(d, c);
    fail("eglMakeCurrent without a surface failed (needs EGL_KHR_surfaceless_context)");
  }
  display_ = d;
  context_ = c;
  const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  if (!version) {
    release();
    throw Error("cannot create an offscreen OpenGL 3.3 context: glGetString returned nothing");
  }
}

OffscreenContext::~OffscreenContext() { release(); }

void OffscreenContext::release() {
  if (!context_) return;
  auto d = static_cast<EGLDisplay>(display_);
  if (eglGetCurrentContext() == static_cast<EGLContext>(context_))
    eglMakeCurrent(d, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(d, static_cast<EGLContext>(context_));
  context_ = nullptr;
}

std::string OffscreenContext::renderer() const {
  const auto* s = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return s ? s : "";
}

std::string OffscreenContext::version() const {
  const auto* s = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  return s ? s : "";
}

void check_gl(const char* where) {
  GLenum first = GL_NO_ERROR;
  for (GLenum e; (e = glGetError()) != GL_NO_ERROR;)
    if (first == GL_NO_ERROR) first = e;
  if (first != GL_NO_ERROR)
    throw Error(std::string("OpenGL error ") + std::to_string(first) + " in " + where);
}

RenderTarget::RenderTarget(int width, int height, int samples) : width_(width), height_(height) {
  if (width < 1 || height < 1 || width > 16384 || height > 16384)
    throw Error("image size must be between 1x1 and 16384x16384, got " + std::to_string(width) +
                "x" + std::to_string(height));
  GLint max_samples = 1;
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  samples_ = std::clamp(samples, 1, std::max(1, static_cast<int>(max_samples)));

  glGenFramebuffers(1, &draw_fbo_);
  glGenRenderbuffers(1, &draw_colour_);
  glGenRenderbuffers(1, &draw_depth_);
  glBindFramebuffer(GL_FRAMEBUFFER, draw_fbo_);
  glBindRenderbuffer(GL_RENDERBUFFER, draw_colour_);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_ > 1 ? samples_ : 0, GL_RGBA8, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, draw_colour_);
  glBindRenderbuffer(GL_RENDERBUFFER, draw_depth_);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_ > 1 ? samples_ : 0, GL_DEPTH_COMPONENT24,
                                   width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, draw_depth_);
  const GLenum draw_status = glCheckFramebufferStatus(GL_FRAMEBUFFER);

  glGenFramebuffers(1, &resolve_fbo_);
  glGenRenderbuffers(1, &resolve_colour_);
  glBindFramebuffer(GL_FRAMEBUFFER, resolve_fbo_);
  glBindRenderbuffer(GL_RENDERBUFFER, resolve_colour_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, resolve_colour_);
  const GLenum resolve_status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (draw_status != GL_FRAMEBUFFER_COMPLETE || resolve_status != GL_FRAMEBUFFER_COMPLETE) {
    release();
    throw Error("framebuffer incomplete (status " + std::to_string(draw_status) + ", " +
                std::to_string(resolve_status) + ") for " + std::to_string(width) + "x" +
                std::to_string(height) + " with " + std::to_string(samples_) + " samples");
  }
  check_gl("RenderTarget");
}

RenderTarget::~RenderTarget() { release(); }

void RenderTarget::release() {
  if (draw_fbo_) glDeleteFramebuffers(1, &draw_fbo_);
  if (resolve_fbo_) glDeleteFramebuffers(1, &resolve_fbo_);
  const GLuint rbs[] = {draw_colour_, draw_depth_, resolve_colour_};
  glDeleteRenderbuffers(3, rbs);  // zeros are ignored
  draw_fbo_ = resolve_fbo_ = draw_colour_ = draw_depth_ = resolve_colour_ = 0;
}

void RenderTarget::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, draw_fbo_);
  glViewport(0, 0, width_, height_);
}

Image RenderTarget::resolve_and_read() const {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, draw_fbo_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolve_fbo_);
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, resolve_fbo_);
  check_gl("RenderTarget::resolve_and_read");
  return read_framebuffer(width_, height_);
}

Image read_framebuffer(int width, int height, int x, int y) {
  Image img;
  img.width = width;
  img.height = height;
  img.rgba.resize(4 * static_cast<std::size_t>(width) * height);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(x, y, width, height, GL_RGBA, GL_UNSIGNED_BYTE, img.rgba.data());
  check_gl("glReadPixels");
  // OpenGL's first row is the bottom one; images are stored top row first.
  const std::size_t row = 4 * static_cast<std::size_t>(width);
  for (int y = 0; y < height / 2; ++y)
    std::swap_ranges(img.rgba.begin() + y * row, img.rgba.begin() + (y + 1) * row,
                     img.rgba.begin() + (height - 1 - y) * row);
  return img;
}

}  // namespace s4d
