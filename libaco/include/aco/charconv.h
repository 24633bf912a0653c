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
#include <cstdint>
#include <cstring>
#include <string>
#include <system_error>
#include <type_traits>

namespace aco {

namespace detail {

// Exact fast paths for the browser build, whose snprintf and strtod work in
// software long double (fmodl, __addtf3: a quarter of the page's outputs at
// 10^5 holes, issue 84). Each gives the very text or value the C library
// does, or says it cannot (the caller falls back), and the suite checks them
// against the library's on the desktop.

__extension__ typedef unsigned __int128 Uint128;  // (g++, clang and Emscripten have it; __extension__: not ISO)

// printf("%.*f", precision, value) for |value| < 2^53 and precision <= 9:
// the double's exact binary value times 10^precision, rounded half to even.
inline bool fixed_to_chars(char* first, char* last, double value, int precision, char*& end) {
  if (!(std::fabs(value) < 9007199254740992.0) || precision < 0 || precision > 9) return false;
  int exponent = 0;
  const double fraction = std::frexp(std::fabs(value), &exponent);  // value = fraction * 2^exponent, fraction in [0.5, 1)
  const auto mantissa = static_cast<std::uint64_t>(std::ldexp(fraction, 53));  // exact: 53 bits
  const int shift = 53 - exponent;  // value = mantissa / 2^shift
  unsigned long long scale = 1;
  for (int i = 0; i < precision; ++i) scale *= 10;
  const Uint128 scaled = static_cast<Uint128>(mantissa) * scale;  // < 2^83
  Uint128 units = 0;  // value * 10^precision, rounded
  if (shift <= 0) {
    units = scaled << -shift;
  } else if (shift < 127) {
    units = scaled >> shift;
    const Uint128 rest = scaled & ((static_cast<Uint128>(1) << shift) - 1);
    const Uint128 half = static_cast<Uint128>(1) << (shift - 1);
    if (rest > half || (rest == half && (units & 1))) ++units;
  }  // else: below 2^-44 of a unit, rounds to 0
  char digits[48];
  int n = 0;
  while (units > ~std::uint64_t{0}) {  // (rare: 128-bit division is slow in the browser)
    digits[n++] = static_cast<char>('0' + static_cast<int>(units % 10));
    units /= 10;
  }
  std::uint64_t small = static_cast<std::uint64_t>(units);
  do {
    digits[n++] = static_cast<char>('0' + static_cast<int>(small % 10));
    small /= 10;
  } while (small > 0 || n <= precision);
  const std::ptrdiff_t size = (std::signbit(value) ? 1 : 0) + n + (precision > 0 ? 1 : 0);
  if (size > last - first) return false;
  char* out = first;
  if (std::signbit(value)) *out++ = '-';
  for (int i = n - 1; i >= 0; --i) {
    *out++ = digits[i];
    if (i == precision && precision > 0) *out++ = '.';
  }
  end = out;
  return true;
}

// from_chars of a plain decimal ("-12.375", "7", ".5", "3."): with at most 15
// significant digits and 22 after the point, the digits and the power of ten
// are exact doubles and one division rounds correctly (Clinger 1990). false:
// not such a number (an exponent, more digits, inf, nan): the caller reads it.
inline bool plain_decimal_from_chars(const char* first, const char* last, double& value, const char*& end) {
  const char* p = first;
  const bool negative = p < last && *p == '-';
  if (negative) ++p;
  std::uint64_t digits = 0;
  int significant = 0, after_point = 0;
  bool any = false, point = false;
  for (; p < last; ++p) {
    if (*p == '.' && !point) {
      point = true;
      continue;
    }
    if (*p < '0' || *p > '9') break;
    any = true;
    if (digits != 0 || *p != '0') ++significant;
    digits = digits * 10 + static_cast<std::uint64_t>(*p - '0');
    if (point) ++after_point;
    if (significant > 15 || after_point > 22) return false;
  }
  if (!any || (p < last && (*p == 'e' || *p == 'E'))) return false;
  static const double kPowers[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                   1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
  const double magnitude = static_cast<double>(digits) / kPowers[after_point];
  value = negative ? -magnitude : magnitude;
  end = p;
  return true;
}

}  // namespace detail

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
  const char* plain_end = nullptr;
  if (detail::plain_decimal_from_chars(first, last, value, plain_end)) return {plain_end, std::errc()};
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
  char* fixed_end = nullptr;
  if (format == std::chars_format::fixed && detail::fixed_to_chars(first, last, value, precision, fixed_end)) {
    return {fixed_end, std::errc()};
  }
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
