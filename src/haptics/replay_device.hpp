// ReplayDevice: plays a recorded or generated trajectory tick by tick, deterministically, and checks
// the forces the loop writes against the recorded ones (bit for bit) when the file has them.
#pragma once
#include "haptics/trajectory_file.hpp"

namespace s4d {

class ReplayDevice final : public Device {
 public:
  // `compare_forces`: the trajectory was recorded from a session, so its force columns are meaningful.
  ReplayDevice(Trajectory trajectory, bool compare_forces);
  std::string_view name() const override { return "replay"; }
  const DeviceCapabilities& capabilities() const override { return trajectory_.header.caps; }
  DeviceStatus read(const DeviceInput& in, DeviceState& out) override;
  void write_force(const Vec3& force) override;
  std::optional<std::uint32_t> scripted_events() const override { return events_; }

  const Trajectory& trajectory() const { return trajectory_; }
  bool finished() const { return next_ >= trajectory_.ticks.size(); }
  std::size_t played() const { return next_; }
  std::uint64_t compared() const { return compared_; }
  std::uint64_t mismatches() const { return mismatches_; }
  // The first mismatching tick (valid when mismatches() > 0).
  std::uint64_t first_mismatch_tick() const { return first_mismatch_; }

 private:
  Trajectory trajectory_;
  bool compare_;
  std::size_t next_ = 0;      // index of the next record to play
  std::size_t current_ = 0;   // index of the record played last
  std::uint32_t events_ = 0;
  bool playing_ = false;      // the last read() played a record (not past the end)
  std::uint64_t compared_ = 0, mismatches_ = 0, first_mismatch_ = 0;
};

}  // namespace s4d
