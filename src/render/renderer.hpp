// Renderer: draws a Scene with OpenGL 3.3 core into the current framebuffer. R^4 objects are
// projected by the scene's Frame<4> to R^3 and coloured by 4D depth; R^3 objects are drawn as they
// are, coloured by view depth. Curves become lit tubes, or flat strands (view.curve_mode: the plain
// shadow, the crossing diagram with its gaps); surfaces are lit two-sided, see-through when
// view.opacity < 1.
#pragma once
#include <cstddef>
#include <memory>

#include "core/vec.hpp"
#include "io/image.hpp"
#include "io/scene.hpp"
#include "core/camera.hpp"
#include "render/scene_geometry.hpp"

namespace s4d {

// What one Renderer::draw sent to the GPU. A live simulation moves the vertices every frame but
// rarely changes the triangles, so index buffers are kept while their indices are unchanged.
struct UploadStats {
  std::size_t vertex_bytes = 0;  // vertex data (positions, normals, colours) sent
  std::size_t index_bytes = 0;   // index data sent
  int vertex_uploads = 0;        // vertex buffers filled
  int index_uploads = 0;         // index buffers filled (a see-through surface re-sorted counts)
  int meshes = 0;                // meshes drawn (objects and overlays, empty ones included)
};

// Needs a current OpenGL 3.3 core context for its whole life (GLFW window or OffscreenContext).
class Renderer {
 public:
  Renderer();
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Draws into the bound framebuffer, viewport (x, y, width, height) in OpenGL's pixels (y up);
  // only that rectangle is cleared, so a window's other parts (its panels) can surround it.
  void draw(const Scene& scene, int width, int height, int x = 0, int y = 0);
  // Reads back that rectangle of the bound framebuffer as an image (top row first).
  Image read_pixels(int width, int height, int x = 0, int y = 0) const;
  // The camera of the last draw (identity-looking default before the first): lets the app map
  // the mouse to shadow space with exactly the matrices that were drawn.
  const Camera& camera() const;
  // The intersection curves of the last draw (computed = false unless view.intersections).
  const IntersectionSummary& intersections() const;
  // What the last draw uploaded.
  const UploadStats& uploads() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Renders a scene without a display: EGL surfaceless (Mesa llvmpipe works without a GPU), into a
// multisampled framebuffer object. Throws s4d::Error if no OpenGL 3.3 context can be made.
// `intersections`, when given, receives what Renderer::intersections() says of the drawing.
Image render_offscreen(const Scene& scene, int width, int height,
                       IntersectionSummary* intersections = nullptr);

}  // namespace s4d
