// Test-only references that share no code with src/proximity: brute-force closest points (dense
// barycentric sampling refined by accelerated projected gradient) and random configurations.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <random>
#include <vector>

#include "core/vec.hpp"

namespace s4d::test {

// Euclidean projection onto the probability simplex {w >= 0, sum w = 1} (sort-based).
template <int K>
std::array<double, K> project_simplex(std::array<double, K> v) {
  std::array<double, K> u = v;
  std::sort(u.begin(), u.end(), std::greater<>());
  double css = 0, theta = 0;
  for (int i = 0; i < K; ++i) {
    css += u[i];
    const double t = (css - 1) / (i + 1);
    if (u[i] - t > 0) theta = t;
  }
  for (double& x : v) x = std::max(x - theta, 0.0);
  return v;
}

template <int D, int K>
Vec<D> combine(const std::array<Vec<D>, K>& s, const std::array<double, K>& w) {
  Vec<D> p = Vec<D>::Zero();
  for (int i = 0; i < K; ++i) p += w[i] * s[i];
  return p;
}

// Barycentric sample points of a K-simplex on a regular lattice with n steps per edge.
template <int K>
std::vector<std::array<double, K>> lattice(int n) {
  std::vector<std::array<double, K>> out;
  if constexpr (K == 1) {
    out.push_back({1.0});
  } else if constexpr (K == 2) {
    for (int i = 0; i <= n; ++i) out.push_back({1.0 - double(i) / n, double(i) / n});
  } else {
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j)
        out.push_back({1.0 - double(i + j) / n, double(i) / n, double(j) / n});
  }
  return out;
}

// Minimum distance between two simplices: dense sampling, then FISTA on the barycentric weights
// of both, restarted from the best iterate (the function is convex, so this converges).
template <int D, int KA, int KB>
double brute_force_distance(std::array<Vec<D>, KA> A, std::array<Vec<D>, KB> B) {
  // Distances do not change under translation; centring keeps the gradient step well scaled.
  const Vec<D> origin = A[0];
  for (auto& v : A) v -= origin;
  for (auto& v : B) v -= origin;
  const int n = KA == 3 && KB == 3 ? 12 : 24;
  const auto la = lattice<KA>(n);
  const auto lb = lattice<KB>(n);
  double best = std::numeric_limits<double>::infinity();
  std::array<double, KA> wa{};
  std::array<double, KB> wb{};
  for (const auto& a : la) {
    const Vec<D> p = combine<D, KA>(A, a);
    for (const auto& b : lb) {
      const double d = (p - combine<D, KB>(B, b)).squaredNorm();
      if (d < best) best = d, wa = a, wb = b;
    }
  }
  // Lipschitz constant of the gradient: 2 * largest eigenvalue of M^T M <= 2 * trace.
  double lip = 0;
  for (const auto& v : A) lip += v.squaredNorm();
  for (const auto& v : B) lip += v.squaredNorm();
  lip = 2 * std::max(lip, 1e-300);
  for (int restart = 0; restart < 6; ++restart) {
    std::array<double, KA> xa = wa, ya = wa;
    std::array<double, KB> xb = wb, yb = wb;
    double tk = 1;
    for (int it = 0; it < 4000; ++it) {
      const Vec<D> r = combine<D, KA>(A, ya) - combine<D, KB>(B, yb);
      std::array<double, KA> na;
      std::array<double, KB> nb;
      for (int i = 0; i < KA; ++i) na[i] = ya[i] - 2 * A[i].dot(r) / lip;
      for (int j = 0; j < KB; ++j) nb[j] = yb[j] + 2 * B[j].dot(r) / lip;
      na = project_simplex<KA>(na);
      nb = project_simplex<KB>(nb);
      const double tn = 0.5 * (1 + std::sqrt(1 + 4 * tk * tk));
      for (int i = 0; i < KA; ++i) ya[i] = na[i] + (tk - 1) / tn * (na[i] - xa[i]);
      for (int j = 0; j < KB; ++j) yb[j] = nb[j] + (tk - 1) / tn * (nb[j] - xb[j]);
      ya = project_simplex<KA>(ya);
      yb = project_simplex<KB>(yb);
      xa = na;
      xb = nb;
      tk = tn;
      const double d = (combine<D, KA>(A, xa) - combine<D, KB>(B, xb)).squaredNorm();
      if (d < best) best = d, wa = xa, wb = xb;
    }
  }
  return std::sqrt(best);
}

// First-order optimality gap of a candidate pair (p on A, q on B): an upper bound on
// |p - q|^2 - min^2, exact for this convex problem. Zero (to rounding) iff the pair is optimal.
template <int D, int KA, int KB>
double optimality_gap(const std::array<Vec<D>, KA>& A, const std::array<Vec<D>, KB>& B,
                      const Vec<D>& p, const Vec<D>& q) {
  const Vec<D> g = 2 * (p - q);
  double ga = 0, gb = 0;
  for (const auto& a : A) ga = std::max(ga, -(a - p).dot(g));
  for (const auto& b : B) gb = std::max(gb, (b - q).dot(g));
  return ga + gb;
}

template <int D>
Mat<D> random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> n(0, 1);
  Mat<D> m;
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) m(i, j) = n(rng);
  Eigen::HouseholderQR<Mat<D>> qr(m);
  Mat<D> q = qr.householderQ();
  if (q.determinant() < 0) q.col(0) *= -1;
  return q;
}

template <int D>
Vec<D> random_vec(std::mt19937& rng, double scale = 1) {
  std::uniform_real_distribution<double> u(-scale, scale);
  Vec<D> v;
  for (int i = 0; i < D; ++i) v[i] = u(rng);
  return v;
}

// The triangles of an n × n grid of vertices (vertex (i, j) is i·n + j), two a square.
inline std::vector<std::array<int, 3>> grid_cells(int n) {
  std::vector<std::array<int, 3>> cells;
  for (int i = 0; i + 1 < n; ++i)
    for (int j = 0; j + 1 < n; ++j) {
      const int a = i * n + j;
      cells.push_back({a, a + 1, a + n + 1});
      cells.push_back({a, a + n + 1, a + n});
    }
  return cells;
}

}  // namespace s4d::test
