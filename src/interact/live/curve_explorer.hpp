// CurveExplorer: the paper's navigation of a knot's image (4.3.1, Fig. 5): a probe held to the
// curve's image in the view walks along its own strand — from segment to adjacent segment, so at
// a crossing it goes on along its strand instead of jumping to the visually nearer one — guided
// by the force suggestion (C_p = C + V/R projected onto the image, a damped spring); every
// crossing it passes is an event, over or under (4.3.2), and the Gauss code is built up from them.
//
// The image (the curve seen through the view, with its crossings) is built off the loop thread
// (build_curve_image allocates) and swapped in by the tick, which never allocates.
#pragma once
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/frame.hpp"
#include "haptics/force_models.hpp"
#include "haptics/spsc_queue.hpp"
#include "shape/curve.hpp"

namespace s4d {

struct CurveCrossingEvent {
  double time = 0;
  int label = 0;         // 1-based: crossings numbered by first visit along the curve (Gauss code)
  bool over = false;     // the probe's strand passes over there
  double point[2] = {};  // view (x, y) of the crossing
};

// A position on the image: a component, a segment of it and the fraction along that segment.
struct CurveProbe {
  int component = -1, segment = 0;
  double t = 0;
  bool valid() const { return component >= 0; }
};

// The curve as the view shows it: per component its points' view (x, y) and depth, and the
// crossings on it in order along it.
struct CurveImage {
  struct Mark {  // a crossing as one strand meets it
    int segment = 0;
    double t = 0;
    int label = 0;
    bool over = false;
    Vec2 point = Vec2::Zero();
  };
  struct Component {
    std::vector<Vec2> image;
    std::vector<double> depth;  // larger = nearer the eye
    bool closed = false;
    std::vector<Mark> marks;    // by (segment, t)
    int segments() const { return closed ? static_cast<int>(image.size()) : static_cast<int>(image.size()) - 1; }
  };
  std::vector<Component> components;
  int crossings = 0;
  Frame<3> frame;  // the view: its first two axes span the image, the third points at the eye
  bool same_layout(const CurveImage& o) const;  // the same components with the same point counts
};

// The image of `curve` through `frame`, crossings labelled 1, 2, ... by first visit walking the
// components in order from their first point (as KnotDiagram's Gauss code numbers them). Throws
// s4d::Error for a curve with no component or a component of fewer than 2 points.
std::unique_ptr<CurveImage> build_curve_image(const Curve<3>& curve, const Frame<3>& frame);

class CurveExplorer {
 public:
  static constexpr std::size_t kEventCapacity = 256;
  static constexpr std::size_t kGaussCapacity = 4096;

  CurveExplorer();
  // Takes `image` in place of the current one, which `image` then holds (to be freed off the loop
  // thread; the swap itself never allocates). The probe keeps its place when the layout is the
  // same, else it is lifted.
  void swap_image(CurveImage& image) noexcept;
  const CurveImage& image() const { return *image_; }
  // Puts the probe at the point of the image nearest (x, y) of the view; starts a new Gauss code.
  bool place(const Vec2& at) noexcept;
  void lift() noexcept { probe_ = CurveProbe{}; }

  // The tick: the probe walks its strand towards the prediction C + V/R of the hand's view point
  // `c` moving at `v`; returns the navigation spring's force from c towards the probe (view x, y).
  Vec2 update(const Vec2& c, const Vec2& v, double rate_hz, double time, const DampedSpring& spring) noexcept;
  // Walks the probe towards `target` along its strand; returns where it ends (view x, y).
  Vec2 move_to(const Vec2& target, double time) noexcept;

  std::optional<CurveCrossingEvent> pop_event() { return events_.try_pop(); }
  const CurveProbe& probe() const { return probe_; }
  Vec2 probe_point() const;
  double probe_depth() const;  // the strand's view depth where the probe is
  int crossing_count() const { return image_->crossings; }
  // The Gauss code of the passes so far, "+k" over, "-k" under (the paper's students' request).
  const std::vector<int>& gauss_so_far() const { return gauss_; }
  std::string gauss_text() const;
  // How far (image units) the probe must get from a crossing before passing it again counts: the
  // hand's tremor at a crossing must not ring a cue per jitter.
  void set_rearm_distance(double d) { rearm_ = std::isfinite(d) && d >= 0 ? d : 0; }

 private:
  Vec2 point(int comp, int seg, double t) const;
  void passed(int comp, int seg, double t0, double t1, double time) noexcept;

  std::unique_ptr<CurveImage> image_ = std::make_unique<CurveImage>();
  CurveProbe probe_;
  SpscQueue<CurveCrossingEvent, kEventCapacity> events_;
  std::vector<int> gauss_;
  double rearm_ = 0;
  int last_label_ = 0;  // the crossing passed last, not passable again until the probe is rearm_ away
  Vec2 last_point_ = Vec2::Zero();
  bool armed_ = true;
};

}  // namespace s4d
