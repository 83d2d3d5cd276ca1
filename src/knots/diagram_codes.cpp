// The codes through Regina's readers (Link::fromPD, Link::fromDT, written after SnapPea's), with
// the spellings of the other sources turned into ones Regina takes.
#include "knots/diagram_codes.hpp"

#include <cctype>

#include "core/error.hpp"
#include "knots/regina_link.hpp"

namespace s4d {

KnotDiagram diagram_from_pd(const std::string& code) {
  std::string text = code;
  for (char& c : text)
    if (c == '{' || c == '}') c = ' ';
  bool any_digit = false;
  for (char c : text) any_digit = any_digit || std::isdigit(static_cast<unsigned char>(c));
  if (!any_digit) throw Error("a PD code needs crossings such as [[1,5,2,4],[3,1,4,6],[5,3,6,2]]; got '" + code + "'");
  try {
    return diagram_from_regina(regina::Link::fromPD(text));
  } catch (const regina::InvalidArgument& e) {
    throw Error("not a PD code of a knot or link ('" + code + "'): " + e.what());
  }
}

KnotDiagram diagram_from_dt(const std::string& code) {
  // "DT[4, 6, 2]", "[4, 6, 2]", "(4,6,2)" and "4 6 2" are one code; letters alone are alphabetical.
  std::string text = code;
  if (const auto at = text.find("DT"); at != std::string::npos) text.erase(at, 2);
  for (char& c : text)
    if (c == ',' || c == '[' || c == ']' || c == '(' || c == ')' || c == '{' || c == '}') c = ' ';
  if (text.find_first_not_of(" \t\n") == std::string::npos)
    throw Error("a DT code needs even numbers such as \"4 6 2\" (or letters such as \"bca\"); got '" + code + "'");
  try {
    return diagram_from_regina(regina::Link::fromDT(text));
  } catch (const regina::InvalidArgument& e) {
    throw Error("not a DT code of a knot ('" + code + "'): " + e.what());
  }
}

KnotDiagram diagram_from_knot_sig(const std::string& sig) {
  try {
    return diagram_from_regina(regina::Link::fromKnotSig(sig));
  } catch (const regina::InvalidArgument& e) {
    throw Error("not a knot signature ('" + sig + "'): " + e.what());
  }
}

std::string dt_code(const KnotDiagram& diagram) {
  if (diagram.component_count() != 1)
    throw Error("a DT code is written for knots; this diagram has " + std::to_string(diagram.component_count()) +
                " components (use its PD code)");
  return to_regina_link(diagram).dt(false);
}

}  // namespace s4d
