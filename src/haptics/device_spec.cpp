// Device choice parsing and the backend factory.
#include "haptics/device_spec.hpp"

#include "core/error.hpp"
#include "haptics/mouse_device.hpp"
#include "haptics/openhaptics_device.hpp"
#include "haptics/replay_device.hpp"
#include "haptics/simulated_arm.hpp"
#include "haptics/spacenav_device.hpp"

namespace s4d {

DeviceSpec parse_device_spec(std::string_view text) {
  DeviceSpec s;
  if (text == "mouse") {
    s.kind = DeviceSpec::Kind::mouse;
  } else if (text == "spacenav") {
    s.kind = DeviceSpec::Kind::spacenav;
  } else if (text == "openhaptics") {
    s.kind = DeviceSpec::Kind::openhaptics;
  } else if (text == "sim") {
    s.kind = DeviceSpec::Kind::sim;
  } else if (text.rfind("replay:", 0) == 0 && text.size() > 7) {
    s.kind = DeviceSpec::Kind::replay;
    s.file = std::string(text.substr(7));
  } else {
    throw Error("unknown device '" + std::string(text) + "': expected " + kDeviceSpecHelp);
  }
  return s;
}

std::string to_string(const DeviceSpec& spec) {
  switch (spec.kind) {
    case DeviceSpec::Kind::mouse: return "mouse";
    case DeviceSpec::Kind::replay: return "replay:" + spec.file;
    case DeviceSpec::Kind::spacenav: return "spacenav";
    case DeviceSpec::Kind::openhaptics: return "openhaptics";
    case DeviceSpec::Kind::sim: return "sim";
  }
  return "?";
}

std::unique_ptr<Device> make_device(const DeviceSpec& spec) {
  switch (spec.kind) {
    case DeviceSpec::Kind::mouse: return std::make_unique<MouseDevice>();
    case DeviceSpec::Kind::replay: return std::make_unique<ReplayDevice>(read_trajectory(spec.file), true);
    case DeviceSpec::Kind::spacenav: return std::make_unique<SpacenavDevice>();
    case DeviceSpec::Kind::openhaptics: return std::make_unique<OpenHapticsDevice>();
    case DeviceSpec::Kind::sim: return std::make_unique<SimulatedArm>();
  }
  throw Error("unknown device kind");
}

}  // namespace s4d
