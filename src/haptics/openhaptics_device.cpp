// OpenHaptics backend. HDAPI runs its own servo thread; an asynchronous callback there publishes the
// device state and applies the latest force, both through lock-free triple buffers, so our loop and
// the HD scheduler never wait on each other. Units: HDAPI millimetres converted to metres here.
#include "haptics/openhaptics_device.hpp"

#include "core/error.hpp"

#ifdef S4D_HAVE_OPENHAPTICS
#include <HD/hd.h>

#include <array>
#include <atomic>

#include "haptics/triple_buffer.hpp"
#endif

namespace s4d {

bool OpenHapticsDevice::available_in_build() {
#ifdef S4D_HAVE_OPENHAPTICS
  return true;
#else
  return false;
#endif
}

#ifdef S4D_HAVE_OPENHAPTICS

struct OpenHapticsDevice::Impl {
  struct Sample {
    std::array<double, 3> position_mm{};
    std::array<double, 3> velocity_mm_s{};
    int buttons = 0;
  };
  HHD handle = HD_INVALID_HANDLE;
  HDSchedulerHandle callback = HD_INVALID_HANDLE;
  TripleBuffer<Sample> state;                    // HD servo thread -> our loop
  TripleBuffer<std::array<double, 3>> force;     // our loop -> HD servo thread (N)
  std::atomic<bool> fault{false};

  static HDCallbackCode HDCALLBACK servo(void* user) {
    auto* self = static_cast<Impl*>(user);
    hdBeginFrame(self->handle);
    Sample& s = self->state.back();
    hdGetDoublev(HD_CURRENT_POSITION, s.position_mm.data());
    hdGetDoublev(HD_CURRENT_VELOCITY, s.velocity_mm_s.data());
    hdGetIntegerv(HD_CURRENT_BUTTONS, &s.buttons);
    self->state.publish();
    const std::array<double, 3>& f = self->force.read();
    hdSetDoublev(HD_CURRENT_FORCE, f.data());
    hdEndFrame(self->handle);
    const HDErrorInfo e = hdGetError();
    if (HD_DEVICE_ERROR(e)) {
      self->fault.store(true, std::memory_order_relaxed);
      return HD_CALLBACK_DONE;
    }
    return HD_CALLBACK_CONTINUE;
  }

  // Returns an empty string on success, otherwise what HDAPI said.
  std::string start() {
    handle = hdInitDevice(HD_DEFAULT_DEVICE);
    HDErrorInfo e = hdGetError();
    if (HD_DEVICE_ERROR(e)) return std::string("hdInitDevice failed: ") + hdGetErrorString(e.errorCode);
    hdEnable(HD_FORCE_OUTPUT);
    force.write({0, 0, 0});
    fault.store(false);
    callback = hdScheduleAsynchronous(&Impl::servo, this, HD_MAX_SCHEDULER_PRIORITY);
    hdStartScheduler();
    e = hdGetError();
    if (HD_DEVICE_ERROR(e)) {
      stop();
      return std::string("hdStartScheduler failed: ") + hdGetErrorString(e.errorCode);
    }
    return {};
  }
  void stop() {
    hdStopScheduler();
    if (callback != HD_INVALID_HANDLE) hdUnschedule(callback);
    if (handle != HD_INVALID_HANDLE) hdDisableDevice(handle);
    callback = HD_INVALID_HANDLE;
    handle = HD_INVALID_HANDLE;
  }
};

OpenHapticsDevice::OpenHapticsDevice() : impl_(std::make_unique<Impl>()) {
  if (const std::string err = impl_->start(); !err.empty()) throw Error("openhaptics: " + err);
  HDdouble v = 0;
  hdGetDoublev(HD_NOMINAL_MAX_FORCE, &v);
  caps_.max_force = v;  // N
  hdGetDoublev(HD_NOMINAL_MAX_CONTINUOUS_FORCE, &v);
  caps_.max_continuous_force = v;  // N
  hdGetDoublev(HD_NOMINAL_MAX_STIFFNESS, &v);
  caps_.max_stiffness = v * 1000.0;  // N/mm -> N/m
  HDdouble box[6] = {};
  hdGetDoublev(HD_USABLE_WORKSPACE_DIMENSIONS, box);  // mm: min xyz, max xyz
  caps_.workspace_min = Vec3(box[0], box[1], box[2]) * 1e-3;
  caps_.workspace_max = Vec3(box[3], box[4], box[5]) * 1e-3;
  caps_.max_force_rate = 1000;  // N/s
  caps_.outputs_force = true;
  caps_.nominal_rate = 1000;
}

OpenHapticsDevice::~OpenHapticsDevice() {
  impl_->force.write({0, 0, 0});
  impl_->stop();
}

DeviceStatus OpenHapticsDevice::read(const DeviceInput&, DeviceState& out) {
  if (impl_->fault.load(std::memory_order_relaxed)) return DeviceStatus::disconnected;
  const Impl::Sample& s = impl_->state.read();
  out.position = Vec3(s.position_mm[0], s.position_mm[1], s.position_mm[2]) * 1e-3;
  out.velocity = Vec3(s.velocity_mm_s[0], s.velocity_mm_s[1], s.velocity_mm_s[2]) * 1e-3;
  out.target = out.position;
  out.buttons = static_cast<std::uint32_t>(s.buttons);
  return DeviceStatus::ok;
}

void OpenHapticsDevice::write_force(const Vec3& force) {
  impl_->force.write({force[0], force[1], force[2]});
}

bool OpenHapticsDevice::reconnect() {
  impl_->stop();
  return impl_->start().empty();
}

#else  // built without OpenHaptics

struct OpenHapticsDevice::Impl {};

OpenHapticsDevice::OpenHapticsDevice() {
  throw Error("openhaptics: this build has no OpenHaptics support (HD/hd.h and libHD were not found when "
              "configuring; install the OpenHaptics SDK and re-run cmake)");
}
OpenHapticsDevice::~OpenHapticsDevice() = default;
DeviceStatus OpenHapticsDevice::read(const DeviceInput&, DeviceState&) { return DeviceStatus::disconnected; }
void OpenHapticsDevice::write_force(const Vec3&) {}
bool OpenHapticsDevice::reconnect() { return false; }

#endif

}  // namespace s4d
