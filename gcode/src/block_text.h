#pragma once
// A line's code without its comments, uppercased: what the drilling reader's
// format check and the keep-style writer look at. Lenient: an unclosed "("
// comments out the rest (the reader proper refuses it, naming the line).
#include <algorithm>
#include <cctype>
#include <string>
#include <string_view>

namespace gcode {

inline std::string code_of(std::string_view raw) {
  std::string code;
  int depth = 0;
  for (char ch : raw) {
    if (ch == '(') ++depth;
    else if (ch == ')') depth = std::max(0, depth - 1);
    else if (ch == ';' && depth == 0) break;
    else if (depth == 0) code += static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  }
  return code;
}

}  // namespace gcode
