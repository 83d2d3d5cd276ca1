// The simulation panel (play, physics, the hand, status), the scenario banner, the ribbon and
// history panels, the restore dialog and the generator dialog.
// Sections: [SECTION] Simulation panel, [SECTION] Scenario banner, [SECTION] Generator dialog
#include "app/panels.hpp"

#include <imgui.h>

#include <cmath>
#include <cstdio>

#include "app/panel_settings.hpp"
#include "interact/session/autosave.hpp"
#include "interact/live/live_simulation.hpp"
#include "io/object_file.hpp"
#include "scenario/world_builder.hpp"

namespace s4d {

using panel_detail::record_tool_setting;

namespace {

constexpr const char* kIntegratorNames[] = {"symplectic-euler", "paper-euler"};

std::string seconds(double s) {
  char b[32];
  std::snprintf(b, sizeof b, "%.2f s", s);
  return b;
}

// Pins each simulated object's highest vertex against gravity (one undoable step): what holds a
// cloth or a chain up when gravity is turned on with nothing pinned.
void pin_the_top(Session& session, const Vec4& gravity) {
  const HapticSnapshot* snap = session.snapshot();
  if (!snap || snap->point_dimension < 3 || !(gravity.norm() > 0)) return;
  const int dim = snap->point_dimension;
  const int nv = static_cast<int>(snap->points.size()) / dim;
  std::vector<int> starts;
  for (int o = 0; o < static_cast<int>(session.scene().objects.size()); ++o)
    if (const int f = session.first_vertex(o); f >= 0 && f < nv) starts.push_back(f);
  std::sort(starts.begin(), starts.end());
  starts.push_back(nv);
  session.record("pin the top");
  for (std::size_t k = 0; k + 1 < starts.size(); ++k) {
    int top = -1;
    double best = -1e300;
    for (int v = starts[k]; v < starts[k + 1]; ++v) {
      double up = 0;
      for (int c = 0; c < std::min(dim, 4); ++c) up -= gravity[c] * snap->points[static_cast<std::size_t>(v * dim + c)];
      if (up > best) best = up, top = v;
    }
    if (top >= 0) session.send(live::Pin{top, live::PinAction::kPin});
  }
}

}  // namespace

// [SECTION] Simulation panel
void Panels::simulation_panel(GuiModel& model) {
  if (!model.dock.begin(Side::kLeft, "Simulation")) return;
  Session& session = model.session;
  if (!session.simulating()) {
    if (!session.physics_error().empty()) {
      ImGui::TextColored(ImVec4(1, 0.55f, 0.3f, 1), "not simulated:");
      ImGui::TextWrapped("%s", session.physics_error().c_str());
      ImGui::TextDisabled("the scene stays viewable");
    } else {
      ImGui::TextWrapped("nothing to simulate: sketch a knot (K), or open or create an object");
    }
    model.dock.end();
    return;
  }
  const HapticSnapshot* snap = session.snapshot();
  const SceneStatus st = snap ? snap->status : SceneStatus{};
  if (ImGui::Button(st.playing ? "Pause" : "Play")) session.send(st.playing ? live::Request(live::Pause{}) : live::Request(live::Play{}));
  ImGui::SameLine();
  if (ImGui::Button("Step")) session.send(live::StepOnce{});
  ImGui::SameLine();
  if (ImGui::Button("Reset")) {
    session.record("reset the simulation");
    session.send(live::Reset{});
  }
  if (session.scenario()) {
    ImGui::SameLine();
    if (!st.script_running) {
      if (ImGui::Button("Play script")) session.send(live::PlayScript{});
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("from the start, the scenario's scripted hand does it (as shadow4d run does)");
    } else if (ImGui::Button("Stop script")) {
      session.send(live::StopScript{});
    }
  }
  float scale_before = model.time_scale;
  if (ImGui::SliderFloat("time scale", &model.time_scale, 0.05f, 2.0f, "%.2fx", ImGuiSliderFlags_Logarithmic))
    session.send(live::SetTimeScale{model.time_scale});
  record_tool_setting(model, "change the time scale", [&] { std::swap(model.time_scale, scale_before); });
  if (curves_are_bodies(model.scene())) {
    if (ImGui::Button(st.relaxing ? "Stop relaxing (L)" : "Relax (L)")) toggle_relax(model);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("the knot energy (repulsion, even spacing, bending) pulls the knot towards a round,\n"
                        "even shape, live, until stopped; collision avoidance keeps every strand from passing\n"
                        "through another, so the knot stays the same (also: shadow4d knot relax CURVE --out OUT)");
    ImGui::SameLine();
    ImGui::TextDisabled("drag a strand: an isotopy (Alt: along the depth)");
  }

  physics_settings(model, st);
  hand_settings(model, st);
  simulation_status(model, st);
  model.dock.end();
}

// The World's physics, edited live: each whole change one undoable step, sent at most every 150 ms.
void Panels::physics_settings(GuiModel& model, const SceneStatus& st) {
  Session& session = model.session;
  ImGui::Separator();
  ImGui::TextUnformatted("Physics (applied live)");
  PhysicsSettings& p = model.scene().physics;
  const PhysicsSettings before = p;
  bool changed = false, released = false;
  // One change of a setting (a whole slider drag) is one undoable step, with the value before it.
  auto record_setting = [&] {
    const PhysicsSettings now = p;
    p = before;
    session.record("change the physics");
    p = now;
  };
  auto edited = [&] {
    if (ImGui::IsItemActivated()) record_setting();
    changed = changed || ImGui::IsItemEdited();
    released = released || ImGui::IsItemDeactivatedAfterEdit();
  };
  bool gravity_on = p.gravity.norm() > 0;
  static Vec4 gravity_saved(0, -9.81, 0, 0);
  if (ImGui::Checkbox("gravity", &gravity_on)) {
    record_setting();
    if (gravity_on) {
      p.gravity = gravity_saved;
      if (st.pinned == 0) model.status = "gravity on with nothing pinned: everything falls (Simulation > Pin the top holds it up)";
    } else {
      gravity_saved = p.gravity;
      p.gravity.setZero();
    }
    released = true;
  }
  if (gravity_on) {
    float g[4] = {static_cast<float>(p.gravity[0]), static_cast<float>(p.gravity[1]), static_cast<float>(p.gravity[2]),
                  static_cast<float>(p.gravity[3])};
    if (ImGui::DragFloat4("g (x y z w)", g, 0.05f, -50.0f, 50.0f, "%.2f")) p.gravity = Vec4(g[0], g[1], g[2], g[3]);
    edited();
    if (st.pinned == 0 && st.held_vertex < 0) {  // everything would fall out of view without a word
      ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 0.7f, 0.3f, 1));
      ImGui::TextWrapped("Nothing is pinned: with gravity everything falls out of view.");
      ImGui::PopStyleColor();
      if (ImGui::SmallButton("Pin the top")) {
        pin_the_top(session, p.gravity);
        model.status = "pinned the top of each object (P or a right click unpins; clear pins frees all)";
      }
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("pins each object's highest vertex, as a hand would hold it up");
    }
  }
  auto slider = [&](const char* label, double& value, double lo, double hi, const char* format, bool log) {
    float f = static_cast<float>(value);
    if (ImGui::SliderFloat(label, &f, static_cast<float>(lo), static_cast<float>(hi), format,
                           log ? ImGuiSliderFlags_Logarithmic : 0))
      value = f;
    edited();
  };
  slider("friction", p.friction, 0.0, 2.0, "%.2f", false);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("0 = slippery: the cloth slides off the ribbon");
  slider("stiffness N/m", p.stiffness, 1.0, 5000.0, "%.0f", true);
  slider("thickness", p.thickness, 0.001, 0.2, "%.3f", true);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("the contact layer δ collision avoidance keeps between sheets in R^4");
  slider("damping N s/m", p.damping, 0.0, 1.0, "%.3f", false);
  int integrator = p.integrator == "paper-euler" || p.integrator == "explicit-euler" ? 1 : 0;
  if (ImGui::Combo("integrator", &integrator, kIntegratorNames, 2)) {
    record_setting();
    p.integrator = kIntegratorNames[integrator];
    released = true;
  }
  const auto now = std::chrono::steady_clock::now();
  if (released || (changed && now - last_settings_send_ > std::chrono::milliseconds(150))) {
    session.send(live::SetPhysics::from(p));
    last_settings_send_ = now;
  }
  if (st.message[0]) ImGui::TextColored(ImVec4(1, 0.55f, 0.3f, 1), "%s", st.message);

}

// The hand: the loop's live parameters, the Touch tool's carry, the pins.
void Panels::hand_settings(GuiModel& model, const SceneStatus& st) {
  Session& session = model.session;
  const HapticSnapshot* snap = session.snapshot();
  ImGui::Separator();
  ImGui::TextUnformatted("Hand");
  if (snap) {
    for (int i = 0; i < snap->param_count && i < kLiveParamCount; ++i) {
      const SceneParam& sp = snap->params[i];
      double v = sp.value;
      char label[64];
      std::snprintf(label, sizeof label, "%s##band%d", sp.name, i);
      if (ImGui::SliderScalar(label, ImGuiDataType_Double, &v, &sp.min, &sp.max, "%.3g")) session.loop()->set_param(i, v);
      record_tool_setting(model, std::string("change the hand's ") + sp.name, [] {});
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", sp.unit);
    }
  }
  {  // the Touch tool: pull one vertex on the band, or carry a patch that stays where it is left
    GrabTool& g = model.grab;
    bool carry_before = g.carry();
    int rings_before = g.carry_rings();
    const auto put_back = [&] {
      const bool c = g.carry();
      const int r = g.carry_rings();
      g.set_carry(carry_before);
      g.set_carry_rings(rings_before);
      carry_before = c;
      rings_before = r;
    };
    bool carry = g.carry();
    if (ImGui::Checkbox("carry a patch (C)", &carry)) g.set_carry(carry);
    record_tool_setting(model, "change the touch", put_back);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("on: a drag carries the patch around the vertex (the vertices within so many rings\n"
                        "of mesh edges, the one pressed on first: never another sheet),\n"
                        "which stays held where it is let go (clear pins or P frees it; Ctrl+Z undoes it);\n"
                        "off: a drag pulls one vertex on the rubber band");
    if (g.carry()) {
      int r = g.carry_rings();
      if (ImGui::SliderInt("rings ([ ])", &r, GrabTool::kMinCarryRings, GrabTool::kMaxCarryRings)) g.set_carry_rings(r);
      record_tool_setting(model, "change the carry rings", put_back);
      if (ImGui::IsItemHovered())
        ImGui::SetTooltip("the patch: the vertex pressed on and every vertex within this many edges of it");
    }
  }
  ImGui::Text("pins: %d", st.pinned);
  ImGui::SameLine();
  if (ImGui::SmallButton("clear pins")) {
    session.record("clear the pins");
    session.send(live::ClearPins{});
  }
  if (st.held_vertex >= 0)
    ImGui::Text("holding vertex %d %s: %.2f N", st.held_vertex,
                st.grab_mode == 1 ? (session.dimension() == 3 ? "(along the depth)" : "(along w)") : "", st.band_force);

}

// What the simulation is doing: its clock and rate, contacts, and the independent checks.
void Panels::simulation_status(GuiModel& model, const SceneStatus& st) {
  Session& session = model.session;
  ImGui::Separator();
  const SimulationRates r = session.rates();
  ImGui::Text("t = %s, %lld steps (%s)", seconds(st.sim_time).c_str(), static_cast<long long>(st.sim_steps),
              st.playing ? "playing" : "paused");
  ImGui::Text("%.0f steps/s, real-time ratio %.2f", r.steps_per_second, r.real_time_ratio);
  if (st.lag > 0.05) ImGui::TextColored(ImVec4(1, 0.8f, 0.3f, 1), "the physics cannot keep up: slow motion");
  ImGui::Text("contacts %d, rollbacks %lld, fail-safe freezes %lld", st.contacts, static_cast<long long>(st.rollbacks),
              static_cast<long long>(st.ccd_freezes + st.global_freezes));
  const MonitorResult c = session.checks();
  if (c.valid) {
    const ImVec4 colour = c.true_intersections == 0 ? ImVec4(0.5f, 0.95f, 0.5f, 1) : ImVec4(1, 0.3f, 0.3f, 1);
    ImGui::TextColored(colour, "true intersections: %d", c.true_intersections);
    if (std::isfinite(c.min_gap)) {
      ImGui::SameLine();
      ImGui::Text("  smallest gap %.4f", c.min_gap);
    }
    ImGui::TextDisabled("checked at t = %.2f s (%.0f ms a check)", c.sim_time, c.check_ms);
  } else {
    ImGui::TextDisabled("checking...");
  }
}

// [SECTION] Scenario banner
std::string instruction_text(GuiModel& model) {
  const auto& sc = model.session.scenario();
  if (sc) return sc->name + ": " + sc->instruction;
  return model.scene().instruction;
}

int instruction_lines(GuiModel& model, float width) {
  const std::string text = instruction_text(model);
  if (text.empty()) return 0;
  const float inner = std::max(width - 2 * ImGui::GetStyle().WindowPadding.x, 50.0f);
  const float h = ImGui::CalcTextSize(text.c_str(), nullptr, false, inner).y;
  const int lines = static_cast<int>(std::ceil(h / ImGui::GetTextLineHeight() - 0.01f));
  return std::max(lines, 1) + (model.session.scenario() ? 2 : 0);  // and the verdict's and progress's lines
}

// The instruction in the band above the view, with the live verdict: never over what it says to touch.
void Panels::scenario_banner(GuiModel& model) {
  const Rect& band = model.layout.band;
  const auto& sc = model.session.scenario();
  if (band.empty()) return;
  ImGui::SetNextWindowPos(ImVec2(band.x, band.y));
  ImGui::SetNextWindowSize(ImVec2(band.w, band.h));
  ImGui::Begin("##instruction", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                             ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus);
  ImGui::PushTextWrapPos(0);
  ImGui::TextUnformatted(instruction_text(model).c_str());
  ImGui::PopTextWrapPos();
  if (sc) {
    const MonitorResult c = model.session.checks();
    if (c.verdict) {
      const bool pass = c.verdict->pass && c.true_intersections == 0;
      ImGui::TextColored(pass ? ImVec4(0.5f, 0.95f, 0.5f, 1) : ImVec4(1, 0.75f, 0.35f, 1), "%s", pass ? "PASS" : "not yet");
      ImGui::SameLine();
      ImGui::TextUnformatted(c.verdict->detail.c_str());
      if (const auto& p = c.verdict->progress) {
        char line[160];
        if (std::isfinite(p->start))
          std::snprintf(line, sizeof line, "%s %.3g -> %.3g, goal %s %.3g", p->what.c_str(), p->start, p->now,
                        p->rising ? ">=" : "<=", p->goal);
        else
          std::snprintf(line, sizeof line, "%s %.3g, goal %s %.3g", p->what.c_str(), p->now, p->rising ? ">" : "<", p->goal);
        ImGui::SetNextItemWidth(std::min(200.0f * model.ui_scale, ImGui::GetContentRegionAvail().x * 0.3f));
        ImGui::ProgressBar(static_cast<float>(pass ? 1.0 : p->fraction()), ImVec2(200.0f * model.ui_scale, 0), "");
        ImGui::SameLine();
        ImGui::TextUnformatted(line);
        model.hint_progress = line;
      }
      if (!model.hint_next.empty()) {
        ImGui::SameLine();
        if (ImGui::SmallButton("Show me")) model.show_me = true;
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", model.hint_next.c_str());
      }
    } else {
      ImGui::TextDisabled("checking...");
    }
    if (ImGui::IsWindowHovered())
      ImGui::SetTooltip("Space plays; Simulation > Play script shows it done;\nshadow4d run %s gives the same verdict",
                        sc->file.filename().string().c_str());
  }
  ImGui::End();
}

// The ribbon tool's options, while it is the tool.
void Panels::ribbon_panel(GuiModel& model) {
  if (model.tool != ToolChoice::kSketchRibbon) return;
  if (!model.dock.begin(Side::kRight, "Ribbon")) return;
  RibbonSketchOptions& o = model.ribbon.options;
  RibbonSketchOptions before = o;
  const auto put_back = [&] { std::swap(o, before); };
  float width = static_cast<float>(o.width);
  if (ImGui::SliderFloat("width", &width, 0.0f, 1.0f, width > 0 ? "%.3f" : "from the view")) o.width = width;
  record_tool_setting(model, "change the ribbon's width", put_back);
  ImGui::Checkbox("closed (a loop)", &o.closed);
  record_tool_setting(model, "change the ribbon's ends", put_back);
  ImGui::SliderInt("across", &o.across, 2, 8);
  record_tool_setting(model, "change the ribbon's rows", put_back);
  RibbonTool& tool = model.ribbon;
  if (!tool.kept_stroke().empty()) {  // a stroke that made no ribbon, kept for another try
    ImGui::Separator();
    ImGui::PushTextWrapPos(0);
    ImGui::TextColored(ImVec4(1, 0.6f, 0.15f, 1), "The stroke (orange) made no ribbon at width %.3g:", tool.last_width());
    ImGui::TextUnformatted(tool.refusal().c_str());
    ImGui::PopTextWrapPos();
    if (tool.suggested_width() > 0) {
      char use[64];
      std::snprintf(use, sizeof use, "Width %.3g, try again", tool.suggested_width());
      if (ImGui::Button(use)) {
        model.session.record("change the ribbon's width");
        o.width = tool.suggested_width();
        tool.retry(model.session);
      }
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("the widest ribbon that lies flat along this stroke");
    }
    if (ImGui::Button("Try again (Enter)")) tool.retry(model.session);
    ImGui::SameLine();
    if (ImGui::Button("Drop it (Esc)")) tool.drop_kept();
  }
  if (const SketchedRibbon* r = tool.last()) {
    ImGui::Text("last: %zu rows, length %.2f, %zu passage(s)", r->w.size(), r->length, r->passages.size());
    if (r->smoothing.rounds > 0)
      ImGui::TextDisabled("smoothed %d time(s) at %d turn(s), moved <= %.3g", r->smoothing.rounds, r->smoothing.turns,
                          r->smoothing.moved);
    for (const RibbonPassage& p : r->passages)
      ImGui::BulletText("%s %s (gap %.3f)", p.below ? "below" : "above",
                        p.surface < 0 ? "itself" : "another surface", p.gap);
  }
  model.dock.end();
}

// Every step done (oldest first) and undone (greyed, next to redo first); the buttons walk it.
void Panels::history_panel(GuiModel& model) {
  if (!model.show_history) return;
  if (!model.dock.begin(Side::kLeft, "History", &model.show_history)) return;
  Session& s = model.session;
  const History& h = s.history();
  if (ImGui::Button("Undo")) undo_or_redo(model, false);
  ImGui::SameLine();
  if (ImGui::Button("Redo")) undo_or_redo(model, true);
  ImGui::SameLine();
  ImGui::TextDisabled("%zu step(s), %.1f MB", h.done_labels().size() + h.undone_labels().size(),
                      static_cast<double>(h.bytes()) / (1 << 20));
  ImGui::Separator();
  const auto done = h.done_labels();
  for (std::size_t i = 0; i < done.size(); ++i) ImGui::Text("%zu  %s", i + 1, done[i].c_str());
  for (const std::string& l : h.undone_labels()) ImGui::TextDisabled("    %s (undone)", l.c_str());
  if (done.empty() && !h.can_redo()) ImGui::TextDisabled("nothing done yet");
  ImGui::TextDisabled("the last %zu steps or %zu MB are kept", History::kMaxSteps, History::kMaxBytes >> 20);
  model.dock.end();
}

// After a crash or a kill: the autosave the last run left, taken up or set aside.
void Panels::restore_dialog(GuiModel& model) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.3f), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  ImGui::Begin("Restore your work?", nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse);
  const SessionFile& f = *model.pending_restore;
  ImGui::PushTextWrapPos(ImGui::GetFontSize() * 40);
  ImGui::TextWrapped("A window that is no longer running left unfinished work: %s.",
                     describe_unfinished(model.autosave_path, f).c_str());
  ImGui::PopTextWrapPos();
  ImGui::Text("%zu object(s) and %d step(s) of work.", f.scene.objects.size(), f.history_head);
  if (ImGui::Button("Restore")) {
    const SessionFile saved = *model.pending_restore;
    model.pending_restore.reset();
    open_session(model, saved, model.autosave_path);
  }
  ImGui::SameLine();
  if (ImGui::Button("Start afresh")) {
    model.pending_restore.reset();
    model.status = "the autosave stays in " + model.autosave_path + " until the next one";
  }
  ImGui::End();
}

// [SECTION] Generator dialog
void Panels::generator_dialog(GuiModel& model) {
  if (!generator_dialog_open_) return;
  const GeneratorInfo* info = find_generator(generator_);
  if (!info) {
    generator_dialog_open_ = false;
    return;
  }
  ImGui::SetNextWindowSize(ImVec2(360, 0), ImGuiCond_Appearing);
  ImGui::Begin(("Create " + info->name).c_str(), &generator_dialog_open_);
  ImGui::TextWrapped("%s", info->description.c_str());
  for (const auto& p : info->params) {
    double& value = generator_params_[p.name];
    if (p.integer) {
      int i = static_cast<int>(std::lround(value));
      ImGui::DragInt(p.name.c_str(), &i, 0.25f, static_cast<int>(p.min), static_cast<int>(p.max));
      value = i;
    } else {
      float f = static_cast<float>(value);
      ImGui::DragFloat(p.name.c_str(), &f, static_cast<float>((p.max - p.min) / 500.0),
                       static_cast<float>(p.min), static_cast<float>(p.max), "%.3f");
      value = f;
    }
    if (ImGui::IsItemHovered() && !p.help.empty()) ImGui::SetTooltip("%s", p.help.c_str());
  }
  // Where the object goes: its offset from where the generator puts it (usually the origin).
  float at[4] = {static_cast<float>(generator_offset_[0]), static_cast<float>(generator_offset_[1]),
                 static_cast<float>(generator_offset_[2]), static_cast<float>(generator_offset_[3])};
  const bool in_r4 = info->dim == 4;
  if (in_r4 ? ImGui::DragFloat4("position (x y z w)", at, 0.01f, -100.0f, 100.0f, "%.2f")
            : ImGui::DragFloat3("position (x y z)", at, 0.01f, -100.0f, 100.0f, "%.2f"))
    generator_offset_ = Vec4(at[0], at[1], at[2], in_r4 ? at[3] : 0.0f);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("added beside what is in the scene (also: a scene's \"offset\", or NAME:k=v@x,y,z[,w])");
  const bool replace = ImGui::Button("Replace scene");
  ImGui::SameLine();
  const bool add = ImGui::Button("Add to scene");
  if (replace || add) {
    try {
      SceneObject obj;
      obj.generator = GeneratorCall{info->name, generator_params_};
      obj.placement.offset = generator_offset_;
      obj.shape = placed(generate(info->name, generator_params_), obj.placement);
      obj.name = info->name + "-" + std::to_string(model.created + 1);
      if (replace) {
        Document d;
        d.spec = info->name;
        d.scene.objects.push_back(std::move(obj));
        open(model, std::move(d));
        if (info->dim == 4) model.view.turn_to_generic_view();
      } else {
        const std::string label = "create " + obj.name;
        model.session.add_object(std::move(obj), label);  // the bodies there keep their motion and pins
      }
      ++model.created;
      model.status = "created " + info->name;
    } catch (const std::exception& e) {
      model.error = e.what();
    }
  }
  ImGui::End();
}


}  // namespace s4d
