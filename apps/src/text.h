#pragma once
// Small text helpers the readers in apps/ share.
#include <cctype>
#include <string_view>

namespace app {

// Without leading and trailing white space (blanks, tabs, CR, LF).
inline std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

}  // namespace app
