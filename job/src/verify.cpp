#include "job/verify.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <tuple>

#include "gcode/program.h"

namespace job {

namespace {

// Whether a tool of `tool_mm` (milling a helix of path radius `milled_r`, or 0) makes a hole of `hole_mm`.
bool makes(double tool_mm, double milled_r, double hole_mm, const planning::Tooling& tooling, std::uint32_t operation) {
  constexpr double kSame = 0.0015;  // a diameter printed with 3 decimals
  // A tap, a countersink, a counterbore (issue 82): the tool of the operation's
  // own diameter, or a counterbore milled by the end mill's helix to it.
  if (operation != 0) {
    return milled_r == 0 ? std::fabs(tool_mm - hole_mm) <= kSame : std::fabs(2.0 * milled_r + tool_mm - hole_mm) <= kMilledToleranceMm;
  }
  const bool end_mill = tooling.end_mill_mm && std::fabs(tool_mm - *tooling.end_mill_mm) <= kSame;
  if (milled_r > 0) {
    return (!tooling.end_mill_mm || end_mill) && std::fabs(2.0 * milled_r + tool_mm - hole_mm) <= kMilledToleranceMm;
  }
  if (end_mill && std::fabs(tool_mm - hole_mm) <= kMilledToleranceMm) return true;  // plunged: the end mill's size
  if (tooling.drills.empty()) return std::fabs(tool_mm - hole_mm) <= kSame;
  return std::any_of(tooling.drills.begin(), tooling.drills.end(), [&](const planning::OwnedDrill& o) {
    return std::fabs(o.diameter_mm - tool_mm) <= kSame && o.fits(hole_mm);
  });
}

// Positions bucketed on a grid for near-linear matching: (cell, index)
// pairs sorted once, each cell's found by binary search. A std::multimap
// cost a tenth of plan's whole run on 10^5 holes (a node a hole).
class CellIndex {
 public:
  using Cell = std::pair<long long, long long>;
  void add(Cell c, std::size_t i) { entries_.push_back({c, i}); }
  void seal() { std::sort(entries_.begin(), entries_.end()); }
  template <class F>
  void each_in(Cell c, F&& f) const {
    auto it = std::lower_bound(entries_.begin(), entries_.end(), std::make_pair(c, std::size_t{0}));
    for (; it != entries_.end() && it->first == c; ++it) f(it->second);
  }
  // Where the 3 x 3 cells about each of `cells` begin in the sorted entries,
  // a column's three cells lying together: for all the cells at once, by
  // one sweep in their own order, instead of three binary searches a cell
  // (at 10^6 holes those were most of the page's self-check, issue 84).
  using Around = std::array<std::size_t, 3>;
  std::vector<Around> around(const std::vector<Cell>& cells) const {
    std::vector<std::size_t> order(cells.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return cells[a] < cells[b]; });
    std::vector<Around> out(cells.size());
    for (long long dx = -1; dx <= 1; ++dx) {
      std::size_t at = 0;  // (cx + dx, cy - 1) only grows with (cx, cy)
      for (std::size_t k : order) {
        const Cell from{cells[k].first + dx, cells[k].second - 1};
        while (at < entries_.size() && entries_[at].first < from) ++at;
        out[k][static_cast<std::size_t>(dx + 1)] = at;
      }
    }
    return out;
  }
  // Every entry in the 3 x 3 cells about c, from where around() found them.
  template <class F>
  void each_around(Cell c, const Around& from, F&& f) const {
    for (long long dx = -1; dx <= 1; ++dx) {
      const long long column = c.first + dx;
      for (std::size_t i = from[static_cast<std::size_t>(dx + 1)];
           i < entries_.size() && entries_[i].first.first == column && entries_[i].first.second <= c.second + 1; ++i) {
        f(entries_[i].second);
      }
    }
  }

 private:
  std::vector<std::pair<Cell, std::size_t>> entries_;
};

}  // namespace

std::vector<std::string> check_drilled(const gcode::Interpretation& run, const aco::HoleSet& expected,
                                       const planning::Tooling& tooling,
                                       const std::vector<planning::OperationSpec>& operations) {
  // Each input hole must be drilled exactly once, at its place (within the
  // program's printed precision), by a tool of its diameter.
  const double tol = run.inch ? 0.00006 * 25.4 + 1e-6 : 0.0006 + 1e-6;
  std::vector<char> used(run.holes.size(), 0);
  // Bucket drilled positions on a grid of the tolerance for near-linear matching.
  CellIndex grid;
  auto cell = [&](double x, double y) { return std::make_pair(std::llround(x / (2 * tol)), std::llround(y / (2 * tol))); };
  for (std::size_t i = 0; i < run.holes.size(); ++i) grid.add(cell(run.holes[i].x_mm, run.holes[i].y_mm), i);
  grid.seal();
  std::vector<std::string> faults;
  std::map<std::pair<long long, std::uint32_t>, int> tool_of_diameter;  // (diameter µm, operation) → tool
  // Issue 82: where each hole feature's operations are made (program hole
  // index, by the expected hole), to check their order at each place.
  std::vector<std::size_t> made_by(expected.size(), run.holes.size());
  // (Reused from hole to hole, and the place written only for a fault: at
  // 10^6 holes this check is part of every plan's outputs, in the page too.)
  std::vector<std::size_t> matches, same_tool;
  std::vector<CellIndex::Cell> cells;
  cells.reserve(expected.size());
  for (const aco::Hole& h : expected) cells.push_back(cell(h.center.x, h.center.y));
  const std::vector<CellIndex::Around> around = grid.around(cells);
  for (const aco::Hole& h : expected) {
    matches.clear();
    const std::size_t k = static_cast<std::size_t>(&h - expected.data());
    grid.each_around(cells[k], around[k], [&](std::size_t i) {
      const auto& d = run.holes[i];
      if (std::fabs(d.x_mm - h.center.x) <= tol && std::fabs(d.y_mm - h.center.y) <= tol) matches.push_back(i);
    });
    const auto at_text = [&] { return "(" + gcode::format_number(h.center.x, 3) + ", " + gcode::format_number(h.center.y, 3) + ")"; };
    if (matches.empty()) {
      const std::string at = at_text();
      faults.push_back("hole " + at + " D" + gcode::format_number(h.diameter, 3) + " is not drilled");
      continue;
    }
    // Concentric holes share a position: the one that drills this hole is the
    // one whose tool has its diameter, where the program names its tools.
    same_tool.clear();
    for (std::size_t m : matches) {
      auto known = run.tool_diameter_mm.find(run.holes[m].tool);
      if (known == run.tool_diameter_mm.end() || h.diameter <= 0 ||
          makes(known->second, run.holes[m].milled_radius_mm, h.diameter, tooling, h.operation)) {
        same_tool.push_back(m);
      }
    }
    if (same_tool.empty()) {
      const std::string at = at_text();
      const auto& d = run.holes[matches.front()];
      faults.push_back("hole " + at + " D" + gcode::format_number(h.diameter, 3) + " is " +
                       (d.milled_radius_mm > 0 ? "milled to D" + gcode::format_number(2 * d.milled_radius_mm + run.tool_diameter_mm.at(d.tool), 3) + " with T"
                                               : std::string("drilled with T")) +
                       std::to_string(d.tool) + " D" + gcode::format_number(run.tool_diameter_mm.at(d.tool), 3) +
                       " (line " + std::to_string(d.line) + ")");
      for (std::size_t m : matches) used[m] = 1;
      continue;
    }
    // One drilled hole for one input hole: input holes closer than the
    // printed precision (distinct in the input, one place in the program)
    // each take one; a drilled hole left over is a hole drilled again.
    auto free = std::find_if(same_tool.begin(), same_tool.end(), [&](std::size_t m) { return !used[m]; });
    if (free == same_tool.end()) {
      faults.push_back("hole " + at_text() + " D" + gcode::format_number(h.diameter, 3) + " is not drilled (line " +
                       std::to_string(run.holes[same_tool.front()].line) + " drills the hole beside it)");
      continue;
    }
    used[*free] = 1;
    made_by[static_cast<std::size_t>(&h - expected.data())] = *free;
    const auto& d = run.holes[*free];
    if (h.operation != 0 && h.operation <= operations.size()) {
      const planning::OperationSpec& spec = operations[h.operation - 1];
      if (spec.kind == gcode::Operation::Tap && spec.pitch_mm > 0 && d.pitch_mm &&
          std::fabs(*d.pitch_mm - spec.pitch_mm) > 0.01 * spec.pitch_mm) {
        faults.push_back("hole " + at_text() + ": the tap (line " + std::to_string(d.line) + ") runs at " + gcode::format_short(*d.pitch_mm, 4) +
                         " mm a turn where the " + (spec.thread.empty() ? std::string("thread") : spec.thread) + "'s pitch is " +
                         gcode::format_short(spec.pitch_mm, 4) + " mm");
      }
    }
    const auto key = std::make_pair(std::llround(h.diameter * 1000.0), h.operation);
    auto [it, inserted] = tool_of_diameter.try_emplace(key, d.tool);  // (no node made when it is there)
    // Two tools for one diameter: sister tools (a worn drill replaced) when
    // the program names both with that diameter; otherwise a fault.
    const bool sisters = run.tool_diameter_mm.count(it->second) && run.tool_diameter_mm.count(d.tool);
    if (!inserted && it->second != d.tool && !sisters) {
      faults.push_back("holes of D" + gcode::format_number(h.diameter, 3) + " are drilled with T" +
                       std::to_string(it->second) + " and T" + std::to_string(d.tool));
    }
  }
  if (!operations.empty()) {
    // A feature's operations share its hole's place exactly: by place, each
    // in its kind's turn (a countersink and a counterbore share theirs).
    auto kind_of = [&](const aco::Hole& h) {
      return h.operation == 0 || h.operation > operations.size() ? gcode::Operation::Drill : operations[h.operation - 1].kind;
    };
    auto turn = [](gcode::Operation k) { return k == gcode::Operation::Counterbore ? static_cast<int>(gcode::Operation::Countersink) : static_cast<int>(k); };
    std::map<std::pair<double, double>, std::vector<std::size_t>> at_place;
    for (std::size_t k = 0; k < expected.size(); ++k) {
      if (made_by[k] < run.holes.size()) at_place[{expected[k].center.x, expected[k].center.y}].push_back(k);
    }
    for (auto& [place, ks] : at_place) {
      if (ks.size() < 2) continue;
      std::sort(ks.begin(), ks.end(), [&](std::size_t a, std::size_t b) { return made_by[a] < made_by[b]; });
      for (std::size_t q = 1; q < ks.size(); ++q) {
        const aco::Hole& before = expected[ks[q - 1]];
        const aco::Hole& after = expected[ks[q]];
        if (turn(kind_of(before)) <= turn(kind_of(after))) continue;
        const std::string at = "(" + gcode::format_number(place.first, 3) + ", " + gcode::format_number(place.second, 3) + ")";
        faults.push_back("hole " + at + ": the " + gcode::to_string(kind_of(before)) + " (line " +
                         std::to_string(run.holes[made_by[ks[q - 1]]].line) + ") comes before the " +
                         gcode::to_string(kind_of(after)) + " (line " + std::to_string(run.holes[made_by[ks[q]]].line) + ")");
      }
    }
  }
  CellIndex expected_grid;
  if (std::count(used.begin(), used.end(), 0) > 0) {
    for (std::size_t k = 0; k < expected.size(); ++k) expected_grid.add(cell(expected[k].center.x, expected[k].center.y), k);
    expected_grid.seal();
  }
  for (std::size_t i = 0; i < run.holes.size(); ++i) {
    if (used[i]) continue;
    const auto& d = run.holes[i];
    const std::string at = "(" + gcode::format_number(d.x_mm, 3) + ", " + gcode::format_number(d.y_mm, 3) + ")";
    bool again = false;
    const auto [cx, cy] = cell(d.x_mm, d.y_mm);
    for (long long dx = -1; dx <= 1 && !again; ++dx) {
      for (long long dy = -1; dy <= 1 && !again; ++dy) {
        expected_grid.each_in({cx + dx, cy + dy}, [&](std::size_t k) {
          const aco::Point2 c = expected[k].center;
          again = again || (std::fabs(d.x_mm - c.x) <= tol && std::fabs(d.y_mm - c.y) <= tol);
        });
      }
    }
    faults.push_back(again ? "hole " + at + " is drilled again (line " + std::to_string(run.holes[i].line) + ")"
                           : "line " + std::to_string(run.holes[i].line) + " drills " + at + ", which is not an input hole");
  }
  return faults;
}

std::vector<std::string> check_same_holes(const gcode::Interpretation& run, const gcode::DrillingProgram& expected) {
  // Both programs' printed precision: positions and depths agree within it.
  const double tol = (run.inch || expected.inch ? 0.00006 * 25.4 : 0.0006) + 1e-6;
  struct Key {
    int tool;
    double x, y, z;
    std::uint32_t line;
    int offset;  // the work offset: a second fixture's holes are others at the same X, Y (issue 83)
    std::optional<double> peck, dwell_s;  // a canned cycle's Q; the dwell, canned or expanded (gcode::DrilledHole)
    std::optional<double> pitch;          // a tap's (issue 82): G33.1's K, G84's F over S
  };
  auto key_of = [](const gcode::DrilledHole& h) {
    return Key{h.tool, h.x_mm, h.y_mm, h.bottom_z_mm, h.line, h.work_offset, h.peck_mm, h.dwell_s, h.pitch_mm};
  };
  std::vector<Key> want, got;
  for (const gcode::ToolRun& r : expected.runs) {
    for (const gcode::ProgramHole& h : r.holes) want.push_back(key_of(gcode::drilled_hole(r, h)));
  }
  for (const auto& h : run.holes) got.push_back(key_of(h));
  // Made the same way: the same dwell, canned or expanded, and where both are
  // canned cycles the same peck (issue 83); a tap at the same pitch within 1 % (issue 82).
  auto same_making = [&](const Key& a, const Key& b) {
    return (!a.dwell_s || !b.dwell_s || std::fabs(*a.dwell_s - *b.dwell_s) <= 1e-3) &&
           (!a.peck || !b.peck || std::fabs(*a.peck - *b.peck) <= tol) &&
           (!a.pitch || !b.pitch || std::fabs(*a.pitch - *b.pitch) <= 0.01 * *b.pitch);
  };
  auto order = [](const Key& a, const Key& b) { return std::tie(a.x, a.y, a.tool, a.z) < std::tie(b.x, b.y, b.tool, b.z); };
  std::sort(got.begin(), got.end(), order);
  std::vector<char> used(got.size(), 0);
  std::vector<std::string> faults;
  auto at = [](const Key& k) {
    return "(" + gcode::format_number(k.x, 3) + ", " + gcode::format_number(k.y, 3) + ")";
  };
  for (const Key& w : want) {
    // Candidates: drilled holes within tolerance in X (got is sorted by X).
    auto lo = std::lower_bound(got.begin(), got.end(), w.x - tol, [](const Key& k, double x) { return k.x < x; });
    const Key* near = nullptr;
    std::size_t match = got.size();
    for (auto it = lo; it != got.end() && it->x <= w.x + tol; ++it) {
      const std::size_t i = static_cast<std::size_t>(it - got.begin());
      if (used[i] || std::fabs(it->y - w.y) > tol) continue;
      if (!near) near = &*it;
      if (it->tool == w.tool && std::fabs(it->z - w.z) <= tol && it->offset == w.offset && same_making(*it, w)) {
        match = i;
        break;
      }
    }
    if (match < got.size()) {
      used[match] = 1;
      continue;
    }
    if (!near) {
      faults.push_back("hole " + at(w) + " of line " + std::to_string(w.line) + " is not drilled");
    } else {
      auto in = [](int offset) { return offset == 54 ? std::string() : " in " + gcode::work_offset_text(offset); };
      faults.push_back("hole " + at(w) + in(w.offset) + " of line " + std::to_string(w.line) + " (T" + std::to_string(w.tool) +
                       ", Z" + gcode::format_number(w.z, 3) + ") is drilled with T" + std::to_string(near->tool) + " to Z" +
                       gcode::format_number(near->z, 3) + (near->offset != w.offset ? (in(near->offset).empty() ? " in G54" : in(near->offset)) : "") +
                       (same_making(*near, w) ? std::string()
                                              : ", dwelling " + gcode::format_number(near->dwell_s.value_or(0), 3) + " s" +
                                                    (near->peck ? " with pecks of " + gcode::format_number(*near->peck, 3) : std::string()) +
                                                    " where the input dwells " + gcode::format_number(w.dwell_s.value_or(0), 3) + " s" +
                                                    (w.peck ? " with pecks of " + gcode::format_number(*w.peck, 3) : std::string()) +
                                                    (near->pitch && w.pitch && std::fabs(*near->pitch - *w.pitch) > 0.01 * *w.pitch
                                                         ? "; tapped at " + gcode::format_short(*near->pitch, 4) + " mm a turn where the input taps at " +
                                                               gcode::format_short(*w.pitch, 4)
                                                         : std::string())) +
                       " (line " + std::to_string(near->line) + ")");
      used[static_cast<std::size_t>(near - got.data())] = 1;
    }
  }
  for (std::size_t i = 0; i < got.size(); ++i) {
    if (!used[i]) faults.push_back("line " + std::to_string(got[i].line) + " drills " + at(got[i]) + ", which the input program does not");
  }
  return faults;
}

planning::Tooling tooling_of_table(const planning::ToolTable& table) {
  planning::Tooling t;
  for (const planning::ToolTableEntry& e : table.entries) {
    const double d = e.tool.diameter_mm;
    if (e.tool.end_mill) {
      t.end_mill_mm = d;
      continue;
    }
    // A --tools table gives ranges (takes_mm is the owned-tools plan's, never parsed).
    // fits(hole): d >= hole - minus and d <= hole + plus, for hole in [min, max].
    t.drills.push_back({d, std::max(0.0, e.max_hole_mm - d), std::max(0.0, d - e.min_hole_mm)});
  }
  return t;
}

std::vector<std::string> self_check(const std::string& program_text, const aco::HoleSet& expected,
                                    const planning::Tooling& tooling, const std::vector<planning::OperationSpec>& operations) {
  try {
    return check_drilled(gcode::interpret(program_text), expected, tooling, operations);
  } catch (const gcode::ProgramError& e) {
    return {"the program does not read back: line " + std::to_string(e.line()) + ": " + e.what()};
  }
}

std::vector<std::string> self_check(const std::string& program_text, const gcode::DrillingProgram& input) {
  try {
    // Its milling copied as written: read the same way the input was, plunges no holes.
    return check_same_holes(input.milling_lines.empty() ? gcode::interpret(program_text)
                                                        : gcode::interpret_keeping_milling(program_text),
                            input);
  } catch (const gcode::ProgramError& e) {
    return {"the program does not read back: line " + std::to_string(e.line()) + ": " + e.what()};
  }
}

}  // namespace job
