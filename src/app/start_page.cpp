#include "app/start_page.hpp"

#include "render/gl.hpp"
#include <imgui.h>

#include <algorithm>
#include <cstdint>

#include "app/panels.hpp"
#include "render/gl_context.hpp"
#include "render/renderer.hpp"
#include "scenario/scenario.hpp"

namespace s4d {

namespace {

constexpr int kPictureW = 320, kPictureH = 200;  // rendered once, drawn at the UI's scale

unsigned upload(const Image& img) {
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, img.width, img.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, img.rgba.data());
  glBindTexture(GL_TEXTURE_2D, 0);
  return tex;
}

void title(const char* text) { ImGui::TextColored(ImVec4(0.95f, 0.8f, 0.45f, 1), "%s", text); }

void heading(const char* text) {
  ImGui::Spacing();
  title(text);
  ImGui::Separator();
}

// The last item's rectangle, for the window's dump (tests press where it is drawn), when it is
// wholly on the page as it is scrolled now.
void keep_item(GuiModel& model, const std::string& name) {
  const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
  const Rect r{lo.x, lo.y, hi.x - lo.x, hi.y - lo.y}, page = model.layout.page;
  if (r.x >= page.x && r.y >= page.y && r.right() <= page.right() && r.bottom() <= page.bottom())
    model.start_cards.emplace_back(name, r);
}

bool page_button(GuiModel& model, const char* label) {
  const bool pressed = ImGui::Button(label);
  keep_item(model, label);
  return pressed;
}

void open_empty(GuiModel& model) {
  Document d;
  d.spec = "an empty scene";
  Panels::open(model, std::move(d));
}

}  // namespace

StartPage::~StartPage() {
  for (const Example& e : examples_)
    if (e.texture) glDeleteTextures(1, &e.texture);
}

void StartPage::load(const std::filesystem::path& scenarios, const RecentFiles& recent) {
  examples_.clear();
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(scenarios, ec)) {
    if (entry.path().extension() != ".json") continue;
    Example e;
    e.file = entry.path();
    try {
      const Scenario s = load_scenario(e.file);
      e.name = s.name;
      e.figure = s.figure;
      e.summary = s.summary.empty() ? s.instruction : s.summary;
    } catch (const std::exception& err) {
      e.name = e.file.stem().string();
      e.error = err.what();
    }
    examples_.push_back(std::move(e));
  }
  // In the paper's order: by figure, then name.
  std::sort(examples_.begin(), examples_.end(), [](const Example& a, const Example& b) {
    auto number = [](const std::string& f) { return f.size() > 5 ? std::atof(f.c_str() + 5) : 1e9; };
    return std::pair(number(a.figure), a.name) < std::pair(number(b.figure), b.name);
  });
  recent_ = recent.read();
}

// The example's picture: its scene as `shadow4d render` draws it, into a texture (once).
void StartPage::draw_picture(Example& e) {
  if (e.drawn) return;
  e.drawn = true;
  if (!e.error.empty()) return;
  try {
    const Document doc = load_document(e.file.string());
    GLint fbo = 0;
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &fbo);
    {
      RenderTarget target(kPictureW, kPictureH, 4);
      Renderer renderer;
      target.bind();
      renderer.draw(doc.scene, kPictureW, kPictureH);
      e.texture = upload(target.resolve_and_read());
    }
    glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(fbo));
  } catch (const std::exception& err) {
    e.error = err.what();
  }
}

void StartPage::draw(GuiModel& model) {
  const Rect& r = model.layout.page;
  model.start_cards.clear();
  if (r.empty()) return;
  ImGui::SetNextWindowPos(ImVec2(r.x, r.y));
  ImGui::SetNextWindowSize(ImVec2(r.w, r.h));
  ImGui::Begin("Start", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                                     ImGuiWindowFlags_NoBringToFrontOnFocus);
  ImGui::SetWindowFontScale(1.4f);
  ImGui::TextUnformatted("shadow4d: touch higher-dimensional objects through their shadows");
  ImGui::SetWindowFontScale(1.0f);
  ImGui::TextDisabled("Choose an example of the paper, an exercise, or start from nothing. File > Start page comes back here.");
  draw_examples(model);
  draw_starts(model);
  ImGui::End();
}

void StartPage::draw_examples(GuiModel& model) {
  heading("The paper's examples (each opens paused, its instruction above the view, its verdict live)");
  // Pictures as large as leave the examples half the page in two or three rows, with the
  // exercises and the starts below them in sight.
  const float s = model.ui_scale, line = ImGui::GetTextLineHeightWithSpacing();
  const float avail = ImGui::GetContentRegionAvail().x, gap = ImGui::GetStyle().ItemSpacing.x * 2;
  const int n = std::max(1, static_cast<int>(examples_.size()));
  int per_row = 1;
  ImVec2 pic;
  for (int rows = 1; rows <= n; ++rows) {
    const float h = std::min(kPictureH * 0.7f * s, 0.5f * model.layout.page.h / rows - 4 * line);
    pic = ImVec2(h * kPictureW / kPictureH, h);
    per_row = std::max(1, static_cast<int>(avail / (pic.x + gap)));
    if (per_row * rows >= n) break;
  }
  for (std::size_t i = 0; i < examples_.size(); ++i) {
    Example& e = examples_[i];
    draw_picture(e);
    if (i % static_cast<std::size_t>(per_row) != 0) ImGui::SameLine();
    ImGui::BeginGroup();
    ImGui::PushID(static_cast<int>(i));
    bool open = false;
    if (e.texture) {
      open = ImGui::ImageButton(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(e.texture)), pic);
    } else {
      open = ImGui::Button(e.name.c_str(), ImVec2(pic.x + 2 * ImGui::GetStyle().FramePadding.x, pic.y));
    }
    keep_item(model, e.name);
    if (ImGui::IsItemHovered() && !e.error.empty()) ImGui::SetTooltip("%s", e.error.c_str());
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + pic.x);
    ImGui::Text("%s%s%s", e.figure.c_str(), e.figure.empty() ? "" : "  ", e.name.c_str());
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
    ImGui::TextWrapped("%s", e.summary.c_str());
    ImGui::PopStyleColor();
    ImGui::PopTextWrapPos();
    ImGui::PopID();
    ImGui::EndGroup();
    if (open) Panels::open(model, e.file.string());
  }
}

void StartPage::draw_starts(GuiModel& model) {
  const float col = std::max(ImGui::GetContentRegionAvail().x / 3, 200.0f);
  ImGui::Spacing();
  ImGui::Separator();
  ImGui::BeginGroup();
  title("Knot exercises (the paper's user study)");
  if (page_button(model, "Untangle the unknot (Fig. 15)")) Panels::open(model, (example_folder(model, &DataDirs::scenes) / "fig15-tangled-unknot.json").string());
  if (page_button(model, "Are these the same knot?")) {
    open_empty(model);
    model.open_same_knot = true;
  }
  if (page_button(model, "Unknot it by one crossing change")) {
    open_empty(model);
    model.open_unknot = true;
  }
  ImGui::EndGroup();
  ImGui::SameLine(col);
  ImGui::BeginGroup();
  title("Start from nothing, or a surface");
  if (page_button(model, "Sketch a knot")) {
    open_empty(model);
    model.choose(ToolChoice::kSketchKnot);
  }
  if (page_button(model, "Sketch a ribbon")) {
    open_empty(model);
    model.choose(ToolChoice::kSketchRibbon);
  }
  if (page_button(model, "The spun trefoil")) Panels::open(model, (example_folder(model, &DataDirs::scenes) / "spun-trefoil.json").string());
  if (page_button(model, "The Clifford torus")) Panels::open(model, "clifford-torus");
  if (page_button(model, "Open a file...")) model.open_file_dialog = true;
  ImGui::EndGroup();
  ImGui::SameLine(2 * col);
  ImGui::BeginGroup();
  title("Recent sessions and files");
  if (recent_.empty()) ImGui::TextDisabled("(no session or file opened yet)");
  for (const std::filesystem::path& p : recent_) {
    if (page_button(model, p.filename().string().c_str())) Panels::open(model, p.string());
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", p.string().c_str());
  }
  ImGui::EndGroup();

  heading("Mouse and keys (Help > Keys shows them beside the view)");
  if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_SizingFixedFit)) {
    for (const KeyHelp& k : window_keys()) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(k.keys);
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(k.what);
    }
    ImGui::EndTable();
  }
}

}  // namespace s4d
