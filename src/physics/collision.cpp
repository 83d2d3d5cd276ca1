// Repulsion impulses with friction, the paper's closest-point displacement, and the continuous
// fail-safe that guarantees separated end states (see collision.hpp for the scheme).
#include "physics/collision.hpp"

#include <algorithm>
#include <cmath>

#include "proximity/closest_points.hpp"
#include "proximity/continuous_collision.hpp"
#include "proximity/separating_axes.hpp"

namespace s4d {

namespace {

// The share of the gap to δ closed per step by the paper's displacement: a full correction in one
// step would turn a resting contact into a jitter.
constexpr double kPushFraction = 0.5;
// Pairs are gathered a little beyond δ so that one approaching within the step is seen in time.
constexpr double kGatherFactor = 1.5;
// The proximity list reaches (1 + skin) × the gather distance. Measured on the crumpled 64² cloth
// (instructions a step under callgrind, steps 611-710 of bench/physics_bench's scene): skin 0.35
// → 8.68 M, 0.5 → 8.50 M, 0.75 → 9.66 M; a wider list costs more to build than its rarer rebuilds
// save.
constexpr double kProximitySkin = 0.5;
// Cap of the continuous test's iterations per pair (see failsafe_pass).
constexpr int kCcdIterations = 24;

template <int D, int K>
Simplex<D, K> gather(std::span<const Vec<D>> x, const std::array<int, K>& c) {
  Simplex<D, K> s;
  for (int q = 0; q < K; ++q) s[q] = x[c[q]];
  return s;
}

// The model's cells of this solver's kind.
template <int D, int K>
const std::vector<std::array<int, K>>& cells_of(const Model<D>& model) {
  if constexpr (K == 3) return model.triangles;
  else return model.segments;
}

}  // namespace

template <int D, int K>
CollisionSolver<D, K>::CollisionSolver(const Model<D>& model)
    : prox_(std::vector<Cell<K>>(cells_of<D, K>(model).begin(), cells_of<D, K>(model).end())) {
  hit_.assign(model.nv, 0);
  w_.assign(model.nv, 0.0);
  kick_.assign(model.nv, 0.0);
  prox_.set_skin(kProximitySkin);
  contacts_.reserve(4 * cells_of<D, K>(model).size() + 16);
  pairs_.reserve(4 * cells_of<D, K>(model).size() + 16);
}

template <int D, int K>
void CollisionSolver<D, K>::gather_contacts(const Model<D>& model, std::span<const Vec<D>> x0, double reach) {
  const auto& cells = cells_of<D, K>(model);
  contacts_.clear();
  auto add = [&](int a, int b, const std::array<double, 3>& wa, const std::array<double, 3>& wb, const Vec<D>& n,
                 double d) {
    // Ring pairs (joined by a mesh edge, sharing no vertex) are left to the springs, and so are
    // segments a few edges apart along their chain; the fail-safe still guards them.
    if constexpr (K == 2)
      if (model.chain_near(a, b)) return;
    Contact c;
    c.a = a;
    c.b = b;
    c.wa = wa;
    c.wb = wb;
    c.n = n;
    c.d = d;
    for (int q = 0; q < K; ++q) c.wsum += wa[q] * wa[q] * w_[cells[a][q]] + wb[q] * wb[q] * w_[cells[b][q]];
    contacts_.push_back(c);
  };
  if (model.params.persistent_contacts) {
    cache_.update(prox_, cells, x0, reach);
    // One contact per pair of closest features: on two sheets lying on each other a vertex above
    // a vertex is the closest pair of up to 36 triangle pairs, each the same constraint.
    features_.reset(cache_.entries().size());
    // A carried distance never falls below its lower bound, and a pair solved at 0 (no normal)
    // stays at 0: d in (0, reach] says both that it may be in reach and that it has a direction.
    for (const typename ContactCache<D, K>::Entry& e : cache_.entries())
      if (e.d <= reach && e.d > 0 && features_.insert(e.key_a, e.key_b))
        add(e.a, e.b, e.wa, e.wb, e.n, e.d);
    return;
  }
  prox_.pairs_within(x0, reach, pairs_, RingPairs::kExclude);
  for (const ProximityPair<D>& pp : pairs_) {
    const ClosestPoints<D>& cp = pp.closest;
    if (!(cp.distance > 0)) continue;  // no direction to push along; the fail-safe holds them
    add(pp.a, pp.b, cp.wa, cp.wb, (cp.p - cp.q) / cp.distance, cp.distance);
  }
}

template <int D, int K>
void CollisionSolver<D, K>::repulsion(const Model<D>& model, std::span<const Vec<D>> x0,
                                   std::span<Vec<D>> x1, std::span<Vec<D>> v,
                                   std::span<const std::uint8_t> pinned, double dt,
                                   CollisionStats& stats) {
  const double delta = model.contact_thickness;
  const double reach = kGatherFactor * delta;
  const auto& cells = cells_of<D, K>(model);
  for (int k = 0; k < model.nv; ++k) w_[k] = pinned[k] ? 0.0 : model.inv_mass[k];
  gather_contacts(model, x0, reach);
  if (contacts_.empty()) return;
  const double mu = model.params.friction;
  int acted = 0;
  // Gauss-Seidel sweeps. A contact's relative normal velocity changes by at most the weighted sum
  // of its vertices' velocity changes since it was last looked at (|Δv| accumulated per vertex in
  // kick_), so one that had more slack than that cannot need an impulse and is skipped: after the
  // first sweep only the contacts the impulses really reach are visited.
  std::fill(kick_.begin(), kick_.end(), 0.0);
  const auto kicks = [&](const Contact& c, const auto& ta, const auto& tb) {
    double k = 0;
    for (int q = 0; q < K; ++q) k += c.wa[q] * kick_[ta[q]] + c.wb[q] * kick_[tb[q]];
    return k;
  };
  for (int sweep = 0; sweep < model.params.collision_iterations; ++sweep) {
    bool any = false;
    // A contact's velocity changed by at most twice the largest kick (its weights sum to one a
    // side): those with more slack are passed over without reading their vertices.
    const double kick_max = sweep > 0 ? 2 * *std::max_element(kick_.begin(), kick_.end()) : 0.0;
    for (Contact& c : contacts_) {
      if (sweep > 0 && c.slack > kick_max) continue;
      const auto& ta = cells[c.a];
      const auto& tb = cells[c.b];
      if (sweep > 0 && !(kicks(c, ta, tb) - c.kicks >= c.slack)) continue;
      if (!(c.wsum > 0)) continue;
      Vec<D> u = Vec<D>::Zero();
      for (int q = 0; q < K; ++q) u += c.wa[q] * v[ta[q]] - c.wb[q] * v[tb[q]];
      const double vn = u.dot(c.n);
      // Approach is allowed down to δ; inside δ the pair may only stay or separate.
      const double vn_target = c.d >= delta ? (delta - c.d) / dt : 0.0;
      if (!(vn < vn_target)) {
        // The kicks so far are a part of the bound worth reading only where the slack is small;
        // 0 (kicks only grow) is the safe side and spares the first sweep those loads.
        c.slack = vn - vn_target;
        c.kicks = sweep > 0 ? kicks(c, ta, tb) : 0.0;
        continue;
      }
      const double dvn = vn_target - vn;
      Vec<D> dir = c.n * (dvn / c.wsum);
      // Coulomb friction: the tangential slip shrinks by at most μ times the normal change.
      const Vec<D> ut = u - vn * c.n;
      const double slip = ut.norm();
      if (mu > 0 && slip > 0) dir -= ut * (std::min(slip, mu * dvn) / slip / c.wsum);
      for (int q = 0; q < K; ++q) {
        const Vec<D> da = c.wa[q] * w_[ta[q]] * dir;
        const Vec<D> db = c.wb[q] * w_[tb[q]] * dir;
        v[ta[q]] += da;
        x1[ta[q]] += dt * da;
        v[tb[q]] -= db;
        x1[tb[q]] -= dt * db;
        kick_[ta[q]] += da.norm();
        kick_[tb[q]] += db.norm();
      }
      c.slack = 0;
      c.kicks = kicks(c, ta, tb);
      any = true;
      if (sweep == 0) ++acted;
    }
    if (!any) break;
  }
  // The paper's response: equal and opposite displacement along the closest-point line, back
  // towards δ. Positions only, so it cannot feed kinetic energy.
  for (const Contact& c : contacts_) {
    if (c.d >= delta || !(c.wsum > 0)) continue;
    const auto& ta = cells[c.a];
    const auto& tb = cells[c.b];
    const Vec<D> dir = c.n * (kPushFraction * (delta - c.d) / c.wsum);
    for (int q = 0; q < K; ++q) {
      x1[ta[q]] += c.wa[q] * w_[ta[q]] * dir;
      x1[tb[q]] -= c.wb[q] * w_[tb[q]] * dir;
    }
    ++acted;
  }
  stats.contacts = acted;
  stats.nonfinite = !touched_finite(model, x1, v);
}

template <int D, int K>
bool CollisionSolver<D, K>::touched_finite(const Model<D>& model, std::span<const Vec<D>> x,
                                        std::span<const Vec<D>> v) const {
  // Per contact while contacts are few; beyond a sixth of the vertices the whole arrays are
  // checked at once (a resting fold has thousands of contacts sharing each vertex).
  if (6 * contacts_.size() > static_cast<std::size_t>(model.nv)) return all_finite<D>(x) && all_finite<D>(v);
  const auto& tris = cells_of<D, K>(model);
  for (const Contact& c : contacts_)
    for (int q = 0; q < K; ++q)
      for (const int k : {tris[c.a][q], tris[c.b][q]})
        if (!all_finite(x[k]) || !all_finite(v[k])) return false;
  return true;
}

template <int D, int K>
int CollisionSolver<D, K>::failsafe_pass(const Model<D>& model, std::span<const Vec<D>> x0,
                                         std::span<Vec<D>> x1) {
  const auto& tris = cells_of<D, K>(model);
  const double eta = model.hard_thickness;
  const std::span<const Vec<D>> xe(x1.data(), x1.size());
  std::fill(hit_.begin(), hit_.end(), std::uint8_t{0});
  int hits = 0;
  CcdOptions opt;
  opt.thickness = eta;
  // Conservative advancement crawls when a pair closes fast on a small gap; past this many
  // distance evaluations it reports contact (the safe side) and the pair's vertices stop.
  opt.max_iterations = kCcdIterations;
  prox_.step_candidates(x0, xe, eta, [&](int i, int j) {
    const auto& ta = tris[i];
    const auto& tb = tris[j];
    const Simplex<D, K> a0 = gather<D, K>(x0, ta), b0 = gather<D, K>(x0, tb);
    const Simplex<D, K> a1 = gather<D, K>(xe, ta), b1 = gather<D, K>(xe, tb);
    const double speed = relative_speed_bound<D, K, K>(a0, a1, b0, b1);
    if (speed == 0) return;  // still relative to each other: the gap at x0 (> η) stays
    if (distance_lower_bound<D, K, K>(a0, b0, eta + speed) - speed > eta) return;
    if (!earliest_contact<D, K, K>(a0, a1, b0, b1, opt).hit) return;
    ++hits;
    for (int q = 0; q < K; ++q) {
      hit_[ta[q]] = 1;
      hit_[tb[q]] = 1;
    }
  });
  return hits;
}

template <int D, int K>
CollisionStats CollisionSolver<D, K>::solve(const Model<D>& model, std::span<const Vec<D>> x0,
                                            std::span<Vec<D>> x1, std::span<Vec<D>> v,
                                            std::span<const std::uint8_t> pinned, double dt) {
  CollisionStats stats;
  if (!model.params.collisions || cells_of<D, K>(model).empty()) return stats;
  repulsion(model, x0, x1, v, pinned, dt, stats);
  for (int pass = 0; pass < model.params.ccd_passes; ++pass) {
    ++stats.ccd_passes;
    if (failsafe_pass(model, x0, x1) == 0) return stats;
    // Stop the vertices of every pair that would come within η: back to where they started,
    // which was safe. Others keep moving; the next pass checks the new combination.
    for (int k = 0; k < model.nv; ++k)
      if (hit_[k] && (x1[k] != x0[k] || v[k] != Vec<D>::Zero())) {
        x1[k] = x0[k];
        v[k].setZero();
        ++stats.frozen;
      }
  }
  // Not converged: stop everything. x0 is η-separated, so this is always safe.
  for (int k = 0; k < model.nv; ++k) {
    x1[k] = x0[k];
    v[k].setZero();
  }
  stats.global_freeze = true;
  return stats;
}

template class CollisionSolver<2, 2>;
template class CollisionSolver<3, 2>;
template class CollisionSolver<4, 2>;
template class CollisionSolver<2, 3>;
template class CollisionSolver<3, 3>;
template class CollisionSolver<4, 3>;

}  // namespace s4d
