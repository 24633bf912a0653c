#pragma once
// Small text helpers the readers in apps/ share.
#include <cctype>
#include <string>
#include <string_view>

namespace app {

// Without leading and trailing white space (blanks, tabs, CR, LF).
inline std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

// Text safe inside XML/HTML content and attribute values; control characters become blanks.
inline std::string xml_escape(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (char c : s) {
    switch (c) {
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '&': out += "&amp;"; break;
      case '"': out += "&quot;"; break;
      default: out += (static_cast<unsigned char>(c) < 32) ? ' ' : c;
    }
  }
  return out;
}

}  // namespace app
