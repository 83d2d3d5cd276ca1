// Mirror, reverse and delete on the points themselves: no diagram is needed, so they work on any
// curve in any view, and a mirrored or reversed knot keeps its shape.
#include "knots/curve_edits.hpp"

#include <algorithm>
#include <string>

#include "core/error.hpp"

namespace s4d {

namespace {
void check_component(const Curve<3>& curve, int c, const char* what) {
  const int n = static_cast<int>(curve.components.size());
  if (c < 0 || c >= n)
    throw Error(std::string("cannot ") + what + " component " + std::to_string(c + 1) + ": the curve has " +
                std::to_string(n) + " component(s), numbered from 1");
}
}  // namespace

Curve<3> mirrored_curve(const Curve<3>& curve) {
  double lo = 0, hi = 0;
  bool any = false;
  for (const auto& p : curve.components)
    for (const Vec3& q : p.points) {
      lo = any ? std::min(lo, q.z()) : q.z();
      hi = any ? std::max(hi, q.z()) : q.z();
      any = true;
    }
  Curve<3> out = curve;
  for (auto& p : out.components)
    for (Vec3& q : p.points) q.z() = lo + hi - q.z();
  return out;
}

Curve<3> with_component_reversed(const Curve<3>& curve, int c) {
  check_component(curve, c, "reverse");
  Curve<3> out = curve;
  auto& pts = out.components[static_cast<std::size_t>(c)].points;
  std::reverse(pts.begin(), pts.end());
  return out;
}

Curve<3> with_component_deleted(const Curve<3>& curve, int c) {
  check_component(curve, c, "delete");
  if (curve.components.size() == 1) throw Error("cannot delete the only component: a knot needs a curve");
  Curve<3> out = curve;
  out.components.erase(out.components.begin() + c);
  return out;
}

}  // namespace s4d
