// AsyncSimulation: the simulation follows the haptic clock on its own thread, receives the tool force,
// publishes whole states, and a slow simulation never blocks the haptic side.
#include "haptics/async_simulation.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

namespace s4d {
namespace {

// Two free unit-mass points; optionally slow (sleeps in every step), counting its steps.
class PointsSim final : public GrabbableSimulation {
 public:
  explicit PointsSim(int sleep_us = 0) : sleep_us_(sleep_us) {}
  int vertex_count() const override { return 2; }
  Vec3 shadow_position(int v) const override { return x_[v]; }
  Vec3 shadow_velocity(int v) const override { return v_[v]; }
  void set_external_force(int v, const Vec3& f) override {
    f_[0] = f_[1] = Vec3::Zero();
    if (v >= 0) f_[v] = f;
  }
  void step(double dt) override {
    if (sleep_us_) std::this_thread::sleep_for(std::chrono::microseconds(sleep_us_));
    for (int i = 0; i < 2; ++i) {
      v_[i] += dt * f_[i];
      x_[i] += dt * v_[i];
    }
    ++steps;
  }
  void reset() override {
    x_[0] = x_[1] = v_[0] = v_[1] = Vec3::Zero();
    steps = 0;
  }
  std::atomic<int> steps{0};

 private:
  int sleep_us_;
  Vec3 x_[2] = {Vec3::Zero(), Vec3::Zero()}, v_[2] = {Vec3::Zero(), Vec3::Zero()};
  Vec3 f_[2] = {Vec3::Zero(), Vec3::Zero()};
};

template <typename Pred>
bool wait_for(Pred pred) {
  for (int i = 0; i < 2000 && !pred(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  return pred();
}

TEST(AsyncSimulation, FollowsTheHapticClockAndAppliesTheForce) {
  auto inner = std::make_unique<PointsSim>();
  PointsSim* raw = inner.get();
  AsyncSimulation sim(std::move(inner), 1e-3);
  EXPECT_EQ(sim.vertex_count(), 2);
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_EQ(sim.simulation_steps(), 0u) << "never runs ahead of the haptic clock";
  sim.set_external_force(1, Vec3(0, 2, 0));
  for (int i = 0; i < 100; ++i) sim.step(1e-3);
  ASSERT_TRUE(wait_for([&] { return sim.simulation_steps() == 100; }));
  std::this_thread::sleep_for(std::chrono::milliseconds(10));
  EXPECT_EQ(sim.simulation_steps(), 100u);
  EXPECT_EQ(raw->steps.load(), 100);
  sim.step(0);  // pick up the latest state
  ASSERT_TRUE(wait_for([&] {
    sim.step(0);
    return sim.shadow_position(1).y() > 0;
  }));
  EXPECT_EQ(sim.shadow_position(0), Vec3::Zero()) << "only the held vertex moved";
  EXPECT_GT(sim.shadow_velocity(1).y(), 0);
  std::vector<double> pts(6);
  sim.copy_points(pts);
  EXPECT_EQ(pts[4], sim.shadow_position(1).y());
  sim.reset();
  ASSERT_TRUE(wait_for([&] {
    sim.step(0);
    return sim.shadow_position(1) == Vec3::Zero();
  }));
}

TEST(AsyncSimulation, ASlowSimulationNeverBlocksTheHapticSide) {
  AsyncSimulation sim(std::make_unique<PointsSim>(5000), 1e-3);  // 5 ms per 1 ms step
  double worst_us = 0;
  for (int i = 0; i < 300; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    sim.set_external_force(0, Vec3(1, 0, 0));
    sim.step(1e-3);
    (void)sim.shadow_position(0);
    worst_us = std::max(
        worst_us, std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count());
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  EXPECT_LT(worst_us, 1000) << "the haptic side only swaps buffers";
  EXPECT_LT(sim.simulation_steps(), 200u) << "the simulation fell behind";
  EXPECT_LE(sim.lag(), 0.1 + 0.01) << "but trails by at most 0.1 s (slow motion beyond)";
}

}  // namespace
}  // namespace s4d
