// The rubber band tool: pick on button press, damped spring while held, reaction into the simulation.
#include "haptics/rubber_band_scene.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "haptics/force_models.hpp"

namespace s4d {

void GrabbableSimulation::copy_points(std::span<double> out) const {
  const int n = std::min<int>(vertex_count(), static_cast<int>(out.size() / 3));
  for (int v = 0; v < n; ++v) {
    const Vec3 p = shadow_position(v);
    for (int k = 0; k < 3; ++k) out[3 * v + k] = p[k];
  }
}

int GrabbableSimulation::nearest_vertex(const Vec3& p) const {
  int best = -1;
  double best_d2 = std::numeric_limits<double>::infinity();
  for (int v = 0; v < vertex_count(); ++v) {
    const double d2 = (shadow_position(v) - p).squaredNorm();
    if (d2 < best_d2) {
      best_d2 = d2;
      best = v;
    }
  }
  return best;
}

RubberBandScene::RubberBandScene(std::unique_ptr<GrabbableSimulation> sim) : sim_(std::move(sim)) {
  params_[kK] = {"K", 150, 0, 1000, "N/m"};
  params_[kB] = {"B", 0.5, 0, 10, "N s/m"};
  params_[kSubsteps] = {"substeps", 1, 1, 16, ""};
  params_[kHold] = {"hold", 0, 0, 1, "1 = held without a button"};
}

void RubberBandScene::reset() {
  sim_->set_external_force(-1, Vec3::Zero());
  sim_->reset();
  picked_ = -1;
}

ToolOutput RubberBandScene::step(const DeviceState& device, double dt) {
  ToolOutput out;
  out.anchor = device.position;
  const bool held = (device.buttons & 1u) || params_[kHold].value >= 0.5;
  if (!held) {
    picked_ = -1;
  } else if (picked_ < 0) {
    picked_ = sim_->nearest_vertex(device.position);
  }
  const int substeps = std::clamp(static_cast<int>(std::lround(params_[kSubsteps].value)), 1, 16);
  const double h = dt / substeps;
  Vec3 felt = Vec3::Zero();
  for (int s = 0; s < substeps; ++s) {
    if (picked_ >= 0) {
      // The pointer moves over the tick; hold it at its sampled position (zero-order hold, as the device).
      const auto band = rubber_band_force<3>(device.position, device.velocity, sim_->shadow_position(picked_),
                                             sim_->shadow_velocity(picked_),
                                             {params_[kK].value, params_[kB].value});
      sim_->set_external_force(picked_, band.on_b);
      felt += band.on_a;
    } else {
      sim_->set_external_force(-1, Vec3::Zero());
    }
    sim_->step(h);
  }
  if (picked_ >= 0) {
    out.force = felt / substeps;  // average over the tick: what a 1 kHz device can render
    out.anchor = sim_->shadow_position(picked_);
    out.engaged = true;
  }
  return out;
}

}  // namespace s4d
