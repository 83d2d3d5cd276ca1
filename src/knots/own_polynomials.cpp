// The skein recursion: walk the components from their first visits; the first crossing met from
// below is switched (P+ = alpha^-2 P- + alpha^-1 z P0, P- = alpha^2 P+ - alpha z P0). Once every
// crossing is first met from above the diagram is descending, an unlink.
#include "knots/own_polynomials.hpp"

#include <numeric>
#include <unordered_map>

#include "core/error.hpp"

namespace s4d {

namespace {

Laurent2 monomial(long ea, long ez, std::int64_t c) {
  Laurent2 p;
  p.add(ea, ez, c);
  return p;
}

Laurent2 plus(const Laurent2& a, const Laurent2& b) {
  Laurent2 r = a;
  for (const auto& [e, c] : b.terms) r.add(e.first, e.second, c);
  return r;
}

// (alpha - alpha^-1) / z to the power m - 1.
Laurent2 unlink(int m) {
  Laurent2 r = monomial(0, 0, 1);
  const Laurent2 delta = plus(monomial(1, -1, 1), monomial(-1, -1, -1));
  for (int i = 1; i < m; ++i) r = r * delta;
  return r;
}

class Skein {
 public:
  Laurent2 operator()(GaussDiagram g) {
    reduce_r1_r2(g);
    if (g.crossings() == 0) return unlink(static_cast<int>(g.comps.size()));
    const std::string key = g.key();
    if (const auto it = memo_.find(key); it != memo_.end()) return it->second;
    const int bad = first_crossing_met_from_below(g);
    Laurent2 result;
    if (bad < 0) {
      result = unlink(static_cast<int>(g.comps.size()));
    } else {
      const int sign = g.sign[bad];
      GaussDiagram switched = g;
      switched.switch_crossing(bad);
      const Laurent2 p_switched = (*this)(std::move(switched));
      const Laurent2 p_smoothed = (*this)(g.smoothed(bad));
      if (sign > 0)
        result = plus(monomial(-2, 0, 1) * p_switched, monomial(-1, 1, 1) * p_smoothed);
      else
        result = plus(monomial(2, 0, 1) * p_switched, monomial(1, 1, -1) * p_smoothed);
    }
    memo_.emplace(key, result);
    return result;
  }

 private:
  static int first_crossing_met_from_below(const GaussDiagram& g) {
    std::vector<char> seen(g.sign.size(), 0);
    for (const auto& comp : g.comps)
      for (const GaussVisit& v : comp) {
        if (seen[v.crossing]) continue;
        if (!v.over) return v.crossing;
        seen[v.crossing] = 1;
      }
    return -1;
  }

  std::unordered_map<std::string, Laurent2> memo_;
};

Laurent1 times(const Laurent1& a, const Laurent1& b) {
  Laurent1 r;
  for (const auto& [ea, ca] : a.terms)
    for (const auto& [eb, cb] : b.terms) r.add(ea + eb, ca * cb);
  return r;
}

}  // namespace

Laurent2 homfly_polynomial(const GaussDiagram& diagram) { return Skein{}(diagram); }
Laurent2 homfly_polynomial(const KnotDiagram& diagram) { return homfly_polynomial(GaussDiagram::of(diagram)); }

Laurent1 jones_from_homfly(const Laurent2& homfly, int components) {
  // alpha = s^-2, z = s - s^-1; multiply through by z^(m-1) first so every power of z is >= 0.
  const int shift = std::max(0, components - 1);
  Laurent1 z;
  z.add(1, 1);
  z.add(-1, -1);
  Laurent1 sum;
  for (const auto& [e, c] : homfly.terms) {
    const long zpow = e.second + shift;
    if (zpow < 0) throw Error("HOMFLY-PT has a power of z below -(components - 1)");
    Laurent1 term;
    term.add(-2 * e.first, c);
    for (long i = 0; i < zpow; ++i) term = times(term, z);
    for (const auto& [k, v] : term.terms) sum.add(k, v);
  }
  // Divide by (s - s^-1) `shift` times: f = (s - s^-1) g gives g_(e-1) = f_e + g_(e+1), from the top.
  for (int i = 0; i < shift && !sum.is_zero(); ++i) {
    const long top = sum.terms.rbegin()->first, bottom = sum.terms.begin()->first;
    Laurent1 g;
    for (long e = top; e > bottom; --e) g.add(e - 1, sum.coeff(e) + g.coeff(e + 1));
    if (!(times(g, z) == sum)) throw Error("HOMFLY-PT does not give an integral Jones polynomial");
    sum = g;
  }
  return sum;
}

Laurent1 jones_by_state_sum(const KnotDiagram& d) {
  const int n = d.crossing_count();
  if (n > 24) throw Error("the Kauffman bracket state sum is limited to 24 crossings");
  // Edges: edge p leaves passage p. Each crossing joins the four edge ends of its two passages.
  std::vector<int> in_edge(d.passages.size());
  for (const auto& comp : d.components)
    for (std::size_t i = 0; i < comp.size(); ++i) in_edge[comp[(i + 1) % comp.size()]] = comp[i];
  int free_circles = 0;
  for (const auto& comp : d.components) free_circles += comp.empty();
  // The ends of crossing k, counter-clockwise: a = under in, b, c = under out, d (as pd()).
  struct Ends {
    int a, b, c, d;
  };
  std::vector<Ends> ends;
  for (const auto& x : d.crossings) {
    const int ui = in_edge[x.under], uo = x.under, oi = in_edge[x.over], oo = x.over;
    ends.push_back(x.sign > 0 ? Ends{ui, oo, uo, oi} : Ends{ui, oi, uo, oo});
  }
  // The A-smoothing joins the regions swept counter-clockwise from the incoming under strand:
  // (a, b) and (c, d); the B-smoothing (a, d) and (b, c).
  const int edges = static_cast<int>(d.passages.size());
  std::map<long, std::int64_t> bracket;  // in A
  std::vector<int> parent(edges);
  for (std::uint64_t state = 0; state < (std::uint64_t{1} << n); ++state) {
    std::iota(parent.begin(), parent.end(), 0);
    auto root = [&](int i) {
      while (parent[i] != i) i = parent[i] = parent[parent[i]];
      return i;
    };
    auto join = [&](int x, int y) { parent[root(x)] = root(y); };
    int a_count = 0;
    for (int k = 0; k < n; ++k) {
      const Ends& e = ends[k];
      if ((state >> k) & 1) {
        join(e.a, e.d);
        join(e.b, e.c);
      } else {
        ++a_count;
        join(e.a, e.b);
        join(e.c, e.d);
      }
    }
    int loops = free_circles;
    for (int i = 0; i < edges; ++i) loops += root(i) == i;
    // A^(a - b) (-A^2 - A^-2)^(loops - 1)
    std::map<long, std::int64_t> term{{a_count - (n - a_count), 1}};
    for (int l = 1; l < loops; ++l) {
      std::map<long, std::int64_t> next;
      for (const auto& [e, c] : term) {
        next[e + 2] -= c;
        next[e - 2] -= c;
      }
      term = std::move(next);
    }
    for (const auto& [e, c] : term) bracket[e] += c;
  }
  // V = (-A^3)^(-w) <D>, A = t^(-1/4) = s^(-1/2): A^e = s^(-e/2); every exponent is even then.
  const int w = d.writhe();
  Laurent1 v;
  const std::int64_t sign = (w % 2 == 0) ? 1 : -1;
  for (const auto& [e, c] : bracket) {
    if (c == 0) continue;
    const long ea = e - 3L * w;
    if (ea % 2 != 0) throw Error("the Kauffman bracket has an odd power of A: an inconsistent diagram");
    v.add(-ea / 2, sign * c);
  }
  return v;
}

}  // namespace s4d
