// The codes through Regina's readers (Link::fromPD, Link::fromDT, written after SnapPea's) where the
// build has Regina, else through the own readers (own_codes.hpp; no DT reader), with the spellings
// of the other sources turned into ones the readers take.
#include "knots/diagram_codes.hpp"

#include <cctype>

#include "core/error.hpp"
#include "knots/own_codes.hpp"
#include "knots/regina_engine.hpp"

namespace s4d {

KnotDiagram diagram_from_pd(const std::string& code) {
  std::string text = code;
  for (char& c : text)
    if (c == '{' || c == '}') c = ' ';
  bool any_digit = false;
  for (char c : text) any_digit = any_digit || std::isdigit(static_cast<unsigned char>(c));
  if (!any_digit) throw Error("a PD code needs crossings such as [[1,5,2,4],[3,1,4,6],[5,3,6,2]]; got '" + code + "'");
#if S4D_WITH_REGINA
  return regina_diagram_from_pd(text);
#else
  return diagram_from_pd_numbers(text);
#endif
}

KnotDiagram diagram_from_dt(const std::string& code) {
  // "DT[4, 6, 2]", "[4, 6, 2]", "(4,6,2)" and "4 6 2" are one code; letters alone are alphabetical.
  std::string text = code;
  if (const auto at = text.find("DT"); at != std::string::npos) text.erase(at, 2);
  for (char& c : text)
    if (c == ',' || c == '[' || c == ']' || c == '(' || c == ')' || c == '{' || c == '}') c = ' ';
  if (text.find_first_not_of(" \t\n") == std::string::npos)
    throw Error("a DT code needs even numbers such as \"4 6 2\" (or letters such as \"bca\"); got '" + code + "'");
#if S4D_WITH_REGINA
  return regina_diagram_from_dt(text);
#else
  throw Error("reading a DT code needs Regina, which this build lacks (a DT code leaves the embedding to be "
              "found); give the knot's PD code instead");
#endif
}

std::string pd_list(const KnotDiagram& diagram) {
  std::string s = "[";
  bool first = true;
  for (const auto& x : diagram.pd()) {
    s += std::string(first ? "" : ",") + "[" + std::to_string(x[0]) + "," + std::to_string(x[1]) + "," +
         std::to_string(x[2]) + "," + std::to_string(x[3]) + "]";
    first = false;
  }
  return s + "]";
}

std::string dt_code(const KnotDiagram& diagram) {
  if (diagram.component_count() != 1)
    throw Error("a DT code is written for knots; this diagram has " + std::to_string(diagram.component_count()) +
                " components (use its PD code)");
#if S4D_WITH_REGINA
  return regina_dt(diagram);
#else
  return dt_text(diagram, false);
#endif
}

}  // namespace s4d
