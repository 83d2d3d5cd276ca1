// SVG and TikZ text of a view's crossing diagram, written from curve_diagram's strands.
#include "render/diagram_export.hpp"

#include <array>
#include <filesystem>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/error.hpp"
#include "io/text_scanner.hpp"
#include "render/scene_geometry.hpp"

namespace s4d {

namespace {

// Fixed-point with three decimals: a thousandth of a pixel, and no exponents for TikZ.
std::string fixed(double v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.3f", std::abs(v) < 5e-4 ? 0.0 : v);
  return buf;
}

std::string xml_escaped(const std::string& s) {
  std::string out;
  for (const char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default:
        // Control characters are not allowed in XML 1.0 text.
        out += (static_cast<unsigned char>(c) < 0x20 && c != '\t') ? '?' : c;
    }
  }
  return out;
}

// A name inside a TeX comment: one line, no characters that could end it.
std::string comment_safe(const std::string& s) {
  std::string out;
  for (const char c : s) out += (static_cast<unsigned char>(c) < 0x20) ? '?' : c;
  return out;
}

// Each strand's colour index: its component counted over the objects' images in order.
std::vector<int> component_indices(const CurveDiagram& d) {
  std::vector<int> first_of_object;
  int next = 0;
  for (const ScreenImage& im : d.screen.images) {
    if (static_cast<int>(first_of_object.size()) <= im.object) first_of_object.resize(im.object + 1, 0);
    first_of_object[static_cast<std::size_t>(im.object)] = next;
    next += static_cast<int>(im.image.components.size());
  }
  std::vector<int> out;
  for (const DiagramStrand& s : d.strands)
    out.push_back((s.object < static_cast<int>(first_of_object.size()) ? first_of_object[s.object] : 0) + s.run);
  return out;
}

std::string hex(const Vec3f& c) {
  char buf[8];
  auto byte = [](float v) { return static_cast<int>(std::lround(std::clamp(v, 0.f, 1.f) * 255)); };
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", byte(c.x()), byte(c.y()), byte(c.z()));
  return buf;
}

std::string names(const CurveDiagram& d, const Scene& scene) {
  std::string out;
  for (const ScreenImage& im : d.screen.images) {
    if (!out.empty()) out += ", ";
    out += "'" + scene.objects.at(static_cast<std::size_t>(im.object)).name + "'";
  }
  return out.empty() ? "no curves" : out;
}

void check_size(int width, int height) {
  if (width < 1 || height < 1)
    throw Error("a diagram needs a picture size of at least 1x1, got " + std::to_string(width) + "x" +
                std::to_string(height));
}

}  // namespace

Vec3f diagram_colour(int index) {
  // Ink on paper first, then Tableau's ten, which stay apart when printed.
  static constexpr std::array<std::array<int, 3>, 10> kPalette{{{26, 26, 26},
                                                                 {31, 119, 180},
                                                                 {214, 39, 40},
                                                                 {44, 160, 44},
                                                                 {255, 127, 14},
                                                                 {148, 103, 189},
                                                                 {140, 86, 75},
                                                                 {227, 119, 194},
                                                                 {23, 190, 207},
                                                                 {188, 189, 34}}};
  const auto& c = kPalette[static_cast<std::size_t>(((index % 10) + 10) % 10)];
  return Vec3f(c[0], c[1], c[2]) / 255.f;
}

CurveDiagram view_diagram(const Scene& scene, int width, int height) {
  check_size(width, height);
  Scene diagram_view = scene;
  diagram_view.view.curve_mode = CurveMode::kDiagram;
  return build_scene_geometry(diagram_view, static_cast<double>(width) / height).diagram;
}

std::string diagram_svg(const CurveDiagram& d, const Scene& scene, int width, int height) {
  check_size(width, height);
  const std::vector<int> component = component_indices(d);
  const double stroke = d.half_width * height;  // 2 h screen units, a screen unit height / 2 pixels
  std::ostringstream o;
  o << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
    << "\" viewBox=\"0 0 " << width << " " << height << "\">\n"
    << "  <title>" << xml_escaped("Crossing diagram of the view: " + names(d, scene) + ", " +
                                  std::to_string(d.gaps.size()) + " crossing(s)")
    << "</title>\n"
    << "  <rect width=\"" << width << "\" height=\"" << height << "\" fill=\"#ffffff\"/>\n"
    << "  <g fill=\"none\" stroke-width=\"" << fixed(stroke)
    << "\" stroke-linecap=\"butt\" stroke-linejoin=\"round\">\n";
  for (std::size_t i = 0; i < d.strands.size(); ++i) {
    const DiagramStrand& s = d.strands[i];
    o << "    <path data-object=\"" << xml_escaped(scene.objects.at(static_cast<std::size_t>(s.object)).name)
      << "\" data-component=\"" << s.run << "\" stroke=\"" << hex(diagram_colour(component[i])) << "\" d=\"";
    for (std::size_t k = 0; k < s.points.size(); ++k) {
      const Vec2 p = screen_to_pixels(s.points[k], d.aspect, width, height);
      o << (k == 0 ? "M " : " L ") << fixed(p.x()) << " " << fixed(p.y());
    }
    if (s.closed) o << " Z";
    o << "\"/>\n";
  }
  o << "  </g>\n</svg>\n";
  return o.str();
}

std::string diagram_tikz(const CurveDiagram& d, const Scene& scene, int width, int height, double width_cm) {
  check_size(width, height);
  if (!(width_cm > 0 && std::isfinite(width_cm))) throw Error("a TikZ diagram needs a positive width in cm");
  const std::vector<int> component = component_indices(d);
  const double unit = width_cm / width;  // cm per pixel
  char unit_text[32];
  std::snprintf(unit_text, sizeof unit_text, "%.6fcm", unit);
  std::ostringstream o;
  o << "% The crossing diagram of a shadow4d view: " << comment_safe(names(d, scene)) << ", " << d.gaps.size()
    << " crossing(s), " << d.strands.size() << " strand(s).\n"
    << "% Coordinates are the pixels of a " << width << " x " << height
    << " picture of the view, y up. Needs \\usepackage{tikz}.\n"
    << "\\begin{tikzpicture}[x=" << unit_text << ", y=" << unit_text << ", line cap=butt, line join=round]\n";
  int colours = 0;
  for (const int c : component) colours = std::max(colours, c + 1);
  for (int c = 0; c < colours; ++c) {
    const Vec3f rgb = diagram_colour(c) * 255.f;
    o << "  \\definecolor{s4dcomponent" << c << "}{RGB}{" << std::lround(rgb.x()) << "," << std::lround(rgb.y())
      << "," << std::lround(rgb.z()) << "}\n";
  }
  const std::string line_width = fixed(d.half_width * height * unit) + "cm";
  for (std::size_t i = 0; i < d.strands.size(); ++i) {
    const DiagramStrand& s = d.strands[i];
    o << "  \\draw[s4dcomponent" << component[i] << ", line width=" << line_width << "] ";
    for (std::size_t k = 0; k < s.points.size(); ++k) {
      const Vec2 p = screen_to_pixels(s.points[k], d.aspect, width, height);
      o << (k == 0 ? "" : " -- ") << "(" << fixed(p.x()) << "," << fixed(height - p.y()) << ")";
    }
    o << (s.closed ? " -- cycle;\n" : ";\n");
  }
  o << "\\end{tikzpicture}\n";
  return o.str();
}

bool has_curves(const Scene& scene) {
  for (const SceneObject& o : scene.objects)
    if (!is_surface(o.shape)) return true;
  return false;
}

std::string export_diagram(const Scene& scene, const std::string& path, int width, int height) {
  if (!has_curves(scene)) throw Error("the scene has no curves to draw a crossing diagram of");
  const CurveDiagram diagram = view_diagram(scene, width, height);
  std::filesystem::path out(path);
  const bool tikz = out.extension() == ".tex";
  if (!tikz && out.extension() != ".svg") out += ".svg";
  write_text_file(out, tikz ? diagram_tikz(diagram, scene, width, height) : diagram_svg(diagram, scene, width, height));
  return out.string();
}

}  // namespace s4d
