// The libspnav backend. libspnav keeps one global connection, so at most one SpacenavDevice exists.
#include "haptics/spacenav_device.hpp"

#include <poll.h>
#include <sys/socket.h>

#include <algorithm>
#include <cstdlib>

#include "core/error.hpp"

#ifdef S4D_HAVE_SPNAV
#include <spnav.h>
#endif

namespace s4d {

bool SpacenavDevice::available_in_build() {
#ifdef S4D_HAVE_SPNAV
  return true;
#else
  return false;
#endif
}

SpacenavDevice::SpacenavDevice(const SpacenavConfig& config) : config_(config) {
  caps_.workspace_min = -config.half_extent;
  caps_.workspace_max = config.half_extent;
  caps_.outputs_force = false;
  caps_.max_force = 0;
  caps_.nominal_rate = 1000;
#ifdef S4D_HAVE_SPNAV
  if (spnav_open() == -1)
    throw Error("spacenav: cannot connect to spacenavd (no spacenavd running? start it with "
                "'spacenavd' or 'systemctl start spacenavd')");
  open_ = true;
#else
  throw Error("spacenav: this build has no libspnav support (install libspnav-dev and reconfigure)");
#endif
}

SpacenavDevice::~SpacenavDevice() {
#ifdef S4D_HAVE_SPNAV
  if (open_) spnav_close();
#endif
}

bool SpacenavDevice::reconnect() {
#ifdef S4D_HAVE_SPNAV
  if (open_) spnav_close();
  open_ = spnav_open() != -1;
  axes_.fill(0);  // a stale deflection must not keep the stylus moving
  return open_;
#else
  return false;
#endif
}

DeviceStatus SpacenavDevice::read(const DeviceInput& in, DeviceState& out) {
#ifdef S4D_HAVE_SPNAV
  if (!open_) return DeviceStatus::disconnected;
  // A daemon that went away leaves the socket readable at end-of-file, or hung up.
  const int fd = spnav_fd();
  if (fd < 0) return DeviceStatus::disconnected;
  pollfd p{fd, POLLIN, 0};
  if (::poll(&p, 1, 0) > 0) {
    char byte;
    if ((p.revents & (POLLHUP | POLLERR | POLLNVAL)) ||
        ((p.revents & POLLIN) && ::recv(fd, &byte, 1, MSG_PEEK | MSG_DONTWAIT) == 0)) {
      spnav_close();
      open_ = false;
      axes_.fill(0);
      return DeviceStatus::disconnected;
    }
  }
  spnav_event ev;
  while (spnav_poll_event(&ev) > 0) {
    if (ev.type == SPNAV_EVENT_MOTION) {
      axes_ = {ev.motion.x, ev.motion.y, ev.motion.z, ev.motion.rx, ev.motion.ry, ev.motion.rz};
    } else if (ev.type == SPNAV_EVENT_BUTTON && ev.button.bnum >= 0 && ev.button.bnum < 32) {
      const std::uint32_t bit = 1u << ev.button.bnum;
      buttons_ = ev.button.press ? (buttons_ | bit) : (buttons_ & ~bit);
    }
  }
#endif
  // spacenavd's z points away from the user; the device frame has z towards the user (like the Omni).
  const Vec3 raw(axes_[0], axes_[1], -axes_[2]);
  Vec3 v = Vec3::Zero();
  for (int i = 0; i < 3; ++i) {
    const double a = std::abs(raw[i]) > config_.dead_zone ? raw[i] : 0.0;
    v[i] = std::clamp(a / config_.full_deflection, -1.0, 1.0) * config_.full_speed;
  }
  const Vec3 next = caps_.clamp(position_ + in.dt * v);
  out.velocity = in.dt > 0 ? Vec3((next - position_) / in.dt) : Vec3::Zero();
  position_ = next;
  out.position = out.target = position_;
  out.buttons = buttons_;
  return DeviceStatus::ok;
}

}  // namespace s4d
