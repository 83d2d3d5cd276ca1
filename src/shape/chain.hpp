// A 4D chain: 2-spheres and ribbon loops, alternately linked, hanging down the y axis.
#pragma once
#include "shape/surface.hpp"

namespace s4d {

// Element k (k = 0 .. links-1) is centred at (0, -k·kChainSpacing, 0, 0): even k a round
// 2-sphere of radius kChainSphereRadius in the hyperplane w = 0, odd k a ribbon loop whose core
// circle lies in the plane spanned by y and w. That circle crosses w = 0 twice, once inside the
// ball of the sphere above and once inside the ball of the sphere below, which is how a circle
// links a 2-sphere in R^4. The loops are kept short of the spheres' centres so that consecutive
// loops never meet. n is the resolution of each element. One Surface, one component per element.
Surface<4> chain(int links, int n);

inline constexpr double kChainSpacing = 1.0;
inline constexpr double kChainSphereRadius = 0.5;
inline constexpr double kChainLoopInset = 0.2;   // the loop stops this far short of each centre
inline constexpr double kChainRibbonWidth = 0.2;

}  // namespace s4d
