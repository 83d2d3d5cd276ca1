#include "app/tool_registry.hpp"

#include <GLFW/glfw3.h>

#include <array>

#include "app/panels.hpp"

namespace s4d {

namespace {

const std::array<ToolEntry, 4> kTools{{
    {ToolChoice::kTouch, GLFW_KEY_T, "T", "Touch", "Tools",
     "left-drag a surface, or a knot's strand: a rubber band pulls the point under the cursor\n"
     "(Alt: along the shadow ray, w or a knot's depth; a knot never passes through itself);\n"
     "C: carry a patch ([ ] size it); Tab: the next sheet under the cursor; P or right click: pin / unpin;\n"
     "the wheel while holding: the hand in depth. On empty space the drag turns the view.",
     [](GuiModel& m) -> Tool& { return m.grab; }},
    {ToolChoice::kExplore, GLFW_KEY_E, "E", "Explore", "Tools",
     "press on a surface of R^4 and move: the probe keeps to its sheet through the shadow's\n"
     "self-intersections, the hand feels the navigation spring, and each curve passed\n"
     "sounds: high where the probe's sheet is above in w, low where it is below\n"
     "(also: shadow4d explore SCENE --through ...)",
     [](GuiModel& m) -> Tool& { return m.explore; }},
    {ToolChoice::kSketchKnot, GLFW_KEY_K, "K", "Sketch a knot", "Create",
     "draw a closed curve with the left button in the plane facing you;\n"
     "where it crosses what is drawn it passes over, or under with shift held.\n"
     "Enter makes it a knot of R^3, named live in the Knot panel; then the tool is Touch again.\n"
     "(also: shadow4d knot sketch STROKE --knot --out KNOT)",
     [](GuiModel& m) -> Tool& { return m.knot; }},
    {ToolChoice::kSketchRibbon, GLFW_KEY_R, "R", "Sketch a ribbon", "Create",
     "draw a ribbon's centre line with the left button on the plane facing you (wheel: its\n"
     "depth); where it passes another surface's shadow it goes above in w, or below with\n"
     "shift held. It is smoothed in w keeping every choice, checked to be embedded and\n"
     "simulated: above then below through a sphere links them. Then the tool is Touch again.\n"
     "A rough stroke is smoothed where the ribbon would fold (within half its width); one that\n"
     "still folds is kept: [ ] narrow or widen the ribbon, Enter tries it again, Esc drops it.\n"
     "(also: shadow4d sketch-ribbon SCENE STROKE --out OUT.json)",
     [](GuiModel& m) -> Tool& { return m.ribbon; }},
}};

const std::array<KeyHelp, 18> kWindowKeys{{
    {"left drag", "the active tool; on empty space, turn the view"},
    {"Shift + drag", "turn in 4D: xw across, yw up and down"},
    {"Ctrl + drag", "turn in 4D: zw"},
    {"right or middle drag, arrows", "pan the view"},
    {"wheel", "zoom (while holding: the hand in depth)"},
    {"right click", "change a crossing, or pin / unpin"},
    {"F", "frame all: every object in the view"},
    {"T  E  K  R", "Touch, Explore, Sketch a knot, Sketch a ribbon"},
    {"Esc", "back to Touch, dropping a stroke being drawn or kept"},
    {"Space", "play / pause the simulation"},
    {"Ctrl+Z, Ctrl+Shift+Z or Ctrl+Y", "undo, redo"},
    {"M", "the next curve drawing: tubes, shadow, diagram"},
    {"L", "relax the knot (its energy, live)"},
    {"H", "touch and sound only: hide the picture"},
    {"W", "the slice w = c of the surfaces of R^4 (Slice panel)"},
    {"Alt + wheel", "move the slice's level c"},
    {"F12", "screenshot of the view"},
    {"? or F1", "this card of keys"},
}};

}  // namespace

std::span<const ToolEntry> tool_entries() { return kTools; }

const ToolEntry& tool_entry(ToolChoice id) {
  for (const ToolEntry& e : kTools)
    if (e.id == id) return e;
  return kTools[0];
}

std::span<const KeyHelp> window_keys() { return kWindowKeys; }

}  // namespace s4d
