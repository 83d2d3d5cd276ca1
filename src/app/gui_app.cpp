// The window loop: events -> mouse mapping -> panels -> scene drawing -> ImGui -> swap.
#include "app/gui_app.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <cstdio>
#include <iostream>

#include "app/haptics_window.hpp"
#include "app/panels.hpp"
#include "app/sketch_tool.hpp"
#include "io/image.hpp"
#include "render/renderer.hpp"
#include "render/view_edit.hpp"

namespace s4d {

namespace {

void glfw_error(int code, const char* text) { std::fprintf(stderr, "glfw error %d: %s\n", code, text); }

// While sketching, the left button draws (shift: the stroke passes under); on release the
// stroke becomes a knot added to the scene.
void handle_sketch(GLFWwindow* window, GuiModel& model, SketchTool& tool, const Camera& camera,
                   const Vec2& cursor, bool captured) {
  if (ImGui::IsKeyPressed(GLFW_KEY_ESCAPE) && !ImGui::GetIO().WantTextInput) {
    model.sketching = false;
    model.status = "";
  }
  if (!model.sketching) {
    tool.cancel();
    return;
  }
  int w = 0, h = 0;
  glfwGetWindowSize(window, &w, &h);
  const Vec2 size(w, h);
  const bool pressed = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
  const bool under = ImGui::GetIO().KeyShift;
  if (pressed && !tool.drawing() && !captured) tool.begin(camera, cursor, size, glfwGetTime(), under);
  else if (pressed && tool.drawing()) tool.add(cursor, size, glfwGetTime(), under);
  else if (!pressed && tool.drawing() && tool.screen().size() < 3) {
    tool.cancel();
    model.status = std::string("a click is not a stroke; ") + kSketchHelp;
  } else if (!pressed && tool.drawing()) {
    SceneObject obj;
    bool made = false;
    try {
      obj.shape = tool.finish();
      made = true;
    } catch (const std::exception& e) {
      model.error = e.what();
    }
    // Kept even when it made no knot (File > Save last sketch stroke), to look into.
    model.last_stroke = stroke_as_curve(tool.last_stroke());
    if (made) {
      obj.name = "sketch-" + std::to_string(++model.created);
      model.scene.objects.push_back(std::move(obj));
      model.scene.view.intersections = true;  // its crossings and Gauss code
      model.status = std::string("sketched ") + model.scene.objects.back().name + "; " + kSketchHelp;
    }
  }
  // The stroke so far: white where it passes over, blue where under.
  ImDrawList* draw = ImGui::GetForegroundDrawList();
  const auto& pts = tool.screen();
  for (std::size_t i = 1; i < pts.size(); ++i)
    draw->AddLine(ImVec2(float(pts[i - 1].first.x()), float(pts[i - 1].first.y())),
                  ImVec2(float(pts[i].first.x()), float(pts[i].first.y())),
                  pts[i].second ? IM_COL32(90, 150, 255, 255) : IM_COL32(240, 240, 240, 255), 3.0f);
}

// A right click on a crossing's dot changes that crossing of the curve, as seen (the paper's
// "what does changing this crossing give?").
void change_crossing_at(GLFWwindow* window, GuiModel& model, const Camera& camera, const Vec2& cursor) {
  int w = 0, h = 0;
  glfwGetWindowSize(window, &w, &h);
  const ScreenCrossing* best = nullptr;
  double best_px = 14;  // pixels: about a dot's size
  const ScreenCrossings found = screen_crossings(model.scene, camera);
  for (const ScreenCrossing& c : found.crossings) {
    const Vec2 at = camera.ndc(c.over);
    const Vec2 px((at.x() + 1) / 2 * w, (1 - at.y()) / 2 * h);
    if ((px - cursor).norm() < best_px) {
      best_px = (px - cursor).norm();
      best = &c;
    }
  }
  if (!best) return;
  try {
    SceneObject& obj = model.scene.objects[best->object];
    obj.shape = change_crossing_in_view(model.scene, camera, *best, 2.5 * model.scene.view.tube_radius);
    obj.generator.reset();  // edited geometry: saved as a file beside the scene
    obj.source_path.clear();
    model.status = "changed a crossing of '" + obj.name + "'";
  } catch (const std::exception& e) {
    model.error = e.what();
  }
}

// Mouse drags that ImGui does not want go to the view: plain = trackball, shift = xw/yw,
// ctrl = zw; the wheel zooms. While sketching, the left button draws instead.
void handle_mouse(GLFWwindow* window, GuiModel& model, SketchTool& sketch, const Camera& camera,
                  double& last_x, double& last_y) {
  double x = 0, y = 0;
  glfwGetCursorPos(window, &x, &y);
  const double dx = x - last_x, dy = y - last_y;
  last_x = x;
  last_y = y;
  const ImGuiIO& io = ImGui::GetIO();
  handle_sketch(window, model, sketch, camera, Vec2(x, y), io.WantCaptureMouse);
  if (io.WantCaptureMouse) return;
  if (io.MouseWheel != 0) model.view.scroll(io.MouseWheel);
  if (!model.sketching && ImGui::IsMouseClicked(ImGuiMouseButton_Right)) change_crossing_at(window, model, camera, Vec2(x, y));
  if (model.sketching || glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) != GLFW_PRESS) return;
  int w = 0, h = 0;
  glfwGetWindowSize(window, &w, &h);
  const DragMode mode = io.KeyShift  ? DragMode::kRotateW
                        : io.KeyCtrl ? DragMode::kRotateZW
                                     : DragMode::kTrackball;
  model.view.drag(mode, dx, dy, h);
}

void handle_keys(GuiModel& model) {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantTextInput) return;
  if (io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_Q)) model.quit = true;
  if (ImGui::IsKeyPressed(GLFW_KEY_F12)) model.want_screenshot = true;
}

void save_shot(const Image& image, const std::string& path, GuiModel& model) {
  try {
    write_png(image, path);
    model.status = "saved " + path;
  } catch (const std::exception& e) {
    model.error = e.what();
  }
}

}  // namespace

int run_gui_app(const GuiOptions& options) {
  glfwSetErrorCallback(glfw_error);
  if (!glfwInit()) {
    std::cerr << "shadow4d: cannot open a window (glfwInit failed); try `shadow4d demo`\n";
    return 1;
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_SAMPLES, 4);
  GLFWwindow* window = glfwCreateWindow(options.width, options.height, "shadow4d", nullptr, nullptr);
  if (!window) {
    std::cerr << "shadow4d: cannot create an OpenGL 3.3 window; try `shadow4d demo`\n";
    glfwTerminate();
    return 1;
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(1);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // layout is not persisted: every start looks the same
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");

  int exit_code = 0;
  {
    Renderer renderer;
    Panels panels;
    SketchTool sketch;
    HapticsWindow haptics;
    if (!options.device.empty()) haptics.start(options.device);
    GuiModel model;
    Panels::open(model, options.open_spec.empty() ? "clifford-torus" : options.open_spec);
    if (!model.error.empty() && !options.open_spec.empty()) {
      std::cerr << "shadow4d: " << model.error << "\n";
      exit_code = 1;
    }
    double last_x = 0, last_y = 0;
    glfwGetCursorPos(window, &last_x, &last_y);
    for (int frame = 1; !glfwWindowShouldClose(window) && !model.quit; ++frame) {
      glfwPollEvents();
      ImGui_ImplOpenGL3_NewFrame();
      ImGui_ImplGlfw_NewFrame();
      ImGui::NewFrame();
      handle_mouse(window, model, sketch, renderer.camera(), last_x, last_y);
      handle_keys(model);
      panels.draw(model, ImGui::GetIO().Framerate);
      if (model.open_haptics) {
        model.open_haptics = false;
        if (!haptics.running()) haptics.start("mouse");
        haptics.open() = true;
      }
      haptics.draw();
      ImGui::Render();

      int fw = 0, fh = 0;
      glfwGetFramebufferSize(window, &fw, &fh);
      model.view.apply_to(model.scene);
      if (fw > 0 && fh > 0) {
        renderer.draw(model.scene, fw, fh);
        model.intersections = renderer.intersections();
        if (model.want_screenshot) {  // the picture without the panels
          model.want_screenshot = false;
          save_shot(renderer.read_pixels(fw, fh), model.screenshot_path, model);
        }
      }
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
      const bool last = options.frames > 0 && frame >= options.frames;
      if (last && !options.window_shot.empty()) {
        try {
          write_png(renderer.read_pixels(fw, fh), options.window_shot);
          std::cout << options.window_shot << "\n";
        } catch (const std::exception& e) {
          std::cerr << "shadow4d: " << e.what() << "\n";
          exit_code = 1;
        }
      }
      glfwSwapBuffers(window);
      if (last) break;
    }
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  glfwTerminate();
  return exit_code;
}

}  // namespace s4d
