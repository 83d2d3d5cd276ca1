// Renderer tests through EGL llvmpipe (no display, no GPU). If no GL context can be made these
// FAIL rather than skip: CI has Mesa, so a missing context is a real breakage. Covers the
// drawing modes, see-through surfaces, the intersection marks and what each draw uploads.
#include "render/renderer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "render/gl_context.hpp"
#include "render/test_shapes.hpp"

namespace s4d {
namespace {

constexpr int kW = 160, kH = 120;

TEST(OffscreenContext, GivesOpenGL33CoreWithMultisampling) {
  OffscreenContext ctx;
  const std::string version = ctx.version();
  ASSERT_FALSE(version.empty());
  const int major = version[0] - '0', minor = version[2] - '0';
  EXPECT_GE(major * 10 + minor, 33) << version;
  EXPECT_FALSE(ctx.renderer().empty());
  RenderTarget target(32, 16, 4);
  EXPECT_GE(target.samples(), 1);
  EXPECT_LE(target.samples(), 4);
  // Two contexts one after the other (each render_offscreen makes its own) must both work.
  OffscreenContext again;
  EXPECT_FALSE(again.version().empty());
}

TEST(RenderOffscreen, EmptySceneIsExactlyTheBackground) {
  Scene sc;
  sc.view.background = Vec3f(0.2f, 0.4f, 0.6f);
  const Image img = render_offscreen(sc, 40, 30);
  ASSERT_EQ(img.width, 40);
  ASSERT_EQ(img.height, 30);
  for (std::size_t i = 0; i < img.rgba.size(); i += 4) {
    EXPECT_NEAR(img.rgba[i], 51, 1);
    EXPECT_NEAR(img.rgba[i + 1], 102, 1);
    EXPECT_NEAR(img.rgba[i + 2], 153, 1);
    EXPECT_EQ(img.rgba[i + 3], 255);
  }
}

TEST(RenderOffscreen, BadSizeThrows) {
  EXPECT_THROW(render_offscreen(Scene{}, 0, 10), Error);
  EXPECT_THROW(render_offscreen(Scene{}, 10, -1), Error);
}

// Pixels of the true intersections' magenta: nothing else drawn is that colour (the depth maps
// run blue-white-red).
int magenta_pixels(const Image& img) {
  int n = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const auto* p = img.pixel(x, y);
      n += p[0] > 150 && p[1] < 90 && p[2] > 130;
    }
  return n;
}

TEST(RenderOffscreen, IntersectionCurvesAreDrawnWhenAsked) {
  Scene sc = test::scene_of(test::crossing_planes());
  sc.frame.rotate(Plane{0, 3}, 0.5);
  sc.frame.rotate(Plane{1, 2}, 0.35);
  sc.frame.rotate(Plane{0, 2}, 0.17);
  EXPECT_EQ(magenta_pixels(render_offscreen(sc, 320, 240)), 0);
  sc.view.intersections = true;
  IntersectionSummary drawn;
  const Image img = render_offscreen(sc, 320, 240, &drawn);
  EXPECT_TRUE(drawn.computed);
  EXPECT_EQ(drawn.true_points, 1);
  EXPECT_GT(magenta_pixels(img), 10) << "the bead on the true 4D point";
}

// Pixels the crossing dots add to an image of `curve` (seen down -z): those near-white with the
// dots drawn and not without them. The curve is dark blue, so only the dots (and highlights,
// which are in both images) are near-white.
int crossing_dot_pixels(const Curve<3>& curve) {
  Scene sc = test::scene_of(curve);
  sc.objects[0].colour = Vec3f(0.1f, 0.1f, 0.4f);
  sc.view.depth_colour = false;
  sc.view.tube_radius = 0.1;
  auto white = [](const Image& img) {
    std::vector<bool> w(static_cast<std::size_t>(img.width) * img.height);
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) {
        const auto* p = img.pixel(x, y);
        w[static_cast<std::size_t>(y) * img.width + x] = p[0] > 200 && p[1] > 200 && p[2] > 200;
      }
    return w;
  };
  const auto plain = white(render_offscreen(sc, 320, 240));
  sc.view.intersections = true;
  IntersectionSummary drawn;
  const auto dotted = white(render_offscreen(sc, 320, 240, &drawn));
  EXPECT_EQ(drawn.crossings, 1);
  int n = 0;
  for (std::size_t i = 0; i < plain.size(); ++i) n += dotted[i] && !plain[i];
  return n;
}

// A strand along x under one along y, 0.1 apart in depth at the crossing (the tubes, radius 0.1,
// overlap there): the dot on the over strand shows whole when that strand climbs towards the eye
// at 55°, as when it lies flat. It used to sit at the tube's plain radius and show as a crescent.
TEST(RenderOffscreen, CrossingDotsShowWholeOnAStrandInclinedToTheScreen) {
  auto crossing = [](double incline) {
    const Vec3 over(0, 0, 0.1), dir(0, std::cos(incline), std::sin(incline));
    Curve<3> c;
    c.components.push_back({{Vec3(-1, 0, 0), Vec3(1, 0, 0)}, false});
    c.components.push_back({{over - 0.6 * dir, over + 0.6 * dir}, false});
    return c;
  };
  const int flat = crossing_dot_pixels(crossing(0.0));
  EXPECT_GT(flat, 40);
  const int inclined = crossing_dot_pixels(crossing(55.0 * std::acos(-1.0) / 180.0));
  EXPECT_GT(inclined, 0.85 * flat);
  EXPECT_LT(inclined, 1.15 * flat) << "the dot looks the same size";
}

TEST(RenderOffscreen, CliffordTorusCoverageIsSensible) {
  Scene sc = test::scene_of(test::clifford_torus(48));
  sc.frame.rotate(Plane{0, 3}, 0.5);
  sc.frame.rotate(Plane{1, 2}, 0.6);
  const Image img = render_offscreen(sc, kW, kH);
  const double c = test::coverage(img, sc.view.background);
  EXPECT_GT(c, 0.25) << "the fitted torus should fill a good part of the frame";
  EXPECT_LT(c, 0.75) << "but not all of it";
}

TEST(RenderOffscreen, TrefoilTubeCoverageIsSensible) {
  Scene sc = test::scene_of(test::trefoil(200));
  sc.view.tube_radius = 0.08;
  const Image img = render_offscreen(sc, kW, kH);
  const double c = test::coverage(img, sc.view.background);
  EXPECT_GT(c, 0.08);
  EXPECT_LT(c, 0.5);
}

// Mean colour of the non-background pixels in the columns [x0, x1).
Vec3f mean_colour(const Image& img, const Vec3f& bg, int x0, int x1) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int n = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = x0; x < x1; ++x) {
      const auto* p = img.pixel(x, y);
      if (std::abs(p[0] - bg.x() * 255) + std::abs(p[1] - bg.y() * 255) + std::abs(p[2] - bg.z() * 255) < 10)
        continue;
      sum += Eigen::Vector3d(p[0], p[1], p[2]);
      ++n;
    }
  return n ? Vec3f((sum / n / 255).cast<float>()) : Vec3f(-1, -1, -1);
}

TEST(RenderOffscreen, ColourFollowsW) {
  // w = 0.5 x: the right half of the square is nearer in 4D, so redder; the left bluer.
  Scene sc = test::scene_of(test::tilted_square(0.5));
  const Image img = render_offscreen(sc, kW, kH);
  const Vec3f left = mean_colour(img, sc.view.background, 0, kW / 3);
  const Vec3f right = mean_colour(img, sc.view.background, 2 * kW / 3, kW);
  ASSERT_GE(left.x(), 0) << "nothing drawn on the left";
  ASSERT_GE(right.x(), 0) << "nothing drawn on the right";
  EXPECT_GT(right.x() - right.z(), 0.25f) << "right side should be red";
  EXPECT_LT(left.x() - left.z(), -0.15f) << "left side should be blue";
  // Flip the sign of w with a half turn in the zw plane: the colours swap sides.
  sc.frame.rotate(Plane{2, 3}, test::kPi);
  const Image flipped = render_offscreen(sc, kW, kH);
  const Vec3f left2 = mean_colour(flipped, sc.view.background, 0, kW / 3);
  EXPECT_GT(left2.x() - left2.z(), 0.25f);
}

TEST(RenderOffscreen, FourDimensionalRotationChangesTheImage) {
  Scene sc = test::scene_of(test::clifford_torus(48));
  sc.frame.rotate(Plane{1, 2}, 0.6);
  const Image a = render_offscreen(sc, kW, kH);
  sc.frame.rotate(Plane{0, 3}, test::kPi / 4);
  const Image b = render_offscreen(sc, kW, kH);
  EXPECT_GT(test::differing_fraction(a, b, 24), 0.2);
}

TEST(RenderOffscreen, WireframeDrawsDarkEdgesOverTheSurface) {
  Scene sc = test::scene_of(test::tilted_square(0.5, 8));
  const Image plain = render_offscreen(sc, kW, kH);
  sc.view.wireframe = true;
  const Image wire = render_offscreen(sc, kW, kH);
  EXPECT_GT(test::differing_fraction(plain, wire, 24), 0.03);
  const Vec3f bg = sc.view.background * 255;
  auto dark = [&](const Image& img) {
    int n = 0;
    for (std::size_t i = 0; i < img.rgba.size(); i += 4) {
      const auto* p = &img.rgba[i];
      const bool background = std::abs(p[0] - bg.x()) + std::abs(p[1] - bg.y()) + std::abs(p[2] - bg.z()) < 4;
      n += p[0] < 40 && p[1] < 40 && p[2] < 45 && !background;
    }
    return n;
  };
  EXPECT_GT(dark(wire), dark(plain) + 200);
}

TEST(RenderOffscreen, ShadowModeIsFlatAndUnlit) {
  // A trough curved along y with w = 0.5 x. In the flat shadow mode its colour is w's colour
  // only, so the centre column (x = 0) is one colour; lit, it shades with the curvature.
  Scene sc = test::scene_of(test::tilted_square(0.5, 33, 0.8));
  sc.view.trackball = Eigen::Quaterniond(Eigen::AngleAxisd(-0.5, Vec3::UnitX()));
  const Image lit = render_offscreen(sc, kW, kH);
  sc.view.shadow = true;
  const Image flat = render_offscreen(sc, kW, kH);
  EXPECT_GT(test::differing_fraction(lit, flat, 24), 0.1);
  const Vec3f bg = sc.view.background * 255;
  auto column_spread = [&](const Image& img) {
    int lo = 255, hi = 0;
    for (int y = 0; y < kH; ++y) {
      const auto* p = img.pixel(kW / 2, y);
      if (std::abs(p[0] - bg.x()) + std::abs(p[1] - bg.y()) + std::abs(p[2] - bg.z()) < 30) continue;
      // Skip anti-aliased silhouette pixels: they blend with the background.
      const auto* up = img.pixel(kW / 2, std::max(y - 1, 0));
      const auto* down = img.pixel(kW / 2, std::min(y + 1, kH - 1));
      if (std::abs(up[0] - bg.x()) < 30 || std::abs(down[0] - bg.x()) < 30) continue;
      lo = std::min<int>(lo, p[1]);
      hi = std::max<int>(hi, p[1]);
    }
    return hi - lo;
  };
  EXPECT_LE(column_spread(flat), 3);
  EXPECT_GT(column_spread(lit), 40);
}

TEST(RenderOffscreen, DepthColourOffGivesGrey) {
  Scene sc = test::scene_of(test::clifford_torus(32));
  sc.frame.rotate(Plane{0, 3}, 0.5);
  sc.frame.rotate(Plane{1, 2}, 0.6);
  auto max_chroma = [&](const Image& img) {
    int worst = 0;
    for (std::size_t i = 0; i < img.rgba.size(); i += 4)
      worst = std::max(worst, std::abs(int(img.rgba[i]) - int(img.rgba[i + 2])));
    return worst;
  };
  EXPECT_GT(max_chroma(render_offscreen(sc, kW, kH)), 60) << "depth colour should show red/blue";
  sc.view.depth_colour = false;
  // kGrey is a slightly warm grey (0.78, 0.76, 0.72): red - blue stays within ~0.06 of full scale.
  EXPECT_LE(max_chroma(render_offscreen(sc, kW, kH)), 18);
}

// A square of R^4 facing +z at height z and depth w, centred at (cx, 0), half-width 0.6.
Surface<4> square_at(double cx, double z, double w) {
  Surface<4> s;
  for (const auto& [u, v] : {std::pair{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}})
    s.vertices.emplace_back(cx + 0.6 * u, 0.6 * v, z, w);
  s.triangles = {{0, 1, 2}, {0, 2, 3}};
  return s;
}

// A square in front (z = 0.5, nearer in w: red) of another (z = -0.5, farther in w: blue),
// overlapping in the middle columns, drawn flat (a pixel is its colour blended, nothing else).
// Returns the mean colour (0-255) of the overlap and of the part where only the front one is.
struct OverlapColours {
  Vec3f overlap, front_only;
};
OverlapColours overlap_colours(double opacity, bool front_first, bool one_object) {
  Surface<4> front = square_at(-0.3, 0.5, 1), back = square_at(0.3, -0.5, -1);
  Scene sc;
  if (one_object) {  // one surface with both sheets: its triangles are sorted, not the objects
    Surface<4> both = front_first ? front : back;
    const Surface<4>& second = front_first ? back : front;
    both.vertices.insert(both.vertices.end(), second.vertices.begin(), second.vertices.end());
    both.triangles.insert(both.triangles.end(), {{4, 5, 6}, {4, 6, 7}});
    sc = test::scene_of(both);
  } else {
    sc = test::scene_of(front_first ? front : back);
    sc.objects.push_back(test::scene_of(front_first ? back : front).objects[0]);
    sc.objects[1].name = "second";
  }
  sc.view.shadow = true;
  sc.view.opacity = opacity;
  const Image img = render_offscreen(sc, 320, 240);
  const Camera cam = build_scene_geometry(sc, 320.0 / 240).camera;
  auto mean = [&](double x0, double x1) {  // over x in [x0, x1], |y| < 0.3 on the front square
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    int n = 0;
    const Vec2 lo = cam.ndc(Vec3(x0, -0.3, 0.5)), hi = cam.ndc(Vec3(x1, 0.3, 0.5));
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) {
        const double nx = 2.0 * (x + 0.5) / img.width - 1, ny = 1 - 2.0 * (y + 0.5) / img.height;
        if (nx < lo.x() || nx > hi.x() || ny < lo.y() || ny > hi.y()) continue;
        const auto* p = img.pixel(x, y);
        sum += Eigen::Vector3d(p[0], p[1], p[2]);
        ++n;
      }
    EXPECT_GT(n, 100);
    return Vec3f((sum / std::max(n, 1)).cast<float>());
  };
  // The front square spans x in [-0.9, 0.3], the back one [-0.3, 0.9], seen smaller by
  // perspective (its near edge at x = -0.2 on the front square): [-0.1, 0.1] is in both,
  // [-0.8, -0.4] in front only.
  return {mean(-0.1, 0.1), mean(-0.8, -0.4)};
}

// At opacity 0.4 the overlap mixes the front red with the back blue as "over" blending in depth
// order does (0.4 front + 0.6 (0.4 back + 0.6 background)); at 1 the back one is hidden. The
// result depends neither on the order of the objects in the scene nor on that of a surface's
// triangles: they are drawn far to near.
TEST(RenderOffscreen, SeeThroughSurfacesShowTheSheetBehind) {
  const Vec3f bg = Scene{}.view.background * 255;
  const Vec3f red = map_colour(ColourMap::kCoolWarm, 1) * 255, blue = map_colour(ColourMap::kCoolWarm, 0) * 255;
  const OverlapColours opaque = overlap_colours(1.0, true, false);
  EXPECT_LT((opaque.overlap - red).cwiseAbs().maxCoeff(), 3) << "the back square is hidden";
  for (const bool one_object : {false, true})
    for (const bool front_first : {true, false}) {
      SCOPED_TRACE(std::string(one_object ? "one object" : "two objects") + (front_first ? ", front first" : ", back first"));
      const OverlapColours c = overlap_colours(0.4, front_first, one_object);
      const Vec3f mixed = 0.4f * red + 0.6f * (0.4f * blue + 0.6f * bg);
      EXPECT_LT((c.overlap - mixed).cwiseAbs().maxCoeff(), 4)
          << "the blue square shows through: " << c.overlap.transpose() << " vs " << mixed.transpose();
      const Vec3f alone = 0.4f * red + 0.6f * bg;
      EXPECT_LT((c.front_only - alone).cwiseAbs().maxCoeff(), 4) << c.front_only.transpose();
    }
}

// Tubes stay opaque in front of a see-through surface.
TEST(RenderOffscreen, TubesStayOpaqueWhenSurfacesAreSeeThrough) {
  Scene sc;
  sc.objects.push_back(test::flat_square(0, -0.5, 1.0, Vec3f(0, 1, 0), "back"));
  Curve<3> bar;
  bar.components.push_back({{Vec3(-0.8, 0, 0.3), Vec3(0.8, 0, 0.3)}, false});
  SceneObject tube;
  tube.name = "bar";
  tube.shape = bar;
  tube.colour = Vec3f(1, 0, 0);
  sc.objects.push_back(tube);
  sc.view.depth_colour = false;
  sc.view.shadow = true;
  sc.view.tube_radius = 0.1;
  const Image opaque = render_offscreen(sc, 160, 120);
  sc.view.opacity = 0.3;
  const Image clear = render_offscreen(sc, 160, 120);
  const auto* centre_opaque = opaque.pixel(80, 60);
  const auto* centre_clear = clear.pixel(80, 60);
  EXPECT_GT(centre_clear[0], 250) << "the tube is drawn in full";
  EXPECT_EQ(centre_clear[1], centre_opaque[1]);
  const Vec2 above = build_scene_geometry(sc, 160.0 / 120).camera.ndc(Vec3(0, 0.5, -0.5));
  const int ax = static_cast<int>((above.x() + 1) / 2 * 160), ay = static_cast<int>((1 - above.y()) / 2 * 120);
  EXPECT_GT(opaque.pixel(ax, ay)[1], 250) << "the square, above the tube";
  EXPECT_LT(clear.pixel(ax, ay)[1], 0.5 * opaque.pixel(ax, ay)[1]) << "fades";
}

// Pixels of a strong red (the above marks) and a strong blue (the below marks): the grey
// surfaces, the yellow curve and the green beads are neither.
bool strong_red(const std::uint8_t* p) { return p[0] > 90 && p[0] > 2.5 * p[1] && p[0] > 2 * p[2]; }
bool strong_blue(const std::uint8_t* p) { return p[2] > 90 && p[2] > 1.8 * p[0] && p[2] > 1.4 * p[1]; }

// Distance in pixels from (x, y) to the segment between the screen images of a and b.
double pixels_to_segment(const Camera& cam, const Image& img, int x, int y, const Vec3& a, const Vec3& b) {
  auto pixel = [&](const Vec3& p) {
    const Vec2 n = cam.ndc(p);
    return Vec2((n.x() + 1) / 2 * img.width, (1 - n.y()) / 2 * img.height);
  };
  const Vec2 pa = pixel(a), pb = pixel(b), q(x + 0.5, y + 0.5);
  const double t = std::clamp((q - pa).dot(pb - pa) / (pb - pa).squaredNorm(), 0.0, 1.0);
  return (pa + t * (pb - pa) - q).norm();
}

// The two squares crossing in the shadow apart in w, grey, seen from above the crossing: with the
// intersections on, red and blue pixels appear, all along the crossing (the x axis from -0.8 to
// 1), and none without.
TEST(RenderOffscreen, AboveBelowMarksAreVisibleAlongTheCurve) {
  Scene sc = test::scene_of(test::sheets_apart_in_w());
  sc.view.depth_colour = false;
  sc.view.tube_radius = 0.06;  // marks of 0.021, 0.09 from the curve
  sc.view.trackball = Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Vec3::UnitX()) * Eigen::AngleAxisd(0.3, Vec3::UnitY()));
  const Camera cam = build_scene_geometry(sc, 320.0 / 240).camera;
  struct Found {
    int red = 0, blue = 0;
    double red_from = 1, red_to = 0, blue_from = 1, blue_to = 0;  // their extent along the curve
  };
  const Vec3 a(-0.8, 0, 0), b(1, 0, 0);  // the crossing
  auto find = [&](const Image& img) {
    Found f;
    const Vec2 pa = (cam.ndc(a) + Vec2::Ones()) / 2, pb = (cam.ndc(b) + Vec2::Ones()) / 2;
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) {
        const auto* p = img.pixel(x, y);
        const bool r = strong_red(p), bl = strong_blue(p);
        if (!r && !bl) continue;
        EXPECT_LT(pixels_to_segment(cam, img, x, y, a, b), 16) << "pixel " << x << ", " << y << " is off the curve";
        const Vec2 q((x + 0.5) / img.width, 1 - (y + 0.5) / img.height);
        const double t = (q - pa).dot(pb - pa) / (pb - pa).squaredNorm();
        (r ? f.red : f.blue)++;
        double& from = r ? f.red_from : f.blue_from;
        double& to = r ? f.red_to : f.blue_to;
        from = std::min(from, t);
        to = std::max(to, t);
      }
    return f;
  };
  const Found plain = find(render_offscreen(sc, 320, 240));
  EXPECT_EQ(plain.red, 0);
  EXPECT_EQ(plain.blue, 0);
  sc.view.intersections = true;
  const Image marked = render_offscreen(sc, 320, 240);
  const Found f = find(marked);
  EXPECT_GT(f.red, 150);
  EXPECT_GT(f.blue, 150);
  EXPECT_GT(f.red_to - f.red_from, 0.8) << "red all along the curve";
  EXPECT_GT(f.blue_to - f.blue_from, 0.8) << "blue all along the curve";
  write_png(marked, ::testing::TempDir() + "above_below_marks_test.png");  // to look at
}

// A second draw of the same mesh with moved vertices sends the vertices again but no indices;
// new triangles are sent; the picture drawn from the kept buffers is the one a fresh renderer
// draws. A see-through surface's sorted triangles are sent when their order changes only.
TEST(Renderer, UploadsOnlyWhatChanged) {
  Scene first = test::scene_of(test::clifford_torus(24));
  first.frame.rotate(Plane{0, 3}, 0.5);
  Scene moved = first;
  moved.frame.rotate(Plane{1, 3}, 0.4);  // every vertex moves, the triangles stay
  Scene curves = moved;
  curves.view.intersections = true;
  Scene remeshed = moved;
  remeshed.objects[0].shape = test::clifford_torus(20);
  Scene clear = remeshed;
  clear.view.opacity = 0.5;
  // The pictures a fresh renderer draws, made first: render_offscreen makes its own context.
  const Image expect_moved = render_offscreen(moved, 96, 72);
  const Image expect_remeshed = render_offscreen(remeshed, 96, 72);
  const Image expect_clear = render_offscreen(clear, 96, 72);

  OffscreenContext ctx;
  RenderTarget target(96, 72, 4);
  Renderer r;
  auto draw = [&](const Scene& sc) {
    target.bind();
    r.draw(sc, 96, 72);
    return r.uploads();
  };
  const std::size_t vertex_bytes = 24 * 24 * 9 * sizeof(float);
  const std::size_t index_bytes = 2 * 24 * 24 * 3 * sizeof(std::uint32_t);
  UploadStats u = draw(first);
  EXPECT_EQ(u.meshes, 1);
  EXPECT_EQ(u.vertex_uploads, 1);
  EXPECT_EQ(u.vertex_bytes, vertex_bytes);
  EXPECT_EQ(u.index_uploads, 1);
  EXPECT_EQ(u.index_bytes, index_bytes);

  u = draw(moved);
  EXPECT_EQ(u.vertex_uploads, 1);
  EXPECT_EQ(u.vertex_bytes, vertex_bytes);
  EXPECT_EQ(u.index_uploads, 0);
  EXPECT_EQ(u.index_bytes, 0u);
  EXPECT_EQ(test::differing_fraction(target.resolve_and_read(), expect_moved, 0), 0.0);

  u = draw(curves);  // the overlays appear (curves, marks): their buffers are new, then kept
  EXPECT_EQ(u.meshes, 3);
  EXPECT_EQ(u.index_uploads, 2);
  EXPECT_EQ(draw(curves).index_uploads, 0) << "the same curves again";

  u = draw(remeshed);  // new triangles, and the overlays' buffers freed
  EXPECT_EQ(u.meshes, 1);
  EXPECT_EQ(u.index_uploads, 1);
  EXPECT_EQ(u.index_bytes, 2 * 20 * 20 * 3 * sizeof(std::uint32_t));
  EXPECT_EQ(test::differing_fraction(target.resolve_and_read(), expect_remeshed, 0), 0.0);

  // See-through: the triangles sorted far to near are a new order once, then the same while
  // nothing moves.
  EXPECT_EQ(draw(clear).index_uploads, 1);
  EXPECT_EQ(draw(clear).index_uploads, 0);
  EXPECT_EQ(test::differing_fraction(target.resolve_and_read(), expect_clear, 0), 0.0);
}

TEST(Renderer, DrawIntoATargetMatchesRenderOffscreen) {
  Scene sc = test::scene_of(test::trefoil(120));
  const Image expected = render_offscreen(sc, 64, 48);
  OffscreenContext ctx;
  RenderTarget target(64, 48, 4);
  Renderer r;
  target.bind();
  r.draw(sc, 64, 48);
  const Image got = target.resolve_and_read();
  EXPECT_EQ(test::differing_fraction(expected, got, 0), 0.0);
  // Reading the resolved framebuffer again through the renderer gives the same pixels.
  EXPECT_EQ(test::differing_fraction(got, r.read_pixels(64, 48), 0), 0.0);
  EXPECT_GT(r.camera().distance, 0);
  // Drawing again with fewer objects (GPU buffers freed) still works.
  target.bind();
  r.draw(Scene{}, 64, 48);
  EXPECT_LT(test::coverage(target.resolve_and_read(), Scene{}.view.background), 0.001);
}

}  // namespace
}  // namespace s4d
