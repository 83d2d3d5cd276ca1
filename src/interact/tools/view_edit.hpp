// Editing a curve through the view, as the paper's 2D tool does with its shadow: changing one
// crossing of the diagram the camera sees.
#pragma once
#include "core/camera.hpp"
#include "interact/tools/tool.hpp"
#include "view/view_crossings.hpp"
#include "io/scene.hpp"

#include <optional>

namespace s4d {

class Session;

// The shape of crossing c's curve object (c from screen_crossings(scene, camera)) with that
// crossing changed: the under strand's vertices near it move along their own lines of sight
// towards the eye until it passes `clearance` in front of the over strand. Every vertex keeps its
// place on the screen, so the view's diagram is the same but for that crossing; this is checked,
// and a narrower bump is tried when another crossing would change too. A curve of R^4 keeps each
// point's w of the view. Throws s4d::Error when the object is no curve, part of it is behind the
// eye, or no bump changes that crossing alone.
Shape change_crossing_in_view(const Scene& scene, const Camera& camera, const ScreenCrossing& c,
                              double clearance);

// The crossing whose dot lies within 14 pixels of the cursor, if any.
std::optional<ScreenCrossing> crossing_under(const ToolView& view, const Scene& scene);

// The crossing change of the window's right click: the crossing whose dot lies within 14 pixels
// of the cursor, changed in scene's curve; false when no dot is there. What happened (or why it
// could not) is left in `message`.
// The change is one undoable step of the session.
bool change_crossing_under(const ToolView& view, Session& session, std::string& message);

}  // namespace s4d
