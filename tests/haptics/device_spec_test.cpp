// `--device` parsing, and each backend opened through the factory (or refusing with a clear reason).
#include "haptics/device_spec.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "core/error.hpp"
#include "haptics/openhaptics_device.hpp"
#include "haptics/spacenav_device.hpp"
#include "haptics/trajectory_file.hpp"

namespace s4d {
namespace {

std::string error_of(const DeviceSpec& spec) {
  try {
    make_device(spec);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(DeviceSpec, ParsesEveryForm) {
  EXPECT_EQ(parse_device_spec("mouse").kind, DeviceSpec::Kind::mouse);
  EXPECT_EQ(parse_device_spec("sim").kind, DeviceSpec::Kind::sim);
  EXPECT_EQ(parse_device_spec("spacenav").kind, DeviceSpec::Kind::spacenav);
  EXPECT_EQ(parse_device_spec("openhaptics").kind, DeviceSpec::Kind::openhaptics);
  const DeviceSpec r = parse_device_spec("replay:/tmp/a b.traj");
  EXPECT_EQ(r.kind, DeviceSpec::Kind::replay);
  EXPECT_EQ(r.file, "/tmp/a b.traj");
  for (const char* s : {"mouse", "sim", "spacenav", "openhaptics", "replay:x.traj"})
    EXPECT_EQ(to_string(parse_device_spec(s)), s);
}

TEST(DeviceSpec, RejectsUnknownWithTheAcceptedForms) {
  for (const char* bad : {"", "Mouse", "replay", "replay:", "phantom", "sim "}) {
    try {
      parse_device_spec(bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(kDeviceSpecHelp), std::string::npos) << e.what();
    }
  }
}

TEST(DeviceSpec, OpensTheAlwaysAvailableBackends) {
  EXPECT_EQ(make_device(parse_device_spec("mouse"))->name(), "mouse");
  auto sim = make_device(parse_device_spec("sim"));
  EXPECT_EQ(sim->name(), "sim");
  EXPECT_DOUBLE_EQ(sim->capabilities().max_force, 3.3);
  EXPECT_DOUBLE_EQ(sim->capabilities().max_continuous_force, 0.88);
  EXPECT_NEAR((sim->capabilities().workspace_max - sim->capabilities().workspace_min).x(), 0.160, 1e-12);
  const auto p = std::filesystem::temp_directory_path() / "s4d_haptics_spec.traj";
  write_trajectory(p, circle_trajectory(0.01, 1000, 0.01, 1, 0));
  EXPECT_EQ(make_device(parse_device_spec("replay:" + p.string()))->name(), "replay");
}

TEST(DeviceSpec, UnavailableBackendsSayWhy) {
  const std::string missing = error_of(parse_device_spec("replay:/no/such/file.traj"));
  EXPECT_NE(missing.find("/no/such/file.traj"), std::string::npos) << missing;
  // No spacenavd runs on the build machine (and it may be built without libspnav): a clear message.
  const std::string sn = error_of(parse_device_spec("spacenav"));
  if (SpacenavDevice::available_in_build())
    EXPECT_NE(sn.find("no spacenavd"), std::string::npos) << sn;
  else
    EXPECT_NE(sn.find("no libspnav support"), std::string::npos) << sn;
  if (!OpenHapticsDevice::available_in_build()) {
    const std::string oh = error_of(parse_device_spec("openhaptics"));
    EXPECT_NE(oh.find("no OpenHaptics support"), std::string::npos) << oh;
  }
}

}  // namespace
}  // namespace s4d
