// std::from_chars for double where the standard library has it (libstdc++), and the same contract
// through strtod where it does not (emscripten's libc++ 14, the web build): no leading blanks or
// '+', no hexadecimal prefix, '.' as the decimal point, result_out_of_range beyond double's range.
#pragma once
#include <cerrno>
#include <charconv>
#include <cstdlib>
#include <string>
#include <system_error>

namespace s4d {

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

}  // namespace s4d
