// Scene factory and the demo hand path.
#include "haptics/haptic_session.hpp"

#include <cmath>

#include "core/error.hpp"
#include "haptics/async_simulation.hpp"
#include "haptics/rubber_band_scene.hpp"
#include "haptics/sticky_plane_scene.hpp"
#include "haptics/world_simulation.hpp"
#include "shape/surfaces_4d.hpp"

namespace s4d {

std::unique_ptr<HapticScene> make_haptic_scene(const SceneChoice& choice) {
  if (choice.name == "plane" || choice.name == "sticky-plane") return std::make_unique<StickyPlaneScene>();
  if (choice.name == "cloth" || choice.name == "rubber-band") {
    if (choice.cloth_n < 2 || choice.cloth_n > 256)
      throw Error("cloth size must be between 2 and 256 vertices per side, got " +
                  std::to_string(choice.cloth_n));
    PhysicsParams<4> p;
    p.gravity = Vec4(0, -9.81, 0, 0);
    p.collisions = choice.collisions;
    ModelBuilder<4> builder(p);
    builder.add_body(cloth(choice.cloth_n, choice.cloth_size));
    World<4> world(builder.build());
    // Hang it by its two top corners.
    const double half = 0.5 * choice.cloth_size;
    for (int v = 0; v < world.vertex_count(); ++v) {
      const Vec4& x = world.positions()[v];
      if (x.y() > half - 1e-9 && std::abs(std::abs(x.x()) - half) < 1e-9) world.pin(v);
    }
    Frame<4> frame;
    frame.rotate(Plane{0, 3}, 0.4);  // a generic view: the shadow mixes x and w
    std::unique_ptr<GrabbableSimulation> sim =
        std::make_unique<WorldSimulation<4>>(std::move(world), frame, 1.0);
    if (choice.async_physics) sim = std::make_unique<AsyncSimulation>(std::move(sim), p.time_step);
    return std::make_unique<RubberBandScene>(std::move(sim));
  }
  throw Error("unknown haptic scene '" + choice.name + "': expected " + kSceneChoiceHelp);
}

Vec3 demo_hand_path(double t, const Vec3& start, double press) {
  const double r = 0.02, w = 2 * M_PI * 0.5;
  const double pressing = std::min(1.0, t / 0.3);  // press in over 0.3 s, then circle
  const double tt = std::max(0.0, t - 0.3);
  return start + Vec3(r * (std::cos(w * tt) - 1), r * std::sin(w * tt), -press * pressing);
}

}  // namespace s4d
