// Plain xyz(w) curve reader and writer. Line-based on purpose: blank lines carry meaning here.
#include "io/curve_text.hpp"

#include <array>

#include "core/error.hpp"
#include "io/text_scanner.hpp"

namespace s4d {

namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

// Points of all components in one flat array, so the dimension can be fixed by the first line.
struct Parsed {
  int dim = 0;
  std::vector<double> coords;            // point_count × dim
  std::vector<std::size_t> starts;       // first point of each component
  std::vector<bool> closed;              // per component
  std::vector<int> first_lines;          // line of each component's first point
};

template <int D>
Curve<D> build(const Parsed& p) {
  Curve<D> c;
  c.components.resize(p.starts.size());
  const std::size_t total = p.coords.size() / D;
  for (std::size_t k = 0; k < p.starts.size(); ++k) {
    const std::size_t end = k + 1 < p.starts.size() ? p.starts[k + 1] : total;
    Polyline<D>& poly = c.components[k];
    poly.closed = p.closed[k];
    poly.points.resize(end - p.starts[k]);
    for (std::size_t i = p.starts[k]; i < end; ++i)
      for (int d = 0; d < D; ++d) poly.points[i - p.starts[k]][d] = p.coords[i * D + d];
  }
  return c;
}

}  // namespace

Shape parse_curve_text(std::string_view text, const std::string& origin) {
  Parsed p;
  bool in_component = false;
  bool pending_open = false;
  int pending_line = 0;
  int line_no = 0;
  std::size_t pos = 0;
  auto count_of = [&](std::size_t k) {
    const std::size_t end = k + 1 < p.starts.size() ? p.starts[k + 1] : p.coords.size() / p.dim;
    return end - p.starts[k];
  };
  auto end_component = [&] {
    if (in_component) {
      const std::size_t k = p.starts.size() - 1;
      if (count_of(k) < 2)
        throw ParseError(
            origin, p.first_lines[k],
            "a curve component needs at least 2 points, this one has " + std::to_string(count_of(k)));
    }
    in_component = false;
  };

  while (pos < text.size()) {
    ++line_no;
    const std::size_t nl = text.find('\n', pos);
    const std::size_t end = nl == std::string_view::npos ? text.size() : nl;
    std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;

    const std::string_view t = trim(line);
    if (t.empty()) {
      end_component();
      continue;
    }
    if (t.substr(0, 2) == "#!") {
      const std::string_view d = trim(t.substr(2));
      end_component();
      if (d == "open" || d == "closed") {
        pending_open = d == "open";
        pending_line = line_no;
      } else {
        throw ParseError(origin, line_no,
                         "unknown directive " + quote_token(t) + " (expected '#! open' or '#! closed')");
      }
      continue;
    }
    const std::size_t hash = line.find('#');
    if (hash != std::string_view::npos) line = line.substr(0, hash);

    std::array<double, 4> v{};
    int n = 0;
    std::size_t i = 0;
    while (i < line.size()) {
      while (i < line.size() && is_space(line[i])) ++i;
      if (i >= line.size()) break;
      const std::size_t s = i;
      while (i < line.size() && !is_space(line[i])) ++i;
      const std::string_view tok = line.substr(s, i - s);
      if (n >= 4)
        throw ParseError(origin, line_no, "too many coordinates: a point has 3 (x y z) or 4 (x y z w)");
      if (!parse_double(tok, v[n]))
        throw ParseError(origin, line_no, "expected a finite number, found " + quote_token(tok));
      ++n;
    }
    if (n == 0) continue;  // a comment-only line does not separate components
    if (p.dim == 0) {
      if (n != 3 && n != 4)
        throw ParseError(
            origin, line_no,
            "a point has 3 (x y z) or 4 (x y z w) coordinates, this line has " + std::to_string(n));
      p.dim = n;
    } else if (n != p.dim) {
      throw ParseError(origin, line_no,
                       "this point has " + std::to_string(n) + " coordinates, but the file is " +
                           std::to_string(p.dim) + "-dimensional (from its first point)");
    }
    if (!in_component) {
      p.starts.push_back(p.coords.size() / p.dim);
      p.closed.push_back(!pending_open);
      p.first_lines.push_back(line_no);
      pending_open = false;
      pending_line = 0;
      in_component = true;
    }
    p.coords.insert(p.coords.end(), v.begin(), v.begin() + n);
  }
  end_component();
  if (pending_line) throw ParseError(origin, pending_line, "'#!' directive is not followed by a component");
  if (p.dim == 0) throw ParseError(origin, line_no, "no points: expected lines of 'x y z' or 'x y z w'");
  if (p.dim == 3) return build<3>(p);
  return build<4>(p);
}

Shape read_curve_text(const std::filesystem::path& path) {
  return parse_curve_text(read_text_file(path), path.string());
}

template <int D>
std::string format_curve_text(const Curve<D>& c) {
  if (c.components.empty()) throw Error("cannot write an empty curve (no components)");
  std::string out = "# shadow4d curve in R^" + std::to_string(D) + ", " +
                    std::to_string(c.components.size()) + " component(s); blank lines separate components\n";
  for (std::size_t k = 0; k < c.components.size(); ++k) {
    const Polyline<D>& poly = c.components[k];
    if (poly.points.size() < 2)
      throw Error("cannot write curve: component " + std::to_string(k) + " has fewer than 2 points");
    out += "\n";
    if (!poly.closed) out += "#! open\n";
    for (const Vec<D>& v : poly.points) {
      if (!v.allFinite())
        throw Error("cannot write curve: component " + std::to_string(k) + " has a non-finite point");
      for (int d = 0; d < D; ++d) {
        if (d) out += ' ';
        append_double(out, v[d]);
      }
      out += '\n';
    }
  }
  return out;
}

template <int D>
void write_curve_text(const Curve<D>& c, const std::filesystem::path& path) {
  write_text_file(path, format_curve_text(c));
}

template std::string format_curve_text<3>(const Curve<3>&);
template std::string format_curve_text<4>(const Curve<4>&);
template void write_curve_text<3>(const Curve<3>&, const std::filesystem::path&);
template void write_curve_text<4>(const Curve<4>&, const std::filesystem::path&);

}  // namespace s4d
