// Camera: view and projection matrices from the trackball quaternion, with the distance fitted
// to the scene's bounding sphere when the view asks for it (distance 0).
#pragma once
#include "core/vec.hpp"
#include <vector>

namespace s4d {

using Mat4 = Eigen::Matrix4d;

// A sphere containing every finite point: centre of the bounding box, radius to the farthest
// point.
struct BoundingSphere {
  Vec3 centre = Vec3::Zero();
  double radius = 0;  // 0 for no points or a single point
};
BoundingSphere bounding_sphere(const std::vector<Vec3>& points);

struct Camera {
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  // camera axes in the world
  Vec3 target = Vec3::Zero();  // the point looked at (the bounding sphere's centre)
  double distance = 1;         // from the eye to the target, scene units
  double fov_y = 0.6;          // vertical field of view, radians
  double aspect = 1;           // width / height
  double near_plane = 0.01;    // scene units, > 0
  double far_plane = 100;      // scene units, > near_plane

  // The eye sits on the camera's +z axis: with the identity orientation it looks down -z with
  // x to the right and y up, so larger z is nearer, as in Frame<3>'s depth convention.
  Vec3 eye() const;
  Mat4 view() const;        // world -> eye coordinates
  Mat4 projection() const;  // eye -> clip coordinates (OpenGL conventions, NDC z in [-1, 1])
  // Distance in front of the eye along the view direction (positive for visible points).
  double view_depth(const Vec3& p) const;
  // Normalised device coordinates of p on the screen (x right, y up, [-1, 1] across the view).
  Vec2 ndc(const Vec3& p) const;
};

// Distance at which a sphere of `radius` exactly fits the narrower of the two fields of view.
double fit_distance(double radius, double fov_y, double aspect);

// Builds the camera for `sphere`: `distance` <= 0 fits the sphere (with a small margin);
// near/far planes bracket the sphere. fov_deg is clamped to [1, 170] degrees and a degenerate
// sphere (radius 0) is treated as radius 1, so any input gives usable matrices.
Camera make_camera(const BoundingSphere& sphere, const Eigen::Quaterniond& orientation,
                   double distance, double fov_deg, double aspect,
                   double zoom = 1.0);

}  // namespace s4d
