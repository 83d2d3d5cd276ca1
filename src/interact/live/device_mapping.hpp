// DeviceMapping: the device's workspace (metres) laid onto the view's 3D shadow space (scene
// units) — the paper's "3D shadow space is the human-accessible dimension". The device's axes
// follow the camera (x right, y up, z toward the eye), so the hand moves as the picture does.
// And what the device's first button does in the scene (DeviceButton).
#pragma once
#include "core/vec.hpp"

namespace s4d {

// What a haptic device's first button does under a tool (the mouse's press reaches the tool itself).
enum class DeviceButton : int {
  kGrab = 0,     // hold the vertex nearest the device's point on the rubber band
  kExplore = 1,  // start the probe there
  kNone = 2,     // nothing in the simulation: the tool reads the button itself (a sketch draws)
};

struct DeviceMapping {
  Vec3 centre = Vec3::Zero();            // shadow point at the workspace's centre
  Mat<3> axes = Mat<3>::Identity();      // columns: the device's x, y, z in shadow space
  double metres_per_unit = 0.05;         // m of device motion per scene unit
  Vec3 workspace_centre = Vec3::Zero();  // m

  Vec3 to_shadow(const Vec3& device) const {
    return centre + axes * ((device - workspace_centre) / metres_per_unit);
  }
  Vec3 to_device(const Vec3& shadow) const {
    return workspace_centre + metres_per_unit * (axes.transpose() * (shadow - centre));
  }
  // A direction or velocity (no offset).
  Vec3 vector_to_shadow(const Vec3& d) const { return axes * (d / metres_per_unit); }
  Vec3 vector_to_device(const Vec3& s) const { return metres_per_unit * (axes.transpose() * s); }

  // Fits a ball of `radius` around `centre` into a workspace box (half extents `half`, m),
  // with the camera's orientation as axes. Degenerate input gives a usable mapping.
  static DeviceMapping fit(const Vec3& centre, double radius, const Mat<3>& axes, const Vec3& workspace_centre,
                           const Vec3& half) {
    DeviceMapping m;
    m.centre = centre.allFinite() ? centre : Vec3::Zero();
    m.axes = axes.allFinite() ? axes : Mat<3>::Identity();
    const double r = radius > 1e-9 && std::isfinite(radius) ? radius : 1.0;
    const double h = half.minCoeff() > 0 ? half.minCoeff() : 0.05;
    m.metres_per_unit = h / r;
    m.workspace_centre = workspace_centre;
    return m;
  }
};

}  // namespace s4d
