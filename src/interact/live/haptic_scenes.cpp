// The haptic loop's scenes by name, the cloth as a scene, and the held live simulation.
#include "interact/live/haptic_scenes.hpp"

#include <algorithm>
#include <limits>

#include "core/error.hpp"
#include "haptics/sticky_plane_scene.hpp"
#include "scenario/scenario.hpp"
#include "shape/generators.hpp"

namespace s4d {

namespace {

// A live simulation that plays its hold script from the start and after every reset.
class HeldLiveSimulation final : public HapticScene {
 public:
  HeldLiveSimulation(std::string name, std::unique_ptr<HapticScene> live) : name_(std::move(name)), live_(std::move(live)) {
    live_->command(live::command(live::PlayScript{}));
  }
  std::string_view name() const override { return name_; }
  ToolOutput step(const DeviceState& device, double dt) override { return live_->step(device, dt); }
  void reset() override { live_->command(live::command(live::PlayScript{})); }
  std::span<SceneParam> params() override { return live_->params(); }
  void set_param(int index, double value) override { live_->set_param(index, value); }
  int point_count() const override { return live_->point_count(); }
  int point_dimension() const override { return live_->point_dimension(); }
  void copy_points(std::span<double> out) const override { live_->copy_points(out); }
  void command(const SceneCommand& c) override {
    const live::Request* r = live::request(c);
    if (r && std::holds_alternative<live::Reset>(*r)) reset();
    else live_->command(c);
  }
  void copy_status(SceneStatus& out) const override { live_->copy_status(out); }
  void copy_flags(std::span<std::uint8_t> out) const override { live_->copy_flags(out); }

 private:
  std::string name_;
  std::unique_ptr<HapticScene> live_;
};

const Surface<4>& surface4(const Scene& scene, int o) {
  const auto* s = std::get_if<Surface<4>>(&scene.objects.at(static_cast<std::size_t>(o)).shape);
  if (!s) throw Error("object '" + scene.objects[static_cast<std::size_t>(o)].name + "' is no surface of R^4");
  return *s;
}

}  // namespace

Scene haptic_cloth_scene(int n, double size, bool collisions) {
  if (n < 2 || n > 256)
    throw Error("cloth size must be between 2 and 256 vertices per side, got " + std::to_string(n));
  Scene s;
  s.description = "A 4D cloth hung by its top corners, for the haptic loop (scene units are device metres).";
  SceneObject o;
  o.name = "cloth";
  o.generator = GeneratorCall{"cloth", {{"n", n}, {"size", size}}};
  o.shape = generate("cloth", o.generator->params);
  s.objects.push_back(std::move(o));
  s.physics.gravity = Vec4(0, -9.81, 0, 0);  // m/s²
  s.physics.collisions = collisions;
  s.frame.rotate(Plane{0, 3}, 0.4);  // rad: a generic view, the shadow mixes x and w
  return s;
}

std::vector<int> haptic_cloth_corners(int n) { return {n - 1, n * n - 1}; }  // (i, j) = (0, n−1), (n−1, n−1)

std::unique_ptr<HapticScene> make_held_live_simulation(std::string name, const Scene& scene, const std::string& object,
                                                       std::vector<int> held, const LiveOptions& options) {
  Scenario hold;
  hold.scene = scene;
  hold.name = name + " (held)";
  hold.dim = 4;
  ScriptAction a;
  a.kind = "hold";
  a.select.object = object;
  a.select.indices = std::move(held);
  hold.script.push_back(std::move(a));
  if (hold.object_index(object) < 0) throw Error("no object named '" + object + "' to hold");
  const Surface<4>& s = surface4(scene, hold.object_index(object));
  for (int v : hold.script[0].select.indices)
    if (v < 0 || v >= static_cast<int>(s.vertices.size()))
      throw Error(object + ": vertex " + std::to_string(v) + " out of range to hold");
  return std::make_unique<HeldLiveSimulation>(std::move(name), make_live_simulation(scene, &hold, options));
}

Vec3 shadow_of_vertex(const Scene& scene, int o, int v) {
  const Surface<4>& s = surface4(scene, o);
  return scene.frame.shadow(s.vertices.at(static_cast<std::size_t>(v)));
}

DeviceMapping fit_to_workspace(const Scene& scene, const DeviceCapabilities& caps) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  std::vector<Vec3> shadows;
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    const auto* s = std::get_if<Surface<4>>(&scene.objects[o].shape);
    if (!s) continue;
    for (const Vec4& p : s->vertices) {
      shadows.push_back(scene.frame.shadow(p));
      lo = lo.cwiseMin(shadows.back());
      hi = hi.cwiseMax(shadows.back());
    }
  }
  const Vec3 centre = shadows.empty() ? Vec3::Zero() : Vec3(0.5 * (lo + hi));
  double radius = 0;
  for (const Vec3& p : shadows) radius = std::max(radius, (p - centre).norm());
  return DeviceMapping::fit(centre, radius, Mat<3>::Identity(), caps.workspace_centre(),
                            0.5 * (caps.workspace_max - caps.workspace_min));
}

HapticSceneSetup make_haptic_scene(const HapticSceneChoice& choice) {
  HapticSceneSetup setup;
  if (choice.name == "plane" || choice.name == "sticky-plane") {
    setup.scene = std::make_unique<StickyPlaneScene>();
    return setup;
  }
  if (choice.name != "cloth" && choice.name != "rubber-band")
    throw Error("unknown haptic scene '" + choice.name + "': expected " + kHapticSceneHelp);
  const int n = choice.cloth_n;
  const Scene scene = haptic_cloth_scene(n, choice.cloth_size, choice.collisions);
  LiveOptions o;
  o.async_physics = choice.async_physics;
  o.frame = scene.frame;
  o.mapping.metres_per_unit = 1;  // the cloth is made in device metres, centred on the workspace
  setup.scene = make_held_live_simulation("cloth", scene, "cloth", haptic_cloth_corners(n), o);
  // The hand starts on the vertex in the middle of the cloth's lower half, and holds it.
  setup.held_vertex = (n / 2) * n + n / 4;
  setup.hand_start = o.mapping.to_device(shadow_of_vertex(scene, 0, setup.held_vertex));
  setup.press = 0;
  return setup;
}

}  // namespace s4d
