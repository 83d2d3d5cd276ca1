// The haptic servo loop: absolute-deadline sleeping with clock_nanosleep(TIMER_ABSTIME), one ordered
// tick, lock-free publishing. Nothing here throws or allocates once running (snapshot point buffers
// are sized on first publish).
#include "haptics/haptic_loop.hpp"

#include <pthread.h>
#include <sched.h>
#include <time.h>

#include <algorithm>
#include <cerrno>
#include <cmath>

#include "core/error.hpp"

namespace s4d {
namespace {

std::int64_t now_ns() {
  timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec;
}

timespec to_timespec(std::int64_t ns) {
  return {static_cast<time_t>(ns / 1'000'000'000), static_cast<long>(ns % 1'000'000'000)};
}

}  // namespace

HapticLoop::HapticLoop(std::unique_ptr<Device> device, std::unique_ptr<HapticScene> scene,
                       const HapticLoopConfig& config)
    : config_(config),
      dt_(1.0 / config.rate_hz),
      device_(std::move(device)),
      scene_(std::move(scene)),
      period_stats_(1e6 / config.rate_hz),
      work_stats_(1e6 / config.rate_hz) {
  if (!device_ || !scene_) throw Error("haptic loop needs a device and a scene");
  if (!(config.rate_hz >= 10 && config.rate_hz <= 20000))
    throw Error("haptic rate must be between 10 and 20000 Hz, got " + std::to_string(config.rate_hz));
  safety_.set_config(SafetyConfig::for_device(device_->capabilities()));
  config_.publish_every = std::max(1, config_.publish_every);
  publish();
}

HapticLoop::~HapticLoop() {
  stop();
  collect_retired();
  if (recorder_) {
    try {
      recorder_->close();
    } catch (...) {  // a destructor cannot report; finish_recording() is the checked path
    }
  }
}

void HapticLoop::start() {
  if (running_.load()) throw Error("haptic loop already running");
  stop_.store(false);
  running_.store(true);
  thread_ = std::thread([this] { thread_main(); });
}

void HapticLoop::stop() {
  if (!thread_.joinable()) return;
  stop_.store(true);
  thread_.join();
  running_.store(false);
  publish();
  collect_retired();
}

void HapticLoop::run_ticks(std::uint64_t n) {
  if (running_.load()) throw Error("run_ticks: the haptic thread is running");
  for (std::uint64_t i = 0; i < n; ++i) tick(false);
  publish();
}

void HapticLoop::record_to(const std::filesystem::path& path, const std::string& setup) {
  if (running_.load()) throw Error("start recording before the haptic loop runs");
  TrajectoryHeader h;
  h.rate = config_.rate_hz;
  h.device = std::string(device_->name());
  h.scene = std::string(scene_->name());
  h.caps = device_->capabilities();
  h.setup = setup.substr(0, setup.find('\n'));
  for (const SceneParam& p : scene_->params()) h.params.emplace_back(p.name, p.value);
  if (recorder_) recorder_->close();
  recorder_ = std::make_unique<TrajectoryRecorder>(path, h);
}

void HapticLoop::finish_recording() {
  if (running_.load()) throw Error("stop the haptic loop before finishing the recording");
  if (!recorder_) return;
  auto r = std::move(recorder_);
  r->close();
}

bool HapticLoop::post(const HapticCommand& cmd) {
  std::lock_guard lock(producer_mutex_);
  collect_retired();
  if (!running_.load()) {  // no thread: apply right away; a reset is reported by the next tick
    bool reset = false;
    apply(cmd, reset);
    pending_reset_ = pending_reset_ || reset;
    publish();
    collect_retired();
    return true;
  }
  return commands_.try_push(cmd);
}

void HapticLoop::replace_device(std::unique_ptr<Device> device) {
  if (!device) throw Error("replace_device: no device");
  Device* raw = device.release();
  if (!post({HapticCommand::Kind::replace_device, 0, 0, raw})) {
    delete raw;
    throw Error("haptic loop command queue is full; try again");
  }
}

void HapticLoop::set_pointer(const Vec3& target, std::uint32_t buttons) {
  pointer_.write({target, buttons, true});
}

const HapticSnapshot& HapticLoop::snapshot() { return snapshots_.read(); }

void HapticLoop::collect_retired() {
  while (auto d = retired_.try_pop()) delete *d;
}

void HapticLoop::apply(const HapticCommand& cmd, bool& reset) {
  switch (cmd.kind) {
    case HapticCommand::Kind::set_param:
      scene_->set_param(cmd.index, cmd.value);
      break;
    case HapticCommand::Kind::reset_scene:
      scene_->reset();
      reset = true;
      break;
    case HapticCommand::Kind::scene:
      scene_->command(cmd.scene);
      break;
    case HapticCommand::Kind::reset_stats:
      period_stats_.reset();
      work_stats_.reset();
      period_summary_ = period_stats_.summary();
      work_summary_ = work_stats_.summary();
      break;
    case HapticCommand::Kind::replace_device: {
      if (!cmd.device) break;
      device_->write_force(Vec3::Zero());
      Device* old = device_.release();
      device_.reset(cmd.device);
      if (!retired_.try_push(old)) delete old;  // the UI has not collected 16 old devices: rare
      safety_.set_config(SafetyConfig::for_device(device_->capabilities()));
      connected_ = true;
      break;
    }
  }
}

void HapticLoop::tick(bool deadline_missed) {
  const std::uint64_t t = tick_.load(std::memory_order_relaxed);
  bool reset = pending_reset_;
  pending_reset_ = false;
  for (int i = 0; i < 32; ++i) {  // bounded per tick so a flood of commands cannot stall the servo
    auto cmd = commands_.try_pop();
    if (!cmd) break;
    apply(*cmd, reset);
  }

  const Pointer& p = pointer_.read();
  const DeviceInput in{dt_, p.target, p.buttons, p.valid};
  DeviceState s;
  const bool was_connected = connected_;
  connected_ = device_->read(in, s) == DeviceStatus::ok;
  if (connected_ && !was_connected) ++reconnects_;  // back, by reconnect() or by itself
  if (!connected_ && was_connected) ++disconnects_;
  if (connected_ && s.position.allFinite() && s.velocity.allFinite()) {
    state_ = s;
  } else {
    state_.velocity.setZero();  // hold the last known pose: the scene keeps running undisturbed
    if (!connected_ && was_connected) next_reconnect_tick_ = t + 1;
  }
  if (!connected_ && t >= next_reconnect_tick_) {
    next_reconnect_tick_ = t + static_cast<std::uint64_t>(std::max(1.0, config_.reconnect_interval / dt_));
    device_->reconnect();  // takes effect from the next read
  }

  std::uint32_t events = (deadline_missed ? kEventDeadlineMissed : 0) | (reset ? kEventSceneReset : 0) |
                         (connected_ ? 0 : kEventDisconnected);
  if (const auto scripted = device_->scripted_events()) {  // a replay reproduces the recorded events
    if ((*scripted & kEventSceneReset) && !reset) scene_->reset();
    events = *scripted | (connected_ ? 0 : kEventDisconnected);
  }

  tool_ = scene_->step(state_, dt_);
  output_ = safety_.apply(tool_.force,
                          {(events & kEventDeadlineMissed) != 0, (events & kEventSceneReset) != 0,
                           (events & kEventDisconnected) == 0},
                          dt_);
  if (connected_) device_->write_force(output_);
  max_output_ = std::max(max_output_, output_.norm());

  if (recorder_) {
    TickRecord r;
    r.tick = t;
    r.events = events;
    r.set_state(state_);
    for (int k = 0; k < 3; ++k) r.force[k] = output_[k];
    recorder_->push(r);
  }
  tick_.store(t + 1, std::memory_order_relaxed);
  if ((t + 1) % static_cast<std::uint64_t>(config_.publish_every) == 0) publish();
}

void HapticLoop::publish() {
  HapticSnapshot& s = snapshots_.back();
  s.tick = tick_.load(std::memory_order_relaxed);
  s.time = static_cast<double>(s.tick) * dt_;
  s.running = running_.load(std::memory_order_relaxed);
  s.realtime = realtime_;
  s.device_connected = connected_;
  s.device_name = device_->name().data();
  s.caps = device_->capabilities();
  s.device = state_;
  s.tool = tool_;
  s.force_output = output_;
  s.max_force_output = max_output_;
  s.safety_gain = safety_.gain();
  s.safety_phase = safety_.phase();
  s.safety = safety_.counters();
  s.period = period_summary_;
  s.work = work_summary_;
  s.recent_count = period_stats_.recent(s.recent_periods_us);
  const auto params = scene_->params();
  s.param_count = std::min<int>(static_cast<int>(params.size()), HapticSnapshot::kMaxParams);
  std::copy_n(params.begin(), s.param_count, s.params.begin());
  s.point_dimension = scene_->point_dimension();
  const std::size_t n = static_cast<std::size_t>(scene_->point_count()) * s.point_dimension;
  if (s.points.size() != n) s.points.resize(n);  // allocates only when the scene's size changes
  scene_->copy_points(s.points);
  if (s.velocities.size() != n) s.velocities.resize(n);
  scene_->copy_velocities(s.velocities);
  const std::size_t nf = static_cast<std::size_t>(scene_->point_count());
  if (s.flags.size() != nf) s.flags.resize(nf);
  scene_->copy_flags(s.flags);
  scene_->copy_status(s.status);
  s.reconnects = reconnects_;
  s.disconnects = disconnects_;
  snapshots_.publish();
}

void HapticLoop::thread_main() {
#ifdef __linux__  // real-time scheduling and pinning are Linux's (the web page never starts the thread)
  if (config_.realtime_priority) {
    sched_param sp{};
    sp.sched_priority = std::min(80, sched_get_priority_max(SCHED_FIFO));
    realtime_ = pthread_setschedparam(pthread_self(), SCHED_FIFO, &sp) == 0;
  }
  if (config_.cpu >= 0) {
    cpu_set_t set;
    CPU_ZERO(&set);
    CPU_SET(config_.cpu, &set);
    pthread_setaffinity_np(pthread_self(), sizeof set, &set);
  }
#endif
  const auto period = static_cast<std::int64_t>(std::llround(1e9 / config_.rate_hz));
  const std::uint64_t summary_every =
      std::max<std::uint64_t>(1, static_cast<std::uint64_t>(config_.rate_hz / 10));
  std::int64_t deadline = now_ns();
  std::int64_t last_wake = deadline;
  bool missed = false;
  std::uint64_t n = 0;
  while (!stop_.load(std::memory_order_relaxed)) {
    deadline += period;
    const timespec ts = to_timespec(deadline);
    while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) == EINTR) {
    }
    const std::int64_t wake = now_ns();
    period_stats_.add_period(static_cast<double>(wake - last_wake) * 1e-3);
    period_stats_.add_lateness(static_cast<double>(wake - deadline) * 1e-3);
    last_wake = wake;
    tick(missed);
    const std::int64_t end = now_ns();
    work_stats_.add_period(static_cast<double>(end - wake) * 1e-3);
    // Finishing after the next deadline means that tick is already late: count it and re-align the
    // schedule to now instead of bursting through the lost ticks.
    missed = end > deadline + period;
    if (missed) {
      period_stats_.add_missed();
      deadline = end - period;
    }
    if (++n % summary_every == 0) {
      period_summary_ = period_stats_.summary();
      work_summary_ = work_stats_.summary();
    }
  }
  device_->write_force(Vec3::Zero());
  period_summary_ = period_stats_.summary();
  work_summary_ = work_stats_.summary();
}

}  // namespace s4d
