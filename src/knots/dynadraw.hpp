// Dynadraw stroke smoothing (Haeberli 1989; the paper's section 4.2): a virtual mass pulled towards
// the cursor by a damped spring traces a smooth, calligraphic version of a jittery hand stroke.
#pragma once
#include <vector>

#include "core/vec.hpp"

namespace s4d {

struct DynadrawParams {
  double mass = 1.0;        // kg, the pen's virtual mass
  double stiffness = 400;   // N/m, spring from pen to cursor
  double damping = 30;      // N·s/m, drag on the pen (40 = critical for these m, k)
};

// One pen, fed cursor samples as they arrive. Works in any dimension (2D sketch plane, 3D, 4D).
template <int D>
class Dynadraw {
 public:
  explicit Dynadraw(const DynadrawParams& p = {}) : p_(p) {}

  // Puts the pen at rest on `at` (the start of a stroke).
  void reset(const Vec<D>& at) {
    x_ = at;
    v_ = Vec<D>::Zero();
    started_ = true;
  }
  // Advances the pen by dt seconds towards `cursor` and returns its new position. Semi-implicit
  // in the drag, so any dt > 0 is stable for the damping term; non-finite input leaves the pen.
  const Vec<D>& step(const Vec<D>& cursor, double dt) {
    if (!started_) reset(cursor);
    if (!(dt > 0) || !cursor.allFinite()) return x_;
    const Vec<D> a = p_.stiffness / p_.mass * (cursor - x_);
    v_ = (v_ + dt * a) / (1.0 + dt * p_.damping / p_.mass);
    x_ += dt * v_;
    return x_;
  }
  const Vec<D>& position() const { return x_; }
  const Vec<D>& velocity() const { return v_; }

 private:
  DynadrawParams p_;
  Vec<D> x_ = Vec<D>::Zero();  // pen position
  Vec<D> v_ = Vec<D>::Zero();  // pen velocity
  bool started_ = false;
};

// Smooths a whole stroke sampled every dt seconds: the pen starts on the first sample, follows
// the rest, and is then allowed `settle_steps` extra steps on the last sample so the stroke ends
// where the hand stopped. Returns one pen position per input sample plus the settling ones.
template <int D>
std::vector<Vec<D>> dynadraw_stroke(const std::vector<Vec<D>>& samples, double dt,
                                    const DynadrawParams& p = {}, int settle_steps = 0) {
  std::vector<Vec<D>> out;
  if (samples.empty()) return out;
  Dynadraw<D> pen(p);
  pen.reset(samples.front());
  out.reserve(samples.size() + settle_steps);
  for (const auto& s : samples) out.push_back(pen.step(s, dt));
  for (int i = 0; i < settle_steps; ++i) out.push_back(pen.step(samples.back(), dt));
  return out;
}

}  // namespace s4d
