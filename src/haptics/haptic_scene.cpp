// Shared parameter handling of haptic scenes.
#include "haptics/haptic_scene.hpp"

#include <algorithm>
#include <cmath>

namespace s4d {

void HapticScene::set_param(int index, double value) {
  auto ps = params();
  if (index < 0 || index >= static_cast<int>(ps.size()) || !std::isfinite(value)) return;
  ps[index].value = std::clamp(value, ps[index].min, ps[index].max);
}

int HapticScene::find_param(std::string_view name) {
  auto ps = params();
  for (int i = 0; i < static_cast<int>(ps.size()); ++i)
    if (name == ps[i].name) return i;
  return -1;
}

}  // namespace s4d
