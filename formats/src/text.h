#pragma once
// Small text helpers every reader shares.
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>

#include "aco/charconv.h"
#include "formats/error.h"
#include "formats/holes.h"

namespace formats {

// Without leading and trailing white space (blanks, tabs, CR, LF).
inline std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

// A whole finite decimal number, leading "+" allowed, surrounding blanks ignored.
inline bool parse_number(std::string_view s, double& out) {
  s = trim(s);
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  if (s.empty()) return false;
  auto r = aco::from_chars(s.data(), s.data() + s.size(), out);
  return r.ec == std::errc() && r.ptr == s.data() + s.size() && std::isfinite(out);
}

// The file's name without folder and extension; "stdin" for standard input.
inline std::string stem(const std::string& path) {
  std::string base = file_name(path);
  if (auto dot = base.find_last_of('.'); dot != std::string::npos && dot > 0) base.resize(dot);
  return base.empty() || base == "-" ? "stdin" : base;
}

inline std::string lower_ext(const std::string& path) {
  auto dot = path.find_last_of('.');
  if (dot == std::string::npos) return "";
  std::string e = path.substr(dot + 1);
  for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

// Lines of a text with 1-based numbers.
template <class F>
inline void for_each_line(std::string_view data, F&& f) {
  std::size_t pos = 0;
  std::uint32_t no = 0;
  while (pos < data.size()) {
    std::size_t nl = data.find('\n', pos);
    if (nl == std::string_view::npos) nl = data.size();
    std::string_view line = data.substr(pos, nl - pos);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    pos = nl + 1;
    if (!f(++no, line)) return;
  }
}

// Refuses more holes than the limit (--max-holes), naming the line that passed it.
inline void check_limit(const std::string& path, std::uint32_t line, std::size_t count, const dxf::ReadOptions& limit) {
  if (count > limit.max_holes) {
    throw InputError(path, line, "more than " + std::to_string(limit.max_holes) + " holes (" + limit.max_holes_named + ")");
  }
}

}  // namespace formats
