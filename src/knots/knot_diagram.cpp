// The codes of a KnotDiagram (Gauss forms, PD), its writhe and linking numbers, crossing changes.
#include "knots/knot_diagram.hpp"

#include <algorithm>
#include <sstream>

#include "core/error.hpp"

namespace s4d {

// [SECTION] codes

int KnotDiagram::writhe() const {
  int w = 0;
  for (const auto& c : crossings) w += c.sign;
  return w;
}

std::vector<std::vector<int>> KnotDiagram::linking_numbers() const {
  const int m = component_count();
  std::vector<std::vector<int>> lk(m, std::vector<int>(m, 0));
  for (const auto& c : crossings) {
    const int i = passages[c.over].component, j = passages[c.under].component;
    if (i == j) continue;
    lk[i][j] += c.sign;
    lk[j][i] += c.sign;
  }
  // Each pair of components crosses an even number of times; the linking number is half the sum.
  for (auto& row : lk)
    for (auto& v : row) v /= 2;
  return lk;
}

namespace {
template <typename F>
std::string join_components(const KnotDiagram& d, F&& visit_text) {
  std::ostringstream out;
  for (std::size_t c = 0; c < d.components.size(); ++c) {
    if (c) out << " | ";
    bool first = true;
    for (int p : d.components[c]) {
      if (!first) out << ", ";
      out << visit_text(p);
      first = false;
    }
  }
  return out.str();
}

std::string signed_label(bool positive, int crossing) {
  std::string s = positive ? "" : "-";
  s += std::to_string(crossing + 1);
  return s;
}
}  // namespace

std::string KnotDiagram::gauss_code() const {
  return join_components(*this, [&](int p) {
    const auto& v = passages[p];
    return signed_label(v.over, v.crossing);
  });
}

std::string KnotDiagram::extended_gauss_code() const {
  std::vector<char> seen(crossings.size(), 0);
  return join_components(*this, [&](int p) {
    const auto& v = passages[p];
    bool positive;
    if (!seen[v.crossing]) {
      seen[v.crossing] = 1;
      positive = v.over;
    } else {
      positive = crossings[v.crossing].sign > 0;
    }
    return signed_label(positive, v.crossing);
  });
}

std::string KnotDiagram::signed_gauss_code() const {
  return join_components(*this, [&](int p) {
    const auto& v = passages[p];
    return std::to_string(v.crossing + 1) + (crossings[v.crossing].sign > 0 ? "+" : "-") +
           (v.over ? "a" : "b");
  });
}

std::vector<std::array<int, 4>> KnotDiagram::pd() const {
  std::vector<int> in_edge(passages.size()), out_edge(passages.size());
  int next = 1;
  for (const auto& comp : components) {
    const int m = static_cast<int>(comp.size());
    for (int k = 0; k < m; ++k) {
      out_edge[comp[k]] = next + k;                    // edge k leaves passage k
      in_edge[comp[(k + 1) % m]] = next + k;           // ... and enters passage k + 1
    }
    next += m;
  }
  std::vector<std::array<int, 4>> x;
  x.reserve(crossings.size());
  for (const auto& c : crossings) {
    // Counter-clockwise from the incoming under edge: a positive crossing meets the outgoing
    // over edge next, a negative one the incoming over edge.
    if (c.sign > 0)
      x.push_back({in_edge[c.under], out_edge[c.over], out_edge[c.under], in_edge[c.over]});
    else
      x.push_back({in_edge[c.under], in_edge[c.over], out_edge[c.under], out_edge[c.over]});
  }
  return x;
}

std::string KnotDiagram::pd_code() const {
  std::ostringstream out;
  out << "PD[";
  const auto x = pd();
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (i) out << ", ";
    out << "X[" << x[i][0] << ", " << x[i][1] << ", " << x[i][2] << ", " << x[i][3] << "]";
  }
  out << "]";
  return out.str();
}

KnotDiagram KnotDiagram::with_crossing_changed(int k) const {
  if (k < 0 || k >= crossing_count())
    throw Error("crossing " + std::to_string(k + 1) + " does not exist (the diagram has " +
                std::to_string(crossing_count()) + " crossings)");
  KnotDiagram d = *this;
  auto& c = d.crossings[k];
  std::swap(c.over, c.under);
  std::swap(c.depth_over, c.depth_under);
  d.passages[c.over].over = true;
  d.passages[c.under].over = false;
  c.sign = -c.sign;
  return d;
}

KnotDiagram KnotDiagram::with_component_reversed(int c) const {
  if (c < 0 || c >= component_count())
    throw Error("component " + std::to_string(c + 1) + " does not exist (the diagram has " +
                std::to_string(component_count()) + " components)");
  KnotDiagram d = *this;
  std::reverse(d.components[c].begin(), d.components[c].end());
  for (auto& x : d.crossings)
    if ((passages[x.over].component == c) != (passages[x.under].component == c)) x.sign = -x.sign;
  d.normalise();
  return d;
}

KnotDiagram KnotDiagram::mirrored() const {
  KnotDiagram d = *this;
  for (auto& c : d.crossings) {
    c.sign = -c.sign;
    std::swap(c.over, c.under);
    std::swap(c.depth_over, c.depth_under);
  }
  for (auto& p : d.passages) p.over = !p.over;
  return d;
}

void KnotDiagram::normalise() {
  std::vector<int> label(crossings.size(), -1);
  int next = 0;
  for (const auto& comp : components)
    for (int p : comp)
      if (label[passages[p].crossing] < 0) label[passages[p].crossing] = next++;
  std::vector<DiagramCrossing> sorted(crossings.size());
  for (std::size_t i = 0; i < crossings.size(); ++i) sorted[label[i]] = crossings[i];
  crossings = std::move(sorted);
  for (auto& p : passages) p.crossing = label[p.crossing];
}

}  // namespace s4d
