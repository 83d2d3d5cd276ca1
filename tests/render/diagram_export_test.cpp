// The diagram's SVG and TikZ: a path per strand run, valid XML (read back by python3's parser),
// coordinates the screen positions of the curve's points in the picture's pixels, one colour per
// component, names escaped.
#include "render/diagram_export.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "core/error.hpp"
#include "render/scene_geometry.hpp"
#include "render/test_shapes.hpp"

namespace s4d {
namespace {

constexpr int kW = 640, kH = 480;

Scene trefoil_scene() { return load_scene(std::string(S4D_SOURCE_DIR) + "/scenes/trefoil-knot.json"); }

std::filesystem::path temp_file(const std::string& name) {
  return std::filesystem::temp_directory_path() / ("s4d_diagram_" + std::to_string(::getpid()) + "_" + name);
}

std::string read(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// What python3's XML parser makes of an SVG: "ok <paths>" and each path's data-object on a line,
// or its error.
std::string python_reads(const std::string& svg) {
  const auto file = temp_file("in.svg"), script = temp_file("check.py"), out = temp_file("out.txt");
  std::ofstream(file) << svg;
  std::ofstream(script) << "import sys, xml.etree.ElementTree as ET\n"
                           "ns = '{http://www.w3.org/2000/svg}'\n"
                           "root = ET.parse(sys.argv[1]).getroot()\n"
                           "assert root.tag == ns + 'svg', root.tag\n"
                           "paths = list(root.iter(ns + 'path'))\n"
                           "print('ok', len(paths))\n"
                           "for p in paths: print(p.get('data-object'))\n";
  const std::string command = "python3 " + script.string() + " " + file.string() + " > " + out.string() + " 2>&1";
  const int status = std::system(command.c_str());
  std::string text = read(out);
  for (const auto& p : {file, script, out}) std::filesystem::remove(p);
  return status == 0 ? text : "failed: " + text;
}

std::vector<std::vector<Vec2>> svg_paths(const std::string& svg, std::vector<bool>* closed = nullptr,
                                         std::vector<std::string>* strokes = nullptr) {
  std::vector<std::vector<Vec2>> out;
  const std::regex path(R"re(<path [^>]*stroke="(#[0-9a-f]{6})" d="([^"]*)"/>)re");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), path); it != std::sregex_iterator(); ++it) {
    if (strokes) strokes->push_back((*it)[1]);
    std::istringstream d((*it)[2]);
    std::vector<Vec2> pts;
    std::string token;
    bool z = false;
    while (d >> token) {
      if (token == "Z") {
        z = true;
        continue;
      }
      EXPECT_TRUE(token == "M" || token == "L") << token;
      double x = 0, y = 0;
      d >> x >> y;
      pts.emplace_back(x, y);
    }
    if (closed) closed->push_back(z);
    out.push_back(std::move(pts));
  }
  return out;
}

std::vector<std::vector<Vec2>> tikz_paths(const std::string& tikz, std::vector<bool>* closed = nullptr) {
  std::vector<std::vector<Vec2>> out;
  std::istringstream lines(tikz);
  std::string line;
  const std::regex point(R"(\((-?[0-9.]+),(-?[0-9.]+)\))");
  while (std::getline(lines, line)) {
    if (line.find("\\draw[") == std::string::npos) continue;
    std::vector<Vec2> pts;
    for (auto it = std::sregex_iterator(line.begin(), line.end(), point); it != std::sregex_iterator(); ++it)
      pts.emplace_back(std::stod((*it)[1]), std::stod((*it)[2]));
    if (closed) closed->push_back(line.find("-- cycle;") != std::string::npos);
    out.push_back(std::move(pts));
  }
  return out;
}

// The pixel of shadow-space point p in a kW × kH picture, from the camera's own matrices.
Vec2 pixel_of(const Camera& cam, const Vec3& p) {
  const Vec2 ndc = cam.ndc(p);
  return Vec2((ndc.x() + 1) / 2 * kW, (1 - ndc.y()) / 2 * kH);
}

// Every path is its strand in pixels (to the written thousandth), and every inner point is where
// the camera puts one of the curve's points.
void expect_paths_are_the_strands(const std::vector<std::vector<Vec2>>& paths, const CurveDiagram& d,
                                  const Scene& sc, const Camera& cam, bool y_up) {
  ASSERT_EQ(paths.size(), d.strands.size());
  std::vector<Vec2> curve;
  for (const Polyline<3>& p : drawn_curve(sc.objects[0].shape, sc.frame))
    for (const Vec3& q : p.points) curve.push_back(pixel_of(cam, q));
  for (std::size_t i = 0; i < paths.size(); ++i) {
    const DiagramStrand& s = d.strands[i];
    ASSERT_EQ(paths[i].size(), s.points.size());
    for (std::size_t k = 0; k < s.points.size(); ++k) {
      Vec2 got = paths[i][k];
      if (y_up) got.y() = kH - got.y();
      EXPECT_LT((got - screen_to_pixels(s.points[k], d.aspect, kW, kH)).norm(), 1e-3);
      if (k == 0 || k + 1 == s.points.size()) continue;
      double best = 1e9;
      for (const Vec2& c : curve) best = std::min(best, (c - got).norm());
      EXPECT_LT(best, 1e-3) << "point " << k << " of path " << i << " is not a curve point";
    }
  }
}

// The shipped trefoil's diagram: three paths (one per run between under-passes), valid XML,
// their points the curve's in the picture.
TEST(DiagramExport, TrefoilSvgHasAPathPerStrandRunAtTheCurvesPixels) {
  const Scene sc = trefoil_scene();
  const CurveDiagram d = view_diagram(sc, kW, kH);
  ASSERT_EQ(d.gaps.size(), 3u);
  const std::string svg = diagram_svg(d, sc, kW, kH);
  EXPECT_EQ(python_reads(svg), "ok 3\ntrefoil\ntrefoil\ntrefoil\n");
  std::vector<bool> closed;
  std::vector<std::string> strokes;
  const auto paths = svg_paths(svg, &closed, &strokes);
  ASSERT_EQ(paths.size(), 3u) << "runs = under-passes";
  for (const bool z : closed) EXPECT_FALSE(z) << "each run stops at a gap";
  for (const std::string& s : strokes) EXPECT_EQ(s, strokes[0]) << "one colour for the one component";
  Scene diagram_mode = sc;
  diagram_mode.view.curve_mode = CurveMode::kDiagram;
  const Camera cam = build_scene_geometry(diagram_mode, static_cast<double>(kW) / kH).camera;
  expect_paths_are_the_strands(paths, d, sc, cam, false);
  // The same diagram the window draws in diagram mode.
  const CurveDiagram drawn = build_scene_geometry(diagram_mode, static_cast<double>(kW) / kH).diagram;
  ASSERT_EQ(drawn.strands.size(), d.strands.size());
  for (std::size_t i = 0; i < d.strands.size(); ++i) EXPECT_EQ(drawn.strands[i].points, d.strands[i].points);
  // As wide as the strands are drawn: 2 half-widths of the screen's height of 2.
  EXPECT_NE(svg.find("stroke-width=\"" + std::to_string(d.half_width * kH).substr(0, 5)), std::string::npos);
}

TEST(DiagramExport, TrefoilTikzHasADrawPerStrandRunAtTheCurvesPixels) {
  const Scene sc = trefoil_scene();
  const CurveDiagram d = view_diagram(sc, kW, kH);
  const std::string tikz = diagram_tikz(d, sc, kW, kH, 8);
  EXPECT_NE(tikz.find("\\begin{tikzpicture}[x=0.012500cm, y=0.012500cm"), std::string::npos) << "8 cm wide";
  EXPECT_NE(tikz.find("\\end{tikzpicture}\n"), std::string::npos);
  EXPECT_LT(tikz.find("\\begin{tikzpicture}"), tikz.find("\\draw"));
  EXPECT_NE(tikz.find("\\definecolor{s4dcomponent0}{RGB}{26,26,26}"), std::string::npos);
  std::vector<bool> closed;
  const auto paths = tikz_paths(tikz, &closed);
  ASSERT_EQ(paths.size(), 3u);
  for (const bool c : closed) EXPECT_FALSE(c);
  Scene diagram_mode = sc;
  diagram_mode.view.curve_mode = CurveMode::kDiagram;
  const Camera cam = build_scene_geometry(diagram_mode, static_cast<double>(kW) / kH).camera;
  expect_paths_are_the_strands(paths, d, sc, cam, true);
  // Every line but the two comments is TikZ: no stray text in the picture.
  std::istringstream lines(tikz);
  std::string line;
  int comments = 0;
  while (std::getline(lines, line)) {
    if (line.rfind("%", 0) == 0) {
      ++comments;
      continue;
    }
    const bool tikz_line = line.rfind("\\begin{tikzpicture}", 0) == 0 || line == "\\end{tikzpicture}" ||
                           line.rfind("  \\definecolor{", 0) == 0 || line.rfind("  \\draw[", 0) == 0;
    EXPECT_TRUE(tikz_line) << line;
  }
  EXPECT_EQ(comments, 2);
}

// The plain shadow's curve and a link: a closed component without gaps is one closed path; each
// component of a link has its own colour.
TEST(DiagramExport, ComponentsHaveTheirOwnColoursAndAnUncutLoopIsClosed) {
  Curve<3> two = test::trefoil(120);
  Polyline<3> ring;
  for (int i = 0; i < 60; ++i) {  // a small circle far off to the side: no crossings with the knot
    const double t = 2 * test::kPi * i / 60;
    ring.points.push_back(Vec3(3 + 0.3 * std::cos(t), 0.3 * std::sin(t), 0));
  }
  two.components.push_back(ring);
  const Scene sc = test::scene_of(two);
  const CurveDiagram d = view_diagram(sc, kW, kH);
  const std::string svg = diagram_svg(d, sc, kW, kH);
  ASSERT_EQ(python_reads(svg).substr(0, 5), "ok 4\n");
  std::vector<bool> closed;
  std::vector<std::string> strokes;
  svg_paths(svg, &closed, &strokes);
  ASSERT_EQ(strokes.size(), 4u);
  EXPECT_EQ(std::set<std::string>(strokes.begin(), strokes.end()).size(), 2u);
  EXPECT_EQ(std::count(closed.begin(), closed.end(), true), 1) << "the ring, uncut";
  EXPECT_EQ(strokes.back(), "#1f77b4") << "the second component in the palette's second colour";
  std::vector<bool> tikz_closed;
  tikz_paths(diagram_tikz(d, sc, kW, kH), &tikz_closed);
  EXPECT_EQ(tikz_closed, closed);
  EXPECT_NE(diagram_tikz(d, sc, kW, kH).find("\\definecolor{s4dcomponent1}{RGB}{31,119,180}"), std::string::npos);
}

// Names are escaped: a knot called <"a" & 'b'> still makes valid XML, which reads the name back.
TEST(DiagramExport, NamesAreEscaped) {
  Scene sc = test::scene_of(test::trefoil(90));
  sc.objects[0].name = "<\"a\" & 'b'>";
  const CurveDiagram d = view_diagram(sc, 200, 150);
  const std::string svg = diagram_svg(d, sc, 200, 150);
  EXPECT_EQ(python_reads(svg), "ok 3\n<\"a\" & 'b'>\n<\"a\" & 'b'>\n<\"a\" & 'b'>\n");
  sc.objects[0].name = "line\nbreak";
  const std::string tikz = diagram_tikz(view_diagram(sc, 200, 150), sc, 200, 150);
  EXPECT_NE(tikz.find("'line?break'"), std::string::npos) << "a name cannot end the comment";
}

TEST(DiagramExport, BadSizesAreRefused) {
  const Scene sc = test::scene_of(test::trefoil(90));
  EXPECT_THROW(view_diagram(sc, 0, 10), Error);
  const CurveDiagram d = view_diagram(sc, 100, 100);
  EXPECT_THROW(diagram_svg(d, sc, 100, -1), Error);
  EXPECT_THROW(diagram_tikz(d, sc, 100, 100, 0), Error);
}

// The window's File > Export crossing diagram: the extension chooses the format.
TEST(DiagramExport, ExportChoosesTheFormatByExtensionAndRefusesASceneWithoutCurves) {
  const Scene sc = trefoil_scene();
  const auto tex = temp_file("export.tex");
  EXPECT_EQ(export_diagram(sc, tex.string(), 320, 240), tex.string());
  EXPECT_NE(read(tex).find("\\begin{tikzpicture}"), std::string::npos);
  const auto bare = temp_file("export");
  const std::string written = export_diagram(sc, bare.string(), 320, 240);
  EXPECT_EQ(written, bare.string() + ".svg");
  EXPECT_NE(read(written).find("<svg"), std::string::npos);
  std::filesystem::remove(tex);
  std::filesystem::remove(written);
  const Scene surfaces = test::scene_of(test::clifford_torus(16));
  EXPECT_FALSE(has_curves(surfaces));
  EXPECT_TRUE(has_curves(sc));
  EXPECT_THROW(export_diagram(surfaces, temp_file("none.svg").string(), 320, 240), Error);
}

}  // namespace
}  // namespace s4d
