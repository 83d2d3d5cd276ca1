// The input file's `dump` (see window_dump.hpp).
#include "app/window_dump.hpp"

#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <imgui.h>
#include <nlohmann/json.hpp>

#include "app/dock.hpp"
#include "app/screen.hpp"
#include "app/tool_settings.hpp"

namespace s4d {

namespace {

using Json = nlohmann::ordered_json;

// The live simulation: its status, every vertex (world coordinates) and where its shadow is on the
// screen (null when behind the eye), for tests that press on a chosen vertex.
void dump_simulation(Json& j, Session& s, const Camera& camera, const Rect& view) {
  j["simulating"] = s.simulating();
  j["state_pending"] = s.state_pending();
  j["physics_error"] = s.physics_error();
  if (const HapticSnapshot* snap = s.snapshot()) {
    const SceneStatus& st = snap->status;
    j["sim_time"] = st.sim_time;
    j["sim_steps"] = st.sim_steps;
    // The Simulation panel's figures: simulated seconds per wall second over the last second.
    j["real_time_ratio"] = s.rates().real_time_ratio;
    j["steps_per_second"] = s.rates().steps_per_second;
    j["playing"] = st.playing;
    j["held_vertex"] = st.held_vertex;
    j["grab_mode"] = st.grab_mode;
    j["pinned"] = st.pinned;
    j["contacts"] = st.contacts;
    j["rollbacks"] = st.rollbacks;
    j["device"] = snap->device_name;
    j["max_force_output"] = snap->max_force_output;
    j["safety_nonfinite"] = snap->safety.nonfinite;
    j["loop_period_p999_us"] = snap->period.p999_us;
    j["dim"] = snap->point_dimension;
    j["positions"] = snap->points;
    j["band_force"] = st.band_force;
    Json pins = Json::array();
    for (std::size_t v = 0; v < snap->flags.size(); ++v)
      if (snap->flags[v] & 1) pins.push_back(v);
    j["pinned_vertices"] = pins;
    j["carry_rings"] = st.carry_rings;
    Json pixels = Json::array();
    const int nv = snap->point_dimension > 0 ? static_cast<int>(snap->points.size()) / snap->point_dimension : 0;
    for (int v = 0; v < nv; ++v) {
      ImVec2 px;
      const Vec3 p = s.vertex_shadow(v);
      pixels.push_back(to_screen(camera, p, view, px) ? Json{px.x, px.y} : Json(nullptr));
    }
    j["vertex_pixels"] = pixels;
    j["exploring"] = st.exploring;
    j["probe_w"] = st.probe_w;
    j["relaxing"] = st.relaxing;
  }
  // The World's cells, so a test can check every saved state with a checker of its own.
  Json tris = Json::array();
  for (const Triangle& t : s.triangles()) tris.push_back({t[0], t[1], t[2]});
  j["triangles"] = tris;
}

// The independent checks and the scenario's verdict, live.
void dump_checks(Json& j, const Session& s) {
  const MonitorResult c = s.checks();
  j["checked"] = c.valid;
  j["true_intersections"] = c.true_intersections;
  j["min_gap"] = std::isfinite(c.min_gap) ? Json(c.min_gap) : Json(nullptr);
  if (c.verdict) j["verdict"] = {{"pass", c.verdict->pass}, {"detail", c.verdict->detail}};
}

// The tools' state: the explorer's passes, the last ribbon's passages, the sheets under the cursor
// and the knot sketch.
void dump_tools(Json& j, GuiModel& model) {
  Session& s = model.session;
  j["tool"] = model.active_tool()->name();
  Json passes = Json::array();
  for (const SceneEvent& e : model.explore.passes())
    passes.push_back(e.kind == kEventPassedAbove ? "above" : e.kind == kEventPassedBelow ? "below" : e.kind == kEventCrossedOver ? "over" : "under");
  j["explore_gauss"] = model.explore.gauss_so_far();
  j["explore_passes"] = passes;
  if (const SketchedRibbon* r = model.ribbon.last()) {
    Json ps = Json::array();
    for (const RibbonPassage& p : r->passages) ps.push_back(p.below ? "below" : "above");
    j["ribbon_passages"] = ps;
    j["ribbon_smoothing_rounds"] = r->smoothing.rounds;
  }
  // A stroke that made no ribbon, kept for another try: its samples, and the width it was tried at.
  j["ribbon_kept_samples"] = model.ribbon.kept_stroke().size();
  j["ribbon_width"] = model.ribbon.last_width();
  j["hits_under_cursor"] = model.grab.hits().size();
  Json hits = Json::array();
  for (const SheetHit& h : model.grab.hits())
    hits.push_back({{"w", h.w}, {"vertex", s.first_vertex(h.object) < 0 ? -1 : s.first_vertex(h.object) + h.vertex}});
  j["hits"] = hits;
  const SketchPublished& k = model.knot.published();
  j["sketch"] = {{"active", k.active},
                 {"drawing", k.drawing},
                 {"points", k.point_count},
                 {"components", k.component_count},
                 {"crossings_chosen", k.crossing_count},
                 {"blocked_ticks", k.status.blocked_ticks},
                 {"crossings_refused", k.status.crossings_refused},
                 {"max_repulsion", k.status.max_repulsion},
                 {"max_lag_near", k.status.max_lag_near},
                 {"last_gauss", model.knot.last_gauss()},
                 {"last_name", model.knot.last_name()}};
  j["sheet"] = model.grab.sheet();
  j["tool_settings"] = tool_settings(model);
}

// What the view shows: its 4D frame, the drawing mode, and where the shadow's pinch points are.
void dump_view(Json& j, GuiModel& model, const Camera& camera, const Rect& view) {
  const Frame<4>& f = model.scene().frame;
  Json frame = Json::array();
  for (int r = 0; r < 4; ++r)
    for (int k = 0; k < 4; ++k) frame.push_back(f.matrix()(r, k));
  j["frame"] = frame;
  j["perspective"] = f.perspective();  // the 4D eye's distance along w; 0 orthographic
  Json controls = Json::object();
  for (const auto& [name, r] : model.view_controls) controls[name] = {r.x, r.y, r.right(), r.bottom()};
  j["view_controls"] = controls;
  const Eigen::Quaterniond& q = model.view.trackball();
  j["trackball"] = {q.w(), q.x(), q.y(), q.z()};
  j["zoom"] = model.view.zoom();
  j["objects"] = model.scene().objects.size();
  if (model.intersections.computed) {
    Json pinch = Json::array();
    for (const Vec3& p : model.intersections.pinch_at) {
      ImVec2 px;
      const bool seen = to_screen(camera, p, view, px);
      pinch.push_back({{"at", {p.x(), p.y(), p.z()}}, {"pixel", seen ? Json{px.x, px.y} : Json(nullptr)}});
    }
    j["pinch_points"] = pinch;
    j["curve_length"] = model.intersections.length;
  }
  j["curve_mode"] = curve_mode_name(model.scene().view.curve_mode);
  j["touch_and_sound_only"] = model.touch_and_sound_only;
  j["depth_tone"] = model.depth_tone;
}

// The scenario's steps as drawn: each marker's and target's pixel (null off the screen), done or not.
void dump_hints(Json& j, const GuiModel& model, const HintMarkers& hints, const Camera& camera) {
  const Rect& view = model.layout.view;
  Json steps = Json::array();
  auto pixel = [&](const Vec4& world) {
    ImVec2 px;
    return to_screen(camera, HintMarkers::shadow_of(model, world), view, px) ? Json{px.x, px.y} : Json(nullptr);
  };
  for (const HintMarkers::Step& s : hints.steps())
    steps.push_back({{"marker", pixel(hints.centre(model, s))}, {"target", pixel(s.target)}, {"done", s.done},
                     {"say", s.say}, {"vertices", s.vertices.size()}});
  j["hints"] = steps;
  j["hint_next"] = model.hint_next;
  j["hint_progress"] = model.hint_progress;
}

}  // namespace

void dump_state(GuiModel& model, const KnotPanels& knots, const SlicePanel& slice, const HintMarkers& hints,
                const std::string& path,
                const Camera& camera, int window_frame) {
  const Rect& view = model.layout.view;
  Json j;
  // The frame and the wall clock (s): two dumps give the frame rate over the frames between them.
  j["window_frame"] = window_frame;
  j["wall_time"] = std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
  j["status"] = model.status;
  j["error"] = model.error;
  // Where the window's parts are: the 3D view and every panel drawn this frame.
  auto rect = [](const Rect& r) { return Json{{"x", r.x}, {"y", r.y}, {"w", r.w}, {"h", r.h}}; };
  j["view"] = rect(view);
  const ImVec2 display = ImGui::GetIO().DisplaySize;  // the window's size (the page's: the browser's)
  j["window"] = {{"w", display.x}, {"h", display.y}};
  if (model.audio)  // cues started and samples mixed: the page's Web Audio, the desktop's SDL2
    j["audio"] = {{"status", model.audio->status()}, {"available", model.audio->available()},
                  {"cues_started", model.audio->cues_started()}, {"frames_rendered", model.audio->frames_rendered()}};
  Json panels = Json::array();
  for (const auto& [name, r] : visible_windows()) {
    Json p = rect(r);
    p["name"] = name;
    panels.push_back(p);
  }
  j["panels"] = panels;
  Json sections = Json::array();  // the columns' section headers: a click opens or closes one
  for (const Dock::Header& h : model.dock.headers())
    sections.push_back({{"name", h.name}, {"rect", {h.rect.x, h.rect.y, h.rect.right(), h.rect.bottom()}}, {"open", h.open}});
  j["sections"] = sections;
  j["ui_scale"] = model.ui_scale;
  j["start_page"] = model.start_page;
  Json cards = Json::array();
  if (model.start_page)
    for (const auto& [name, r] : model.start_cards) {
      Json c = rect(r);
      c["name"] = name;
      cards.push_back(c);
    }
  j["start_cards"] = cards;
  j["exercise_scene"] = model.exercise_return.has_value();
  dump_simulation(j, model.session, camera, view);
  dump_checks(j, model.session);
  dump_hints(j, model, hints, camera);
  dump_tools(j, model);
  dump_view(j, model, camera, view);
  j["knot_panel_name"] = model.knot_panel_name;
  Json knot_panels = Json::object();
  knots.dump(knot_panels);
  j["knot_panels"] = knot_panels;
  Json slice_panel = Json::object();
  slice.dump(slice_panel);
  const Rect& sb = model.slice_button;
  if (!sb.empty()) slice_panel["buttons"]["Slice (W)"] = {sb.x, sb.y, sb.right(), sb.bottom()};
  j["slice_panel"] = slice_panel;
  j["restore_offered"] = model.pending_restore.has_value();
  j["autosave"] = model.autosave_path;  // this window's own (its slot)
  if (model.pending_restore)
    j["restore_offer"] = {{"opened", model.pending_restore->opened}, {"saved_at", model.pending_restore->saved_at},
                          {"closed_by", model.pending_restore->closed_by}};
  j["history"] = model.session.history().done_labels();
  if (path == "-") {  // one line on the standard output: the web page's console, where a test reads it
    std::cout << "dump " << j.dump() << std::endl;
    return;
  }
  std::ofstream out(path);
  out << j.dump(1) << "\n";
  if (!out) model.error = "cannot write " + path;
}

}  // namespace s4d
