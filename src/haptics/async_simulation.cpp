// The simulation thread: read the latest tool force, step, publish, and never run ahead of the haptic clock.
#include "haptics/async_simulation.hpp"

#include <chrono>

#include "core/error.hpp"

namespace s4d {

AsyncSimulation::AsyncSimulation(std::unique_ptr<GrabbableSimulation> inner, double step_dt)
    : inner_(std::move(inner)), step_dt_(step_dt) {
  if (!inner_) throw Error("async simulation needs a simulation");
  if (!(step_dt > 0)) throw Error("async simulation step must be positive");
  n_ = inner_->vertex_count();
  dim_ = inner_->point_dimension();
  for (State& s : state_.slots_unsynchronised()) {  // sized once: no allocation while running
    s.position.resize(n_);
    s.velocity.resize(n_);
    s.points.resize(static_cast<std::size_t>(n_) * dim_);
  }
  publish();
  current_ = &state_.read();
  thread_ = std::thread([this] { run(); });
}

AsyncSimulation::~AsyncSimulation() {
  stop_.store(true);
  if (thread_.joinable()) thread_.join();
}

void AsyncSimulation::set_external_force(int v, const Vec3& f) { force_.write({v, f}); }

void AsyncSimulation::step(double dt) {
  haptic_ns_.fetch_add(static_cast<std::uint64_t>(dt * 1e9 + 0.5), std::memory_order_relaxed);
  current_ = &state_.read();
}

double AsyncSimulation::lag() const {
  return (haptic_ns_.load(std::memory_order_relaxed) - skipped_ns_.load(std::memory_order_relaxed)) * 1e-9 -
         static_cast<double>(sim_steps_.load(std::memory_order_relaxed)) * step_dt_;
}

void AsyncSimulation::copy_points(std::span<double> out) const {
  const std::size_t n = std::min(out.size(), current_->points.size());
  std::copy_n(current_->points.begin(), n, out.begin());
}

void AsyncSimulation::publish() {
  State& s = state_.back();
  for (int v = 0; v < n_; ++v) {
    s.position[v] = inner_->shadow_position(v);
    s.velocity[v] = inner_->shadow_velocity(v);
  }
  inner_->copy_points(s.points);
  state_.publish();
}

void AsyncSimulation::run() {
  const auto step_ns = static_cast<std::uint64_t>(step_dt_ * 1e9 + 0.5);
  while (!stop_.load(std::memory_order_relaxed)) {
    if (reset_requested_.exchange(false, std::memory_order_acq_rel)) {
      inner_->reset();
      publish();
    }
    const std::uint64_t steps = sim_steps_.load(std::memory_order_relaxed);
    const std::uint64_t target =
        haptic_ns_.load(std::memory_order_relaxed) - skipped_ns_.load(std::memory_order_relaxed);
    if (target > steps * step_ns + kMaxLagNs) {
      // Too slow for real time: let the simulation run in slow motion rather than race to catch up later.
      skipped_ns_.fetch_add(target - steps * step_ns - kMaxLagNs, std::memory_order_relaxed);
    }
    if ((steps + 1) * step_ns > target) {
      std::this_thread::sleep_for(std::chrono::microseconds(200));  // ahead of the haptic clock: wait
      continue;
    }
    const Force& f = force_.read();
    inner_->set_external_force(f.vertex, f.force);
    inner_->step(step_dt_);
    sim_steps_.store(steps + 1, std::memory_order_relaxed);
    publish();
  }
}

}  // namespace s4d
