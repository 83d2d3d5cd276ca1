// Build and refit of the broad-phase BVH (traversals are templates in bvh.hpp).
#include "proximity/bvh.hpp"

#include <algorithm>

#include "core/cpu.hpp"

namespace s4d {

#if S4D_X86
namespace {
// Eight lanes at once; per lane the operations of the SSE path, in its order (no FMA in "avx").
// `lo`/`hi`: the leaf's lanes, eight floats an axis.
__attribute__((target("avx"))) unsigned gaps2_avx(const float* a_lo, const float* a_hi,
                                                  const float (*lo)[8], const float (*hi)[8],
                                                  int dims, float r2, float* out) {
  const __m256 zero = _mm256_setzero_ps();
  __m256 acc = zero;
  for (int axis = 0; axis < dims; ++axis) {
    const __m256 g = _mm256_max_ps(
        _mm256_max_ps(_mm256_sub_ps(_mm256_loadu_ps(lo[axis]), _mm256_set1_ps(a_hi[axis])),
                      _mm256_sub_ps(_mm256_set1_ps(a_lo[axis]), _mm256_loadu_ps(hi[axis]))),
        zero);
    acc = _mm256_add_ps(acc, _mm256_mul_ps(g, g));
  }
  acc = _mm256_mul_ps(acc, _mm256_set1_ps(1 - 1e-6f));
  _mm256_storeu_ps(out, acc);
  return static_cast<unsigned>(
      _mm256_movemask_ps(_mm256_cmp_ps(acc, _mm256_set1_ps(r2), _CMP_LE_OQ)));
}
}  // namespace
#endif

template <int D>
unsigned Bvh<D>::leaf_gaps2_avx(int k, int leaf, float r2, float out[kLeafSize]) const {
  static_assert(kLeafSize == 8, "one AVX register holds a leaf");
#if S4D_X86
  const LeafLanes& l = lanes_[leaf];
  return gaps2_avx(prim_f_[k].lo, prim_f_[k].hi, l.lo, l.hi, D, r2, out);
#else
  (void)k, (void)leaf, (void)r2, (void)out;
  return 0;  // never called: cpu::kHasAvx is false
#endif
}

template <int D>
void Bvh<D>::build(std::span<const Box<D>> boxes) {
  ++builds_;
  nodes_.clear();
  leaves_.clear();
  order_.resize(boxes.size());
  prim_boxes_.clear();
  prim_f_.clear();
  if (boxes.empty()) {
    built_size_ = 0;
    return;
  }
  std::vector<Vec<D>> centres(boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    order_[i] = static_cast<int>(i);
    // A non-finite box gets a finite centre so the split stays well defined; `near` lets NaN
    // boxes through, and the narrow phase (NaN distance) decides what that means.
    const Vec<D> c = 0.5 * (boxes[i].lo + boxes[i].hi);
    centres[i] = c.allFinite() ? c : Vec<D>::Zero();
  }
  nodes_.reserve(2 * (boxes.size() / kLeafSize + 1));
  build_node(boxes, centres, 0, static_cast<int>(boxes.size()));
  // Leaves numbered in pre-order, which is slot order.
  leaves_.clear();
  for (Node& n : nodes_)
    if (n.count > 0) {
      n.leaf = static_cast<int>(leaves_.size());
      leaves_.push_back({n.first, n.count, static_cast<int>(&n - nodes_.data())});
    }
  prim_boxes_.resize(boxes.size());
  prim_f_.resize(boxes.size());
  for (std::size_t k = 0; k < boxes.size(); ++k) {
    prim_boxes_[k] = boxes[order_[k]];
    prim_f_[k] = FloatBox::outward<D>(prim_boxes_[k]);
  }
  fit_nodes();
  built_size_ = total_half_perimeter();
}

// Topology only: median split on the widest axis of the centres; boxes come from fit_nodes().
template <int D>
int Bvh<D>::build_node(std::span<const Box<D>> boxes, std::vector<Vec<D>>& centres, int begin,
                       int end) {
  const int index = static_cast<int>(nodes_.size());
  nodes_.push_back({});
  if (end - begin <= kLeafSize) {
    nodes_[index].first = begin;
    nodes_[index].count = end - begin;
    return index;
  }
  Box<D> cbox;
  for (int i = begin; i < end; ++i) cbox.add(centres[order_[i]]);
  int axis = 0;
  const Vec<D> ext = cbox.hi - cbox.lo;
  for (int k = 1; k < D; ++k)
    if (ext[k] > ext[axis]) axis = k;
  const int mid = begin + (end - begin) / 2;
  std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                   [&](int a, int b) { return centres[a][axis] < centres[b][axis]; });
  build_node(boxes, centres, begin, mid);  // left child lands at index + 1
  const int right = build_node(boxes, centres, mid, end);
  nodes_[index].first = right;
  nodes_[index].count = 0;
  return index;
}

template <int D>
void Bvh<D>::fit_nodes() {
  lanes_.resize(leaves_.size());
  for (int n = static_cast<int>(nodes_.size()) - 1; n >= 0; --n) {
    Node& node = nodes_[n];
    if (node.count > 0) {
      LeafLanes& l = lanes_[node.leaf];
      l = LeafLanes{};
      for (int j = 0; j < node.count; ++j)
        for (int axis = 0; axis < D; ++axis) {
          l.lo[axis][j] = prim_f_[node.first + j].lo[axis];
          l.hi[axis][j] = prim_f_[node.first + j].hi[axis];
        }
    }
    FloatBox b = prim_f_[node.count > 0 ? node.first : 0];
    if (node.count > 0) {
      for (int i = node.first + 1; i < node.first + node.count; ++i) b.add(prim_f_[i]);
    } else {
      b = nodes_[n + 1].box;
      b.add(nodes_[node.first].box);
    }
    node.box = b;
    node.size = b.half_perimeter(D);
  }
}

template <int D>
void Bvh<D>::refit(std::span<const Box<D>> boxes) {
  if (boxes.size() != order_.size() || nodes_.empty()) {
    build(boxes);
    return;
  }
  for (std::size_t k = 0; k < boxes.size(); ++k) {
    prim_boxes_[k] = boxes[order_[k]];
    prim_f_[k] = FloatBox::outward<D>(prim_boxes_[k]);
  }
  fit_nodes();
  // A tree fitted to far-moved primitives overlaps itself more and more; rebuild it then.
  const double size = total_half_perimeter();
  if (!(size <= 1.5 * built_size_ + 1e-300)) build(boxes);
}

template <int D>
double Bvh<D>::total_half_perimeter() const {
  double s = 0;
  for (const Node& n : nodes_) s += n.size;
  return s;
}

template class Bvh<2>;
template class Bvh<3>;
template class Bvh<4>;

}  // namespace s4d
