// Tool settings gathered from and put back into the window's tools, the hand and the sound.
#include "app/tool_settings.hpp"

#include <algorithm>
#include <cmath>

#include "app/panels.hpp"

namespace s4d {

namespace {

// The hand's parameters are the live simulation's (LiveParam), named as the Haptics panel names
// them; they go to the loop by index.
std::string hand_key(const char* name) { return std::string("hand.") + name; }

}  // namespace

ToolSettings tool_settings(const GuiModel& model) {
  ToolSettings s;
  const RibbonSketchOptions& r = model.ribbon.options;
  s["ribbon.width"] = r.width;
  s["ribbon.closed"] = r.closed ? 1 : 0;
  s["ribbon.across"] = r.across;
  s["simulation.time_scale"] = model.time_scale;
  s["touch.carry"] = model.grab.carry() ? 1 : 0;
  s["touch.carry_rings"] = model.grab.carry_rings();
  s["view.touch_and_sound_only"] = model.touch_and_sound_only ? 1 : 0;
  if (model.audio) {
    s["sound.mute"] = model.audio->muted() ? 1 : 0;
    s["sound.volume"] = model.audio->volume();
  }
  if (const HapticSnapshot* snap = model.session.snapshot())
    for (int i = 0; i < snap->param_count; ++i) s[hand_key(snap->params[i].name)] = snap->params[i].value;
  return s;
}

void apply_tool_settings(GuiModel& model, const ToolSettings& settings) {
  auto get = [&](const std::string& key, double lo, double hi, auto&& apply) {
    const auto it = settings.find(key);
    if (it != settings.end() && std::isfinite(it->second)) apply(std::clamp(it->second, lo, hi));
  };
  RibbonSketchOptions& r = model.ribbon.options;
  get("ribbon.width", 0.0, 1e6, [&](double v) { r.width = v; });
  get("ribbon.closed", 0.0, 1.0, [&](double v) { r.closed = v > 0.5; });
  get("ribbon.across", 2.0, 64.0, [&](double v) { r.across = static_cast<int>(std::lround(v)); });
  get("touch.carry", 0.0, 1.0, [&](double v) { model.grab.set_carry(v > 0.5); });
  get("touch.carry_rings", GrabTool::kMinCarryRings, GrabTool::kMaxCarryRings,
      [&](double v) { model.grab.set_carry_rings(static_cast<int>(std::lround(v))); });
  get("simulation.time_scale", 0.01, 4.0, [&](double v) {
    model.time_scale = static_cast<float>(v);
    model.session.send(live::SetTimeScale{v});
  });
  get("view.touch_and_sound_only", 0.0, 1.0, [&](double v) { model.touch_and_sound_only = v > 0.5; });
  if (model.audio) {
    get("sound.mute", 0.0, 1.0, [&](double v) { model.audio->set_mute(v > 0.5); });
    get("sound.volume", 0.0, 1.0, [&](double v) { model.audio->set_volume(static_cast<float>(v)); });
  }
  // The hand's parameters need the loop's list of them (names, ranges): until a snapshot has it
  // (a session just opened), they wait in pending_settings for the next frame.
  Session& session = model.session;
  const HapticSnapshot* snap = session.snapshot();
  if (!snap || !session.loop()) {
    for (const auto& [key, value] : settings)
      if (key.rfind("hand.", 0) == 0) model.pending_settings[key] = value;
    return;
  }
  for (int i = 0; i < snap->param_count; ++i) {
    const SceneParam& p = snap->params[i];
    get(hand_key(p.name), p.min, p.max, [&](double v) { session.loop()->set_param(i, v); });
  }
}

}  // namespace s4d
