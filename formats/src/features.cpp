// Hole features from a drawing's circles, arcs and callouts (formats/features.h).
#include "formats/features.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <unordered_map>

#include "aco/utf8.h"
#include "formats/error.h"
#include "formats/processes.h"
#include "formats/threads.h"
#include "gcode/program.h"

namespace formats {

namespace {

std::string mm(double v) { return gcode::format_number(v, 3); }

// Circles by X, to find those whose centre lies within kConcentricMm of a point.
class CentresByX {
 public:
  explicit CentresByX(const aco::HoleSet& circles) : circles_(circles), order_(circles.size()) {
    std::iota(order_.begin(), order_.end(), std::size_t{0});
    std::sort(order_.begin(), order_.end(), [&](std::size_t a, std::size_t b) {
      return circles[a].center.x < circles[b].center.x || (circles[a].center.x == circles[b].center.x && a < b);
    });
  }
  // Calls f(i) for every circle i whose centre lies within kConcentricMm of p.
  template <typename F>
  void near(aco::Point2 p, F f) const {
    auto it = std::lower_bound(order_.begin(), order_.end(), p.x - kConcentricMm,
                               [&](std::size_t i, double x) { return circles_[i].center.x < x; });
    for (; it != order_.end() && circles_[*it].center.x <= p.x + kConcentricMm; ++it) {
      if (aco::euclidean(circles_[*it].center, p) <= kConcentricMm) f(*it);
    }
  }
  const std::vector<std::size_t>& order() const { return order_; }

 private:
  const aco::HoleSet& circles_;
  std::vector<std::size_t> order_;
};

// What decided a larger circle.
struct Ring {
  std::size_t circle = 0;
  FeatureKind kind = FeatureKind::Undecided;
  double depth_mm = 0.0, angle_deg = 0.0;
  std::string evidence;
};

struct Group {
  aco::Point2 center;
  std::vector<std::size_t> circles;  // ascending diameter once grouped
  std::vector<Ring> rings;           // every circle but the smallest
  const Thread* thread = nullptr;
  std::string thread_evidence;
};

bool same_diameter(double a, double b) { return std::fabs(a - b) <= std::max(0.05, 0.01 * std::max(a, b)); }

// The layer's words (letters, digits and apostrophes), upper case.
std::vector<std::string> words_of(const std::string& text) {
  std::vector<std::string> words;
  std::string w;
  for (std::size_t i = 0; i <= text.size(); ++i) {
    const unsigned char c = i < text.size() ? static_cast<unsigned char>(text[i]) : ' ';
    if (std::isalnum(c) || c == '\'') {
      w += static_cast<char>(std::toupper(c));
    } else if (c == 0xE2 && i + 2 < text.size() && static_cast<unsigned char>(text[i + 1]) == 0x80 &&
               static_cast<unsigned char>(text[i + 2]) == 0x99) {
      w += '\'';  // ’ (U+2019), as CAD fonts write C’BORE
      i += 2;
    } else if (!w.empty()) {
      words.push_back(w);
      w.clear();
    }
  }
  return words;
}

bool is_counterbore_word(const std::string& w) {
  return w == "CBORE" || w == "C'BORE" || w == "COUNTERBORE" || w == "SPOTFACE" || w == "SFACE";
}
bool is_countersink_word(const std::string& w) { return w == "CSK" || w == "CSINK" || w == "COUNTERSINK"; }

FeatureKind kind_of_layer(const std::string& layer) {
  for (const std::string& w : words_of(layer)) {
    if (is_counterbore_word(w)) return FeatureKind::Counterbore;
    if (is_countersink_word(w)) return FeatureKind::Countersink;
  }
  return FeatureKind::Undecided;
}

// The symbols a callout is written with, as words.
const char* symbol_word(char32_t cp) {
  switch (cp) {
    case 0x2300: case 0x00D8: case 0x00F8: case 0x2205: return " DIA ";  // ⌀ Ø ø ∅
    case 0x2334: return " CBORE ";                                        // ⌴
    case 0x2335: return " CSK ";                                          // ⌵
    case 0x21A7: return " DEPTH ";                                        // ↧
    case 0x00B0: return " DEG ";                                          // °
    default: return " ";
  }
}

// Fields of a callout, in drawing units (angle in degrees).
struct Callout {
  FeatureKind kind = FeatureKind::Plain;
  double hole = 0.0, outer = 0.0, depth = 0.0, angle = 0.0;
  const dxf::DrawnText* text = nullptr;
};

Callout read_callout(const std::string& plain) {
  Callout c;
  // Tokens: words of letters (and '), numbers (a decimal point or comma between digits).
  std::vector<std::pair<bool, std::string>> tokens;  // (is_number, text)
  for (std::size_t i = 0; i < plain.size();) {
    const unsigned char ch = static_cast<unsigned char>(plain[i]);
    if (std::isdigit(ch) || (ch == '.' && i + 1 < plain.size() && std::isdigit(static_cast<unsigned char>(plain[i + 1])))) {
      std::string n;
      bool point = false;
      while (i < plain.size()) {
        const unsigned char d = static_cast<unsigned char>(plain[i]);
        if (std::isdigit(d)) {
          n += static_cast<char>(d);
        } else if ((d == '.' || d == ',') && !point && i + 1 < plain.size() &&
                   std::isdigit(static_cast<unsigned char>(plain[i + 1]))) {
          n += '.';
          point = true;
        } else {
          break;
        }
        ++i;
      }
      tokens.push_back({true, n});
    } else if (std::isalpha(ch) || ch == '\'') {
      std::string w;
      while (i < plain.size() && (std::isalpha(static_cast<unsigned char>(plain[i])) || plain[i] == '\'')) w += plain[i++];
      tokens.push_back({false, w});
    } else {
      ++i;
    }
  }
  enum class Want { Nothing, Diameter, Depth } want = Want::Nothing;
  double last = 0.0;
  bool have_last = false;
  for (const auto& [is_number, t] : tokens) {
    if (is_number) {
      const double v = std::strtod(t.c_str(), nullptr);
      if (want == Want::Diameter) {
        double& d = c.kind == FeatureKind::Plain ? c.hole : c.outer;  // the first of each
        if (d == 0) d = v;
      } else if (want == Want::Depth && c.kind != FeatureKind::Plain) {
        c.depth = v;
      }
      want = Want::Nothing;
      last = v, have_last = true;
      continue;
    }
    if (t == "DIA") {
      want = Want::Diameter;
    } else if (t == "DEPTH") {
      want = Want::Depth;
    } else if ((t == "DEEP" || t == "DP") && have_last && c.kind != FeatureKind::Plain && c.depth == 0) {
      c.depth = last;
    } else if (t == "DEG" && have_last && c.kind == FeatureKind::Countersink) {
      c.angle = last;
    } else if (is_counterbore_word(t) || is_countersink_word(t)) {
      const FeatureKind k = is_counterbore_word(t) ? FeatureKind::Counterbore : FeatureKind::Countersink;
      if (c.kind != FeatureKind::Plain && c.kind != k) return {};  // names both: nothing is sure
      c.kind = k;
      want = Want::Nothing;
    }
  }
  return c;
}

// The pairs of diameters (hole, larger circle) in 0.01 mm, as callouts decide them.
using DiameterPair = std::pair<long long, long long>;
DiameterPair pair_of(double hole, double outer) { return {std::llround(hole * 100), std::llround(outer * 100)}; }

struct PairDecision {
  FeatureKind kind = FeatureKind::Undecided;
  double depth_mm = 0.0, angle_deg = 0.0;
  std::uint32_t line = 0;
  bool conflict = false;
  std::string text;  // the callout, plain
};

}  // namespace

const char* to_string(FeatureKind kind) {
  switch (kind) {
    case FeatureKind::Plain: return "plain";
    case FeatureKind::Tapped: return "tapped";
    case FeatureKind::Counterbore: return "counterbore";
    case FeatureKind::Countersink: return "countersink";
    case FeatureKind::Undecided: return "undecided";
  }
  return "?";
}

std::string plain_callout(const std::string& text, bool gdt_font) {
  std::string out;
  std::vector<bool> fonts;  // the GD&T font at each open brace
  bool gdt = gdt_font;
  auto until_semicolon = [&](std::size_t from) {
    const std::size_t end = text.find(';', from);
    return end == std::string::npos ? text.size() : end;
  };
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    if (c == '{') {
      fonts.push_back(gdt);
      ++i;
      continue;
    }
    if (c == '}') {
      if (!fonts.empty()) gdt = fonts.back(), fonts.pop_back();
      ++i;
      continue;
    }
    if (c == '\\' && i + 1 < text.size()) {
      const char d = text[i + 1];
      if (d == 'P' || d == 'X' || d == '~' || d == 'N') {
        out += ' ';
        i += 2;
      } else if (d == '\\' || d == '{' || d == '}') {
        out += d;
        i += 2;
      } else if (d == 'F' || d == 'f') {  // \Fgdt; or \fAIGDT|b0|i0|c0|p0;
        const std::size_t end = until_semicolon(i + 2);
        std::string font = text.substr(i + 2, end - i - 2);
        for (char& ch : font) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
        gdt = font.find("GDT") != std::string::npos;
        i = end + 1;
      } else if (d == 'S') {  // a stacked fraction a^b: a/b
        const std::size_t end = until_semicolon(i + 2);
        std::string stacked = text.substr(i + 2, end - i - 2);
        for (char& ch : stacked) ch = (ch == '^' || ch == '#') ? '/' : ch;
        out += " " + stacked + " ";
        i = end + 1;
      } else if (d == 'U' && i + 6 < text.size() && text[i + 2] == '+') {
        const char32_t cp = static_cast<char32_t>(std::strtoul(text.substr(i + 3, 4).c_str(), nullptr, 16));
        out += symbol_word(cp);
        i += 7;
      } else if (std::string("HWQTACcp").find(d) != std::string::npos) {
        i = until_semicolon(i + 2) + 1;  // height, width, slant, tracking, alignment, colour, paragraph
      } else {
        i += 2;  // \L \l \O \o \K \k: lines over and under, no text
      }
      continue;
    }
    if (c == '%' && i + 2 < text.size() && text[i + 1] == '%') {
      const char code = static_cast<char>(std::tolower(static_cast<unsigned char>(text[i + 2])));
      out += code == 'c' ? " DIA " : code == 'd' ? " DEG " : " ";
      i += 3;
      continue;
    }
    const char32_t cp = aco::next_code_point(text, i);
    if (cp >= 0x80) {
      out += symbol_word(cp);
      continue;
    }
    if (gdt) {
      // The GD&T font (gdt.shx, AIGDT): n is Ø, v the counterbore, w the countersink, x the depth.
      const char l = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      if (l == 'n') out += " DIA ";
      else if (l == 'v') out += " CBORE ";
      else if (l == 'w') out += " CSK ";
      else if (l == 'x') out += " DEPTH ";
      else out += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      continue;
    }
    out += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  }
  // One space between words.
  std::string tidy;
  for (char ch : out) {
    if (std::isspace(static_cast<unsigned char>(ch))) {
      if (!tidy.empty() && tidy.back() != ' ') tidy += ' ';
    } else {
      tidy += ch;
    }
  }
  if (!tidy.empty() && tidy.back() == ' ') tidy.pop_back();
  return tidy;
}

RecognizedFeatures recognize_features(const aco::HoleSet& circles, const std::vector<dxf::DrawnArc>& arcs,
                                      const std::vector<dxf::DrawnText>& texts, double unit_mm,
                                      const ProcessTable* processes) {
  RecognizedFeatures r;
  // 1. Concentric circles into groups: each circle's root is the first circle
  // of its group in file order (union-find over the pairs within kConcentricMm).
  const CentresByX by_x(circles);
  std::vector<std::size_t> root(circles.size());
  std::iota(root.begin(), root.end(), std::size_t{0});
  auto find = [&](std::size_t i) {
    while (root[i] != i) i = root[i] = root[root[i]];
    return i;
  };
  for (std::size_t i : by_x.order()) {
    by_x.near(circles[i].center, [&](std::size_t j) {
      const std::size_t a = find(i), b = find(j);
      if (a != b) root[std::max(a, b)] = std::min(a, b);
    });
  }
  for (std::size_t i = 0; i < circles.size(); ++i) root[i] = find(i);
  // Groups only where there is more than one circle, or an arc: a plain hole needs none.
  std::vector<Group> groups;
  std::unordered_map<std::size_t, std::size_t> group_at;  // root → groups
  auto group_of_root = [&](std::size_t first) -> Group& {
    auto [it, fresh] = group_at.emplace(first, groups.size());
    if (fresh) groups.push_back({circles[first].center, {}, {}, nullptr, {}});
    return groups[it->second];
  };
  for (std::size_t i = 0; i < circles.size(); ++i) {
    if (root[i] != i) group_of_root(root[i]).circles.push_back(i);
  }
  for (auto& [first, g] : group_at) groups[g].circles.push_back(first);
  for (Group& g : groups) {
    std::stable_sort(g.circles.begin(), g.circles.end(), [&](std::size_t a, std::size_t b) {
      return circles[a].diameter < circles[b].diameter || (circles[a].diameter == circles[b].diameter && a < b);
    });
    for (std::size_t k = 1; k < g.circles.size(); ++k) g.rings.push_back({g.circles[k], FeatureKind::Undecided, 0, 0, {}});
  }

  // 2. Threads: a concentric arc of about three quarters of a turn, larger than the hole.
  const bool inch = std::fabs(unit_mm - 25.4) < 1e-9;
  std::size_t no_thread = 0;
  std::uint32_t first_no_thread = 0;
  std::string no_thread_example;
  for (const dxf::DrawnArc& a : arcs) {
    if (a.span_deg < kThreadSpanMin - 1e-6 || a.span_deg > kThreadSpanMax + 1e-6) continue;
    std::optional<std::size_t> on;
    by_x.near(a.center, [&](std::size_t i) { on = on ? std::min(*on, root[i]) : root[i]; });
    if (!on) continue;
    const bool grouped = group_at.count(*on) != 0;
    Group& group = group_of_root(*on);
    if (!grouped) group.circles.push_back(*on);  // a single circle: its group made for the arc
    const aco::Hole& hole = circles[group.circles.front()];
    if (!(a.diameter > hole.diameter + 1e-6) || group.thread != nullptr) continue;
    if (const Thread* t = match_thread(a.diameter, hole.diameter, inch)) {
      group.thread = t;
      group.thread_evidence = "arc " + gcode::format_short(a.span_deg) + " deg of D" + gcode::format_short(a.diameter) + ", line " + std::to_string(a.line);
    } else {
      if (no_thread++ == 0) {
        first_no_thread = a.line;
        no_thread_example = "D" + gcode::format_short(a.diameter) + " around D" + gcode::format_short(hole.diameter);
      }
    }
  }
  if (no_thread > 0) {
    r.warnings.push_back({first_no_thread, std::to_string(no_thread) + " arc(s) of about three quarters of a turn around a hole (" +
                                               no_thread_example + ") match no standard thread (ISO metric, UNC, UNF): "
                                               "the holes are drilled as drawn, not tapped"});
  }

  // 3. Larger circles decided by their layer.
  for (Group& g : groups) {
    for (Ring& ring : g.rings) {
      const aco::Hole& c = circles[ring.circle];
      ring.kind = kind_of_layer(c.layer);
      if (ring.kind != FeatureKind::Undecided) ring.evidence = "layer " + c.layer;
    }
  }

  // 4. Callouts beside a feature decide its pair of diameters wherever it recurs.
  std::map<DiameterPair, PairDecision> decided;
  for (const dxf::DrawnText& t : texts) {
    Callout c = read_callout(plain_callout(t.text, t.gdt_font));
    if (c.kind == FeatureKind::Plain || !(c.outer > 0)) continue;
    c.hole *= unit_mm, c.outer *= unit_mm, c.depth *= unit_mm;
    // The nearest feature with a larger circle of the callout's diameters, within reach.
    const Group* nearest = nullptr;
    const Ring* nearest_ring = nullptr;
    double nearest_d = 0.0;
    for (const Group& g : groups) {
      if (g.rings.empty() || (c.hole > 0 && !same_diameter(circles[g.circles.front()].diameter, c.hole))) continue;
      for (const Ring& ring : g.rings) {
        const double d = circles[ring.circle].diameter;
        if (!same_diameter(d, c.outer)) continue;
        for (aco::Point2 p : t.anchors) {
          const double gap = std::max(0.0, aco::euclidean(p, g.center) - d / 2);
          if (gap <= kCalloutReachMm && (nearest == nullptr || gap < nearest_d)) nearest = &g, nearest_ring = &ring, nearest_d = gap;
        }
      }
    }
    if (nearest == nullptr) continue;
    std::string said = plain_callout(t.text, t.gdt_font);
    if (said.size() > 60) said = said.substr(0, 57) + "...";
    PairDecision want{c.kind, c.depth, c.angle, t.line, false, said};
    auto [it, fresh] = decided.emplace(pair_of(circles[nearest->circles.front()].diameter, circles[nearest_ring->circle].diameter), want);
    if (!fresh && it->second.kind != c.kind) it->second.conflict = true;
  }
  std::size_t conflicts = 0;
  std::uint32_t first_conflict = 0;
  for (Group& g : groups) {
    for (Ring& ring : g.rings) {
      if (ring.kind != FeatureKind::Undecided) continue;
      auto it = decided.find(pair_of(circles[g.circles.front()].diameter, circles[ring.circle].diameter));
      if (it == decided.end()) continue;
      if (it->second.conflict) {
        if (conflicts++ == 0) first_conflict = it->second.line;
        continue;
      }
      ring.kind = it->second.kind;
      ring.depth_mm = it->second.depth_mm;
      ring.angle_deg = it->second.angle_deg;
      ring.evidence = "callout \"" + it->second.text + "\", line " + std::to_string(it->second.line);
    }
  }
  if (conflicts > 0) {
    r.warnings.push_back({first_conflict, "callouts name both a counterbore and a countersink for the same diameters: " +
                                              std::to_string(conflicts) + " larger circle(s) left undecided"});
  }

  // 5. One hole and one feature a group, in file order.
  std::map<double, std::size_t> undecided;  // by diameter
  r.holes.reserve(circles.size());
  r.features.reserve(circles.size());
  const Group single{};
  for (std::size_t first = 0; first < circles.size(); ++first) {
    if (root[first] != first) continue;  // its group's hole comes where the group's first circle does
    auto grouped = group_at.find(first);
    const Group& g = grouped == group_at.end() ? single : groups[grouped->second];
    const std::size_t i = g.circles.empty() ? first : g.circles.front();
    const aco::Hole& hole = circles[i];
    HoleFeature f;
    f.center = hole.center;
    f.diameter_mm = hole.diameter;
    f.drill_mm = g.thread ? g.thread->tap_drill_mm : hole.diameter;
    f.layer = hole.layer;
    f.line = hole.source_line;
    f.inch = inch;
    const Ring* decided_ring = nullptr;
    for (const Ring& ring : g.rings) {
      if (ring.kind == FeatureKind::Undecided) f.undecided_mm.push_back(circles[ring.circle].diameter);
      else if (decided_ring == nullptr) decided_ring = &ring;
    }
    const std::string at = g.circles.size() > 1 || g.thread ? " at X" + mm(hole.center.x) + " Y" + mm(hole.center.y) : "";
    if (g.thread) {
      f.kind = FeatureKind::Tapped;
      f.thread = g.thread->name;
      f.pitch_mm = g.thread->pitch_mm;
      f.outer_diameter_mm = g.thread->major_mm;
      f.evidence = g.thread_evidence;
    }
    if (decided_ring != nullptr) {
      const double d = circles[decided_ring->circle].diameter;
      const bool bore = decided_ring->kind == FeatureKind::Counterbore;
      if (!g.thread) {
        f.kind = decided_ring->kind;
        f.outer_diameter_mm = d;
        f.depth_mm = decided_ring->depth_mm;
        f.angle_deg = decided_ring->angle_deg;
        f.evidence = decided_ring->evidence;
      } else {
        f.evidence += "; " + std::string(bore ? "counterbore" : "countersink") + " D" + gcode::format_short(d) + " by " + decided_ring->evidence;
      }
    }
    // A process table's rule decides first: its counterbore or countersink
    // is the larger circle of its diameter (the step's, else the smallest
    // undecided one, else the one the drawing decided).
    const Ring* by_rule = nullptr;
    if (processes != nullptr) {
      // Rules select by the kind as drawn: a plain hole with larger circles nothing decided is undecided.
      const FeatureKind drawn = f.kind == FeatureKind::Plain && !f.undecided_mm.empty() ? FeatureKind::Undecided : f.kind;
      f.rule = matching_rule(*processes, f, to_string(drawn));
      const ProcessRule* rule = f.rule ? &processes->rules[f.rule - 1] : nullptr;
      const ProcessStep* bore = rule ? step_of(*rule, gcode::Operation::Counterbore) : nullptr;
      const ProcessStep* sink = rule ? step_of(*rule, gcode::Operation::Countersink) : nullptr;
      const ProcessStep* step = bore ? bore : sink;
      if (step != nullptr && !g.rings.empty()) {
        for (const Ring& ring : g.rings) {
          const double d = circles[ring.circle].diameter;
          if (step->diameter_mm ? same_diameter(d, *step->diameter_mm) : ring.kind == FeatureKind::Undecided) {
            by_rule = &ring;
            break;
          }
        }
        if (by_rule == nullptr && !step->diameter_mm) by_rule = decided_ring;
      }
      if (by_rule != nullptr && !g.thread) {
        f.kind = bore ? FeatureKind::Counterbore : FeatureKind::Countersink;
        f.outer_diameter_mm = circles[by_rule->circle].diameter;
        f.depth_mm = by_rule == decided_ring ? f.depth_mm : 0.0;
        f.angle_deg = by_rule == decided_ring ? f.angle_deg : 0.0;
        f.evidence = rule->where;
        const double d = circles[by_rule->circle].diameter;
        f.undecided_mm.erase(std::remove(f.undecided_mm.begin(), f.undecided_mm.end(), d), f.undecided_mm.end());
      } else if (rule != nullptr) {
        f.evidence += (f.evidence.empty() ? "" : "; ") + rule->where;
      }
    }
    for (const Ring& ring : g.rings) {
      if (ring.kind != FeatureKind::Undecided || &ring == by_rule) continue;
      const double d = circles[ring.circle].diameter;
      ++undecided[d];
      r.not_made.push_back({circles[ring.circle].source_line,
                            "circle D" + gcode::format_short(d) + " around the hole D" + gcode::format_short(hole.diameter) + at +
                                ", counterbore or countersink undecided"});
    }
    if (f.kind == FeatureKind::Plain && !f.undecided_mm.empty()) {
      f.kind = FeatureKind::Undecided;
      f.outer_diameter_mm = f.undecided_mm.front();
      f.evidence = "concentric circle(s), nothing says which" + (f.evidence.empty() ? "" : "; " + f.evidence);
    }
    aco::Hole drilled = hole;
    drilled.diameter = f.drill_mm;
    r.holes.push_back(std::move(drilled));
    r.features.push_back(std::move(f));
  }

  if (!undecided.empty()) {
    std::string listing;
    std::size_t total = 0;
    for (const auto& [d, n] : undecided) listing += (listing.empty() ? "D" : ", D") + gcode::format_short(d) + " x" + std::to_string(n), total += n;
    r.warnings.push_back({0, std::to_string(total) + " circle(s) around a smaller hole (" + listing +
                                 ") not machined: a counterbore or a countersink? a layer named CBORE or CSK, or a hole "
                                 "callout, says which; --concentric separate drills every circle through"});
  }
  return r;
}

HoleFeature listed_feature(aco::Hole& hole, const ListedFeature& given, bool inch, const ProcessTable* processes,
                           const std::string& path) {
  const std::uint32_t no = hole.source_line;
  HoleFeature f;
  f.center = hole.center;
  f.diameter_mm = f.drill_mm = hole.diameter;
  f.layer = hole.layer;
  f.line = no;
  f.inch = inch;
  f.evidence = "listed";
  if (given.counterbore_mm < 0 || given.counterbore_depth_mm < 0 || given.countersink_mm < 0 || given.countersink_angle_deg < 0 ||
      given.countersink_angle_deg >= 180) {
    throw InputError(path, no, "a counterbore's or countersink's size must be positive (an angle below 180)");
  }
  const double bore = given.counterbore_mm, sink = given.countersink_mm;
  if (!given.thread.empty()) {
    const Thread* t = find_thread(given.thread);
    if (t == nullptr) {
      throw InputError(path, no, "thread \"" + given.thread + "\" is no standard thread (ISO metric coarse or fine: M6, M10x1.25; UNC, UNF: 1/4-20 UNC)");
    }
    if (bore > 0 || sink > 0) throw InputError(path, no, "a tapped hole is not counterbored or countersunk here");
    f.kind = FeatureKind::Tapped;
    f.thread = t->name;
    f.pitch_mm = t->pitch_mm;
    f.outer_diameter_mm = t->major_mm;
    f.drill_mm = hole.diameter = t->tap_drill_mm;
  } else if (bore > 0 && sink > 0) {
    throw InputError(path, no, "a hole is counterbored or countersunk, not both");
  } else if (bore > 0 || sink > 0) {
    f.kind = bore > 0 ? FeatureKind::Counterbore : FeatureKind::Countersink;
    f.outer_diameter_mm = bore > 0 ? bore : sink;
    f.depth_mm = bore > 0 ? given.counterbore_depth_mm : 0.0;
    f.angle_deg = sink > 0 ? given.countersink_angle_deg : 0.0;
    if (!(f.outer_diameter_mm > hole.diameter)) {
      throw InputError(path, no, std::string(bore > 0 ? "counterbore" : "countersink") + " D" + gcode::format_short(f.outer_diameter_mm) +
                                     " is no larger than its hole D" + gcode::format_short(hole.diameter));
    }
  }
  if (processes != nullptr) f.rule = matching_rule(*processes, f, to_string(f.kind));
  return f;
}

std::string features_summary(const std::vector<HoleFeature>& features) {
  std::map<std::string, std::size_t> threads;
  std::size_t tapped = 0, bores = 0, sinks = 0, undecided = 0;
  for (const HoleFeature& f : features) {
    if (f.kind == FeatureKind::Tapped) ++tapped, ++threads[f.thread];
    else if (f.kind == FeatureKind::Counterbore) ++bores;
    else if (f.kind == FeatureKind::Countersink) ++sinks;
    else if (f.kind == FeatureKind::Undecided) ++undecided;
  }
  std::string s;
  auto add = [&](std::size_t n, const std::string& what) {
    if (n > 0) s += (s.empty() ? "" : ", ") + std::to_string(n) + " " + what;
  };
  std::string names;
  for (const auto& kv : threads) names += (names.empty() ? "" : ", ") + kv.first;
  add(tapped, "tapped (" + names + ")");
  add(bores, "counterbored");
  add(sinks, "countersunk");
  add(undecided, "undecided");
  return s;
}

}  // namespace formats
