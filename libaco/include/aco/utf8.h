#pragma once
// UTF-8, one code point at a time: the program's comments write names in any
// script one character a character (issue 85), and hole callouts are read
// with their symbols (⌀ ⌴ ⌵ ↧, issue 82).
#include <cstddef>
#include <string_view>

namespace aco {

// The code point of UTF-8 at `at`, moving past it. What is not well formed
// is one U+FFFD for each stray byte or each sequence cut short.
inline char32_t next_code_point(std::string_view s, std::size_t& at) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char lead = byte(at);
  const std::size_t extra = lead >= 0xC2 && lead < 0xE0 ? 1 : lead >= 0xE0 && lead < 0xF0 ? 2 : lead >= 0xF0 && lead < 0xF5 ? 3 : 0;
  ++at;
  if (lead < 0x80) return lead;
  if (extra == 0) return 0xFFFD;
  char32_t cp = lead & (0x3F >> extra);
  for (std::size_t k = 0; k < extra; ++k) {
    if (at + k >= s.size() || (byte(at + k) & 0xC0) != 0x80) {  // cut short
      at += k;
      return 0xFFFD;
    }
    cp = (cp << 6) | (byte(at + k) & 0x3F);
  }
  at += extra;
  return cp;
}

}  // namespace aco
