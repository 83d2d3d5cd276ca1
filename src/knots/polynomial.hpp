// Small exact Laurent polynomials (one and two variables, int64 coefficients) for knot invariants:
// our own value types so that callers never see Regina's, plus the modular fingerprints the index uses.
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <utility>

namespace s4d {

// A Laurent polynomial in one variable: exponent -> non-zero coefficient.
struct Laurent1 {
  std::map<long, std::int64_t> terms;

  bool is_zero() const { return terms.empty(); }
  std::int64_t coeff(long e) const;
  void add(long e, std::int64_t c);  // drops zero coefficients
  // "-t^4 + t^3 + t" style; "0" for the zero polynomial.
  std::string str(const std::string& var) const;
  // The same polynomial read as one in var^(1/2) (exponents halved): "t^(3/2) - t^(-1/2)".
  std::string str_half(const std::string& var) const;
  friend bool operator==(const Laurent1&, const Laurent1&) = default;
};

// A Laurent polynomial in two variables: (x exponent, y exponent) -> non-zero coefficient.
struct Laurent2 {
  std::map<std::pair<long, long>, std::int64_t> terms;

  bool is_zero() const { return terms.empty(); }
  void add(long ex, long ey, std::int64_t c);
  Laurent2 operator*(const Laurent2& o) const;
  // x -> -1/x: the HOMFLY-PT polynomial (alpha, z) of the mirror image (alpha P+ - alpha^-1 P- =
  // z P0 with P+ and P- swapped). Knots only have even powers of alpha, links may have odd ones.
  Laurent2 mirror_alpha() const;
  std::string str(const std::string& x, const std::string& y) const;
  friend bool operator==(const Laurent2&, const Laurent2&) = default;
};

// Arithmetic modulo the Mersenne prime 2^61 - 1, for polynomial fingerprints: evaluating the
// HOMFLY-PT polynomial at a fixed point mod p is multiplicative under connected sum, so a composite
// knot's fingerprint is the product of its factors' (what the index's factor search relies on).
namespace modp {
inline constexpr std::uint64_t kP = (std::uint64_t{1} << 61) - 1;
std::uint64_t mul(std::uint64_t a, std::uint64_t b);
std::uint64_t pow(std::uint64_t a, std::uint64_t e);
std::uint64_t inv(std::uint64_t a);  // a != 0
}  // namespace modp

// The fixed evaluation point of every fingerprint (index files store values at this point; never
// change it without regenerating data/knots/knot_index.tsv).
inline constexpr std::uint64_t kFingerprintAlpha = 0x1d2c3b4a59687f1ULL;
inline constexpr std::uint64_t kFingerprintZ = 0x0f1e2d3c4b5a697ULL;

// P(alpha0, z0) mod 2^61-1 of a HOMFLY-PT polynomial in (alpha, z).
std::uint64_t homfly_fingerprint(const Laurent2& homfly_az);

// The Conway-normalised Alexander polynomial from HOMFLY-PT in (alpha, z): alpha = 1,
// z = s - 1/s, as a polynomial in s = t^(1/2). For a knot every exponent is even (a symmetric
// polynomial in t with Delta(1) = 1); a link can have odd ones.
Laurent1 alexander_from_homfly(const Laurent2& homfly_az);

// |f(i)| for a polynomial in s = t^(1/2) with integer coefficients, i.e. |f| at t = -1: the
// determinant of a knot or link from its Alexander or Jones polynomial (both in sqrt(t)).
std::int64_t abs_at_t_minus_one(const Laurent1& f_in_sqrt_t);

// Halves every exponent (a polynomial in sqrt(t) that only has even powers, as a polynomial in t);
// returns false and leaves `out` alone when an odd exponent is present.
bool halve_exponents(const Laurent1& f, Laurent1& out);

}  // namespace s4d
