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

template <int D>
class Bvh {
 public:
  // Primitives per leaf. Leaf pairs are tested primitive by primitive (float boxes, then the
  // exact double test); 4 measured fastest of 1, 2, 4, 8 on the crumpled-grid benchmark.
  static constexpr int kLeafSize = 4;

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
  // The walk under self_slot_pairs, one level up: f(a_first, a_count, b_first, b_count) for every
  // pair of leaves whose boxes are near, a leaf with itself included (a_first == b_first), the
  // primitive pairs inside left to the caller (prim_near tests one, as self_slot_pairs does).
  template <class F>
  void self_leaf_pairs(double margin, F&& f) const;
  bool prim_near(int k, int l, float margin) const { return prim_f_[k].near(prim_f_[l], margin); }
  // f(first, count) for every leaf, in tree order.
  template <class F>
  void for_each_leaf(F&& f) const {
    for (const Node& n : nodes_)
      if (n.count > 0) f(n.first, n.count);
  }
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
  };
  int build_node(std::span<const Box<D>> boxes, std::vector<Vec<D>>& centres, int begin, int end);
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

  std::vector<Node> nodes_;  // pre-order: children after their parent
  std::vector<int> order_;   // primitive ids, grouped by leaf
  std::vector<Box<D>> prim_boxes_;   // prim_boxes_[k] is the box of primitive order_[k]
  std::vector<FloatBox> prim_f_;     // the same, outward in float
  double built_size_ = 0;    // total_half_perimeter() right after build()
  long long builds_ = 0;
};

template <int D>
template <class F>
void Bvh<D>::self_slot_pairs(double margin, F&& f) const {
  const float fm = float_margin(margin);
  self_leaf_pairs(margin, [&](int fa, int ca, int fb, int cb) {
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
        f(na.first, na.count, na.first, na.count);
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
      f(na.first, na.count, nb.first, nb.count);
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
