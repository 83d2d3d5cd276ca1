// The 4D chain (see chain.hpp).
#include "shape/chain.hpp"

#include "core/error.hpp"
#include "shape/ribbons.hpp"
#include "shape/surfaces_4d.hpp"

namespace s4d {

namespace {
void append(Surface<4>& to, const Surface<4>& from) {
  const int base = static_cast<int>(to.vertices.size());
  to.vertices.insert(to.vertices.end(), from.vertices.begin(), from.vertices.end());
  for (const Triangle& t : from.triangles) to.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
}
}  // namespace

Surface<4> chain(int links, int n) {
  if (links < 1) throw Error("chain: needs at least one link");
  if (n < 8) throw Error("chain: needs a resolution of at least 8");
  Surface<4> out;
  for (int k = 0; k < links; ++k) {
    const Vec4 centre(0.0, -k * kChainSpacing, 0.0, 0.0);
    if (k % 2 == 0) {
      append(out, uv_sphere<4>(n, kChainSphereRadius, centre));
    } else {
      // Across along x; around in the (y, w)-plane starting at the top (+y), through w > 0.
      append(out, ribbon_loop(centre, Vec4::UnitY(), Vec4::UnitW(), Vec4::UnitX(),
                              kChainSpacing - kChainLoopInset, kChainRibbonWidth, 2 * n, 2));
    }
  }
  return out;
}

}  // namespace s4d
