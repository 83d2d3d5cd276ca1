// Renderer: uploads the frame's SceneGeometry and draws it with one GLSL program in three modes
// (lit, flat shadow, solid wireframe colour), plus render_offscreen for the CLI and tests.
//
// [SECTION] shaders
// [SECTION] gpu meshes
// [SECTION] draw
// [SECTION] offscreen
#include "render/renderer.hpp"

#include <GL/gl.h>
#include <GL/glext.h>

#include <cstdint>
#include <string>
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
out vec4 frag_colour;

float blinn(vec3 n, vec3 l, vec3 v, out float spec) {
  float d = max(dot(n, l), 0.0);
  vec3 h = normalize(l + v);
  spec = d > 0.0 ? pow(max(dot(n, h), 0.0), 64.0) : 0.0;
  return d;
}

void main() {
  if (u_mode == 2) { frag_colour = vec4(u_solid, 1.0); return; }
  if (u_mode == 1) { frag_colour = vec4(v_colour, 1.0); return; }
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
  frag_colour = vec4(min(c, vec3(1.0)), 1.0);
}
)";

constexpr float kWireColour[3] = {0.06f, 0.06f, 0.08f};

}  // namespace

// [SECTION] gpu meshes
namespace {

// One object's buffers; kept across frames and re-filled each draw (the geometry changes with
// every 4D rotation, so caching by content would rarely pay).
struct GpuMesh {
  GLuint vao = 0, vbo = 0, ebo = 0;
  GLsizei index_count = 0;
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
    glDeleteVertexArrays(1, &vao);
  }
  GpuMesh(const GpuMesh&) = delete;
  GpuMesh& operator=(const GpuMesh&) = delete;

  void upload(const DrawObject& obj) {
    const RenderMesh& m = obj.mesh;
    std::vector<float> data;
    data.reserve(9 * m.vertex_count());
    for (std::size_t v = 0; v < m.vertex_count(); ++v) {
      for (int k = 0; k < 3; ++k) data.push_back(static_cast<float>(m.positions[v][k]));
      for (int k = 0; k < 3; ++k) data.push_back(static_cast<float>(m.normals[v][k]));
      for (int k = 0; k < 3; ++k) data.push_back(obj.colours[v][k]);
    }
    glBindVertexArray(vao);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(float)), data.data(),
                 GL_STREAM_DRAW);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(m.indices.size() * sizeof(std::uint32_t)),
                 m.indices.data(), GL_STREAM_DRAW);
    glBindVertexArray(0);
    index_count = static_cast<GLsizei>(m.indices.size());
    surface = obj.surface;
  }

  void draw() const {
    if (index_count == 0) return;
    glBindVertexArray(vao);
    glDrawElements(GL_TRIANGLES, index_count, GL_UNSIGNED_INT, nullptr);
  }
};

Eigen::Matrix4f to_float(const Mat4& m) { return m.cast<float>(); }

}  // namespace

struct Renderer::Impl {
  ShaderProgram program{"surface shader", kVertexShader, kFragmentShader};
  int u_view = program.uniform("u_view");
  int u_projection = program.uniform("u_projection");
  int u_mode = program.uniform("u_mode");
  int u_solid = program.uniform("u_solid");
  std::vector<std::unique_ptr<GpuMesh>> meshes;  // the objects', then the overlays'
  Camera camera;
  IntersectionSummary intersections;
};

Renderer::Renderer() {
  if (!glGetString(GL_VERSION)) throw Error("Renderer needs a current OpenGL context");
  impl_ = std::make_unique<Impl>();
  check_gl("Renderer()");
}

Renderer::~Renderer() = default;

const Camera& Renderer::camera() const { return impl_->camera; }

const IntersectionSummary& Renderer::intersections() const { return impl_->intersections; }

// [SECTION] draw
void Renderer::draw(const Scene& scene, int width, int height) {
  if (width < 1 || height < 1)
    throw Error("cannot draw into a " + std::to_string(width) + "x" + std::to_string(height) + " viewport");
  const SceneGeometry geometry = build_scene_geometry(scene, static_cast<double>(width) / height);
  Impl& r = *impl_;
  r.camera = geometry.camera;
  r.intersections = geometry.intersections;

  const std::size_t count = geometry.objects.size() + geometry.overlays.size();
  while (r.meshes.size() < count) r.meshes.push_back(std::make_unique<GpuMesh>());
  r.meshes.resize(count);  // frees buffers of removed objects
  for (std::size_t i = 0; i < count; ++i)
    r.meshes[i]->upload(i < geometry.objects.size() ? geometry.objects[i]
                                                     : geometry.overlays[i - geometry.objects.size()]);

  glViewport(0, 0, width, height);
  const Vec3f& bg = scene.view.background;
  glClearColor(bg.x(), bg.y(), bg.z(), 1.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  glEnable(GL_MULTISAMPLE);

  r.program.use();
  const Eigen::Matrix4f view = to_float(geometry.camera.view());
  const Eigen::Matrix4f projection = to_float(geometry.camera.projection());
  glUniformMatrix4fv(r.u_view, 1, GL_FALSE, view.data());  // Eigen is column-major, as GL wants
  glUniformMatrix4fv(r.u_projection, 1, GL_FALSE, projection.data());
  glUniform3fv(r.u_solid, 1, kWireColour);

  // Pass 1: the surfaces and tubes. With the wireframe on, push the fill slightly back so the
  // edges drawn at the same depth win the depth test.
  const bool wire = scene.view.wireframe;
  glUniform1i(r.u_mode, scene.view.shadow ? 1 : 0);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  if (wire) {
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.0f, 1.0f);
  }
  for (std::size_t i = 0; i < r.meshes.size(); ++i) {
    const bool lit = i < geometry.objects.size() || geometry.overlays[i - geometry.objects.size()].lit;
    if (!lit && !scene.view.shadow) glUniform1i(r.u_mode, 1);
    r.meshes[i]->draw();
    if (!lit && !scene.view.shadow) glUniform1i(r.u_mode, 0);
  }
  glDisable(GL_POLYGON_OFFSET_FILL);

  // Pass 2: triangle edges of surfaces in a dark colour (tubes would only show their facets).
  if (wire) {
    glUniform1i(r.u_mode, 2);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glDepthFunc(GL_LEQUAL);
    for (const auto& m : r.meshes)
      if (m->surface) m->draw();
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glDepthFunc(GL_LESS);
  }
  glBindVertexArray(0);
  glUseProgram(0);
  check_gl("Renderer::draw");
}

Image Renderer::read_pixels(int width, int height) const {
  if (width < 1 || height < 1)
    throw Error("cannot read a " + std::to_string(width) + "x" + std::to_string(height) + " image");
  return read_framebuffer(width, height);
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
