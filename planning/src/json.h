#pragma once
// The JSON helpers every profile reader here shares (machines, tool tables,
// panels): errors name the file and, for bad JSON, the line.
#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "formats/error.h"

namespace planning {

using UserError = formats::InputError;
using nlohmann::json;

inline double json_number(const json& j, const char* key, double fallback, const std::string& path) {
  if (!j.contains(key)) return fallback;
  const json& v = j.at(key);
  if (!v.is_number()) throw UserError(path, 0, std::string("\"") + key + "\" must be a number");
  const double d = v.get<double>();
  if (!std::isfinite(d)) throw UserError(path, 0, std::string("\"") + key + "\" must be finite");
  return d;
}

inline json parse_json_text(const std::string& text, const std::string& path) {
  try {
    return json::parse(text);
  } catch (const json::parse_error& e) {
    // nlohmann reports a byte offset; turn it into a line.
    const std::size_t at = std::min<std::size_t>(e.byte, text.size());
    const auto line = static_cast<std::uint32_t>(1 + std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
    std::string what = e.what();
    if (auto p = what.find("parse error"); p != std::string::npos) what = what.substr(p);
    throw UserError(path, line, "invalid JSON: " + what);
  } catch (const json::exception& e) {
    // A number too large for a double (out_of_range 406): the reader gives
    // no position for it. Found by the process table's fuzz target.
    std::string what = e.what();
    if (auto p = what.find("] "); p != std::string::npos) what = what.substr(p + 2);
    throw UserError(path, 0, "invalid JSON: " + what);
  }
}

}  // namespace planning
