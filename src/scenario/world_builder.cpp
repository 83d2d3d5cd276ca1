// build_world: scene surfaces (or curves) → ModelBuilder bodies, with the checks a user needs to
// hear about.
#include "scenario/world_builder.hpp"

#include <algorithm>
#include <map>
#include <utility>

#include "core/error.hpp"

namespace s4d {

namespace {

template <int D>
Body<D> as_body(const Shape& shape) {
  if constexpr (D == 4) {
    if (const auto* s3 = std::get_if<Surface<3>>(&shape)) return lift_to_4d(*s3);
    if (const auto* c3 = std::get_if<Curve<3>>(&shape)) return lift_to_4d(*c3);
    if (const auto* c4 = std::get_if<Curve<4>>(&shape)) return *c4;
    return std::get<Surface<4>>(shape);
  } else {
    if (const auto* c3 = std::get_if<Curve<3>>(&shape)) return *c3;
    return std::get<Surface<3>>(shape);
  }
}

int curve_dimension(const Scene& scene) {
  int dim = 0;
  for (const SceneObject& o : scene.objects)
    if (!is_surface(o.shape)) dim = std::max(dim, ambient_dim(o.shape));
  return dim;
}


// An edge of more than two triangles has no side to push along: the physics would be wrong.
template <int D>
void require_manifold(const Surface<D>& s, const std::string& name) {
  std::map<std::pair<int, int>, int> uses;
  for (const Triangle& t : s.triangles)
    for (int c = 0; c < 3; ++c) {
      const int a = t[c], b = t[(c + 1) % 3];
      if (a == b) continue;
      if (++uses[{std::min(a, b), std::max(a, b)}] == 3)
        throw Error("cannot simulate '" + name + "': its edge between vertices " + std::to_string(std::min(a, b)) +
                    " and " + std::to_string(std::max(a, b)) +
                    " is shared by more than two triangles (not a surface there)");
    }
}

template <int D>
Model<D> build_model(const PhysicsSettings& settings, const std::vector<Body<D>>& bodies,
                     const std::vector<double>& masses) {
  ModelBuilder<D> builder(physics_params<D>(settings));
  for (std::size_t b = 0; b < bodies.size(); ++b) builder.add_body(bodies[b], masses[b]);
  return builder.build();
}

}  // namespace

int surface_dimension(const Scene& scene) {
  int dim = 0;
  for (const SceneObject& o : scene.objects)
    if (is_surface(o.shape)) dim = std::max(dim, ambient_dim(o.shape));
  return dim;
}

bool curves_are_bodies(const Scene& scene) { return surface_dimension(scene) == 0 && curve_dimension(scene) > 0; }

int simulation_dimension(const Scene& scene) {
  const int dim = surface_dimension(scene);
  return dim > 0 ? dim : curve_dimension(scene);
}

bool is_body(const Scene& scene, const SceneObject& object) {
  return is_surface(object.shape) || curves_are_bodies(scene);
}

void body_vertex_ranges(const Scene& scene, std::vector<int>& first, std::vector<int>& count) {
  first.assign(scene.objects.size(), -1);
  count.assign(scene.objects.size(), 0);
  const bool curves = curves_are_bodies(scene);
  int nv = 0;
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    const Shape& shape = scene.objects[o].shape;
    if (!curves && !is_surface(shape)) continue;
    first[o] = nv;
    count[o] = point_count(shape);
    nv += count[o];
  }
}

template <int D>
PhysicsParams<D> physics_params(const PhysicsSettings& s) {
  PhysicsParams<D> p;
  p.time_step = s.time_step;
  p.thickness = s.thickness;
  p.gravity = s.gravity.head<D>();
  p.mass = s.mass;
  p.stiffness = s.stiffness;
  p.shear_scale = s.shear_scale;
  p.bending_scale = s.bending_scale;
  p.beta = s.beta;
  p.damping = s.damping;
  p.spring_damping = s.spring_damping;
  p.friction = s.friction;
  p.max_step_motion = s.max_step_motion;
  p.collisions = s.collisions;
  p.integrator = parse_integrator(s.integrator);
  return p;
}

template <int D>
int SceneWorld<D>::object_of_vertex(int v) const {
  for (std::size_t o = 0; o < first.size(); ++o)
    if (first[o] >= 0 && v >= first[o] && v < first[o] + count[o]) return static_cast<int>(o);
  return -1;
}

template <int D>
SceneWorld<D> build_world(const Scene& scene) {
  const int dim = simulation_dimension(scene);
  if (dim == 0) throw Error("nothing to simulate: the scene has no surface or curve");
  if (dim > D) throw Error("this scene's objects lie in R^4 and cannot be simulated in R^3");
  const bool curves = curves_are_bodies(scene);
  std::vector<Body<D>> bodies;
  std::vector<double> masses;
  std::vector<int> first(scene.objects.size(), -1), count(scene.objects.size(), 0), body_object;
  int nv = 0;
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    const SceneObject& obj = scene.objects[o];
    if (!curves && !is_surface(obj.shape)) continue;
    Body<D> body = as_body<D>(obj.shape);
    if (const auto* surface = std::get_if<Surface<D>>(&body)) {
      if (surface->vertices.empty() || surface->triangles.empty())
        throw Error("cannot simulate '" + obj.name + "': it has no triangles");
      require_manifold(*surface, obj.name);
    } else if (std::get<Curve<D>>(body).components.empty()) {
      throw Error("cannot simulate '" + obj.name + "': it has no points");
    }
    first[o] = nv;
    count[o] = body_vertex_count(body);
    nv += count[o];
    bodies.push_back(std::move(body));
    masses.push_back(obj.mass);
    body_object.push_back(static_cast<int>(o));
  }
  Model<D> model;
  try {
    model = build_model<D>(scene.physics, bodies, masses);
  } catch (const Error& e) {
    throw Error(std::string("cannot simulate this scene: ") + e.what());
  }
  return SceneWorld<D>{World<D>(std::move(model)), std::move(first), std::move(count), std::move(bodies),
                       std::move(body_object)};
}

template <int D>
void SceneWorld<D>::apply_settings(const PhysicsSettings& settings) {
  std::vector<Body<D>> now = bodies;
  std::vector<double> masses;
  const auto x = world.positions();
  int v = 0;
  for (std::size_t b = 0; b < now.size(); ++b) {
    if (auto* s = std::get_if<Surface<D>>(&now[b])) {
      for (Vec<D>& p : s->vertices) p = x[v++];
    } else {
      for (Polyline<D>& c : std::get<Curve<D>>(now[b]).components)
        for (Vec<D>& p : c.points) p = x[v++];
    }
    const double m = world.model().mass[static_cast<std::size_t>(world.model().body_first_vertex[b])];
    masses.push_back(m);
  }
  Model<D> model;
  try {
    PhysicsSettings s = settings;
    model = build_model<D>(s, now, masses);
  } catch (const Error& e) {
    throw Error(std::string("cannot apply these physics settings: ") + e.what());
  }
  model.initial = world.model().initial;
  world.set_model(std::move(model));
}

void copy_positions_into(std::span<const int> first, std::span<const int> count, std::span<const double> x, int dim,
                         Scene& scene) {
  for (std::size_t o = 0; o < scene.objects.size() && o < first.size() && o < count.size(); ++o) {
    if (first[o] < 0) continue;
    Shape& shape = scene.objects[o].shape;
    if (ambient_dim(shape) > dim) continue;  // a world of R^3 holds no object of R^4
    if (dim == 4) {  // an object of R^3 moved by a world of R^4 may leave w = 0
      if (const auto* s3 = std::get_if<Surface<3>>(&shape)) shape = lift_to_4d(*s3);
      else if (const auto* c3 = std::get_if<Curve<3>>(&shape)) shape = lift_to_4d(*c3);
    }
    int i = 0;
    for_each_point(shape, [&](auto& p) {
      if (i >= count[o]) return;
      const std::size_t at = static_cast<std::size_t>(first[o] + i++) * static_cast<std::size_t>(dim);
      if (at + static_cast<std::size_t>(dim) > x.size()) return;
      for (int k = 0; k < dim; ++k) p[k] = x[at + static_cast<std::size_t>(k)];
    });
  }
}

template <int D>
void copy_positions_into(const SceneWorld<D>& sw, std::span<const Vec<D>> x, Scene& scene) {
  const std::span<const double> flat(x.empty() ? nullptr : x.front().data(), x.size() * D);
  copy_positions_into(sw.first, sw.count, flat, D, scene);
}

#define S4D_INSTANTIATE(D)                                                                 \
  template PhysicsParams<D> physics_params<D>(const PhysicsSettings&);                     \
  template struct SceneWorld<D>;                                                           \
  template SceneWorld<D> build_world<D>(const Scene&);                                     \
  template void copy_positions_into<D>(const SceneWorld<D>&, std::span<const Vec<D>>, Scene&);
S4D_INSTANTIATE(3)
S4D_INSTANTIATE(4)
#undef S4D_INSTANTIATE

}  // namespace s4d
