// Sketching a ribbon in the 3D shadow (the paper's section 5, Fig. 8 and 14): the knot sketch one
// dimension up. The hand draws the ribbon's centre line in shadow space; where the ribbon's shadow
// passes another surface's shadow (or its own) it goes above in w, or below where the modifier
// was held; w is then smoothed without changing any choice and the ribbon is lifted to R^4.
#pragma once
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.hpp"
#include "core/frame.hpp"
#include "interact/tools/ribbon_centre_line.hpp"
#include "io/scene.hpp"
#include "knots/stroke.hpp"
#include "shape/surface.hpp"

namespace s4d {

// A cursor sample in the shadow (view x, y, z of the frame); `under`: the modifier held, this
// part of the ribbon passes below in w.
using RibbonStrokeSample = StrokeSample<3>;

struct RibbonSketchOptions {
  DynadrawParams pen;
  double width = 0.2;      // across the stroke, scene units
  bool closed = false;     // join the stroke's end to its start (a ribbon loop)
  double spacing = 0;      // between rows along the stroke; 0: min(width / 2, size / 60)
  int across = 2;          // vertices across a row, 2 .. 64
  double clearance = 0;    // w gap kept at every passage, scene units; 0: 0.05 × the stroke's size
  double smoothing = 0;    // length along the ribbon over which w spreads; 0: 0.25 × size
  double max_move = 0.5;   // in widths: how far the centre line may be smoothed off the stroke where
                           // the ribbon would fold onto itself (a sharp corner, a jagged stretch), leaving
                           // no point drawn more than twice that from it; 0: never
};

// One place where the ribbon's shadow passes another sheet's shadow, and the choice made there.
struct RibbonPassage {
  int surface = -1;        // index into the other surfaces; -1: the ribbon itself (another strand)
  bool below = false;      // below in w (the modifier held there); otherwise above
  int row = 0;             // the ribbon's row where the choice was read (for itself: the later strand)
  double at_length = 0;    // arc length of that row along the centre line
  Vec3 place = Vec3::Zero();  // its centre-line point in the shadow
  double ribbon_w = 0;     // the ribbon's w there, after smoothing
  double other_w = 0;      // the other sheet's w there (for itself: the earlier strand's)
  double gap = 0;          // smallest w gap kept over the whole overlap (>= the clearance)
};

struct SketchedRibbon {
  Surface<4> surface;      // world coordinates; grid rows along the stroke × `across`, wrap_i if closed
  std::vector<RibbonPassage> passages;  // in order along the stroke
  std::vector<Vec3> centre;  // rows: the centre line in the shadow (the resampled, smoothed stroke)
  std::vector<double> w;     // rows: view w (constant across a row)
  double length = 0;         // of the centre line
  double clearance = 0;      // the w gap used
  double gap_to_others = 0;  // smallest 4D distance to the other surfaces (infinity: none within
                             // 4 × clearance)
  CentreLineSmoothing smoothing;  // what was done to the stroke where the ribbon would have folded
  std::string changes;       // the same in a sentence ("" when the stroke was kept as drawn)
};

// ribbon_from_sketch's refusal of a ribbon that folds onto itself where the stroke turns too
// sharply for its width, even smoothed as far as it may be. what() says where and what to change.
class RibbonFoldError : public Error {
 public:
  RibbonFoldError(const std::string& what, const Vec3& place, double widest, bool search_cut_short = false,
                  long long search_work = 0)
      : Error(what),
        place(place),
        widest(widest),
        search_cut_short(search_cut_short),
        search_work(search_work) {}
  Vec3 place;             // the fold, in the shadow
  double widest;          // a narrower width whose ribbon lies flat along this stroke (0: none found)
  bool search_cut_short;  // the search for that width stopped at kRibbonSuggestionWork (what() says so)
  long long search_work;  // rows the search's fold tests looked at
};

// The most rows the fold tests of the search for a narrower ribbon look at in all (about 0.1 s):
// a narrow ribbon along a stroke hundreds of widths long has too many to try every width.
// Measured on 351 sketches (the test strokes at widths 0.03 to 0.3, random jagged ones), the most
// a search took was 169 k (a stroke doubling back, a ribbon 1/33 of its size); a fuzzed stroke 585
// widths long took 745 k (tests/data/fuzz_regressions/ribbon_stroke/).
inline constexpr long long kRibbonSuggestionWork = 200000;

// Builds the ribbon: the stroke smoothed (Dynadraw), closed if asked and resampled; where a flat
// ribbon along it would fold onto itself, its centre line smoothed there, no further than
// `max_move` widths from the stroke (ribbon_centre_line.hpp); the width laid across it in the
// plane facing `toward_eye` (shadow space); at every passage through the shadow
// of one of `others` (world coordinates, seen through `frame`) or of itself, w kept at least the
// clearance above, or below where the modifier was held there (where the ribbon passes itself the
// later strand chooses, as in the knot sketch); w smoothed keeping every choice; lifted to R^4 and
// checked to meet neither itself nor the others. `names` (optional, one per other surface) name
// them in the sentences. Throws s4d::Error with a sentence saying where and why for: a stroke of
// fewer than 2 samples, non-finite or backward samples, no extent, a bad width, spacing or
// clearance, choices that contradict each other at one place, or a result that is not embedded;
// RibbonFoldError for a ribbon that still folds onto itself (the stroke turns more sharply than
// half the ribbon's width even smoothed), naming the place, the turn to draw wider and the widest
// ribbon that would lie flat (or that the search for one was cut short, kRibbonSuggestionWork).
SketchedRibbon ribbon_from_sketch(std::span<const RibbonStrokeSample> stroke,
                                  std::span<const Surface<4>> others, const Frame<4>& frame,
                                  const Vec3& toward_eye, const RibbonSketchOptions& options = {},
                                  std::span<const std::string> names = {});

// Whether a stroke for a ribbon `width` wide comes back to where it began (its ends within 1.5
// widths, its length over 6): a loop, as a knot's stroke closes there. The window's tool and
// `shadow4d sketch-ribbon` close such a stroke unless told otherwise.
bool ribbon_stroke_comes_back(std::span<const RibbonStrokeSample> stroke, double width);

// The surfaces of a scene as ribbon_from_sketch takes them, with their names: objects of R^4 as
// they are; an object of R^3 as the view draws it (the 4D frame does not turn it), so in the
// shadow where its points are, at the view's w = 0. Curves are left out and counted.
struct SketchObstacles {
  std::vector<Surface<4>> surfaces;  // world coordinates of R^4
  std::vector<std::string> names;    // one per surface
  int curves = 0;                    // curve objects left out
};
SketchObstacles sketch_obstacles(const Scene& scene);

// Adds the ribbon to the scene as a new object named `name` ("ribbon 2", ... when taken); returns
// the name it got.
std::string add_sketched_ribbon(Scene& scene, const SketchedRibbon& ribbon, const std::string& name = "ribbon");

// A stroke file: one sample per line, "x y z u" (shadow coordinates; u = 1 where the modifier was
// held, 0 elsewhere), '#' comments and blank lines ignored, samples `dt` seconds apart. Throws
// ParseError("file:line: ...") for malformed lines and for a file without samples.
std::vector<RibbonStrokeSample> parse_ribbon_stroke(std::string_view text, const std::string& origin, double dt);
std::vector<RibbonStrokeSample> read_ribbon_stroke(const std::filesystem::path& path, double dt);

}  // namespace s4d
