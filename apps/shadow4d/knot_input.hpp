// What the knot commands (knot, explore) read from the command line: a curve and a view of it.
#pragma once
#include <string>

#include "core/frame.hpp"
#include "shape/curve.hpp"

namespace s4d::cli {

// A curve file, a generator call, or a scene: its curve objects together, as they are stored (a
// link when there are several; its surfaces are left out). Throws s4d::Error when there is none.
Curve<3> load_knot_curve(const std::string& spec);

// "xz=30,yz=10": plane rotations of R^3 in degrees, applied in order. Throws s4d::Error.
Frame<3> parse_view(const std::string& text);

}  // namespace s4d::cli
