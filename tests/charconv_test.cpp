// Issue 84: the browser build's exact fast paths for numbers (aco/charconv.h),
// checked against the C++ library's own on the desktop: the same text for
// every fixed precision the writers use, the same value and end for every
// plain decimal the readers meet, and a refusal (the caller falls back)
// wherever they cannot be exact.
#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstring>
#include <random>
#include <string>

#include "aco/charconv.h"

namespace {

std::string library_fixed(double v, int precision) {
  char buf[128];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, precision);
  return std::string(buf, r.ptr);
}

std::string fast_fixed(double v, int precision) {
  char buf[128];
  char* end = nullptr;
  if (!aco::detail::fixed_to_chars(buf, buf + sizeof buf, v, precision, end)) return "(refused)";
  return std::string(buf, end);
}

TEST(charconv_test, fixed_text_is_the_librarys_for_every_kind_of_value) {
  // Ties, near-ties and the values the writers print most: coordinates in mm and inch.
  const double special[] = {0.0,   -0.0,   0.5,    1.5,    2.5,     0.125,  0.375,  2.675,  1.005,   1.0049999999999999,
                            0.0005, 1e-300, -1e-300, 5e-324, 123.4565, 0.3,    1.0 / 3, 1e15,   9007199254740991.0,
                            -0.0004, 4503599627370495.5, 0.045, 1.25e-5};
  for (double v : special) {
    for (int p = 0; p <= 9; ++p) EXPECT_EQ(fast_fixed(v, p), library_fixed(v, p)) << v << " %." << p << "f";
  }
  std::mt19937_64 rng(84);
  std::uniform_real_distribution<double> mm(-2000.0, 2000.0);
  std::uniform_int_distribution<int> thousandths(-2'000'000, 2'000'000), precision(0, 9);
  for (int i = 0; i < 200000; ++i) {
    const int p = precision(rng);
    const double a = mm(rng);                                 // any double in range
    const double b = thousandths(rng) / 1000.0;               // a 3-decimal value, as read
    const double c = thousandths(rng) / 1000.0 / 25.4;        // and in inch
    const double tie = (thousandths(rng) + 0.5) / std::pow(10.0, p);  // at (or next to) a half
    for (double v : {a, b, c, tie}) ASSERT_EQ(fast_fixed(v, p), library_fixed(v, p)) << v << " %." << p << "f";
  }
  // Out of its range it says so.
  EXPECT_EQ(fast_fixed(1e16, 3), "(refused)");
  EXPECT_EQ(fast_fixed(1.0, 10), "(refused)");
  EXPECT_EQ(fast_fixed(std::nan(""), 3), "(refused)");
}

TEST(charconv_test, plain_decimals_read_to_the_librarys_value) {
  auto check = [](const std::string& text) {
    double want = 0, got = 0;
    const auto r = std::from_chars(text.data(), text.data() + text.size(), want);
    const char* end = nullptr;
    const bool fast = aco::detail::plain_decimal_from_chars(text.data(), text.data() + text.size(), got, end);
    if (!fast) return;  // not a plain decimal it takes: the library reads it
    ASSERT_EQ(r.ec, std::errc()) << text;
    EXPECT_EQ(std::memcmp(&got, &want, sizeof got), 0) << text << ": " << got << " vs " << want;
    EXPECT_EQ(end, r.ptr) << text;
  };
  for (const char* t : {"0", "-0", "0.0", "-0.000", "5.", ".5", "-.5", "12.375", "1.2.3", "7X", "123456789012345",
                        "0.0000000000000000000001", "2.675", "1.005", "-1999.999", "0.1", "0.30000000000000004"}) {
    check(t);
  }
  std::mt19937_64 rng(84);
  std::uniform_int_distribution<long long> digits(-999'999'999'999'999LL, 999'999'999'999'999LL);
  std::uniform_int_distribution<int> places(0, 22);
  for (int i = 0; i < 200000; ++i) {
    std::string s = std::to_string(digits(rng));
    const int k = places(rng);
    const bool negative = s[0] == '-';
    std::string body = negative ? s.substr(1) : s;
    if (k > 0) {
      if (static_cast<int>(body.size()) <= k) body = std::string(static_cast<std::size_t>(k) - body.size() + 1, '0') + body;
      body.insert(body.size() - static_cast<std::size_t>(k), ".");
    }
    check((negative ? "-" : "") + body);
  }
  // What it leaves to the library: an exponent, too many digits, words.
  double v = 0;
  const char* end = nullptr;
  for (const char* t : {"1e5", "1.5E-3", "1234567890123456", "inf", "nan", ".", "-", ""}) {
    EXPECT_FALSE(aco::detail::plain_decimal_from_chars(t, t + std::strlen(t), v, end)) << t;
  }
}

}  // namespace
