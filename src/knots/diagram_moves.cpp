// Reidemeister moves on Gauss diagrams. Faces are traced in the rotation system the signs define:
// counter-clockwise at a positive crossing the half-edges are (under in, over out, under out,
// over in), at a negative one (under in, over in, under out, over out), as in KnotDiagram::pd.
// Sections: [SECTION] the diagram, [SECTION] faces, [SECTION] moves, [SECTION] simplification.
#include "knots/diagram_moves.hpp"

#include <algorithm>
#include <random>

namespace s4d {

// [SECTION] the diagram

GaussDiagram GaussDiagram::of(const KnotDiagram& d) {
  GaussDiagram g;
  for (const auto& c : d.crossings) g.sign.push_back(c.sign);
  for (const auto& comp : d.components) {
    std::vector<GaussVisit> visits;
    for (int p : comp) visits.push_back({d.passages[p].crossing, d.passages[p].over});
    g.comps.push_back(std::move(visits));
  }
  return g;
}

KnotDiagram GaussDiagram::diagram() const {
  KnotDiagram d;
  d.crossings.resize(sign.size());
  for (std::size_t k = 0; k < sign.size(); ++k) d.crossings[k].sign = sign[k];
  for (std::size_t c = 0; c < comps.size(); ++c) {
    std::vector<int> comp;
    for (const GaussVisit& v : comps[c]) {
      const int p = static_cast<int>(d.passages.size());
      d.passages.push_back({v.crossing, v.over, static_cast<int>(c), 0.0});
      (v.over ? d.crossings[v.crossing].over : d.crossings[v.crossing].under) = p;
      comp.push_back(p);
    }
    d.components.push_back(std::move(comp));
  }
  d.normalise();
  return d;
}

std::string GaussDiagram::key() const {
  std::vector<int> label(sign.size(), -1);
  int next = 0;
  std::string k;
  k.reserve(4 * sign.size() + comps.size() + 2);
  for (const auto& comp : comps) {
    k += '|';
    for (const GaussVisit& v : comp) {
      if (label[v.crossing] < 0) label[v.crossing] = next++;
      const int l = label[v.crossing];
      k += static_cast<char>('0' + (l & 63));
      k += static_cast<char>('0' + (l >> 6));
      k += static_cast<char>((v.over ? 'A' : 'a') + (sign[v.crossing] > 0 ? 1 : 0));
    }
  }
  return k;
}

void GaussDiagram::remove_crossings(const std::vector<char>& gone) {
  std::vector<int> label(sign.size(), -1);
  std::vector<int> kept_sign;
  for (auto& comp : comps) {
    std::vector<GaussVisit> kept;
    for (const GaussVisit& v : comp) {
      if (gone[v.crossing]) continue;
      if (label[v.crossing] < 0) {
        label[v.crossing] = static_cast<int>(kept_sign.size());
        kept_sign.push_back(sign[v.crossing]);
      }
      kept.push_back({label[v.crossing], v.over});
    }
    comp = std::move(kept);
  }
  sign = std::move(kept_sign);
}

void GaussDiagram::switch_crossing(int k) {
  sign[k] = -sign[k];
  for (auto& comp : comps)
    for (GaussVisit& v : comp)
      if (v.crossing == k) v.over = !v.over;
}

GaussDiagram GaussDiagram::smoothed(int k) const {
  int co = -1, io = -1, cu = -1, iu = -1;
  for (std::size_t c = 0; c < comps.size(); ++c)
    for (std::size_t i = 0; i < comps[c].size(); ++i)
      if (comps[c][i].crossing == k) {
        (comps[c][i].over ? co : cu) = static_cast<int>(c);
        (comps[c][i].over ? io : iu) = static_cast<int>(i);
      }
  GaussDiagram g;
  g.sign = sign;
  // The run of component c strictly after position `from` up to strictly before `to`, cyclically.
  auto run = [&](int c, int from, int to, std::vector<GaussVisit>& out) {
    const int m = static_cast<int>(comps[c].size());
    for (int i = (from + 1) % m; i != to; i = (i + 1) % m) out.push_back(comps[c][i]);
  };
  for (int c = 0; c < static_cast<int>(comps.size()); ++c) {
    if (c == cu && c != co) continue;
    if (c != co) {
      g.comps.push_back(comps[c]);
      continue;
    }
    std::vector<GaussVisit> a, b;
    if (co == cu) {
      // Arriving along the over strand the walk leaves along the under strand, and vice versa.
      run(c, io, iu, a);
      run(c, iu, io, b);
      g.comps.push_back(std::move(a));
      g.comps.push_back(std::move(b));
    } else {
      run(co, io, io, a);
      run(cu, iu, iu, a);
      g.comps.push_back(std::move(a));
    }
  }
  std::vector<char> gone(sign.size(), 0);
  gone[k] = 1;
  g.remove_crossings(gone);
  return g;
}

// [SECTION] faces

namespace {

struct EdgeRef {
  int comp = 0, pos = 0;  // the edge leaving visit `pos` of component `comp`
};

struct Faces {
  std::vector<std::vector<EdgeRef>> faces;  // each face as the edges along its boundary
};

Faces trace_faces(const GaussDiagram& g) {
  const int n = g.crossings();
  // Per crossing, counter-clockwise slots: the edge there and whether the edge leaves the crossing.
  struct Slot {
    EdgeRef edge;
    bool leaves = false;
  };
  std::vector<std::array<Slot, 4>> slots(n);
  for (int c = 0; c < static_cast<int>(g.comps.size()); ++c) {
    const int m = static_cast<int>(g.comps[c].size());
    for (int i = 0; i < m; ++i) {
      const GaussVisit& v = g.comps[c][i];
      const bool pos = g.sign[v.crossing] > 0;
      const int in_slot = v.over ? (pos ? 3 : 1) : 0;
      const int out_slot = v.over ? (pos ? 1 : 3) : 2;
      slots[v.crossing][in_slot] = {{c, (i + m - 1) % m}, false};
      slots[v.crossing][out_slot] = {{c, i}, true};
    }
  }
  // Where each edge ends: (crossing, slot) at its start and at its end.
  auto other_end = [&](int k, int s) {
    const Slot& sl = slots[k][s];
    const auto& comp = g.comps[sl.edge.comp];
    const int m = static_cast<int>(comp.size());
    const GaussVisit& far = sl.leaves ? comp[(sl.edge.pos + 1) % m] : comp[sl.edge.pos];
    for (int t = 0; t < 4; ++t) {
      const Slot& o = slots[far.crossing][t];
      if (o.edge.comp == sl.edge.comp && o.edge.pos == sl.edge.pos && o.leaves != sl.leaves &&
          (far.crossing != k || t != s))
        return std::make_pair(far.crossing, t);
    }
    return std::make_pair(k, s);  // unreachable for a consistent diagram
  };
  Faces f;
  std::vector<std::array<char, 4>> used(n, {0, 0, 0, 0});
  for (int k = 0; k < n; ++k)
    for (int s = 0; s < 4; ++s) {
      if (used[k][s]) continue;
      std::vector<EdgeRef> face;
      int x = k, t = s;
      while (!used[x][t] && face.size() <= static_cast<std::size_t>(4 * n)) {
        used[x][t] = 1;
        face.push_back(slots[x][t].edge);
        const auto [y, u] = other_end(x, t);
        x = y;
        t = (u + 1) % 4;
      }
      f.faces.push_back(std::move(face));
    }
  return f;
}

const GaussVisit& at(const GaussDiagram& g, const EdgeRef& e, int step) {
  const auto& comp = g.comps[e.comp];
  return comp[(e.pos + step) % comp.size()];
}

}  // namespace

// [SECTION] moves

bool remove_r1(GaussDiagram& g) {
  for (const auto& comp : g.comps) {
    const std::size_t m = comp.size();
    for (std::size_t i = 0; i < m; ++i)
      if (comp[i].crossing == comp[(i + 1) % m].crossing) {
        std::vector<char> gone(g.sign.size(), 0);
        gone[comp[i].crossing] = 1;
        g.remove_crossings(gone);
        return true;
      }
  }
  return false;
}

bool remove_r2(GaussDiagram& g) {
  if (g.crossings() < 2) return false;
  for (const auto& face : trace_faces(g).faces) {
    if (face.size() != 2) continue;
    const GaussVisit &a0 = at(g, face[0], 0), &a1 = at(g, face[0], 1);
    if (a0.crossing == a1.crossing || a0.over != a1.over) continue;
    if (g.sign[a0.crossing] == g.sign[a1.crossing]) continue;
    std::vector<char> gone(g.sign.size(), 0);
    gone[a0.crossing] = gone[a1.crossing] = 1;
    g.remove_crossings(gone);
    return true;
  }
  return false;
}

void reduce_r1_r2(GaussDiagram& g) {
  while (remove_r1(g) || remove_r2(g)) {
  }
}

std::vector<R3Move> r3_moves(const GaussDiagram& g) {
  std::vector<R3Move> out;
  if (g.crossings() < 3) return out;
  for (const auto& face : trace_faces(g).faces) {
    if (face.size() != 3) continue;
    bool top = false;
    std::array<int, 3> ks{};
    R3Move m;
    for (int i = 0; i < 3; ++i) {
      const GaussVisit &s = at(g, face[i], 0), &e = at(g, face[i], 1);
      top = top || (s.over && e.over);
      ks[i] = s.crossing;
      m.edges[i] = {face[i].comp, face[i].pos};
    }
    if (top && ks[0] != ks[1] && ks[1] != ks[2] && ks[0] != ks[2]) out.push_back(m);
  }
  return out;
}

void apply_r3(GaussDiagram& g, const R3Move& move) {
  for (const auto& [c, i] : move.edges) {
    auto& comp = g.comps[c];
    std::swap(comp[i], comp[(i + 1) % comp.size()]);
  }
}

// [SECTION] simplification

GaussDiagram simplify_gauss(GaussDiagram g, const SimplifyOptions& options) {
  reduce_r1_r2(g);
  std::mt19937_64 rng(options.seed);
  GaussDiagram best = g;
  for (int attempt = 0; attempt < options.attempts && best.crossings() > 2; ++attempt) {
    GaussDiagram h = best;
    const int steps = options.walk_length > 0 ? options.walk_length : 3 * h.crossings();
    for (int s = 0; s < steps; ++s) {
      const auto moves = r3_moves(h);
      if (moves.empty()) break;
      apply_r3(h, moves[std::uniform_int_distribution<std::size_t>(0, moves.size() - 1)(rng)]);
      reduce_r1_r2(h);
      if (h.crossings() < best.crossings()) {
        best = h;
        attempt = -1;  // a fresh budget from the smaller diagram
        break;
      }
    }
  }
  return best;
}

KnotDiagram simplify_diagram(const KnotDiagram& d, const SimplifyOptions& options) {
  return simplify_gauss(GaussDiagram::of(d), options).diagram();
}

bool is_alternating(const KnotDiagram& d) {
  for (const auto& comp : d.components)
    for (std::size_t i = 0; i < comp.size(); ++i)
      if (d.passages[comp[i]].over == d.passages[comp[(i + 1) % comp.size()]].over) return false;
  return true;
}

int diagram_pieces(const KnotDiagram& d) {
  std::vector<int> parent(d.components.size());
  for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = static_cast<int>(i);
  auto root = [&](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (const auto& c : d.crossings) parent[root(d.passages[c.over].component)] = root(d.passages[c.under].component);
  int pieces = 0;
  for (std::size_t i = 0; i < parent.size(); ++i) pieces += root(static_cast<int>(i)) == static_cast<int>(i);
  return pieces;
}

}  // namespace s4d
