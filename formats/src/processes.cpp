// A process table's rules matched to hole features (formats/processes.h).
#include "formats/processes.h"

#include <algorithm>
#include <cctype>

#include "formats/features.h"

namespace formats {

namespace {

bool same_text(const std::string& a, const std::string& b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::toupper(static_cast<unsigned char>(x)) == std::toupper(static_cast<unsigned char>(y));
         });
}

}  // namespace

std::uint32_t matching_rule(const ProcessTable& table, const HoleFeature& f, const std::string& drawn_kind) {
  for (std::size_t k = 0; k < table.rules.size(); ++k) {
    const ProcessRule& r = table.rules[k];
    if (!r.layer.empty() && !same_text(r.layer, f.layer)) continue;
    if (!r.kind.empty() && r.kind != drawn_kind) continue;
    if (r.diameter_mm && !(f.diameter_mm >= r.diameter_mm->first - 1e-9 && f.diameter_mm <= r.diameter_mm->second + 1e-9)) continue;
    if (!r.thread.empty() && !same_text(r.thread, f.thread)) continue;
    return static_cast<std::uint32_t>(k + 1);
  }
  return 0;
}

const ProcessStep* step_of(const ProcessRule& rule, gcode::Operation kind) {
  for (const ProcessStep& s : rule.steps) {
    if (s.kind == kind) return &s;
  }
  return nullptr;
}

}  // namespace formats
