// Build and refit of the broad-phase BVH (traversals are templates in bvh.hpp).
#include "proximity/bvh.hpp"

#include <algorithm>
#include <limits>

#include "core/avx4.hpp"
#include "core/cpu.hpp"

namespace s4d {

#if S4D_X86
namespace {
// Eight lanes at once; per lane the operations of the SSE path, in its order (no FMA in "avx").
// `lo`/`hi`: the leaf's lanes, eight floats an axis. Inlined into its two callers (both AVX).
template <int D>
S4D_AVX_INLINE unsigned gaps2_avx(const float* a_lo, const float* a_hi, const float (*lo)[8],
                                  const float (*hi)[8], float r2, float* out) {
  const __m256 zero = _mm256_setzero_ps();
  __m256 acc = zero;
  for (int axis = 0; axis < D; ++axis) {
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

// FloatBox::outward's operations, four axes a register (the same bits).
S4D_AVX_TARGET void gather_outward_avx(std::span<const Box<4>> boxes, std::span<const int> order,
                                       Box<4>* prim, FloatBox* pf) {
  const __m128 abs_mask = _mm_castsi128_ps(_mm_set1_epi32(0x7fffffff));
  const __m128 ulp = _mm_set1_ps(0x1p-23f), tiny = _mm_set1_ps(0x1p-126f);
  const __m128 inf = _mm_set1_ps(std::numeric_limits<float>::infinity());
  const __m128 minus_inf = _mm_set1_ps(-std::numeric_limits<float>::infinity());
  for (std::size_t k = 0; k < order.size(); ++k) {
    const Box<4>& b = boxes[order[k]];
    const __m256d lo = _mm256_loadu_pd(b.lo.data()), hi = _mm256_loadu_pd(b.hi.data());
    _mm256_storeu_pd(prim[k].lo.data(), lo);
    _mm256_storeu_pd(prim[k].hi.data(), hi);
    const __m128 l = _mm256_cvtpd_ps(lo), h = _mm256_cvtpd_ps(hi);
    const __m128 l_out = _mm_sub_ps(l, _mm_add_ps(_mm_mul_ps(_mm_and_ps(l, abs_mask), ulp), tiny));
    const __m128 h_out = _mm_add_ps(h, _mm_add_ps(_mm_mul_ps(_mm_and_ps(h, abs_mask), ulp), tiny));
    _mm_store_ps(pf[k].lo, _mm_blendv_ps(l_out, minus_inf, _mm_cmpunord_ps(l_out, l_out)));
    _mm_store_ps(pf[k].hi, _mm_blendv_ps(h_out, inf, _mm_cmpunord_ps(h_out, h_out)));
  }
}
#endif

template <int D>
void gather_outward_portable(std::span<const Box<D>> boxes, std::span<const int> order,
                             Box<D>* prim, FloatBox* pf) {
  for (std::size_t k = 0; k < order.size(); ++k) {
    prim[k] = boxes[order[k]];
    pf[k] = FloatBox::outward<D>(prim[k]);
  }
}

template <int D>
void Bvh<D>::copy_prims(std::span<const Box<D>> boxes) {
  prim_boxes_.resize(boxes.size());
  prim_f_.resize(boxes.size());
#if S4D_X86
  if constexpr (D == 4)
    if (cpu::kHasAvx) return gather_outward_avx(boxes, order_, prim_boxes_.data(), prim_f_.data());
#endif
  gather_outward_portable<D>(boxes, order_, prim_boxes_.data(), prim_f_.data());
}

template <int D>
unsigned Bvh<D>::leaf_gaps2_avx(int k, int leaf, float r2, float out[kLeafSize]) const {
  static_assert(kLeafSize == 8, "one AVX register holds a leaf");
#if S4D_X86
  const LeafLanes& l = lanes_[leaf];
  return gaps2_avx<D>(prim_f_[k].lo, prim_f_[k].hi, l.lo, l.hi, r2, out);
#else
  (void)k, (void)leaf, (void)r2, (void)out;
  return 0;  // never called: cpu::kHasAvx is false
#endif
}

template <int D>
unsigned Bvh<D>::leaf_rows_near_avx(int la, int lb, float r2) const {
#if S4D_X86
  const FloatBox& box = nodes_[leaves_[lb].node].box;
  const LeafLanes& l = lanes_[la];
  float out[kLeafSize];
  return gaps2_avx<D>(box.lo, box.hi, l.lo, l.hi, r2, out);
#else
  (void)la, (void)lb, (void)r2;
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
  copy_prims(boxes);
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
  copy_prims(boxes);
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

template void gather_outward_portable<2>(std::span<const Box<2>>, std::span<const int>, Box<2>*, FloatBox*);
template void gather_outward_portable<3>(std::span<const Box<3>>, std::span<const int>, Box<3>*, FloatBox*);
template void gather_outward_portable<4>(std::span<const Box<4>>, std::span<const int>, Box<4>*, FloatBox*);
template class Bvh<2>;
template class Bvh<3>;
template class Bvh<4>;

}  // namespace s4d
