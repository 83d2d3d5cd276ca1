// Diagram codes without Regina: Regina's knot signatures (the knot index's `sig` column) read into
// a diagram, PD codes read, and the Gauss, oriented Gauss and DT texts Regina writes, written in
// the same conventions (held equal to Regina's in the tests).
#pragma once
#include <string>

#include "knots/knot_diagram.hpp"

namespace s4d {

// Regina's knot signature (Link::knotSig): in base64 digits (a-z, A-Z, 0-9, +, -), the crossing
// count n (or 63, digits per number, n), the 2n crossings met along the knot, then the 2n
// "passes over" bits and the 2n "positive crossing" bits, six to a digit, lowest bit first.
// Throws Error for a malformed signature.
KnotDiagram diagram_from_knot_sig(const std::string& sig);

// A PD code's numbers, four to a crossing (i the incoming under edge, then counter-clockwise);
// components take the direction of their under strands, else of their edge numbers.
KnotDiagram diagram_from_pd_numbers(const std::string& text);

// Regina's text forms for a knot's diagram (crossings labelled by their index + 1, starting at
// the first passage): "1 -2 3 -1 2 -3", "+>1 -<2 ...", "4 6 2", "bca". Empty for a link (and the
// DT forms for a diagram without crossings, the alphabetical one beyond 26 crossings).
std::string gauss_text(const KnotDiagram& d);
std::string oriented_gauss_text(const KnotDiagram& d);
std::string dt_text(const KnotDiagram& d, bool alphabetical);

}  // namespace s4d

namespace s4d {

// Regina's knot signature of a knot diagram (Link::knotSig(reflection, true)): the least traversal
// over every start, direction, turning over and (when `reflection`) mirror image, in Regina's
// text. Equal signatures: the same diagram up to those symmetries. Error for a link.
std::string knot_sig(const KnotDiagram& d, bool reflection = true);

}  // namespace s4d
