// AsyncSimulation: runs a GrabbableSimulation on its own thread, so a simulation slower than the servo
// period (a 64 x 64 cloth with collision avoidance) never stalls the 1 kHz haptic loop. The loop sees
// the latest published vertex state and posts the tool force; the simulation follows the loop's clock
// and falls behind real time, instead of the loop, when it cannot keep up. Not deterministic: replays
// and tests use the simulation directly.
#pragma once
#include <atomic>
#include <cstdint>
#include <memory>
#include <thread>
#include <vector>

#include "haptics/rubber_band_scene.hpp"
#include "haptics/triple_buffer.hpp"

namespace s4d {

class AsyncSimulation final : public GrabbableSimulation {
 public:
  // `step_dt`: the simulation's own step (s); it runs one step per step_dt of haptic time.
  explicit AsyncSimulation(std::unique_ptr<GrabbableSimulation> inner, double step_dt = 1e-3);
  ~AsyncSimulation() override;

  int vertex_count() const override { return n_; }
  Vec3 shadow_position(int v) const override { return current_->position[v]; }
  Vec3 shadow_velocity(int v) const override { return current_->velocity[v]; }
  void set_external_force(int v, const Vec3& f) override;
  // Haptic side: advances the haptic clock by dt and picks up the latest simulation state.
  void step(double dt) override;
  void reset() override { reset_requested_.store(true, std::memory_order_release); }
  int point_dimension() const override { return dim_; }
  void copy_points(std::span<double> out) const override;

  std::uint64_t simulation_steps() const { return sim_steps_.load(std::memory_order_relaxed); }
  // Haptic time minus simulated time (s), at most 0.1 s; beyond that the simulation runs in slow motion.
  double lag() const;

 private:
  struct State {
    std::vector<Vec3> position, velocity;  // nv each, shadow coordinates
    std::vector<double> points;            // nv x dim, for rendering
  };
  struct Force {
    int vertex = -1;
    Vec3 force = Vec3::Zero();
  };
  void run();
  void publish();

  std::unique_ptr<GrabbableSimulation> inner_;
  int n_, dim_;
  double step_dt_;
  TripleBuffer<State> state_;  // simulation thread -> haptic thread
  TripleBuffer<Force> force_;  // haptic thread -> simulation thread
  const State* current_;       // haptic side: the state read at the last step()
  std::atomic<std::uint64_t> haptic_ns_{0};  // haptic clock, ns
  std::atomic<std::uint64_t> sim_steps_{0};
  std::atomic<std::uint64_t> skipped_ns_{0};  // haptic time the simulation gave up on (slow motion)
  static constexpr std::uint64_t kMaxLagNs = 100'000'000;  // 0.1 s: the most the simulation trails by
  std::atomic<bool> reset_requested_{false}, stop_{false};
  std::thread thread_;
};

}  // namespace s4d
