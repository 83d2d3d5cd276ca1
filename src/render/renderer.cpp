// Renderer: uploads the frame's SceneGeometry and draws it with one GLSL program in three modes
// (lit, flat shadow, solid wireframe colour), opaque things first, then the flat strands of the
// curve modes, and see-through surfaces sorted back to front after them, plus render_offscreen for
// the CLI and tests.
//
// [SECTION] shaders
// [SECTION] gpu meshes
// [SECTION] draw
// [SECTION] offscreen
#include "render/renderer.hpp"

#include "render/gl.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "render/gl_context.hpp"
#include "render/scene_geometry.hpp"
#include "render/shader_program.hpp"

namespace s4d {

// [SECTION] shaders
namespace {

constexpr const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec3 a_colour;
uniform mat4 u_view;
uniform mat4 u_projection;
out vec3 v_position;  // eye space
out vec3 v_normal;    // eye space
out vec3 v_colour;
void main() {
  vec4 p = u_view * vec4(a_position, 1.0);
  v_position = p.xyz;
  v_normal = mat3(u_view) * a_normal;  // the view is a rigid motion: no inverse-transpose needed
  v_colour = a_colour;
  gl_Position = u_projection * p;
}
)";

// Modes: 0 = lit (Blinn-Phong, headlight + fill), 1 = flat (vertex colour, no lighting: the shadow
// drawing, and unlit overlays),
// 2 = one solid colour (wireframe edges).
constexpr const char* kFragmentShader = R"(#version 330 core
in vec3 v_position;
in vec3 v_normal;
in vec3 v_colour;
uniform int u_mode;
uniform vec3 u_solid;
uniform float u_alpha;  // surfaces' opacity (view.opacity); 1 for everything else
out vec4 frag_colour;

float blinn(vec3 n, vec3 l, vec3 v, out float spec) {
  float d = max(dot(n, l), 0.0);
  vec3 h = normalize(l + v);
  spec = d > 0.0 ? pow(max(dot(n, h), 0.0), 64.0) : 0.0;
  return d;
}

void main() {
  if (u_mode == 2) { frag_colour = vec4(u_solid, 1.0); return; }
  if (u_mode == 1) { frag_colour = vec4(v_colour, u_alpha); return; }
  vec3 n = normalize(v_normal);
  // Two-sided: a projected 4D surface shows its back as often as its front.
  if (!gl_FrontFacing) n = -n;
  vec3 v = normalize(-v_position);
  // The headlight sits at the eye, so whatever faces the viewer is lit; the fill light comes
  // from the upper left so shapes read as 3D rather than as flat discs.
  float s1, s2;
  float d1 = blinn(n, v, v, s1);
  float d2 = blinn(n, normalize(vec3(-0.55, 0.65, 0.5)), v, s2);
  // Weights sum to about 1 for a face-on surface so light colours do not saturate to white.
  vec3 c = v_colour * (0.16 + 0.62 * d1 + 0.26 * d2) + vec3(0.20 * s1 + 0.08 * s2);
  frag_colour = vec4(min(c, vec3(1.0)), u_alpha);
}
)";

constexpr float kWireColour[3] = {0.06f, 0.06f, 0.08f};

}  // namespace

// [SECTION] gpu meshes
namespace {

// One object's buffers, kept across frames. The vertex data is sent every draw (it moves with
// every 4D rotation and every simulation step), into the same store when its size is unchanged;
// the indices only when they differ from what the buffer holds, which in a live simulation is
// almost never.
struct GpuMesh {
  GLuint vao = 0, vbo = 0, ebo = 0;
  GLsizei index_count = 0;
  std::size_t vertex_store = 0;        // bytes of the vertex buffer's store
  std::vector<std::uint32_t> indices;  // what the index buffer holds
  std::vector<float> interleaved;      // nv × 9 (position, normal, colour), reused across draws
  std::vector<std::uint32_t> sorted;   // a see-through surface's triangles, far to near
  bool surface = true;

  GpuMesh() {
    glGenVertexArrays(1, &vao);
    glGenBuffers(1, &vbo);
    glGenBuffers(1, &ebo);
    glBindVertexArray(vao);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo);  // recorded in the VAO
    constexpr GLsizei stride = 9 * sizeof(float);
    for (GLuint a = 0; a < 3; ++a) {
      glEnableVertexAttribArray(a);
      glVertexAttribPointer(
          a, 3, GL_FLOAT, GL_FALSE, stride,
          reinterpret_cast<const void*>(static_cast<std::uintptr_t>(3 * a * sizeof(float))));
    }
    glBindVertexArray(0);
  }
  ~GpuMesh() {
    glDeleteBuffers(1, &vbo);
    glDeleteBuffers(1, &ebo);
    if (edge_ebo) glDeleteBuffers(1, &edge_ebo);
    glDeleteVertexArrays(1, &vao);
  }
  GpuMesh(const GpuMesh&) = delete;
  GpuMesh& operator=(const GpuMesh&) = delete;

  // Sends the object's vertices and, when they changed, `order` (its indices, or a sorted copy).
  void upload(const DrawObject& obj, const std::vector<std::uint32_t>& order, UploadStats& stats) {
    const RenderMesh& m = obj.mesh;
    surface = obj.surface;
    interleaved.resize(9 * m.vertex_count());
    float* out = interleaved.data();
    for (std::size_t v = 0; v < m.vertex_count(); ++v) {
      for (int k = 0; k < 3; ++k) *out++ = static_cast<float>(m.positions[v][k]);
      for (int k = 0; k < 3; ++k) *out++ = static_cast<float>(m.normals[v][k]);
      for (int k = 0; k < 3; ++k) *out++ = obj.colours[v][k];
    }
    glBindVertexArray(vao);
    const std::size_t bytes = interleaved.size() * sizeof(float);
    if (bytes > 0 || vertex_store > 0) {
      glBindBuffer(GL_ARRAY_BUFFER, vbo);
      if (bytes == vertex_store) {
        // Orphan the store (the GPU may still be reading last frame's) and fill the new one.
        glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(bytes), nullptr, GL_STREAM_DRAW);
        glBufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(bytes), interleaved.data());
      } else {
        glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(bytes), interleaved.data(), GL_STREAM_DRAW);
        vertex_store = bytes;
      }
      stats.vertex_bytes += bytes;
      ++stats.vertex_uploads;
    }
    if (order != indices) {
      const auto index_bytes = static_cast<GLsizeiptr>(order.size() * sizeof(std::uint32_t));
      glBufferData(GL_ELEMENT_ARRAY_BUFFER, index_bytes, order.data(), GL_STATIC_DRAW);
      indices = order;
      stats.index_bytes += static_cast<std::size_t>(index_bytes);
      ++stats.index_uploads;
    }
    glBindVertexArray(0);
    index_count = static_cast<GLsizei>(indices.size());
  }

  void draw() const {
    if (index_count == 0) return;
    glBindVertexArray(vao);
    glDrawElements(GL_TRIANGLES, index_count, GL_UNSIGNED_INT, nullptr);
  }

  // The triangles' edges as lines: the wireframe where OpenGL ES (WebGL) has no glPolygonMode.
  void draw_edges() {
    if (index_count == 0) return;
    glBindVertexArray(vao);
    if (!edge_ebo) glGenBuffers(1, &edge_ebo);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, edge_ebo);
    if (edges_of != indices) {
      edges.clear();
      for (std::size_t t = 0; t + 2 < indices.size(); t += 3)
        for (int k = 0; k < 3; ++k) {
          edges.push_back(indices[t + static_cast<std::size_t>(k)]);
          edges.push_back(indices[t + static_cast<std::size_t>((k + 1) % 3)]);
        }
      glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(edges.size() * sizeof(std::uint32_t)),
                   edges.data(), GL_STATIC_DRAW);
      edges_of = indices;
    }
    glDrawElements(GL_LINES, static_cast<GLsizei>(edges.size()), GL_UNSIGNED_INT, nullptr);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo);  // the VAO's triangles again
  }
  GLuint edge_ebo = 0;
  std::vector<std::uint32_t> edges, edges_of;  // the lines, and the triangles they were made from
};

// The triangles of `m` from the farthest from the eye to the nearest (by their centres' eye
// depth), into `out`; returns the mean eye depth (negative in front of the eye). Blending
// without depth writes is right when what lies behind is drawn first.
double sort_far_to_near(const RenderMesh& m, const Mat4& view, std::vector<std::uint32_t>& out) {
  const Eigen::RowVector4d z = view.row(2);
  const std::size_t nt = m.triangle_count();
  std::vector<std::pair<double, std::uint32_t>> keys(nt);
  double sum = 0;
  for (std::size_t t = 0; t < nt; ++t) {
    const Vec3 c = m.positions[m.indices[3 * t]] + m.positions[m.indices[3 * t + 1]] +
                   m.positions[m.indices[3 * t + 2]];
    const double depth = z.dot((c / 3).homogeneous());
    keys[t] = {std::isfinite(depth) ? depth : 0.0, static_cast<std::uint32_t>(t)};
    sum += keys[t].first;
  }
  // Stable, so that triangles at one depth keep their order and a still view sorts the same.
  std::stable_sort(keys.begin(), keys.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  out.resize(3 * nt);
  for (std::size_t i = 0; i < nt; ++i)
    for (int k = 0; k < 3; ++k) out[3 * i + k] = m.indices[3 * keys[i].second + k];
  return nt > 0 ? sum / static_cast<double>(nt) : 0.0;
}

Eigen::Matrix4f to_float(const Mat4& m) { return m.cast<float>(); }

}  // namespace

struct Renderer::Impl {
  ShaderProgram program{"surface shader", kVertexShader, kFragmentShader};
  int u_view = program.uniform("u_view");
  int u_projection = program.uniform("u_projection");
  int u_mode = program.uniform("u_mode");
  int u_solid = program.uniform("u_solid");
  int u_alpha = program.uniform("u_alpha");
  std::vector<std::unique_ptr<GpuMesh>> meshes;  // the objects', then the overlays'
  Camera camera;
  IntersectionSummary intersections;
  UploadStats uploads;
};

Renderer::Renderer() {
  if (!glGetString(GL_VERSION)) throw Error("Renderer needs a current OpenGL context");
  impl_ = std::make_unique<Impl>();
  check_gl("Renderer()");
}

Renderer::~Renderer() = default;

const Camera& Renderer::camera() const { return impl_->camera; }

const IntersectionSummary& Renderer::intersections() const { return impl_->intersections; }

const UploadStats& Renderer::uploads() const { return impl_->uploads; }

// [SECTION] draw
void Renderer::draw(const Scene& scene, int width, int height, int x, int y) {
  if (width < 1 || height < 1)
    throw Error("cannot draw into a " + std::to_string(width) + "x" + std::to_string(height) + " viewport");
  const SceneGeometry geometry = build_scene_geometry(scene, static_cast<double>(width) / height);
  Impl& r = *impl_;
  r.camera = geometry.camera;
  r.intersections = geometry.intersections;

  // See-through surfaces are drawn after everything opaque, without writing depth, each sorted
  // far to near and the objects in the same order: a sheet behind is then blended in before the
  // one in front. Two sheets that cross are right on either side of the crossing, up to a
  // triangle's size, which a per-pixel method (depth peeling) would fix at several passes' cost.
  const double opacity = drawn_opacity(scene.view);
  const bool see_through = opacity < 1;
  const Mat4 view_d = geometry.camera.view();
  const std::size_t count = geometry.objects.size() + geometry.overlays.size();
  while (r.meshes.size() < count) r.meshes.push_back(std::make_unique<GpuMesh>());
  r.meshes.resize(count);  // frees buffers of removed objects
  r.uploads = UploadStats{};
  r.uploads.meshes = static_cast<int>(count);
  std::vector<std::pair<double, std::size_t>> blended;  // (mean eye depth, mesh)
  for (std::size_t i = 0; i < count; ++i) {
    const DrawObject& obj =
        i < geometry.objects.size() ? geometry.objects[i] : geometry.overlays[i - geometry.objects.size()];
    GpuMesh& gpu = *r.meshes[i];
    if (see_through && obj.surface && i < geometry.objects.size()) {
      blended.emplace_back(sort_far_to_near(obj.mesh, view_d, gpu.sorted), i);
      gpu.upload(obj, gpu.sorted, r.uploads);
    } else {
      gpu.upload(obj, obj.mesh.indices, r.uploads);
    }
  }
  std::stable_sort(blended.begin(), blended.end());
  std::vector<bool> is_blended(count, false);
  for (const auto& b : blended) is_blended[b.second] = true;

  glViewport(x, y, width, height);
  const Vec3f& bg = scene.view.background;
  glClearColor(bg.x(), bg.y(), bg.z(), 1.0f);
  glClearDepth(1.0);
  glEnable(GL_SCISSOR_TEST);
  glScissor(x, y, width, height);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
#ifndef S4D_GLES
  glEnable(GL_MULTISAMPLE);
#endif

  r.program.use();
  const Eigen::Matrix4f view = to_float(view_d);
  const Eigen::Matrix4f projection = to_float(geometry.camera.projection());
  glUniformMatrix4fv(r.u_view, 1, GL_FALSE, view.data());  // Eigen is column-major, as GL wants
  glUniformMatrix4fv(r.u_projection, 1, GL_FALSE, projection.data());
  glUniform3fv(r.u_solid, 1, kWireColour);
  glUniform1f(r.u_alpha, 1.0f);

  // Pass 1: the opaque surfaces, tubes and overlays. With the wireframe on, push the fill slightly
  // back so the edges drawn at the same depth win the depth test.
  const bool wire = scene.view.wireframe;
  glUniform1i(r.u_mode, scene.view.shadow ? 1 : 0);
#ifndef S4D_GLES
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
#endif
  if (wire) {
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.0f, 1.0f);
  }
  auto object = [&](std::size_t i) -> const DrawObject& {
    return i < geometry.objects.size() ? geometry.objects[i] : geometry.overlays[i - geometry.objects.size()];
  };
  bool any_screen = false;
  for (std::size_t i = 0; i < count; ++i) {
    if (is_blended[i]) continue;
    if (object(i).screen) {
      any_screen = true;
      continue;
    }
    const bool lit = object(i).lit;
    if (!lit && !scene.view.shadow) glUniform1i(r.u_mode, 1);
    r.meshes[i]->draw();
    if (!lit && !scene.view.shadow) glUniform1i(r.u_mode, 0);
  }

  // Pass 1b: the flat strands of the shadow and diagram curve modes, given in normalised device
  // coordinates, unlit. The plain shadow shows no depth: its strands are painted in order, not
  // depth-tested against each other (a link's nearer component would show on top), and then
  // write their depth so that see-through surfaces behind them stay behind.
  if (any_screen) {
    const Eigen::Matrix4f identity = Eigen::Matrix4f::Identity();
    glUniformMatrix4fv(r.u_view, 1, GL_FALSE, identity.data());
    glUniformMatrix4fv(r.u_projection, 1, GL_FALSE, identity.data());
    glUniform1i(r.u_mode, 1);
    const bool painted = scene.view.curve_mode == CurveMode::kShadow;
    if (painted) glDepthMask(GL_FALSE);
    for (std::size_t i = 0; i < count; ++i)
      if (object(i).screen) r.meshes[i]->draw();
    if (painted) {
      glDepthMask(GL_TRUE);
      glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
      for (std::size_t i = 0; i < count; ++i)
        if (object(i).screen) r.meshes[i]->draw();
      glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    }
    glUniformMatrix4fv(r.u_view, 1, GL_FALSE, view.data());
    glUniformMatrix4fv(r.u_projection, 1, GL_FALSE, projection.data());
    glUniform1i(r.u_mode, scene.view.shadow ? 1 : 0);
  }

  // Pass 2: the see-through surfaces, far to near, blended over what is behind them.
  if (!blended.empty()) {
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
    glUniform1f(r.u_alpha, static_cast<float>(opacity));
    for (const auto& b : blended) r.meshes[b.second]->draw();
    glUniform1f(r.u_alpha, 1.0f);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
  }
  glDisable(GL_POLYGON_OFFSET_FILL);

  // Pass 3: triangle edges of surfaces in a dark colour (tubes would only show their facets).
  if (wire) {
    glUniform1i(r.u_mode, 2);
    glDepthFunc(GL_LEQUAL);
#ifdef S4D_GLES
    for (const auto& m : r.meshes)
      if (m->surface) m->draw_edges();
#else
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    for (const auto& m : r.meshes)
      if (m->surface) m->draw();
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
#endif
    glDepthFunc(GL_LESS);
  }
  glBindVertexArray(0);
  glUseProgram(0);
  check_gl("Renderer::draw");
}

Image Renderer::read_pixels(int width, int height, int x, int y) const {
  if (width < 1 || height < 1)
    throw Error("cannot read a " + std::to_string(width) + "x" + std::to_string(height) + " image");
  return read_framebuffer(width, height, x, y);
}

// [SECTION] offscreen
Image render_offscreen(const Scene& scene, int width, int height,
                       IntersectionSummary* intersections) {
  OffscreenContext context;
  RenderTarget target(width, height, 4);
  Renderer renderer;  // declared last: destroyed first, while the context is still current
  target.bind();
  renderer.draw(scene, width, height);
  if (intersections) *intersections = renderer.intersections();
  return target.resolve_and_read();
}

}  // namespace s4d
