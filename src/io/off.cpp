// Geomview OFF / 4OFF / nOFF reader and writer (text form; binary OFF is rejected with a message).
#include "io/off.hpp"

#include <climits>
#include <sstream>

#include "core/error.hpp"
#include "io/text_scanner.hpp"

namespace s4d {

namespace {

struct OffHeader {
  bool st = false, colour = false, normal = false, homogeneous = false;
  int dim = 3;  // ambient dimension of the result
};

// Header keyword: [ST][C][N][4][n]OFF. "4" alone means R^4; "4n" means n+1 homogeneous coordinates.
OffHeader read_header(TextScanner& in) {
  const std::string_view tok = in.next_token("the OFF header");
  std::string_view k = tok;
  OffHeader h;
  auto take = [&k](std::string_view p) {
    if (k.substr(0, p.size()) != p) return false;
    k.remove_prefix(p.size());
    return true;
  };
  h.st = take("ST");
  h.colour = take("C");
  h.normal = take("N");
  const bool four = take("4");
  const bool n = take("n");
  if (k != "OFF")
    in.fail("not an OFF file: expected a header such as OFF, 4OFF or nOFF, found " + quote_token(tok));
  if (n) {
    h.dim = static_cast<int>(in.next_int("the dimension after nOFF", 1, 1000));
    if (h.dim != 3 && h.dim != 4)
      in.fail("nOFF dimension " + std::to_string(h.dim) + " is not supported (only 3 or 4)");
    h.homogeneous = four;
  } else {
    h.dim = four ? 4 : 3;
  }
  return h;
}

template <int D>
Surface<D> read_body(TextScanner& in, const OffHeader& h) {
  const int header_line = in.token_line();
  const long long nv = in.next_int("the vertex count", 0, INT_MAX);
  const long long nf = in.next_int("the face count", 0, INT_MAX);
  in.next_int("the edge count", 0, LLONG_MAX);  // informative only
  const int coords = D + (h.homogeneous ? 1 : 0);
  const int per_vertex = coords + (h.normal ? coords : 0) + (h.colour ? 4 : 0) + (h.st ? 2 : 0);
  in.check_fits(nv, per_vertex, "vertex count");
  in.check_fits(nv * per_vertex + nf * 2, 1, "vertex and face counts");  // a face is >= 2 tokens

  Surface<D> s;
  s.vertices.resize(static_cast<std::size_t>(nv));
  for (long long i = 0; i < nv; ++i) {
    Vec<D>& v = s.vertices[static_cast<std::size_t>(i)];
    for (int c = 0; c < D; ++c) v[c] = in.next_double("a vertex coordinate");
    if (h.homogeneous) {
      const double w = in.next_double("a homogeneous coordinate");
      if (w == 0)
        in.fail("vertex " + std::to_string(i) + " has homogeneous coordinate 0 (a point at infinity)");
      v /= w;
      if (!v.allFinite()) in.fail("vertex " + std::to_string(i) + " overflows after the homogeneous divide");
    }
    for (int c = coords; c < per_vertex; ++c) in.next_double("a vertex normal, colour or texture value");
  }

  s.triangles.reserve(static_cast<std::size_t>(nf));
  for (long long f = 0; f < nf; ++f) {
    const long long n = in.next_int("a face's vertex count", 1, INT_MAX);
    in.check_fits(n, 1, "face vertex count");
    int first = 0, prev = 0;
    for (long long k = 0; k < n; ++k) {
      const int idx = static_cast<int>(in.next_int("a vertex index", 0, nv - 1));
      if (k == 0) {
        first = idx;
      } else if (k >= 2 && first != prev && prev != idx && idx != first) {
        // Fan triangulation: (v0, v_{k-1}, v_k); triangles with a repeated vertex are dropped.
        s.triangles.push_back({first, prev, idx});
      }
      prev = idx;
    }
    in.skip_rest_of_line();  // optional per-face colour
  }
  if (!in.at_end()) in.fail_at(in.line(), "unexpected data after the last face (declared " +
                                               std::to_string(nf) + " faces at line " +
                                               std::to_string(header_line) + ")");

  for (const Directive& d : in.directives()) {
    std::istringstream ss(d.text);
    std::string word;
    ss >> word;
    if (word != "grid") continue;
    long long rows = 0, cols = 0;
    int wi = 0, wj = 0;
    if (!(ss >> rows >> cols >> wi >> wj) || rows <= 0 || cols <= 0 || (wi != 0 && wi != 1) ||
        (wj != 0 && wj != 1))
      in.fail_at(d.line, "malformed '#! grid rows cols wrap_i wrap_j' line");
    // A grid that no longer matches the vertices means the mesh was edited elsewhere: drop it.
    if (rows * cols == nv) s.grid = Grid{static_cast<int>(rows), static_cast<int>(cols), wi == 1, wj == 1};
  }
  return s;
}

}  // namespace

Shape parse_off(std::string_view text, const std::string& origin) {
  TextScanner in(text, origin);
  if (in.at_end()) in.fail_at(1, "empty file: expected an OFF header");
  const OffHeader h = read_header(in);
  {
    // Geomview's binary variant says "BINARY" right after the keyword.
    TextScanner peek = in;
    if (!peek.at_end()) {
      const std::string_view t = peek.next_token("");
      if (t == "BINARY") in.fail("binary OFF is not supported; convert it to text OFF");
    }
  }
  if (h.dim == 3) return read_body<3>(in, h);
  return read_body<4>(in, h);
}

Shape read_off(const std::filesystem::path& path) { return parse_off(read_text_file(path), path.string()); }

Surface<3> read_off3(const std::filesystem::path& path) {
  Shape s = read_off(path);
  if (auto* p = std::get_if<Surface<3>>(&s)) return std::move(*p);
  throw ParseError(path.string(), 1, "expected a surface in R^3 (OFF), found one in R^4");
}

Surface<4> read_off4(const std::filesystem::path& path) {
  Shape s = read_off(path);
  if (auto* p = std::get_if<Surface<4>>(&s)) return std::move(*p);
  throw ParseError(path.string(), 1, "expected a surface in R^4 (4OFF), found one in R^3");
}

template <int D>
std::string format_off(const Surface<D>& s) {
  std::string out;
  out.reserve(s.vertices.size() * D * 20 + s.triangles.size() * 24 + 64);
  for (std::size_t i = 0; i < s.vertices.size(); ++i)
    if (!s.vertices[i].allFinite())
      throw Error("cannot write OFF: vertex " + std::to_string(i) + " is not finite");
  out += D == 3 ? "OFF\n" : "4OFF\n";
  out += "# written by shadow4d\n";
  if (s.grid) {
    const Grid& g = *s.grid;
    out += "#! grid " + std::to_string(g.rows) + " " + std::to_string(g.cols) + " " +
           (g.wrap_i ? "1" : "0") + " " + (g.wrap_j ? "1" : "0") + "\n";
  }
  out += std::to_string(s.vertices.size()) + " " + std::to_string(s.triangles.size()) + " 0\n";
  for (const Vec<D>& v : s.vertices) {
    for (int c = 0; c < D; ++c) {
      if (c) out += ' ';
      append_double(out, v[c]);
    }
    out += '\n';
  }
  for (const Triangle& t : s.triangles) {
    out += "3 ";
    append_int(out, t[0]);
    out += ' ';
    append_int(out, t[1]);
    out += ' ';
    append_int(out, t[2]);
    out += '\n';
  }
  return out;
}

template <int D>
void write_off(const Surface<D>& s, const std::filesystem::path& path) {
  write_text_file(path, format_off(s));
}

template std::string format_off<3>(const Surface<3>&);
template std::string format_off<4>(const Surface<4>&);
template void write_off<3>(const Surface<3>&, const std::filesystem::path&);
template void write_off<4>(const Surface<4>&, const std::filesystem::path&);

}  // namespace s4d
