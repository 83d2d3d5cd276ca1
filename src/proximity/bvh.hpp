// Bounding volume hierarchy over axis-aligned boxes in R^D: the broad phase of every proximity
// query. Built once (median split), refitted each step, rebuilt when refits have loosened it.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <vector>

#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include "core/cpu.hpp"
#include "core/vec.hpp"

namespace s4d {

template <int D>
struct Box {
  Vec<D> lo = Vec<D>::Constant(std::numeric_limits<double>::infinity());
  Vec<D> hi = Vec<D>::Constant(-std::numeric_limits<double>::infinity());

  void add(const Vec<D>& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  void add(const Box& b) {
    lo = lo.cwiseMin(b.lo);
    hi = hi.cwiseMax(b.hi);
  }
  // True when the boxes are no further apart than `margin` along every axis (a necessary
  // condition for two contents to be within Euclidean distance `margin`).
  bool near(const Box& b, double margin) const {
    for (int k = 0; k < D; ++k)
      if (lo[k] > b.hi[k] + margin || b.lo[k] > hi[k] + margin) return false;
    return true;
  }
  double half_perimeter() const { return (hi - lo).cwiseMax(0.0).sum(); }
};

// Node boxes in single precision, rounded outward (so a float test never rejects what the double
// test would keep), four lanes wide whatever D <= 4 is: one SSE compare tests all axes at once.
// Unused lanes span (-inf, +inf) and never separate.
struct alignas(16) FloatBox {
  float lo[4] = {-std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
                 -std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity()};
  float hi[4] = {std::numeric_limits<float>::infinity(), std::numeric_limits<float>::infinity(),
                 std::numeric_limits<float>::infinity(), std::numeric_limits<float>::infinity()};

  template <int D>
  static FloatBox outward(const Box<D>& b);
  // The union; exact in float, so it stays outward.
  void add(const FloatBox& b) {
    for (int k = 0; k < 4; ++k) {
      lo[k] = std::min(lo[k], b.lo[k]);
      hi[k] = std::max(hi[k], b.hi[k]);
    }
  }
  // Same meaning as Box::near with margin m already rounded up to float. Rounding to nearest is
  // monotone, so lo > fl(hi + m) implies lo > hi + m: no pair the doubles keep is lost.
  bool near(const FloatBox& b, float m) const {
#if defined(__SSE2__)
    const __m128 mm = _mm_set1_ps(m);
    const __m128 sep = _mm_or_ps(_mm_cmpgt_ps(_mm_load_ps(lo), _mm_add_ps(_mm_load_ps(b.hi), mm)),
                                 _mm_cmpgt_ps(_mm_load_ps(b.lo), _mm_add_ps(_mm_load_ps(hi), mm)));
    return _mm_movemask_ps(sep) == 0;
#else
    for (int k = 0; k < 4; ++k)
      if (lo[k] > b.hi[k] + m || b.lo[k] > hi[k] + m) return false;
    return true;
#endif
  }
  // Squared Euclidean gap to b, rounded down (each of the seven operations rounds by at most
  // 2^-24 relative). Unused lanes span all of R and add nothing.
  float gap2(const FloatBox& b) const {
#if defined(__SSE2__)
    const __m128 zero = _mm_setzero_ps();
    const __m128 g = _mm_max_ps(_mm_max_ps(_mm_sub_ps(_mm_load_ps(b.lo), _mm_load_ps(hi)),
                                           _mm_sub_ps(_mm_load_ps(lo), _mm_load_ps(b.hi))),
                                zero);
    const __m128 sq = _mm_mul_ps(g, g);
    const __m128 pair = _mm_add_ps(sq, _mm_movehl_ps(sq, sq));
    return _mm_cvtss_f32(_mm_add_ss(pair, _mm_shuffle_ps(pair, pair, 1))) * (1 - 1e-6f);
#else
    float s = 0;
    for (int k = 0; k < 4; ++k) {
      const float g = std::max(std::max(b.lo[k] - hi[k], lo[k] - b.hi[k]), 0.0f);
      s += g * g;
    }
    return s * (1 - 1e-6f);
#endif
  }
  float half_perimeter(int dims) const {
    float s = 0;
    for (int k = 0; k < dims; ++k) s += std::max(hi[k] - lo[k], 0.0f);
    return s;
  }
};

template <int D>
FloatBox FloatBox::outward(const Box<D>& b) {
  static_assert(D >= 1 && D <= 4, "FloatBox holds up to four axes");
  FloatBox f;
  for (int k = 0; k < D; ++k) {
    const float l = static_cast<float>(b.lo[k]), h = static_cast<float>(b.hi[k]);
    // Step out by |x|·2^-23 (one to two ulps, more than the half ulp rounding can lose; 2^-126
    // covers zero and subnormals) always: a branch on the rounding direction mispredicts half
    // the time and cost more than the whole refit. A NaN coordinate keeps the box open on that
    // axis (near() lets NaN boxes through, as Box does).
    const float lo_out = l - (std::abs(l) * 0x1p-23f + 0x1p-126f);
    const float hi_out = h + (std::abs(h) * 0x1p-23f + 0x1p-126f);
    f.lo[k] = lo_out == lo_out ? lo_out : -std::numeric_limits<float>::infinity();
    f.hi[k] = hi_out == hi_out ? hi_out : std::numeric_limits<float>::infinity();
  }
  return f;
}

// Margin rounded up to float (a NaN margin stays NaN: every comparison fails, everything is near).
inline float float_margin(double margin) {
  float m = static_cast<float>(margin);
  if (static_cast<double>(m) < margin) m = std::nextafter(m, std::numeric_limits<float>::infinity());
  return m;
}

// prim[k] = boxes[order[k]] and pf[k] = FloatBox::outward(prim[k]) for k < order.size(): what a
// refit copies. The AVX form (call it only when cpu::kHasAvx) gives the portable one's bits.
template <int D>
void gather_outward_portable(std::span<const Box<D>> boxes, std::span<const int> order,
                             Box<D>* prim, FloatBox* pf);
#if S4D_X86
void gather_outward_avx(std::span<const Box<4>> boxes, std::span<const int> order, Box<4>* prim,
                        FloatBox* pf);
#endif

template <int D>
class Bvh {
 public:
  // Primitives per leaf: two groups of four SIMD lanes (leaf_gaps2 tests a primitive against a
  // whole leaf at once). 8 halves the node pairs a self walk visits against 4.
  static constexpr int kLeafSize = 8;

  // Builds the tree for these boxes (one per primitive; primitive i is boxes[i]).
  void build(std::span<const Box<D>> boxes);
  // Same primitives, new boxes: updates node boxes bottom-up, keeps the topology. Rebuilds
  // instead when the tree has loosened (summed node size 1.5× that right after the last build).
  void refit(std::span<const Box<D>> boxes);
  std::size_t primitive_count() const { return order_.size(); }
  std::size_t node_count() const { return nodes_.size(); }
  bool empty() const { return nodes_.empty(); }

  // Calls f(i, j), i != j, once for every unordered pair of primitives whose boxes are `near`
  // (tested in float, rounded outward: a few pairs a double test would drop may come too).
  template <class F>
  void self_pairs(double margin, F&& f) const {
    self_slot_pairs(margin, [&](int k, int l) { f(order_[k], order_[l]); });
  }
  // Calls f(i, j) for every primitive i of this tree and j of `other` with `near` boxes.
  template <class F>
  void pairs_with(const Bvh& other, double margin, F&& f) const {
    slot_pairs_with(other, margin, [&](int k, int l) { f(order_[k], other.order_[l]); });
  }
  // The same walks, naming primitives by their slot in the tree's order (slot k holds primitive
  // id(k)): callers that keep per-primitive data in slot order read it sequentially.
  template <class F>
  void self_slot_pairs(double margin, F&& f) const;
  template <class F>
  void slot_pairs_with(const Bvh& other, double margin, F&& f) const;
  // The walk under self_slot_pairs, one level up: f(la, lb) for every pair of leaves whose boxes
  // are near, a leaf with itself included (la == lb), the primitive pairs inside left to the
  // caller (prim_near tests one, as self_slot_pairs does). Leaves are numbered in slot order.
  template <class F>
  void self_leaf_pairs(double margin, F&& f) const;
  bool prim_near(int k, int l, float margin) const { return prim_f_[k].near(prim_f_[l], margin); }
  // Squared Euclidean gaps between the box of the primitive in slot k and the boxes of leaf l's
  // primitives (lane j: slot leaf_first(l) + j; lanes past its size are meaningless), in float:
  // each is at most the squared gap of the double boxes (outward float boxes, and the
  // arithmetic's rounding taken off), so a pair within a distance is never lost.
  // Returns the bit mask of the lanes j < kLeafSize whose squared gap is <= r2.
  unsigned leaf_gaps2(int k, int l, float r2, float out[kLeafSize]) const;
  // Its two ways, bit for bit the same gaps (the same operations in the same order): four lanes
  // at a time in SSE (or scalar code), and all eight in one AVX register (bvh.cpp; call it only
  // when cpu::kHasAvx), which leaf_gaps2 takes when the CPU has AVX.
  unsigned leaf_gaps2_portable(int k, int l, float r2, float out[kLeafSize]) const;
  S4D_AVX_TARGET unsigned leaf_gaps2_avx(int k, int l, float r2, float out[kLeafSize]) const;
  S4D_AVX_TARGET unsigned leaf_rows_near_avx(int la, int lb, float r2) const;
  // Whether the box of the primitive in slot k may be within sqrt(r2) of leaf l's box (the same
  // rounding as leaf_gaps2): one test that spares leaf_gaps2 for a primitive far from the leaf.
  bool prim_near_leaf(int k, int l, float r2) const {
    return prim_f_[k].gap2(nodes_[leaves_[l].node].box) <= r2;
  }
  // Bit i set when the box of slot leaf_first(la) + i may be within sqrt(r2) of leaf lb's box,
  // for every i < leaf_size(la) at once. With AVX its gaps are leaf_gaps2's operations on the
  // leaf's box, each at most that of any of lb's primitives (the leaf box holds them and every
  // operation is monotone): a row it drops has no pair leaf_gaps2 would keep.
  unsigned leaf_rows_near(int la, int lb, float r2) const;
  int leaf_count() const { return static_cast<int>(leaves_.size()); }
  int leaf_first(int l) const { return leaves_[l].first; }
  int leaf_size(int l) const { return leaves_[l].count; }
  int id(int slot) const { return order_[slot]; }
  const std::vector<int>& order() const { return order_; }
  // Counts builds (not refits): slot order changes only when this does.
  long long builds() const { return builds_; }
  // Calls f(i) for every primitive whose box is `near` `box`.
  template <class F>
  void query(const Box<D>& box, double margin, F&& f) const;

 private:
  struct Node {
    FloatBox box;
    int first = 0;   // leaf: first index into order_; inner: index of the right child
    int count = 0;   // leaf: number of primitives (> 0); inner: 0 (left child is this + 1)
    float size = 0;  // box half perimeter: decides which side to descend
    int leaf = -1;   // leaf: its number (slot order)
  };
  struct Leaf {
    int first = 0, count = 0, node = 0;
  };
  int build_node(std::span<const Box<D>> boxes, std::vector<Vec<D>>& centres, int begin, int end);
  // prim_boxes_ and prim_f_ from boxes in slot order (an AVX path in R^4: the same boxes).
  void copy_prims(std::span<const Box<D>> boxes);
  void fit_nodes();  // node boxes from prim_boxes_, bottom-up
  double total_half_perimeter() const;
  // The exact (double) test behind every reported pair, after the float one passed.
  template <class F>
  void leaf_pair(const Bvh& other, const Node& na, const Node& nb, double margin, float fm,
                 F& f) const {
    for (int i = na.first; i < na.first + na.count; ++i)
      for (int j = nb.first; j < nb.first + nb.count; ++j)
        if (prim_f_[i].near(other.prim_f_[j], fm)) f(i, j);
  }

  // Every leaf's boxes as four lanes per axis (lane j: slot first + j), for leaf_gaps2.
  struct alignas(32) LeafLanes {
    float lo[4][kLeafSize] = {};
    float hi[4][kLeafSize] = {};
  };
  std::vector<LeafLanes> lanes_;  // per leaf
  std::vector<Leaf> leaves_;      // by number: their slots
  std::vector<Node> nodes_;  // pre-order: children after their parent
  std::vector<int> order_;   // primitive ids, grouped by leaf
  std::vector<Box<D>> prim_boxes_;   // prim_boxes_[k] is the box of primitive order_[k]
  std::vector<FloatBox> prim_f_;     // the same, outward in float
  double built_size_ = 0;    // total_half_perimeter() right after build()
  long long builds_ = 0;
};

template <int D>
inline unsigned Bvh<D>::leaf_rows_near(int la, int lb, float r2) const {
#if S4D_X86
  const unsigned lanes = (1u << leaves_[la].count) - 1;
  if (cpu::kHasAvx) return leaf_rows_near_avx(la, lb, r2) & lanes;
#endif
  unsigned rows = 0;
  for (int i = 0; i < leaves_[la].count; ++i)
    if (prim_near_leaf(leaves_[la].first + i, lb, r2)) rows |= 1u << i;
  return rows;
}

template <int D>
inline unsigned Bvh<D>::leaf_gaps2(int k, int leaf, float r2, float out[kLeafSize]) const {
  return cpu::kHasAvx ? leaf_gaps2_avx(k, leaf, r2, out) : leaf_gaps2_portable(k, leaf, r2, out);
}

template <int D>
inline unsigned Bvh<D>::leaf_gaps2_portable(int k, int leaf, float r2,
                                            float out[kLeafSize]) const {
  static_assert(kLeafSize % 4 == 0, "leaves are groups of four lanes");
  const FloatBox& a = prim_f_[k];
  const LeafLanes& l = lanes_[leaf];
  unsigned near = 0;
#if defined(__SSE2__)
  const __m128 zero = _mm_setzero_ps();
  const __m128 shrink = _mm_set1_ps(1 - 1e-6f);
  const __m128 limit = _mm_set1_ps(r2);
  for (int group = 0; group < kLeafSize; group += 4) {
    __m128 acc = zero;
    for (int axis = 0; axis < D; ++axis) {
      const __m128 g =
          _mm_max_ps(_mm_max_ps(_mm_sub_ps(_mm_load_ps(l.lo[axis] + group), _mm_set1_ps(a.hi[axis])),
                                _mm_sub_ps(_mm_set1_ps(a.lo[axis]), _mm_load_ps(l.hi[axis] + group))),
                     zero);
      acc = _mm_add_ps(acc, _mm_mul_ps(g, g));
    }
    // Each operation rounds by at most 2^-24 relative; seven of them stay under 1e-6.
    acc = _mm_mul_ps(acc, shrink);
    _mm_storeu_ps(out + group, acc);
    near |= static_cast<unsigned>(_mm_movemask_ps(_mm_cmple_ps(acc, limit))) << group;
  }
#else
  for (int j = 0; j < kLeafSize; ++j) {
    float acc = 0;
    for (int axis = 0; axis < D; ++axis) {
      const float g = std::max(std::max(l.lo[axis][j] - a.hi[axis], a.lo[axis] - l.hi[axis][j]), 0.0f);
      acc += g * g;
    }
    out[j] = acc * (1 - 1e-6f);
    if (out[j] <= r2) near |= 1u << j;
  }
#endif
  return near;
}

template <int D>
template <class F>
void Bvh<D>::self_slot_pairs(double margin, F&& f) const {
  const float fm = float_margin(margin);
  self_leaf_pairs(margin, [&](int la, int lb) {
    const int fa = leaves_[la].first, ca = leaves_[la].count;
    const int fb = leaves_[lb].first, cb = leaves_[lb].count;
    if (fa == fb) {
      for (int i = fa; i < fa + ca; ++i)
        for (int j = i + 1; j < fa + ca; ++j)
          if (prim_f_[i].near(prim_f_[j], fm)) f(i, j);
      return;
    }
    for (int i = fa; i < fa + ca; ++i)
      for (int j = fb; j < fb + cb; ++j)
        if (prim_f_[i].near(prim_f_[j], fm)) f(i, j);
  });
}

template <int D>
template <class F>
void Bvh<D>::self_leaf_pairs(double margin, F&& f) const {
  if (nodes_.empty()) return;
  const float fm = float_margin(margin);
  // Stack of node pairs; (n, n) means "pairs within the subtree n". Depth is O(log n) because
  // the build splits at the median; each level adds at most three entries.
  std::array<std::pair<int, int>, 512> stack;
  int top = 0;
  stack[top++] = {0, 0};
  while (top > 0) {
    const auto [a, b] = stack[--top];
    const Node& na = nodes_[a];
    if (a == b) {
      if (na.count > 0) {
        f(na.leaf, na.leaf);
        continue;
      }
      stack[top++] = {a + 1, a + 1};
      stack[top++] = {na.first, na.first};
      if (nodes_[a + 1].box.near(nodes_[na.first].box, fm)) stack[top++] = {a + 1, na.first};
      continue;
    }
    // Only pairs whose boxes are near get pushed, so (a, b) is near here.
    const Node& nb = nodes_[b];
    if (na.count > 0 && nb.count > 0) {
      f(na.leaf, nb.leaf);
      continue;
    }
    // Descend the larger (or the inner) node, testing the children before pushing them.
    const bool split_a = nb.count > 0 || (na.count == 0 && na.size >= nb.size);
    if (split_a) {
      if (nodes_[a + 1].box.near(nb.box, fm)) stack[top++] = {a + 1, b};
      if (nodes_[na.first].box.near(nb.box, fm)) stack[top++] = {na.first, b};
    } else {
      if (na.box.near(nodes_[b + 1].box, fm)) stack[top++] = {a, b + 1};
      if (na.box.near(nodes_[nb.first].box, fm)) stack[top++] = {a, nb.first};
    }
  }
}

template <int D>
template <class F>
void Bvh<D>::slot_pairs_with(const Bvh& other, double margin, F&& f) const {
  if (nodes_.empty() || other.nodes_.empty()) return;
  const float fm = float_margin(margin);
  if (!nodes_[0].box.near(other.nodes_[0].box, fm)) return;
  std::array<std::pair<int, int>, 512> stack;
  int top = 0;
  stack[top++] = {0, 0};
  while (top > 0) {
    const auto [a, b] = stack[--top];
    const Node& na = nodes_[a];
    const Node& nb = other.nodes_[b];
    if (na.count > 0 && nb.count > 0) {
      leaf_pair(other, na, nb, margin, fm, f);
      continue;
    }
    const bool split_a = nb.count > 0 || (na.count == 0 && na.size >= nb.size);
    if (split_a) {
      if (nodes_[a + 1].box.near(nb.box, fm)) stack[top++] = {a + 1, b};
      if (nodes_[na.first].box.near(nb.box, fm)) stack[top++] = {na.first, b};
    } else {
      if (na.box.near(other.nodes_[b + 1].box, fm)) stack[top++] = {a, b + 1};
      if (na.box.near(other.nodes_[nb.first].box, fm)) stack[top++] = {a, nb.first};
    }
  }
}

template <int D>
template <class F>
void Bvh<D>::query(const Box<D>& box, double margin, F&& f) const {
  if (nodes_.empty()) return;
  const float fm = float_margin(margin);
  const FloatBox fb = FloatBox::outward<D>(box);
  std::array<int, 128> stack;
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const int index = stack[--top];
    const Node& n = nodes_[index];
    if (!n.box.near(fb, fm)) continue;
    if (n.count > 0) {
      for (int i = n.first; i < n.first + n.count; ++i)
        if (prim_boxes_[i].near(box, margin)) f(order_[i]);
      continue;
    }
    stack[top++] = index + 1;
    stack[top++] = n.first;
  }
}

extern template class Bvh<2>;
extern template class Bvh<3>;
extern template class Bvh<4>;

}  // namespace s4d
