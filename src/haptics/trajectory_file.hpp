// Device trajectories as text files: what a session's device stream looked like tick by tick (state,
// loop events, the force sent), written exactly (shortest round-trip decimals) so a replay through the
// same scene reproduces every force bit for bit. Also the background writer used while recording.
#pragma once
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <thread>
#include <utility>
#include <vector>

#include "haptics/device.hpp"
#include "haptics/spsc_queue.hpp"

namespace s4d {

// One servo tick. Plain arrays (not Eigen) so it crosses threads through a lock-free ring by memcpy.
struct TickRecord {
  std::uint64_t tick = 0;
  std::uint32_t events = 0;   // kEvent* bits seen by the safety layer this tick
  std::uint32_t buttons = 0;
  double position[3] = {};    // m
  double velocity[3] = {};    // m/s
  double target[3] = {};      // m
  double force[3] = {};       // N, the force written to the device (after safety)

  DeviceState state() const;
  void set_state(const DeviceState& s);
  Vec3 force_vec() const { return {force[0], force[1], force[2]}; }
};

struct TrajectoryHeader {
  double rate = 1000;           // Hz
  std::string device = "sim";   // backend that produced it
  std::string scene = "sticky-plane";
  DeviceCapabilities caps;      // the recorded device's limits (the safety layer depends on them)
  std::vector<std::pair<std::string, double>> params;  // scene parameters at the start
  std::string setup;            // how the scene was built, as the recording tool wrote it (one line)
};

struct Trajectory {
  TrajectoryHeader header;
  std::vector<TickRecord> ticks;
};

// Reads a trajectory; throws ParseError (file:line) on anything malformed and Error if unreadable.
Trajectory read_trajectory(const std::filesystem::path& path);
// The same from text in memory; `origin` names it in errors.
Trajectory parse_trajectory(std::string_view text, const std::string& origin);
void write_trajectory(const std::filesystem::path& path, const Trajectory& t);
std::string format_header(const TrajectoryHeader& h);
void append_record(std::string& out, const TickRecord& r);

// A generated trajectory: the hand draws `turns` circles of `radius` (m) in the z = 0 plane while
// pressing `depth` (m) into it, for `seconds` at `rate` Hz. Forces are left zero (not recorded).
Trajectory circle_trajectory(double seconds, double rate, double radius, double turns, double depth);

// Records ticks from the haptic loop thread: push() copies into a lock-free ring that a writer thread
// drains to the file, so the loop never touches the disk.
class TrajectoryRecorder {
 public:
  // Opens the file and writes the header; throws Error when it cannot be created.
  TrajectoryRecorder(const std::filesystem::path& path, const TrajectoryHeader& header);
  ~TrajectoryRecorder();
  TrajectoryRecorder(const TrajectoryRecorder&) = delete;
  TrajectoryRecorder& operator=(const TrajectoryRecorder&) = delete;

  // Loop thread. False (and counted) when the writer fell 16 s behind.
  bool push(const TickRecord& r);
  // Flushes and closes; throws Error if writing failed or ticks were dropped.
  void close();
  std::uint64_t written() const { return written_.load(); }
  std::uint64_t dropped() const { return dropped_.load(); }
  const std::filesystem::path& path() const { return path_; }

 private:
  void drain();

  std::filesystem::path path_;
  std::ofstream file_;
  SpscQueue<TickRecord, 16384> queue_;
  std::atomic<bool> stop_{false};
  std::atomic<std::uint64_t> written_{0}, dropped_{0};
  std::thread writer_;
  bool closed_ = false;
};

}  // namespace s4d
