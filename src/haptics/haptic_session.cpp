// The demo hand path.
#include "haptics/haptic_session.hpp"

#include <algorithm>
#include <cmath>

namespace s4d {

Vec3 demo_hand_path(double t, const Vec3& start, double press) {
  const double r = 0.02, w = 2 * M_PI * 0.5;
  const double pressing = std::min(1.0, t / 0.3);  // press in over 0.3 s, then circle
  const double tt = std::max(0.0, t - 0.3);
  return start + Vec3(r * (std::cos(w * tt) - 1), r * std::sin(w * tt), -press * pressing);
}

}  // namespace s4d
