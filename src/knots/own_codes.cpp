// Knot signatures and PD codes read, Gauss and DT codes written, without Regina.
#include "knots/own_codes.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <map>
#include <tuple>

#include "core/error.hpp"
#include "knots/diagram_moves.hpp"

namespace s4d {

namespace {

int base64_digit(char c) {
  if (c >= 'a' && c <= 'z') return c - 'a';
  if (c >= 'A' && c <= 'Z') return c - 'A' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+') return 62;
  if (c == '-') return 63;
  return -1;
}

}  // namespace

KnotDiagram diagram_from_knot_sig(const std::string& text) {
  std::string sig;
  for (char c : text)
    if (!std::isspace(static_cast<unsigned char>(c))) sig += c;
  auto bad = [&](const std::string& why) { return Error("not a knot signature ('" + text + "'): " + why); };
  std::vector<int> digit;
  for (char c : sig) {
    if (base64_digit(c) < 0) throw bad(std::string("the character '") + c + "' is not a base64 digit");
    digit.push_back(base64_digit(c));
  }
  if (digit.empty()) throw bad("it is empty");
  std::size_t at = 0;
  std::size_t width = 1;
  auto number = [&](std::size_t w) {
    if (at + w > digit.size()) throw bad("it ends too early");
    std::size_t v = 0;
    for (std::size_t i = 0; i < w; ++i) v |= static_cast<std::size_t>(digit[at + i]) << (6 * i);
    at += w;
    return v;
  };
  std::size_t n = number(1);
  if (n == 63) {
    width = number(1);
    if (width == 0 || width > 4) throw bad("it says " + std::to_string(width) + " digits per number");
    n = number(width);
  }
  GaussDiagram g;
  if (n == 0) {
    if (at != digit.size()) throw bad("an unknot's signature has nothing after its crossing count");
    g.comps.emplace_back();
    return g.diagram();
  }
  const std::size_t bit_digits = (2 * n + 5) / 6;
  if (digit.size() != at + 2 * n * width + 2 * bit_digits)
    throw bad("its length does not fit " + std::to_string(n) + " crossings");
  std::vector<int> crossing(2 * n);
  for (auto& c : crossing) {
    c = static_cast<int>(number(width));
    if (c >= static_cast<int>(n)) throw bad("a crossing number is out of range");
  }
  auto bits = [&]() {
    std::vector<int> b(2 * n);
    for (std::size_t i = 0; i < 2 * n; i += 6) {
      int v = digit[at++];
      for (std::size_t j = 0; j < 6 && i + j < 2 * n; ++j, v >>= 1) b[i + j] = v & 1;
      if (v) throw bad("stray bits after the last crossing");
    }
    return b;
  };
  const std::vector<int> upper = bits(), positive = bits();
  g.sign.assign(n, 0);
  std::vector<int> overs(n, 0), visits(n, 0);
  g.comps.emplace_back();
  for (std::size_t i = 0; i < 2 * n; ++i) {
    const int k = crossing[i], s = positive[i] ? 1 : -1;
    if (g.sign[k] != 0 && g.sign[k] != s) throw bad("crossing " + std::to_string(k) + " has two signs");
    g.sign[k] = s;
    overs[k] += upper[i];
    ++visits[k];
    g.comps[0].push_back({k, upper[i] == 1});
  }
  for (std::size_t k = 0; k < n; ++k)
    if (visits[k] != 2 || overs[k] != 1)
      throw bad("crossing " + std::to_string(k) + " is not passed once over and once under");
  return g.diagram();
}

KnotDiagram diagram_from_pd_numbers(const std::string& text) {
  std::vector<long> num;
  for (std::size_t i = 0; i < text.size();) {
    if (std::isdigit(static_cast<unsigned char>(text[i]))) {
      long v = 0;
      while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) {
        v = 10 * v + (text[i++] - '0');
        if (v > 1000000) throw Error("a PD code's edge number is too large in '" + text + "'");
      }
      num.push_back(v);
    } else if (text[i] == '-') {
      throw Error("a PD code has no negative numbers ('" + text + "')");
    } else {
      ++i;
    }
  }
  if (num.empty() || num.size() % 4 != 0)
    throw Error("a PD code needs four edge numbers per crossing; got " + std::to_string(num.size()) + " numbers");
  const int n = static_cast<int>(num.size() / 4);
  // Where each edge number occurs: (crossing, slot), exactly twice.
  std::map<long, std::vector<std::pair<int, int>>> where;
  for (int x = 0; x < n; ++x)
    for (int s = 0; s < 4; ++s) where[num[4 * x + s]].push_back({x, s});
  for (const auto& [e, at] : where)
    if (at.size() != 2)
      throw Error("edge " + std::to_string(e) + " of the PD code occurs " + std::to_string(at.size()) +
                  " time(s); every edge joins two crossing ends");
  auto far_end = [&](int x, int s) {
    const auto& at = where[num[4 * x + s]];
    return at[0] == std::make_pair(x, s) ? at[1] : at[0];
  };
  GaussDiagram g;
  g.sign.assign(n, 0);
  std::vector<std::array<char, 4>> used(n, {0, 0, 0, 0});
  // Each component with the edge numbers it enters its visits by.
  std::vector<std::pair<std::vector<GaussVisit>, std::vector<long>>> found;
  // Walks a component entering crossing x at slot s; records the visits.
  auto walk = [&](int x, int s) {
    std::vector<GaussVisit> comp;
    std::vector<long> in;
    while (!used[x][s]) {
      const int out = (s + 2) % 4;
      if (s == 2) throw Error("the PD code's under strand at a crossing leaves by its incoming edge");
      used[x][s] = used[x][out] = 1;
      const bool over = s % 2 == 1;
      if (over) g.sign[x] = s == 3 ? 1 : -1;
      comp.push_back({x, over});
      in.push_back(num[4 * x + s]);
      std::tie(x, s) = far_end(x, out);
    }
    found.emplace_back(std::move(comp), std::move(in));
  };
  for (int x = 0; x < n; ++x)
    if (!used[x][0]) walk(x, 0);
  // Components passing over only: the direction of increasing edge numbers.
  for (int x = 0; x < n; ++x)
    if (!used[x][1]) {
      const long j = num[4 * x + 1], l = num[4 * x + 3];
      const bool l_to_j = j == l + 1 || (l > j + 1);
      walk(x, l_to_j ? 3 : 1);
    }
  // As Regina reads them: components in order of their least edge number, each from the visit
  // that edge leaves.
  for (auto& [comp, in] : found) {
    const auto m = static_cast<std::ptrdiff_t>(in.size());
    const auto least = (std::min_element(in.begin(), in.end()) - in.begin() + m - 1) % m;
    std::rotate(comp.begin(), comp.begin() + least, comp.end());
    std::rotate(in.begin(), in.begin() + least, in.end());
  }
  std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.second[0] < b.second[0]; });
  for (auto& f : found) g.comps.push_back(std::move(f.first));
  return g.diagram();
}

std::string gauss_text(const KnotDiagram& d) {
  if (d.component_count() != 1) return "";
  std::string s;
  for (int p : d.components[0]) {
    if (!s.empty()) s += ' ';
    if (!d.passages[p].over) s += '-';
    s += std::to_string(d.passages[p].crossing + 1);
  }
  return s;
}

std::string oriented_gauss_text(const KnotDiagram& d) {
  if (d.component_count() != 1) return "";
  std::string s;
  for (int p : d.components[0]) {
    const Passage& v = d.passages[p];
    // The other strand passes left to right for the under strand of a positive crossing.
    const bool left_to_right = (d.crossings[v.crossing].sign > 0) != v.over;
    if (!s.empty()) s += ' ';
    s += v.over ? '+' : '-';
    s += left_to_right ? '>' : '<';
    s += std::to_string(v.crossing + 1);
  }
  return s;
}

std::string dt_text(const KnotDiagram& d, bool alphabetical) {
  if (d.component_count() != 1 || d.crossing_count() == 0) return "";
  const int n = d.crossing_count();
  if (alphabetical && n > 26) return "";
  // Visits numbered 1..2n along the knot; each crossing pairs an odd and an even number.
  std::vector<int> odd_of(n, 0), even_of(n, 0);
  std::vector<char> even_over(n, 0);
  // As Regina: numbered from the under passage of the first crossing met.
  const auto& comp = d.components[0];
  const int first = d.passages[comp[0]].crossing;
  int start = 0;
  while (d.passages[comp[start]].crossing != first || d.passages[comp[start]].over) ++start;
  for (int i = 0; i < 2 * n; ++i) {
    const Passage& v = d.passages[comp[(start + i) % (2 * n)]];
    if (i % 2 == 0) {
      odd_of[v.crossing] = i + 1;
    } else {
      even_of[v.crossing] = i + 1;
      even_over[v.crossing] = v.over;
    }
  }
  std::vector<int> by_odd(n, 0);
  for (int k = 0; k < n; ++k) {
    if (odd_of[k] == 0 || even_of[k] == 0) return "";  // not a planar knot diagram
    by_odd[(odd_of[k] - 1) / 2] = even_over[k] ? even_of[k] : -even_of[k];  // negative: under at the even visit
  }
  std::string s;
  for (int v : by_odd) {
    if (alphabetical)
      s += static_cast<char>((v > 0 ? 'a' : 'A') + std::abs(v) / 2 - 1);
    else {
      if (!s.empty()) s += ' ';
      s += std::to_string(v);
    }
  }
  return s;
}

}  // namespace s4d

namespace s4d {

namespace {

struct SigStep {
  int crossing = 0;
  int upper = 0;  // 1: passes over
  int sign = 0;
  // Regina's order: crossing label first, then the upper strand first, then positive first.
  bool operator<(const SigStep& o) const {
    if (crossing != o.crossing) return crossing < o.crossing;
    if (upper != o.upper) return upper > o.upper;
    return sign > o.sign;
  }
  bool operator==(const SigStep&) const = default;
};

char base64_char(unsigned v) {
  static const char* digits = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789+-";
  return digits[v & 63];
}

}  // namespace

std::string knot_sig(const KnotDiagram& d, bool reflection) {
  if (d.component_count() != 1) throw Error("a knot signature is written for knots only");
  const auto& comp = d.components[0];
  const int n = d.crossing_count();
  const int len = static_cast<int>(comp.size());
  std::vector<SigStep> best, cur(len);
  std::vector<int> image(n);
  for (int flip_sign = 0; flip_sign < (reflection ? 2 : 1); ++flip_sign)
    for (int flip_strands = 0; flip_strands < 2; ++flip_strands)
      for (int reverse = 0; reverse < 2; ++reverse)
        for (int i0 = 0; i0 < len; ++i0) {
          const Passage& first = d.passages[comp[i0]];
          // Reflection lets every signature start at a positive crossing.
          if (reflection && (flip_sign ? -1 : 1) * d.crossings[first.crossing].sign < 0) continue;
          // Start on the upper strand (the lower one when turned over).
          if (static_cast<int>(first.over) == flip_strands) continue;
          std::fill(image.begin(), image.end(), -1);
          int next = 0;
          bool better = best.empty(), worse = false;
          for (int s = 0; s < len && !worse; ++s) {
            const int idx = ((reverse ? i0 - s : i0 + s) % len + len) % len;
            const Passage& v = d.passages[comp[idx]];
            if (image[v.crossing] < 0) image[v.crossing] = next++;
            cur[s] = {image[v.crossing], static_cast<int>(v.over) ^ flip_strands,
                      (flip_sign ? -1 : 1) * d.crossings[v.crossing].sign};
            if (!better) {
              if (cur[s] < best[s]) better = true;
              else if (best[s] < cur[s]) worse = true;
            }
          }
          if (better && !worse) best = cur;
        }
  std::string out;
  unsigned width = 1;
  if (n >= 63) {
    width = 0;
    for (int t = n; t > 0; t >>= 6) ++width;
    out += base64_char(63);
    out += base64_char(width);
  }
  auto put = [&](unsigned v) {
    for (unsigned i = 0; i < width; ++i) out += base64_char(v >> (6 * i));
  };
  put(static_cast<unsigned>(n));
  for (const SigStep& s : best) put(static_cast<unsigned>(s.crossing));
  for (int field = 0; field < 2; ++field)
    for (int i = 0; i < len; i += 6) {
      unsigned bits = 0;
      for (int j = 0; j < 6 && i + j < len; ++j)
        if (field == 0 ? best[i + j].upper : best[i + j].sign > 0) bits |= 1u << j;
      out += base64_char(bits);
    }
  return out;
}

}  // namespace s4d
