#pragma once
// std::from_chars and std::to_chars for the readers and writers, doubles
// included. libstdc++ (g++ 11 and later) has them for floating point;
// Emscripten's libc++ (3.1.6, the browser build of issue 65) has them for
// integers only, so there doubles go through strtod and snprintf under
// from_chars' own rules: no leading blank or '+', no hexadecimal, the C
// locale's '.' — and both give the correctly rounded value, so a number
// reads and prints the same in the browser as on the desktop.
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <system_error>
#include <type_traits>

namespace aco {

#if defined(__cpp_lib_to_chars) && __cpp_lib_to_chars >= 201611L
using std::from_chars;
using std::to_chars;
#else
template <class Int, std::enable_if_t<std::is_integral_v<Int>, int> = 0>
std::from_chars_result from_chars(const char* first, const char* last, Int& value, int base = 10) {
  return std::from_chars(first, last, value, base);
}
template <class Int, std::enable_if_t<std::is_integral_v<Int>, int> = 0>
std::to_chars_result to_chars(char* first, char* last, Int value) {
  return std::to_chars(first, last, value);
}

inline std::from_chars_result from_chars(const char* first, const char* last, double& value) {
  const char* p = first;
  if (p < last && *p == '-') ++p;
  // What from_chars takes: digits with one '.', or inf/nan; not ' ', '+' or "0x".
  const bool digit_or_dot = p < last && ((*p >= '0' && *p <= '9') || *p == '.');
  const bool word = p < last && (*p == 'i' || *p == 'I' || *p == 'n' || *p == 'N');
  const bool hex = last - p >= 2 && p[0] == '0' && (p[1] == 'x' || p[1] == 'X');
  if ((!digit_or_dot && !word) || hex) return {first, std::errc::invalid_argument};
  std::string text(first, last);
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(text.c_str(), &end);
  if (end == text.c_str()) return {first, std::errc::invalid_argument};
  const char* stop = first + (end - text.c_str());
  if (errno == ERANGE && (v == HUGE_VAL || v == -HUGE_VAL)) return {stop, std::errc::result_out_of_range};
  value = v;
  return {stop, std::errc()};
}

inline std::to_chars_result to_chars(char* first, char* last, double value, std::chars_format format, int precision) {
  const int n = format == std::chars_format::fixed ? std::snprintf(first, static_cast<std::size_t>(last - first), "%.*f", precision, value)
                                                   : std::snprintf(first, static_cast<std::size_t>(last - first), "%.*g", precision, value);
  if (n < 0 || n >= last - first) return {last, std::errc::value_too_large};
  return {first + n, std::errc()};
}

// The shortest text that reads back to `value`.
inline std::to_chars_result to_chars(char* first, char* last, double value) {
  for (int digits = 1; digits <= 17; ++digits) {
    const int n = std::snprintf(first, static_cast<std::size_t>(last - first), "%.*g", digits, value);
    if (n < 0 || n >= last - first) return {last, std::errc::value_too_large};
    if (std::strtod(first, nullptr) == value || digits == 17) return {first + n, std::errc()};
  }
  return {last, std::errc::value_too_large};
}
#endif

}  // namespace aco
