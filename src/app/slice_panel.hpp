// The Slice panel (issue 37), shown while the slice is on (the status line's Slice button, W, View >
// Slice by w = c): the slice of the scene's surfaces of R^4 by the hyperplane w = c of
// the 4D view, which the renderer draws over the faded surfaces (view.slice), named live as a link
// off the UI thread (the Knot panel's worker, the one naming), with its level (slider, Alt+wheel,
// a sweep that animates it), the critical levels, a button that makes it a curve of the scene (one
// undoable step), and the movie strip: thumbnails of evenly spaced slices, a click sets the level.
#pragma once
#include <array>
#include <cstdint>
#include <future>
#include <map>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "core/camera.hpp"
#include "knots/knot_info.hpp"
#include "knots/slice_naming.hpp"
#include "view/scene_slice.hpp"

namespace s4d {

struct GuiModel;

// W: the slice on (at the middle of the surfaces' range of w the first time) or off.
void toggle_slice(GuiModel& model);
// Alt+wheel: the level moves by `notches` fortieths of the range of w.
void step_slice(GuiModel& model, double notches);

class SlicePanel {
 public:
  // Frames of the movie strip.
  static constexpr int kMovieFrames = 9;

  // Draws the panel when the scene has a surface of R^4; names the slice when it changed.
  void draw(GuiModel& model, const Camera& camera);
  // Naming under way (a scripted input's `wait` holds for it).
  bool busy() const;
  // For dump and tests: the name shown for the slice ("" until named, "empty" for none).
  std::string shown_name() const;
  void dump(nlohmann::ordered_json& out) const;

 private:
  bool button(const char* label);
  void remember(const char* label);  // the last item's rectangle, for dump()
  void name_live(const SceneSlice& slice);
  void make_curve(GuiModel& model, const SceneSlice& slice);
  void movie_strip(GuiModel& model, const Camera& camera, double lo, double hi);

  KnotInfoWorker worker_;
  std::size_t submitted_hash_ = 0;
  std::uint64_t submitted_ = 0;
  std::shared_ptr<const KnotInfoWorker::Result> shown_;
  bool drawn_ = false;      // the panel was open this frame
  bool on_ = false;
  double level_ = 0;
  int components_ = 0, open_ = 0;
  bool sweep_ = false;
  double sweep_direction_ = 1;
  CriticalCount critical_;
  std::map<std::string, std::array<float, 4>> buttons_;  // drawn this frame, window pixels
  // The movie strip: its frames' levels, the thumbnails' rectangles, and their names, made
  // together off the UI thread (fast naming) for the state they were asked for.
  bool movie_open_ = false;
  std::vector<double> movie_levels_;
  std::vector<std::array<float, 4>> thumbnails_;
  std::size_t movie_hash_ = 0, movie_named_hash_ = 0;
  std::future<std::vector<SliceNaming>> movie_job_;
  std::vector<SliceNaming> movie_names_;
};

}  // namespace s4d
