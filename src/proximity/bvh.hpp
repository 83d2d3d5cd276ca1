// Bounding volume hierarchy over axis-aligned boxes in R^D: the broad phase of every proximity
// query. Built once (median split), refitted each step, rebuilt when refits have loosened it.
#pragma once
#include <array>
#include <span>
#include <vector>

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

template <int D>
class Bvh {
 public:
  static constexpr int kLeafSize = 2;

  // Builds the tree for these boxes (one per primitive; primitive i is boxes[i]).
  void build(std::span<const Box<D>> boxes);
  // Same primitives, new boxes: updates node boxes bottom-up, keeps the topology. Rebuilds
  // instead when the tree has loosened (summed node size 1.5× that right after the last build).
  void refit(std::span<const Box<D>> boxes);
  std::size_t primitive_count() const { return order_.size(); }
  std::size_t node_count() const { return nodes_.size(); }
  bool empty() const { return nodes_.empty(); }

  // Calls f(i, j), i != j, once for every unordered pair of primitives whose boxes are `near`.
  template <class F>
  void self_pairs(double margin, F&& f) const;
  // Calls f(i, j) for every primitive i of this tree and j of `other` with `near` boxes.
  template <class F>
  void pairs_with(const Bvh& other, double margin, F&& f) const;
  // Calls f(i) for every primitive whose box is `near` `box`.
  template <class F>
  void query(const Box<D>& box, double margin, F&& f) const;

 private:
  struct Node {
    Box<D> box;
    int first = 0;   // leaf: first index into order_; inner: index of the right child
    int count = 0;   // leaf: number of primitives (> 0); inner: 0 (left child is this + 1)
    double size = 0; // box.half_perimeter(), kept with the box: decides which side to descend
  };
  int build_node(std::span<const Box<D>> boxes, std::vector<Vec<D>>& centres, int begin, int end);
  double total_half_perimeter() const;

  std::vector<Node> nodes_;  // pre-order: children after their parent
  std::vector<int> order_;   // primitive ids, grouped by leaf
  std::vector<Box<D>> prim_boxes_;  // prim_boxes_[k] is the box of primitive order_[k]
  double built_size_ = 0;    // total_half_perimeter() right after build()
};

template <int D>
template <class F>
void Bvh<D>::self_pairs(double margin, F&& f) const {
  if (nodes_.empty()) return;
  // Stack of node pairs; (n, n) means "pairs within the subtree n".
  std::array<std::pair<int, int>, 256> stack;
  int top = 0;
  stack[top++] = {0, 0};
  while (top > 0) {
    const auto [a, b] = stack[--top];
    const Node& na = nodes_[a];
    const Node& nb = nodes_[b];
    if (a == b) {
      if (na.count > 0) {
        for (int i = na.first; i < na.first + na.count; ++i)
          for (int j = i + 1; j < na.first + na.count; ++j)
            if (prim_boxes_[i].near(prim_boxes_[j], margin)) f(order_[i], order_[j]);
        continue;
      }
      stack[top++] = {a + 1, a + 1};
      stack[top++] = {na.first, na.first};
      stack[top++] = {a + 1, na.first};
      continue;
    }
    if (!na.box.near(nb.box, margin)) continue;
    if (na.count > 0 && nb.count > 0) {
      for (int i = na.first; i < na.first + na.count; ++i)
        for (int j = nb.first; j < nb.first + nb.count; ++j)
          if (prim_boxes_[i].near(prim_boxes_[j], margin)) f(order_[i], order_[j]);
      continue;
    }
    // Descend the larger (or the inner) node.
    const bool split_a = nb.count > 0 || (na.count == 0 && na.size >= nb.size);
    if (split_a) {
      stack[top++] = {a + 1, b};
      stack[top++] = {na.first, b};
    } else {
      stack[top++] = {a, b + 1};
      stack[top++] = {a, nb.first};
    }
  }
}

template <int D>
template <class F>
void Bvh<D>::pairs_with(const Bvh& other, double margin, F&& f) const {
  if (nodes_.empty() || other.nodes_.empty()) return;
  std::array<std::pair<int, int>, 256> stack;
  int top = 0;
  stack[top++] = {0, 0};
  while (top > 0) {
    const auto [a, b] = stack[--top];
    const Node& na = nodes_[a];
    const Node& nb = other.nodes_[b];
    if (!na.box.near(nb.box, margin)) continue;
    if (na.count > 0 && nb.count > 0) {
      for (int i = na.first; i < na.first + na.count; ++i)
        for (int j = nb.first; j < nb.first + nb.count; ++j)
          if (prim_boxes_[i].near(other.prim_boxes_[j], margin)) f(order_[i], other.order_[j]);
      continue;
    }
    const bool split_a = nb.count > 0 || (na.count == 0 && na.size >= nb.size);
    if (split_a) {
      stack[top++] = {a + 1, b};
      stack[top++] = {na.first, b};
    } else {
      stack[top++] = {a, b + 1};
      stack[top++] = {a, nb.first};
    }
  }
}

template <int D>
template <class F>
void Bvh<D>::query(const Box<D>& box, double margin, F&& f) const {
  if (nodes_.empty()) return;
  std::array<int, 128> stack;
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& n = nodes_[stack[--top]];
    if (!n.box.near(box, margin)) continue;
    if (n.count > 0) {
      for (int i = n.first; i < n.first + n.count; ++i)
        if (prim_boxes_[i].near(box, margin)) f(order_[i]);
      continue;
    }
    stack[top++] = &n - nodes_.data() + 1;
    stack[top++] = n.first;
  }
}

extern template class Bvh<2>;
extern template class Bvh<3>;
extern template class Bvh<4>;

}  // namespace s4d
