// HapticLoop: the 1 kHz servo thread. Each tick, in a fixed order: commands -> read device -> scene
// (tool force model + simulation steps) -> safety -> write force -> record -> publish a snapshot.
// Sleeps to absolute deadlines, measures its own period, owns device and scene while it runs.
#pragma once
#include <array>
#include <atomic>
#include <filesystem>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "haptics/device.hpp"
#include "haptics/force_safety.hpp"
#include "haptics/haptic_scene.hpp"
#include "haptics/period_stats.hpp"
#include "haptics/spsc_queue.hpp"
#include "haptics/trajectory_file.hpp"
#include "haptics/triple_buffer.hpp"

namespace s4d {

struct HapticLoopConfig {
  double rate_hz = 1000;            // Hz, servo rate
  bool realtime_priority = true;    // ask for SCHED_FIFO; without the privilege it runs at normal priority
  double reconnect_interval = 0.5;  // s, between reconnection attempts while the device is gone
  int publish_every = 4;            // ticks between snapshots (250 Hz at 1 kHz: ahead of a 60 Hz renderer)
  int cpu = -1;                     // pin the thread to this CPU when >= 0
};

// A UI request, copied through the bounded lock-free queue.
struct HapticCommand {
  enum class Kind : std::uint8_t { set_param, reset_scene, reset_stats, replace_device, scene };
  Kind kind = Kind::reset_stats;
  int index = 0;            // set_param: parameter index
  double value = 0;         // set_param: new value
  Device* device = nullptr;  // replace_device: ownership passes to the loop
  SceneCommand scene{};     // scene: handed to HapticScene::command
};

// What the renderer and panels see; immutable once published.
struct HapticSnapshot {
  static constexpr int kMaxParams = 16;
  std::uint64_t tick = 0;
  double time = 0;                    // s, ticks x nominal period
  bool running = false;
  bool realtime = false;              // SCHED_FIFO granted
  bool device_connected = true;
  const char* device_name = "";       // static storage (the backends' names)
  DeviceCapabilities caps;
  DeviceState device;
  ToolOutput tool;                    // requested force, anchor (C' / picked vertex)
  Vec3 force_output = Vec3::Zero();   // N, after safety
  double max_force_output = 0;        // N, largest output so far
  double safety_gain = 0;
  SafetyPhase safety_phase = SafetyPhase::waiting;
  SafetyCounters safety;
  PeriodSummary period;               // loop period (refreshed at 10 Hz)
  PeriodSummary work;                 // time spent inside a tick (us)
  std::array<float, PeriodStats::kRecent> recent_periods_us{};
  int recent_count = 0;
  std::array<SceneParam, kMaxParams> params{};
  int param_count = 0;
  std::vector<double> points;         // point_count x point_dimension, the scene's vertices
  int point_dimension = 3;
  std::vector<double> velocities;     // point_count x point_dimension
  std::vector<std::uint8_t> flags;    // point_count, bit 0: pinned
  SceneStatus status;                 // the simulating scene's status
  std::uint64_t reconnects = 0;       // times the device came back after it was gone
  std::uint64_t disconnects = 0;      // times it was lost
};

class HapticLoop {
 public:
  HapticLoop(std::unique_ptr<Device> device, std::unique_ptr<HapticScene> scene,
             const HapticLoopConfig& config = {});
  ~HapticLoop();
  HapticLoop(const HapticLoop&) = delete;
  HapticLoop& operator=(const HapticLoop&) = delete;

  // Starts the servo thread; throws Error when already running or the rate is out of [10, 20000] Hz.
  void start();
  // Stops and joins the thread; the device's last command is a zero force.
  void stop();
  bool running() const { return running_.load(); }

  // Runs n ticks on the calling thread, without sleeping or timing: the same tick the thread runs,
  // hence deterministic (tests, replays, scripted scenarios). Throws Error if the thread is running.
  void run_ticks(std::uint64_t n);

  // Records every tick from the next one on (call before start() / run_ticks, not while running).
  // `setup` (one line) tells a replay how the scene was built beyond its parameters.
  void record_to(const std::filesystem::path& path, const std::string& setup = "");
  // Flushes the recording; throws Error if ticks were lost or the file failed. Not while running.
  void finish_recording();

  // UI side (any thread; the loop never waits on these). False when the queue is full.
  bool post(const HapticCommand& cmd);
  bool set_param(int index, double value) { return post({HapticCommand::Kind::set_param, index, value}); }
  bool reset_scene() { return post({HapticCommand::Kind::reset_scene}); }
  bool reset_stats() { return post({HapticCommand::Kind::reset_stats}); }
  bool send(const SceneCommand& cmd) {
    HapticCommand c;
    c.kind = HapticCommand::Kind::scene;
    c.scene = cmd;
    return post(c);
  }
  // Swaps the device (the old one is destroyed on this thread later); throws Error if the queue is full.
  void replace_device(std::unique_ptr<Device> device);
  // The GUI pointer in device coordinates (m); one writer thread (the UI).
  void set_pointer(const Vec3& target, std::uint32_t buttons);

  // The latest snapshot; one reader thread (the UI). Valid until its next call.
  const HapticSnapshot& snapshot();

  // Direct access while the loop is not running (setup, tests).
  Device& device() { return *device_; }
  HapticScene& scene() { return *scene_; }
  ForceSafety& safety() { return safety_; }
  const HapticLoopConfig& config() const { return config_; }
  std::uint64_t ticks() const { return tick_.load(); }

 private:
  struct Pointer {
    Vec3 target = Vec3::Zero();
    std::uint32_t buttons = 0;
    bool valid = false;
  };

  void thread_main();
  void tick(bool deadline_missed);
  void apply(const HapticCommand& cmd, bool& reset);
  void publish();
  void collect_retired();

  HapticLoopConfig config_;
  double dt_;  // s, nominal period
  std::unique_ptr<Device> device_;
  std::unique_ptr<HapticScene> scene_;
  ForceSafety safety_;
  PeriodStats period_stats_, work_stats_;
  PeriodSummary period_summary_, work_summary_;
  DeviceState state_;
  ToolOutput tool_;
  Vec3 output_ = Vec3::Zero();
  double max_output_ = 0;  // N
  bool connected_ = true;
  bool pending_reset_ = false;  // a reset applied while stopped, reported to safety by the next tick
  std::uint64_t next_reconnect_tick_ = 0;
  std::uint64_t reconnects_ = 0;
  std::uint64_t disconnects_ = 0;
  std::unique_ptr<TrajectoryRecorder> recorder_;

  SpscQueue<HapticCommand, 256> commands_;
  std::mutex producer_mutex_;               // serialises UI threads; the loop never takes it
  SpscQueue<Device*, 16> retired_;          // devices replaced by the loop, deleted by the UI side
  TripleBuffer<Pointer> pointer_;
  TripleBuffer<HapticSnapshot> snapshots_;
  std::atomic<std::uint64_t> tick_{0};
  std::atomic<bool> running_{false}, stop_{false};
  bool realtime_ = false;
  std::thread thread_;
};

}  // namespace s4d
