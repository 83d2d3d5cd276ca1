// The curve modes drawn (EGL llvmpipe, no display): the crossing diagram leaves the background in
// each gap of the under strand and draws the over strand through; the plain shadow is one flat
// colour per strand and shows no depth where strands cross; tubes are drawn as before.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>
#include <vector>

#include "render/renderer.hpp"
#include "render/scene_geometry.hpp"
#include "render/test_shapes.hpp"

namespace s4d {
namespace {

constexpr int kW = 320, kH = 240;

Scene trefoil_scene(CurveMode mode) {
  Scene sc = load_scene(std::string(S4D_SOURCE_DIR) + "/scenes/trefoil-knot.json");
  sc.view.curve_mode = mode;
  sc.view.depth_colour = false;
  return sc;
}

int channel_distance(const std::uint8_t* p, const Vec3f& c) {
  int d = 0;
  for (int k = 0; k < 3; ++k) d = std::max(d, std::abs(int(p[k]) - int(std::lround(c[k] * 255))));
  return d;
}

bool is_background(const Image& img, const Vec2& px, const Vec3f& bg) {
  const int x = static_cast<int>(std::floor(px.x())), y = static_cast<int>(std::floor(px.y()));
  EXPECT_TRUE(x >= 0 && y >= 0 && x < img.width && y < img.height);
  return channel_distance(img.pixel(x, y), bg) <= 6;
}

// Across each gap, halfway between the over strand's edge and the under strand's cut end, the
// under strand's line shows the background on both sides of the crossing; the tubes draw it
// there, and the over strand is drawn at the crossing itself.
TEST(CurveModeRender, DiagramShowsTheBackgroundInEachGapOfTheUnderStrand) {
  const Scene sc = trefoil_scene(CurveMode::kDiagram);
  const Vec3f bg = sc.view.background;
  const SceneGeometry g = build_scene_geometry(sc, static_cast<double>(kW) / kH);
  ASSERT_EQ(g.diagram.gaps.size(), 3u);
  const double h = g.diagram.half_width;
  ASSERT_GT(h * kH / 2, 2.5) << "strands of a few pixels at least, so the gaps show";
  const Image diagram = render_offscreen(sc, kW, kH);
  const Image tubes = render_offscreen(trefoil_scene(CurveMode::kTubes), kW, kH);
  for (const DiagramGap& gap : g.diagram.gaps) {
    SCOPED_TRACE("crossing " + std::to_string(gap.crossing));
    const Vec2& u = gap.under_direction;
    const double sin_t = std::abs(u.x() * gap.over_direction.y() - u.y() * gap.over_direction.x());
    const double s = 0.5 * (h / sin_t + gap.half_length);
    ASSERT_GT(gap.half_length - s, 0.5 * h);
    for (const double side : {1.0, -1.0}) {
      const Vec2 px = screen_to_pixels(gap.at + side * s * u, g.diagram.aspect, kW, kH);
      EXPECT_TRUE(is_background(diagram, px, bg)) << "gap at pixel " << px.transpose();
      EXPECT_FALSE(is_background(tubes, px, bg)) << "the tube passes under at " << px.transpose();
    }
    EXPECT_FALSE(is_background(diagram, screen_to_pixels(gap.at, g.diagram.aspect, kW, kH), bg))
        << "the over strand is drawn across the crossing";
  }
}

// Pixels well inside what is drawn (their 3 × 3 neighbourhood all drawn): the largest channel
// difference from `colour`, over all of them; and how many there are.
struct Inside {
  int spread = 0;
  int count = 0;
};
Inside inside_pixels(const Image& img, const Vec3f& bg, const std::vector<Vec3f>& colours) {
  Inside in;
  for (int y = 1; y + 1 < img.height; ++y)
    for (int x = 1; x + 1 < img.width; ++x) {
      bool inside = true;
      for (int dy = -1; dy <= 1 && inside; ++dy)
        for (int dx = -1; dx <= 1 && inside; ++dx) inside = channel_distance(img.pixel(x + dx, y + dy), bg) > 6;
      if (!inside) continue;
      int best = 255;
      for (const Vec3f& c : colours) best = std::min(best, channel_distance(img.pixel(x, y), c));
      in.spread = std::max(in.spread, best);
      ++in.count;
    }
  return in;
}

// The plain shadow has no shading: inside the strands every pixel is the strand's colour (one
// per object here: a red trefoil and a blue ring beside it), where the lit tubes shade.
TEST(CurveModeRender, PlainShadowIsOneFlatColourPerStrand) {
  Scene sc = trefoil_scene(CurveMode::kShadow);
  const Vec3f red(0.85f, 0.2f, 0.15f), blue(0.2f, 0.35f, 0.9f);
  sc.objects[0].colour = red;
  Curve<3> ring;
  ring.components.push_back({{}, true});
  for (int i = 0; i < 80; ++i) {
    const double t = 2 * test::kPi * i / 80;
    ring.components[0].points.push_back(Vec3(4.5 + 0.8 * std::cos(t), 0.8 * std::sin(t), 0));
  }
  SceneObject o;
  o.name = "ring";
  o.shape = ring;
  o.colour = blue;
  sc.objects.push_back(o);
  const Inside flat = inside_pixels(render_offscreen(sc, kW, kH), sc.view.background, {red, blue});
  EXPECT_GT(flat.count, 300);
  EXPECT_LE(flat.spread, 2) << "flat: every pixel inside a strand is its colour";
  sc.view.curve_mode = CurveMode::kTubes;
  const Inside lit = inside_pixels(render_offscreen(sc, kW, kH), sc.view.background, {red, blue});
  EXPECT_GT(lit.spread, 40) << "the tubes are shaded";
  // The crossing diagram is as flat.
  sc.view.curve_mode = CurveMode::kDiagram;
  EXPECT_LE(inside_pixels(render_offscreen(sc, kW, kH), sc.view.background, {red, blue}).spread, 2);
}

// With the window's defaults (depth colour, the intersection marks on), the plain shadow is still
// Fig. 1a: one colour, no crossing dots; the diagram keeps its depth colours.
TEST(CurveModeRender, PlainShadowIgnoresDepthColourAndCrossingMarks) {
  Scene sc = trefoil_scene(CurveMode::kShadow);
  const Vec3f red(0.85f, 0.2f, 0.15f);
  sc.objects[0].colour = red;
  sc.view.depth_colour = true;
  sc.view.intersections = true;
  const Inside plain = inside_pixels(render_offscreen(sc, kW, kH), sc.view.background, {red});
  EXPECT_GT(plain.count, 300);
  EXPECT_LE(plain.spread, 2) << "no depth colour, no crossing dot: every strand pixel is the one colour";
  sc.view.curve_mode = CurveMode::kDiagram;
  EXPECT_GT(inside_pixels(render_offscreen(sc, kW, kH), sc.view.background, {red}).spread, 40)
      << "the diagram is drawn in depth colours";
}

// The plain shadow tells nothing of depth: where two curves cross, the one drawn later shows,
// whichever is nearer; the tubes show the nearer one.
TEST(CurveModeRender, PlainShadowShowsNoDepthWhereCurvesCross) {
  Scene sc;
  const Vec3f red(0.9f, 0.1f, 0.1f), blue(0.1f, 0.2f, 0.9f);
  for (const auto& [name, z, colour, along_x] :
       {std::tuple{"near", 0.5, red, true}, std::tuple{"far", -0.5, blue, false}}) {
    Curve<3> c;
    c.components.push_back({{along_x ? Vec3(-1, 0, z) : Vec3(0, -1, z), along_x ? Vec3(1, 0, z) : Vec3(0, 1, z)}, false});
    SceneObject o;
    o.name = name;
    o.shape = c;
    o.colour = colour;
    sc.objects.push_back(o);
  }
  sc.view.depth_colour = false;
  sc.view.tube_radius = 0.08;
  auto centre = [&](CurveMode mode) {
    sc.view.curve_mode = mode;
    const Image img = render_offscreen(sc, kW, kH);
    const std::uint8_t* p = img.pixel(kW / 2, kH / 2);
    return channel_distance(p, red) < channel_distance(p, blue) ? "red" : "blue";
  };
  EXPECT_STREQ(centre(CurveMode::kTubes), "red") << "the near tube in front";
  EXPECT_STREQ(centre(CurveMode::kShadow), "blue") << "painted in order, not by depth";
  std::swap(sc.objects[0], sc.objects[1]);
  EXPECT_STREQ(centre(CurveMode::kShadow), "red");
}

// Tubes are what they were: the tubes mode is the default, drawn the same.
TEST(CurveModeRender, TubesAreTheDefaultAndUnchanged) {
  Scene sc = trefoil_scene(CurveMode::kTubes);
  EXPECT_EQ(Scene{}.view.curve_mode, CurveMode::kTubes);
  const Image tubes = render_offscreen(sc, kW, kH);
  sc.view.curve_mode = CurveMode::kDiagram;
  const Image diagram = render_offscreen(sc, kW, kH);
  sc.view.curve_mode = CurveMode::kTubes;
  EXPECT_EQ(test::differing_fraction(tubes, render_offscreen(sc, kW, kH), 0), 0.0)
      << "switching back draws the same picture";
  EXPECT_GT(test::differing_fraction(tubes, diagram, 24), 0.01);
}

}  // namespace
}  // namespace s4d
