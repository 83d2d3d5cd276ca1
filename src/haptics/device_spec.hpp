// The `--device mouse|replay:FILE|spacenav|openhaptics|sim` choice, parsed the same way by the GUI and
// the CLI, and the factory that opens the backend it names.
#pragma once
#include <memory>
#include <string>
#include <string_view>

#include "haptics/device.hpp"

namespace s4d {

inline constexpr const char* kDeviceSpecHelp = "mouse|replay:FILE|spacenav|openhaptics|sim";

struct DeviceSpec {
  enum class Kind { mouse, replay, spacenav, openhaptics, sim };
  Kind kind = Kind::mouse;
  std::string file;  // replay only
  friend bool operator==(const DeviceSpec&, const DeviceSpec&) = default;
};

// Throws Error naming the accepted forms for anything else (including "replay:" without a file).
DeviceSpec parse_device_spec(std::string_view text);
std::string to_string(const DeviceSpec& spec);

// Opens the backend; throws Error with the reason when it cannot (no spacenavd, no OpenHaptics in this
// build, unreadable or malformed replay file with file:line).
std::unique_ptr<Device> make_device(const DeviceSpec& spec);

}  // namespace s4d
