// Geomview VECT / 4VECT / nVECT reader and writer (text form).
#include "io/vect.hpp"

#include <climits>
#include <cstdlib>

#include "core/error.hpp"
#include "io/text_scanner.hpp"

namespace s4d {

namespace {

struct VectHeader {
  int dim = 3;
  bool homogeneous = false;  // "4nVECT": n + 1 coordinates, divided by the last
};

VectHeader read_header(TextScanner& in) {
  const std::string_view tok = in.next_token("the VECT header");
  std::string_view k = tok;
  VectHeader h;
  const bool four = k.substr(0, 1) == "4";
  if (four) k.remove_prefix(1);
  const bool n = k.substr(0, 1) == "n";
  if (n) k.remove_prefix(1);
  if (k != "VECT")
    in.fail("not a VECT file: expected a header such as VECT, 4VECT or nVECT, found " + quote_token(tok));
  if (n) {
    h.dim = static_cast<int>(in.next_int("the dimension after nVECT", 1, 1000));
    if (h.dim != 3 && h.dim != 4)
      in.fail("nVECT dimension " + std::to_string(h.dim) + " is not supported (only 3 or 4)");
    h.homogeneous = four;
  } else {
    h.dim = four ? 4 : 3;
  }
  return h;
}

template <int D>
Curve<D> read_body(TextScanner& in, const VectHeader& h) {
  const long long npoly = in.next_int("the polyline count", 0, INT_MAX);
  const long long nvert = in.next_int("the vertex count", 0, INT_MAX);
  const long long ncol = in.next_int("the colour count", 0, INT_MAX);
  const int coords = D + (h.homogeneous ? 1 : 0);
  // Every polyline has two count tokens; then the vertices, then four values per colour.
  in.check_fits(2 * npoly + coords * nvert + 4 * ncol, 1, "polyline, vertex and colour counts");

  Curve<D> c;
  c.components.resize(static_cast<std::size_t>(npoly));
  long long vertex_sum = 0;
  for (long long i = 0; i < npoly; ++i) {
    const long long nv = in.next_int("a polyline's vertex count", -INT_MAX, INT_MAX);
    const long long a = std::llabs(nv);
    if (a < 2)
      in.fail("polyline " + std::to_string(i) + " has " + std::to_string(a) +
              " vertices; a curve component needs at least 2");
    vertex_sum += a;
    if (vertex_sum > nvert)
      in.fail("polyline vertex counts add up to more than the declared " + std::to_string(nvert) +
              " vertices");
    c.components[static_cast<std::size_t>(i)].closed = nv < 0;
    c.components[static_cast<std::size_t>(i)].points.resize(static_cast<std::size_t>(a));
  }
  if (vertex_sum != nvert)
    in.fail("polyline vertex counts add up to " + std::to_string(vertex_sum) + ", but the header declares " +
            std::to_string(nvert));
  long long colour_sum = 0;
  for (long long i = 0; i < npoly; ++i) {
    const long long nc = in.next_int("a polyline's colour count", 0, INT_MAX);
    const long long nv = static_cast<long long>(c.components[static_cast<std::size_t>(i)].points.size());
    if (nc != 0 && nc != 1 && nc != nv)
      in.fail("polyline " + std::to_string(i) + " has " + std::to_string(nc) + " colours; must be 0, 1 or " +
              std::to_string(nv));
    colour_sum += nc;
  }
  if (colour_sum != ncol)
    in.fail("polyline colour counts add up to " + std::to_string(colour_sum) + ", but the header declares " +
            std::to_string(ncol));

  for (Polyline<D>& p : c.components) {
    for (Vec<D>& v : p.points) {
      for (int k = 0; k < D; ++k) v[k] = in.next_double("a vertex coordinate");
      if (h.homogeneous) {
        const double w = in.next_double("a homogeneous coordinate");
        if (w == 0) in.fail("a vertex has homogeneous coordinate 0 (a point at infinity)");
        v /= w;
        if (!v.allFinite()) in.fail("a vertex overflows after the homogeneous divide");
      }
    }
  }
  for (long long i = 0; i < 4 * ncol; ++i) in.next_double("a colour component");
  if (!in.at_end()) in.fail_at(in.line(), "unexpected data after the last colour");
  return c;
}

}  // namespace

Shape parse_vect(std::string_view text, const std::string& origin) {
  TextScanner in(text, origin);
  if (in.at_end()) in.fail_at(1, "empty file: expected a VECT header");
  const VectHeader h = read_header(in);
  if (h.dim == 3) return read_body<3>(in, h);
  return read_body<4>(in, h);
}

Shape read_vect(const std::filesystem::path& path) { return parse_vect(read_text_file(path), path.string()); }

template <int D>
std::string format_vect(const Curve<D>& c) {
  std::string out = D == 3 ? "VECT\n" : "4VECT\n";
  out += "# written by shadow4d; a negative count is a closed polyline\n";
  for (std::size_t i = 0; i < c.components.size(); ++i) {
    const auto& p = c.components[i];
    if (p.points.size() < 2)
      throw Error("cannot write VECT: component " + std::to_string(i) + " has fewer than 2 points");
    for (const Vec<D>& v : p.points)
      if (!v.allFinite())
        throw Error("cannot write VECT: component " + std::to_string(i) + " has a non-finite point");
  }
  out += std::to_string(c.components.size()) + " " + std::to_string(c.point_count()) + " 0\n";
  for (std::size_t i = 0; i < c.components.size(); ++i) {
    const auto& p = c.components[i];
    const long long n = static_cast<long long>(p.points.size());
    if (i) out += ' ';
    out += std::to_string(p.closed ? -n : n);
  }
  out += "\n";
  for (std::size_t i = 0; i < c.components.size(); ++i) out += i ? " 0" : "0";
  out += "\n";
  for (const auto& p : c.components) {
    for (const Vec<D>& v : p.points) {
      for (int k = 0; k < D; ++k) {
        if (k) out += ' ';
        append_double(out, v[k]);
      }
      out += '\n';
    }
  }
  return out;
}

template <int D>
void write_vect(const Curve<D>& c, const std::filesystem::path& path) {
  write_text_file(path, format_vect(c));
}

template std::string format_vect<3>(const Curve<3>&);
template std::string format_vect<4>(const Curve<4>&);
template void write_vect<3>(const Curve<3>&, const std::filesystem::path&);
template void write_vect<4>(const Curve<4>&, const std::filesystem::path&);

}  // namespace s4d
