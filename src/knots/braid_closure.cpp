// Braid closures: strands on concentric circles; a letter swaps two neighbouring circles while the
// two strands pass above and below each other.
#include "knots/braid_closure.hpp"

#include <cmath>
#include <fstream>
#include <sstream>
#include <numbers>
#include <string>

#include "core/error.hpp"

namespace s4d {

Curve<3> braid_closure(int strands, const std::vector<int>& word, int samples) {
  if (strands < 1) throw Error("a braid needs at least one strand");
  for (int g : word)
    if (g == 0 || std::abs(g) >= strands)
      throw Error("braid generator " + std::to_string(g) + " does not exist on " +
                  std::to_string(strands) + " strands");
  if (samples < 3) samples = 3;
  if (samples % 2 == 0) ++samples;  // the crossing then falls mid-segment, never on a vertex

  // One slot per letter plus a quiet one, so that even the empty word closes up properly.
  const int slots = static_cast<int>(word.size()) + 1;
  const double radius0 = 2.0, gap = 1.0, height = 0.4;
  auto radius_of = [&](double position) { return radius0 + gap * position; };

  Curve<3> curve;
  std::vector<char> used(strands, 0);
  for (int start = 0; start < strands; ++start) {
    if (used[start]) continue;
    Polyline<3> pl;
    pl.closed = true;
    int pos = start;
    do {
      used[pos] = 1;
      for (int k = 0; k < slots; ++k) {
        const int g = k < static_cast<int>(word.size()) ? word[k] : 0;
        const int lo = std::abs(g) - 1;  // the letter swaps positions lo and lo + 1
        int next = pos;
        double z_sign = 0;
        if (g != 0 && (pos == lo || pos == lo + 1)) {
          next = pos == lo ? lo + 1 : lo;
          // Seen from +z with strands running counter-clockwise, the strand moving outwards
          // crosses from right to left of the inward one: over for a positive letter.
          const bool outward = next > pos;
          z_sign = (outward == (g > 0)) ? 1.0 : -1.0;
        }
        for (int i = 0; i < samples; ++i) {
          const double s = static_cast<double>(i) / samples;  // [0, 1) within the slot
          const double theta = 2 * std::numbers::pi * (k + s) / slots;
          const double blend = s * s * (3 - 2 * s);           // smooth step
          const double r = radius_of(pos + (next - pos) * blend);
          const double z = z_sign * height * std::sin(std::numbers::pi * s);
          pl.points.emplace_back(r * std::cos(theta), r * std::sin(theta), z);
        }
        pos = next;
      }
    } while (pos != start);
    curve.components.push_back(std::move(pl));
  }
  return curve;
}

KnotDiagram braid_diagram(int strands, const std::vector<int>& word) {
  if (strands < 1) throw Error("a braid needs at least one strand");
  for (int g : word)
    if (g == 0 || std::abs(g) >= strands)
      throw Error("braid generator " + std::to_string(g) + " does not exist on " +
                  std::to_string(strands) + " strands");
  KnotDiagram d;
  d.crossings.resize(word.size());
  const int slots = static_cast<int>(word.size()) + 1;
  std::vector<char> used(strands, 0);
  for (int start = 0; start < strands; ++start) {
    if (used[start]) continue;
    const int comp = d.component_count();
    d.components.emplace_back();
    int pos = start, turn = 0;
    do {
      used[pos] = 1;
      for (int k = 0; k < static_cast<int>(word.size()); ++k) {
        const int g = word[k], lo = std::abs(g) - 1;
        if (pos != lo && pos != lo + 1) continue;
        const int next = pos == lo ? lo + 1 : lo;
        const bool over = (next > pos) == (g > 0);  // as in braid_closure
        const int p = static_cast<int>(d.passages.size());
        d.passages.push_back({k, over, comp, static_cast<double>(turn * slots + k) + 0.5});
        d.components.back().push_back(p);
        (over ? d.crossings[k].over : d.crossings[k].under) = p;
        d.crossings[k].sign = g > 0 ? 1 : -1;
        pos = next;
      }
      ++turn;
    } while (pos != start);
  }
  d.normalise();
  return d;
}

std::vector<BraidWord> load_braid_table(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error("cannot read the braid table " + path);
  std::vector<BraidWord> table;
  std::string line;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    BraidWord b;
    if (!(fields >> b.name >> b.strands) || b.strands < 1)
      throw ParseError(path, line_no, "expected: name strands generators...");
    int g;
    while (fields >> g) {
      if (g == 0 || std::abs(g) >= b.strands)
        throw ParseError(path, line_no, "generator " + std::to_string(g) + " is out of range");
      b.word.push_back(g);
    }
    if (!fields.eof()) throw ParseError(path, line_no, "a generator is not an integer");
    table.push_back(std::move(b));
  }
  return table;
}

Curve<3> torus_braid_closure(int p, int q, int samples) {
  if (std::abs(p) < 2 || q == 0) throw Error("a torus knot T(p, q) needs |p| >= 2 and q != 0");
  const int n = std::abs(p);
  std::vector<int> word;
  for (int r = 0; r < std::abs(q); ++r)
    for (int i = 1; i < n; ++i) word.push_back((q > 0) == (p > 0) ? i : -i);
  return braid_closure(n, word, samples);
}

}  // namespace s4d
