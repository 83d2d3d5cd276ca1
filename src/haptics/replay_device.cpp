// Replay: the recorded state each tick (held at the last sample once the file ends).
#include "haptics/replay_device.hpp"

#include <cstring>

#include "core/error.hpp"

namespace s4d {

ReplayDevice::ReplayDevice(Trajectory trajectory, bool compare_forces)
    : trajectory_(std::move(trajectory)), compare_(compare_forces) {
  if (trajectory_.ticks.empty()) throw Error("replay: the trajectory has no ticks");
}

DeviceStatus ReplayDevice::read(const DeviceInput&, DeviceState& out) {
  const bool playing = next_ < trajectory_.ticks.size();
  playing_ = playing;
  current_ = playing ? next_++ : trajectory_.ticks.size() - 1;
  const TickRecord& r = trajectory_.ticks[current_];
  out = r.state();
  if (!playing) out.velocity.setZero();  // the file ended: the stylus rests at its last position
  events_ = playing ? r.events : 0;
  return playing && (r.events & kEventDisconnected) ? DeviceStatus::disconnected : DeviceStatus::ok;
}

void ReplayDevice::write_force(const Vec3& force) {
  if (!compare_ || !playing_) return;  // nothing recorded for ticks past the end
  const TickRecord& r = trajectory_.ticks[current_];
  ++compared_;
  double f[3] = {force[0], force[1], force[2]};
  if (std::memcmp(f, r.force, sizeof f) != 0) {
    if (mismatches_ == 0) first_mismatch_ = r.tick;
    ++mismatches_;
  }
}

}  // namespace s4d
