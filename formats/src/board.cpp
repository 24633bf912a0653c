#include "board.h"

#include <algorithm>
#include <cctype>
#include <limits>

#include "formats/error.h"
#include "gcode/program.h"

namespace formats::board {

std::string choose_step(const std::string& path, const std::vector<std::pair<std::string, std::vector<std::string>>>& steps,
                        const std::string& wanted) {
  std::string all;
  for (const auto& [name, placed] : steps) all += (all.empty() ? "" : ", ") + name;
  if (steps.empty()) throw InputError(path, 0, "no step: the job holds no board");
  if (!wanted.empty()) {
    for (const auto& [name, placed] : steps) {
      if (name == wanted) return name;
    }
    // Steps are named in any case (ODB++ folders are lower case, its matrix upper).
    for (const auto& [name, placed] : steps) {
      if (name.size() == wanted.size() && std::equal(name.begin(), name.end(), wanted.begin(), [](char x, char y) {
            return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
          })) {
        return name;
      }
    }
    throw InputError(path, 0, "--step " + wanted + ": no such step; the job's steps: " + all);
  }
  if (steps.size() == 1) return steps.front().first;
  std::vector<std::string> panels;
  for (const auto& [name, placed] : steps) {
    if (placed.empty()) continue;
    bool placed_by_other = false;
    for (const auto& [other, theirs] : steps) {
      placed_by_other = placed_by_other || std::find(theirs.begin(), theirs.end(), name) != theirs.end();
    }
    if (!placed_by_other) panels.push_back(name);
  }
  if (panels.size() == 1) return panels.front();
  throw InputError(path, 0, "the job has " + std::to_string(steps.size()) + " steps (" + all +
                                "); say which to drill with --step NAME");
}

bool fit_slot(const std::vector<aco::Point2>& outline, Slot& slot, aco::Hole& hole) {
  if (outline.size() < 3 || outline.size() > 100000) return false;
  // The narrowest of the rectangles around it whose side is one of its edges
  // (a stadium's straight sides are edges, whatever its round ends are made of).
  double best_width = -1, best_lo = 0, best_hi = 0, best_nlo = 0;
  aco::Point2 best_u{1, 0};
  for (std::size_t i = 0; i < outline.size(); ++i) {
    const aco::Point2 p = outline[i], q = outline[(i + 1) % outline.size()];
    const double len = aco::euclidean(p, q);
    if (!(len > 1e-9)) continue;
    const aco::Point2 u{(q.x - p.x) / len, (q.y - p.y) / len};
    double lo = 1e300, hi = -1e300, nlo = 1e300, nhi = -1e300;
    for (const aco::Point2& o : outline) {
      const double along = o.x * u.x + o.y * u.y, across = -o.x * u.y + o.y * u.x;
      lo = std::min(lo, along), hi = std::max(hi, along);
      nlo = std::min(nlo, across), nhi = std::max(nhi, across);
    }
    if (best_width < 0 || nhi - nlo < best_width - 1e-12) {
      best_width = nhi - nlo, best_lo = lo, best_hi = hi, best_nlo = nlo, best_u = u;
    }
  }
  if (!(best_width > 0)) return false;
  const double length = best_hi - best_lo, mid_along = (best_lo + best_hi) / 2, mid_across = best_nlo + best_width / 2;
  const aco::Point2 u = best_u;
  const aco::Point2 mid{mid_along * u.x - mid_across * u.y, mid_along * u.y + mid_across * u.x};
  if (length - best_width < 1e-3) {  // round: a hole, not a slot
    hole.center = mid;
    hole.diameter = std::max(length, best_width);
    return false;
  }
  // The centre line runs between the centres of the two round ends.
  const double half = (length - best_width) / 2;
  slot.from = {mid.x - u.x * half, mid.y - u.y * half};
  slot.to = {mid.x + u.x * half, mid.y + u.y * half};
  slot.width_mm = best_width;
  return true;
}

LoadedHoles& Sources::of(bool plated, const Span& span) {
  std::string label = plated ? "plated" : "non-plated";
  std::string function = plated ? "Plated" : "NonPlated";
  const int from = span.from == 0 ? 1 : std::min(span.from, span.to);
  const int to = span.from == 0 ? std::max(2, span.conductors) : std::max(span.from, span.to);
  std::string kind = plated ? "PTH" : "NPTH";
  if (!span.through()) {
    // Gerber X2's words for the two spans that do not go through; a back-drill is a blind hole in those words.
    const bool blind = span.back_drill || from == 1 || to == span.conductors;
    kind = blind ? "Blind" : "Buried";
    label += ", " + std::string(span.back_drill ? "back-drill" : blind ? "blind" : "buried") + " " + std::to_string(from) + "-" +
             std::to_string(to);
  }
  for (auto& [l, holes] : made_) {
    if (l == label) return holes;
  }
  LoadedHoles made;
  made.format = format_;
  made.source_label = label;
  made.drill_function = function + "," + std::to_string(from) + "," + std::to_string(to) + "," + kind + ",Drill";
  made_.emplace_back(label, std::move(made));
  return made_.back().second;
}

std::vector<LoadedHoles> Sources::take(const std::string& description, std::vector<Note> warnings, std::vector<Note> skipped) {
  auto rank = [](const std::string& label) { return label == "plated" ? 0 : label == "non-plated" ? 1 : 2; };
  std::stable_sort(made_.begin(), made_.end(), [&](const auto& x, const auto& y) { return rank(x.first) < rank(y.first); });
  std::vector<LoadedHoles> out;
  for (auto& [label, holes] : made_) out.push_back(std::move(holes));
  made_.clear();
  if (out.empty()) {
    out.emplace_back();
    out.back().format = format_;
  }
  if (out.size() == 1) out.front().source_label.clear();  // one source: the file, as any other
  // What concerns the file as a whole is said once, with its first source.
  out.front().description = description;
  out.front().warnings = std::move(warnings);
  out.front().skipped = std::move(skipped);
  return out;
}

std::string size_text(const std::vector<aco::Point2>& points) {
  if (points.empty()) return "";
  double x0 = std::numeric_limits<double>::max(), y0 = x0, x1 = -x0, y1 = -x0;
  for (const aco::Point2& p : points) {
    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
    y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  }
  return gcode::format_number(x1 - x0, 3) + " x " + gcode::format_number(y1 - y0, 3) + " mm";
}

}  // namespace formats::board
