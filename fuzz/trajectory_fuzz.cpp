// libFuzzer target: recorded device trajectories, the replay device's input
// (haptics/trajectory_file).
#include "fuzz_target.hpp"
#include "haptics/trajectory_file.hpp"

S4D_FUZZ_TARGET(text) { s4d::parse_trajectory(text, "fuzz.traj"); }
