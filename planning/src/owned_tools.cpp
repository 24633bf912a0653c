#include "planning/owned_tools.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

#include "aco/charconv.h"
#include "gcode/program.h"
#include "json.h"

namespace planning {

namespace {

std::string fmt3(double v) { return gcode::format_number(v, 3); }

// A number of the list, or the error that names the item.
double number_of(const std::string& text, const std::string& item, const std::string& where) {
  double v = 0.0;
  const char* end = text.data() + text.size();
  auto r = aco::from_chars(text.data(), end, v);
  if (text.empty() || r.ec != std::errc() || r.ptr != end || !std::isfinite(v)) {
    throw UserError(where + ": \"" + item + "\" is not DIA[:-MINUS:+PLUS] in mm (e.g. 0.8 or 0.8:-0.05:+0.1)");
  }
  return v;
}

}  // namespace

std::vector<OwnedDrill> parse_owned_drills(const std::string& list, const std::string& where) {
  std::vector<OwnedDrill> drills;
  std::size_t pos = 0;
  while (pos <= list.size()) {
    std::size_t comma = list.find(',', pos);
    if (comma == std::string::npos) comma = list.size();
    std::string item = list.substr(pos, comma - pos);
    pos = comma + 1;
    item.erase(0, item.find_first_not_of(" \t"));
    item.erase(item.find_last_not_of(" \t") + 1);
    if (item.empty()) {
      if (comma == list.size() && !drills.empty()) break;
      throw UserError(where + ": an empty drill in \"" + list + "\"; give drills as 0.6,0.8,1.0 (mm)");
    }
    OwnedDrill d;
    std::vector<std::string> parts;
    for (std::size_t p = 0;;) {
      const std::size_t colon = item.find(':', p);
      parts.push_back(item.substr(p, colon == std::string::npos ? std::string::npos : colon - p));
      if (colon == std::string::npos) break;
      p = colon + 1;
    }
    if (parts.size() != 1 && parts.size() != 3) {
      throw UserError(where + ": \"" + item + "\" is not DIA[:-MINUS:+PLUS] in mm (e.g. 0.8 or 0.8:-0.05:+0.1)");
    }
    d.diameter_mm = number_of(parts[0], item, where);
    if (!(d.diameter_mm > 0 && d.diameter_mm <= 100)) throw UserError(where + ": drill " + item + " must be in (0, 100] mm");
    if (parts.size() == 3) {
      if (parts[1].empty() || parts[1][0] != '-' || parts[2].empty() || parts[2][0] != '+') {
        throw UserError(where + ": \"" + item + "\": the fit is :-MINUS:+PLUS, e.g. 0.8:-0.05:+0.1");
      }
      d.minus_mm = number_of(parts[1].substr(1), item, where);
      d.plus_mm = number_of(parts[2].substr(1), item, where);
      if (!(d.minus_mm >= 0 && d.minus_mm <= 10 && d.plus_mm >= 0 && d.plus_mm <= 10)) {
        throw UserError(where + ": \"" + item + "\": MINUS and PLUS must be 0..10 mm");
      }
    }
    for (const OwnedDrill& o : drills) {
      if (std::fabs(o.diameter_mm - d.diameter_mm) < 0.0005) throw UserError(where + ": drill " + fmt3(d.diameter_mm) + " is given twice");
    }
    drills.push_back(d);
    if (comma == list.size()) break;
  }
  if (drills.empty()) throw UserError(where + ": no drills given; give them as 0.6,0.8,1.0 (mm)");
  std::sort(drills.begin(), drills.end(), [](const OwnedDrill& a, const OwnedDrill& b) { return a.diameter_mm < b.diameter_mm; });
  return drills;
}

std::vector<DiameterChoice> choose_drills(const std::vector<std::pair<double, std::size_t>>& diameters,
                                          const Tooling& tooling, const std::string& source) {
  const std::vector<OwnedDrill>& drills = tooling.drills;
  std::vector<DiameterChoice> out;
  for (const auto& [d, n] : diameters) out.push_back({d, n, std::nullopt});
  // The diameters some drill fits; the others go to the end mill.
  std::vector<std::size_t> fit;
  std::vector<std::string> unmade;
  std::size_t unmade_holes = 0;
  for (std::size_t i = 0; i < out.size(); ++i) {
    const double d = out[i].designed_mm;
    if (std::any_of(drills.begin(), drills.end(), [&](const OwnedDrill& o) { return o.fits(d); })) {
      fit.push_back(i);
    } else if (!tooling.end_mill_mm || d < *tooling.end_mill_mm - 1e-9) {
      unmade.push_back(fmt3(d) + " mm (" + std::to_string(out[i].holes) + (out[i].holes == 1 ? " hole)" : " holes)"));
      unmade_holes += out[i].holes;
    }
  }
  if (!unmade.empty()) {
    std::string list;
    for (const std::string& u : unmade) list += (list.empty() ? "" : ", ") + u;
    std::string owned;
    for (const OwnedDrill& o : drills) owned += (owned.empty() ? "" : ",") + fmt3(o.diameter_mm);
    throw UserError(source, 0,
                    std::to_string(unmade_holes) + " hole(s) no owned drill fits" +
                        (tooling.end_mill_mm ? " and the " + fmt3(*tooling.end_mill_mm) + " mm end mill is too large for" : "") +
                        ": " + list + " (drills owned: " + (owned.empty() ? "none" : owned) +
                        "; add a drill that fits to --drills" + (tooling.end_mill_mm ? "" : ", or give --end-mill DIA to mill larger holes") + ")");
  }
  if (fit.empty()) return out;
  std::sort(fit.begin(), fit.end(), [&](std::size_t a, std::size_t b) { return out[a].designed_mm < out[b].designed_mm; });
  // A drill takes the hole sizes from D - plus to D + minus: an interval.
  auto high = [&](std::size_t j) { return drills[j].diameter_mm + drills[j].minus_mm; };
  // The fewest drills: the leftmost size not yet covered is taken by the
  // drill that fits it and reaches furthest right.
  std::size_t fewest = 0;
  std::vector<std::size_t> greedy;
  for (std::size_t k = 0; k < fit.size();) {
    const double d = out[fit[k]].designed_mm;
    std::size_t best = drills.size();
    for (std::size_t j = 0; j < drills.size(); ++j) {
      if (drills[j].fits(d) && (best == drills.size() || high(j) > high(best))) best = j;
    }
    greedy.push_back(best);
    ++fewest;
    while (k < fit.size() && drills[best].fits(out[fit[k]].designed_mm)) ++k;
  }
  // Each diameter to the closest drill of a set that fits it (the larger on a tie); the set's misfit.
  auto assign = [&](const std::vector<std::size_t>& set, std::vector<std::size_t>* to) {
    double misfit = 0.0;
    for (std::size_t i : fit) {
      const double d = out[i].designed_mm;
      std::size_t best = drills.size();
      for (std::size_t j : set) {
        if (!drills[j].fits(d)) continue;
        const double e = std::fabs(drills[j].diameter_mm - d);
        if (best == drills.size() || e < std::fabs(drills[best].diameter_mm - d) - 1e-12 ||
            (std::fabs(e - std::fabs(drills[best].diameter_mm - d)) <= 1e-12 && drills[j].diameter_mm > drills[best].diameter_mm)) {
          best = j;
        }
      }
      if (best == drills.size()) return std::numeric_limits<double>::infinity();
      if (to) (*to)[i] = best;
      misfit += std::fabs(drills[best].diameter_mm - d) * static_cast<double>(out[i].holes);
    }
    return misfit;
  };
  // Among the sets of that size, the least misfit: every set when there are
  // few enough to try (a hobbyist's drill set is a dozen), else the greedy one.
  std::vector<std::size_t> useful;
  for (std::size_t j = 0; j < drills.size(); ++j) {
    if (std::any_of(fit.begin(), fit.end(), [&](std::size_t i) { return drills[j].fits(out[i].designed_mm); })) useful.push_back(j);
  }
  double combos = 1.0;
  for (std::size_t k = 0; k < fewest; ++k) combos = combos * static_cast<double>(useful.size() - k) / static_cast<double>(k + 1);
  std::vector<std::size_t> chosen = greedy;
  double best_misfit = assign(greedy, nullptr);
  if (combos <= 200000.0) {
    std::vector<std::size_t> pick(fewest);
    for (std::size_t k = 0; k < fewest; ++k) pick[k] = k;
    while (true) {
      std::vector<std::size_t> set(fewest);
      for (std::size_t k = 0; k < fewest; ++k) set[k] = useful[pick[k]];
      const double m = assign(set, nullptr);
      if (m < best_misfit - 1e-12) {
        best_misfit = m;
        chosen = set;
      }
      // The next combination in lexicographic order.
      std::size_t k = fewest;
      while (k > 0 && pick[k - 1] == useful.size() - fewest + k - 1) --k;
      if (k == 0) break;
      ++pick[k - 1];
      for (std::size_t q = k; q < fewest; ++q) pick[q] = pick[q - 1] + 1;
    }
  }
  std::vector<std::size_t> to(out.size(), drills.size());
  assign(chosen, &to);
  for (std::size_t i : fit) out[i].drill = to[i];
  return out;
}

}  // namespace planning
