// Scene: what the app shows and simulates, and its versioned JSON file format.
// A scene file lists objects (a generator with parameters, or a mesh/curve file path relative to
// the scene file), the 4D frame, the view, and the physics parameters.
#pragma once
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "core/colour_map.hpp"
#include "core/frame.hpp"
#include "shape/generators.hpp"
#include "shape/placement.hpp"
#include "shape/shape.hpp"

namespace s4d {

inline constexpr int kSceneVersion = 1;

struct SceneObject {
  std::string name;                          // shown in the UI; unique within a scene
  std::optional<GeneratorCall> generator;    // how it was made, when generated
  std::string source_path;                   // the file it was read from, when loaded
  Shape shape;                               // the geometry itself (built or loaded)
  std::optional<Vec3f> colour;               // fixed colour when depth colouring is off
  // Linear map, scale, mirrors, w ramp and translation applied once when the object is built
  // or loaded (shape holds the placed geometry).
  Placement placement;
  double mass = 0;                           // kg per vertex in the simulation; 0 = physics.mass
};

// How curves are drawn (the paper's Fig. 1): kTubes, lit tubes (c); kShadow, the plain shadow,
// the curve's image as a flat strip of one width with no lighting (a); kDiagram, the 2½D crossing
// diagram, flat strands with a gap in the under strand at every crossing of the view (b).
// Surfaces are drawn as they are in every mode; depth colour applies in every mode.
enum class CurveMode { kTubes, kShadow, kDiagram };

// "tubes", "shadow", "diagram": the names in scene files and on the command line.
inline const char* curve_mode_name(CurveMode m) {
  switch (m) {
    case CurveMode::kShadow: return "shadow";
    case CurveMode::kDiagram: return "diagram";
    case CurveMode::kTubes: break;
  }
  return "tubes";
}
inline std::optional<CurveMode> parse_curve_mode(const std::string& name) {
  for (CurveMode m : {CurveMode::kTubes, CurveMode::kShadow, CurveMode::kDiagram})
    if (name == curve_mode_name(m)) return m;
  return std::nullopt;
}

struct ViewSettings {
  Eigen::Quaterniond trackball = Eigen::Quaterniond::Identity();  // 3D camera orientation
  double distance = 0;         // camera distance; 0 = fit the scene's bounding sphere
  double zoom = 1;             // multiplies the fitted view: > 1 moves closer (GUI wheel)
  double fov_deg = 35;         // vertical field of view
  bool depth_colour = true;    // 4D depth (w) colour for R^4 objects, view depth for R^3 ones
  ColourMap colour_map = ColourMap::kCoolWarm;
  bool wireframe = false;      // draw triangle edges over the surface
  bool shadow = false;         // flat-shaded shadow drawing (no lighting)
  // Draw the intersection curves of the R^4 surfaces' shadow: shadow-only crossings (the sheets
  // are apart in w) in yellow with a red line on the sheet nearer in w and a blue one on the
  // farther (the paper's above-below markings), true 4D intersections in magenta (the paper's
  // depth test), a bead where a curve ends inside the surface (a pinch point); and a dot on the
  // over strand of each crossing of the curves as the camera sees them.
  bool intersections = false;
  double tube_radius = 0.03;   // curve tube radius, in scene units
  // Tubes, the plain shadow or the crossing diagram; the flat strands are as wide on the screen
  // as a tube at the centre of the view.
  CurveMode curve_mode = CurveMode::kTubes;
  // When fit_radius > 0 the camera frames this ball (shadow space) instead of the drawn objects:
  // the window fixes it while a simulation moves them, so the view holds still under the hand.
  // Not stored in scene files.
  Vec3 fit_centre = Vec3::Zero();
  double fit_radius = 0;
  // Surfaces' opacity in [0.05, 1], 1 = opaque: below 1 a sheet behind shows through the one in
  // front. Curve tubes and the intersection marks stay opaque.
  double opacity = 1;
  Vec3f background{0.08f, 0.09f, 0.11f};
  // The slice of the R^4 surfaces by the hyperplane w = slice_level of the 4D frame (the level
  // set of the 4D depth, view/scene_slice.hpp), drawn over them as tubes in one bright colour;
  // with slice_fade the surfaces are drawn at most kSliceFadeOpacity opaque behind it. Not stored
  // in scene files (the window's Slice panel, `render --slice W`, `slice`).
  bool slice = false;
  double slice_level = std::numeric_limits<double>::quiet_NaN();  // NaN: not chosen (the window takes the middle)
  bool slice_fade = true;
};
inline constexpr double kSliceFadeOpacity = 0.3;

// Physics parameters stored with a scene: the simulation of its surfaces (scenario/world_builder
// turns them into the physics layer's parameters; validated on load).
struct PhysicsSettings {
  double time_step = 1e-3;     // s; the haptic tick
  double thickness = 0.02;     // δ, collision thickness, scene units
  Vec4 gravity = Vec4::Zero(); // m/s², any direction of R^4
  double mass = 1e-3;          // kg per vertex
  double stiffness = 50;       // N/m, structural springs
  double shear_scale = 0.5;    // shear stiffness = shear_scale × stiffness
  double bending_scale = 0.1;  // bending stiffness = bending_scale × stiffness
  double beta = 0;             // exponent of the generalised Hooke law (paper Eq. 1)
  double damping = 0.02;       // N·s/m, on every vertex velocity
  double spring_damping = 0.02;  // N·s/m, along each spring
  double friction = 0.3;       // Coulomb coefficient between touching surfaces (0 = slippery)
  double max_step_motion = 0;  // m per step, 0 = δ (the paper's clamp of a frame's motion)
  bool collisions = true;      // self- and mutual collision avoidance
  std::string integrator = "symplectic-euler";
  friend bool operator==(const PhysicsSettings&, const PhysicsSettings&) = default;
};

struct Scene {
  std::string description;     // what the scene shows, for a person (optional)
  std::string instruction;     // one line: what to do with it by hand, shown in the window (optional)
  std::vector<SceneObject> objects;
  Frame<4> frame;              // the 4D view rotation; R^3 objects sit at w = 0
  ViewSettings view;
  PhysicsSettings physics;
  // A scenario file's "scenario" object (its name, instruction, script and verdict) as JSON
  // text, read by the scenario layer; empty for a plain scene. Written back by save_scene.
  std::string scenario;
};

// Reads a scene file. Mesh paths are resolved relative to the scene file. Throws ParseError
// naming the file (and line, for JSON syntax errors) on anything malformed.
Scene load_scene(const std::filesystem::path& path);
// Parses scene JSON text; `origin` names it in errors and is the base for relative paths.
Scene parse_scene(const std::string& text, const std::filesystem::path& origin);
// Writes a scene. Generated objects are stored by generator call; loaded objects by path;
// objects with neither (edited geometry) are written as meshes beside the scene file.
void save_scene(const Scene& scene, const std::filesystem::path& path);
// How objects are written: by recipe (a generator call, a path, edited geometry in a mesh file
// beside the scene), or inline (every point, as a session keeps the state it had).
enum class ObjectStorage { kByRecipe, kInline };
// The scene's JSON text (what save_scene writes); `path` is where it will live (relative paths
// and mesh files beside it). Throws Error like save_scene.
std::string scene_text(const Scene& scene, const std::filesystem::path& path, ObjectStorage storage);

// Loads any object file by extension: .off/.4off/.noff (surfaces), .vect/.4vect/.txt/.xyz/.curve
// (curves), or a generator call such as "spun-trefoil:n=48". Throws Error/ParseError.
SceneObject load_object(const std::string& spec);
// Loads a scene file (.json) or wraps a single object (see load_object) in a default scene.
Scene load_scene_or_object(const std::string& spec);

}  // namespace s4d
