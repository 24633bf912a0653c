#pragma once
// Small text helpers of the outputs in apps/.
#include <string>
#include <string_view>

namespace job {

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

}  // namespace job
