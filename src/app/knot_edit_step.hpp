// The Knot panel's toolbar edits (mirror, reverse a component, delete a component) as one undoable
// step on the Session: the curve object changed in the scene, the simulation told, the history
// recording the state before.
#pragma once
#include <functional>
#include <string>

#include "interact/session/session.hpp"

namespace s4d {

// Replaces curve object `object` by edit(its curve) as one step called `label` ("mirror 'trefoil'").
// Returns the status line; when the edit throws (a missing component, the last one), nothing
// changes and the line says why.
std::string edit_curve_object(Session& session, int object, const std::string& label,
                              const std::function<Curve<3>(const Curve<3>&)>& edit);

}  // namespace s4d
