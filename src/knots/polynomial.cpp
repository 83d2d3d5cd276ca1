// Laurent polynomial arithmetic, printing and fingerprints for the knot invariants.
#include "knots/polynomial.hpp"

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace s4d {

namespace {
// One term "c x^e" appended in the conventional sign-separated style.
void append_term(std::ostringstream& out, bool first, std::int64_t c, const std::string& mono) {
  if (first) {
    if (c < 0) out << "-";
  } else {
    out << (c < 0 ? " - " : " + ");
  }
  const std::int64_t a = c < 0 ? -c : c;
  if (mono.empty())
    out << a;
  else if (a != 1)
    out << a << " " << mono;
  else
    out << mono;
}

std::string power(const std::string& var, long e) {
  if (e == 0) return {};
  if (e == 1) return var;
  return var + "^" + std::to_string(e);
}

// t^(e/2): "t^(3/2)", "t^(-1/2)", "t^2".
std::string half_power(const std::string& var, long e) {
  if (e % 2 == 0) return power(var, e / 2);
  return var + "^(" + std::to_string(e) + "/2)";
}
}  // namespace

std::int64_t Laurent1::coeff(long e) const {
  const auto it = terms.find(e);
  return it == terms.end() ? 0 : it->second;
}

void Laurent1::add(long e, std::int64_t c) {
  if (c == 0) return;
  auto& v = terms[e];
  v += c;
  if (v == 0) terms.erase(e);
}

std::string Laurent1::str(const std::string& var) const {
  if (terms.empty()) return "0";
  std::ostringstream out;
  bool first = true;
  for (auto it = terms.rbegin(); it != terms.rend(); ++it) {  // highest power first
    append_term(out, first, it->second, power(var, it->first));
    first = false;
  }
  return out.str();
}

std::string Laurent1::str_half(const std::string& var) const {
  if (terms.empty()) return "0";
  std::ostringstream out;
  bool first = true;
  for (auto it = terms.rbegin(); it != terms.rend(); ++it) {
    append_term(out, first, it->second, half_power(var, it->first));
    first = false;
  }
  return out.str();
}

void Laurent2::add(long ex, long ey, std::int64_t c) {
  if (c == 0) return;
  const auto key = std::make_pair(ex, ey);
  auto& v = terms[key];
  v += c;
  if (v == 0) terms.erase(key);
}

Laurent2 Laurent2::operator*(const Laurent2& o) const {
  Laurent2 r;
  for (const auto& [ea, ca] : terms)
    for (const auto& [eb, cb] : o.terms) r.add(ea.first + eb.first, ea.second + eb.second, ca * cb);
  return r;
}

Laurent2 Laurent2::mirror_alpha() const {
  Laurent2 r;
  for (const auto& [e, c] : terms) r.add(-e.first, e.second, e.first % 2 ? -c : c);
  return r;
}

std::string Laurent2::str(const std::string& x, const std::string& y) const {
  if (terms.empty()) return "0";
  std::ostringstream out;
  bool first = true;
  for (auto it = terms.rbegin(); it != terms.rend(); ++it) {
    std::string mono = power(x, it->first.first);
    const std::string my = power(y, it->first.second);
    if (!my.empty()) mono = mono.empty() ? my : mono + " " + my;
    append_term(out, first, it->second, mono);
    first = false;
  }
  return out.str();
}

namespace modp {
std::uint64_t mul(std::uint64_t a, std::uint64_t b) {
  const unsigned __int128 p = static_cast<unsigned __int128>(a) * b;
  std::uint64_t r = static_cast<std::uint64_t>(p & kP) + static_cast<std::uint64_t>(p >> 61);
  if (r >= kP) r -= kP;
  return r;
}
std::uint64_t pow(std::uint64_t a, std::uint64_t e) {
  std::uint64_t r = 1;
  a %= kP;
  while (e) {
    if (e & 1) r = mul(r, a);
    a = mul(a, a);
    e >>= 1;
  }
  return r;
}
std::uint64_t inv(std::uint64_t a) { return pow(a, kP - 2); }  // Fermat: p is prime
}  // namespace modp

namespace {
std::uint64_t pow_signed(std::uint64_t base, std::uint64_t base_inv, long e) {
  return e >= 0 ? modp::pow(base, static_cast<std::uint64_t>(e))
                : modp::pow(base_inv, static_cast<std::uint64_t>(-e));
}
std::uint64_t to_modp(std::int64_t c) {
  const std::int64_t p = static_cast<std::int64_t>(modp::kP);
  std::int64_t r = c % p;
  if (r < 0) r += p;
  return static_cast<std::uint64_t>(r);
}
}  // namespace

std::uint64_t homfly_fingerprint(const Laurent2& h) {
  const std::uint64_t a = kFingerprintAlpha % modp::kP, z = kFingerprintZ % modp::kP;
  const std::uint64_t ai = modp::inv(a), zi = modp::inv(z);
  std::uint64_t sum = 0;
  for (const auto& [e, c] : h.terms) {
    const std::uint64_t t =
        modp::mul(to_modp(c), modp::mul(pow_signed(a, ai, e.first), pow_signed(z, zi, e.second)));
    sum += t;
    if (sum >= modp::kP) sum -= modp::kP;
  }
  return sum;
}

Laurent1 alexander_from_homfly(const Laurent2& h) {
  // alpha = 1 collapses the alpha exponents; then expand z^k = (s - 1/s)^k binomially. Negative
  // powers of z only occur for split links, and they cancel at alpha = 1 (Delta = 0 there).
  std::map<long, std::int64_t> by_z;
  for (const auto& [e, c] : h.terms) by_z[e.second] += c;
  Laurent1 r;
  for (const auto& [k, c] : by_z) {
    if (c == 0) continue;
    if (k < 0) return Laurent1{};  // not a HOMFLY-PT polynomial of any link; answer "unknown"
    // (s - 1/s)^k = sum_j C(k, j) s^(k-j) (-1/s)^j
    std::int64_t binom = 1;
    for (long j = 0; j <= k; ++j) {
      r.add(k - 2 * j, (j % 2 ? -1 : 1) * binom * c);
      binom = binom * (k - j) / (j + 1);
    }
  }
  return r;
}

std::int64_t abs_at_t_minus_one(const Laurent1& f) {
  // s = i: s^e cycles through 1, i, -1, -i.
  std::int64_t re = 0, im = 0;
  for (const auto& [e, c] : f.terms) {
    switch (((e % 4) + 4) % 4) {
      case 0: re += c; break;
      case 1: im += c; break;
      case 2: re -= c; break;
      case 3: im -= c; break;
    }
  }
  if (im == 0) return re < 0 ? -re : re;
  if (re == 0) return im < 0 ? -im : im;
  return static_cast<std::int64_t>(std::llround(std::hypot(double(re), double(im))));
}

bool halve_exponents(const Laurent1& f, Laurent1& out) {
  Laurent1 r;
  for (const auto& [e, c] : f.terms) {
    if (e % 2 != 0) return false;
    r.add(e / 2, c);
  }
  out = std::move(r);
  return true;
}

}  // namespace s4d
