// std::from_chars and std::to_chars for double where the standard library has them (libstdc++),
// and the same contracts through strtod and snprintf where it does not (emscripten's libc++ 14,
// the web build).
#pragma once
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <system_error>

namespace s4d {

// from_chars: no leading blanks or '+', no hexadecimal prefix, '.' as the decimal point,
// result_out_of_range beyond double's range.
inline std::from_chars_result double_from_chars(const char* first, const char* last, double& value) {
#if defined(__cpp_lib_to_chars) || !defined(_LIBCPP_VERSION)
  return std::from_chars(first, last, value);
#else
  const std::string text(first, last);
  const char* s = text.c_str();
  const char* digits = s + (*s == '-' ? 1 : 0);
  const bool refused = text.empty() || *s == '+' || *s == ' ' || *s == '\t' || *s == '\n' || *s == '\r' ||
                       *s == '\f' || *s == '\v' || (digits[0] == '0' && (digits[1] == 'x' || digits[1] == 'X'));
  if (refused) return {first, std::errc::invalid_argument};
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(s, &end);
  if (end == s) return {first, std::errc::invalid_argument};
  const char* stop = first + (end - s);
  if (errno == ERANGE) return {stop, std::errc::result_out_of_range};
  value = v;
  return {stop, std::errc()};
#endif
}

// to_chars: the shortest text that reads back as the same double (the fallback's spelling may
// differ from the standard's, e.g. 0.0001 for 1e-04; both read back exactly).
inline std::to_chars_result double_to_chars(char* first, char* last, double value) {
#if defined(__cpp_lib_to_chars) || !defined(_LIBCPP_VERSION)
  return std::to_chars(first, last, value);
#else
  char buf[40];
  int n = 0;
  for (int digits = 1; digits <= 17; ++digits) {
    n = std::snprintf(buf, sizeof buf, "%.*g", digits, value);
    if (std::strtod(buf, nullptr) == value || value != value) break;
  }
  if (n < 0 || n > last - first) return {last, std::errc::value_too_large};
  std::memcpy(first, buf, static_cast<std::size_t>(n));
  return {first + n, std::errc()};
#endif
}

}  // namespace s4d
