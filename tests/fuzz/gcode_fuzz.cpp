// The readings of a program (verify's lenient one, plan's drilling-only one, with its milling kept)
// and, for what reads as drilling, both writers: the reordered program must
// read back to as many holes as the input has. A mismatch aborts (a finding).
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>
#include <stdexcept>

#include "fuzz_targets.h"
#include "gcode/drilling.h"
#include "gcode/interpreter.h"

namespace {

// The program written with `s`, in its own units and precision.
std::string written(const gcode::DrillingProgram& p, gcode::DrillingWriteSettings s) {
  s.inch = p.inch;
  s.decimals = p.decimals;
  std::ostringstream out;
  gcode::write_drilling(out, p, s);
  return out.str();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text = ACO_FUZZ_INPUT(data, size);
  try {
    gcode::interpret(text);
  } catch (const gcode::ProgramError&) {
  }
  try {
    const gcode::DrillingProgram p = gcode::read_drilling(text);
    for (bool keep : {false, true}) {
      gcode::DrillingWriteSettings s;
      s.keep_style = keep;
      const gcode::DrillingProgram back = gcode::read_drilling(written(p, s));
      if (!keep && back.hole_count() != p.hole_count()) std::abort();
    }
    // GRBL and Marlin: canned cycles written out as moves read back to the same holes.
    for (gcode::Dialect d : {gcode::Dialect::Grbl, gcode::Dialect::Marlin}) {
      gcode::DrillingWriteSettings s;
      s.dialect = d;
      s.travel_feed_mm_min = 5000;
      std::string out;
      try {
        out = written(p, s);
      } catch (const std::invalid_argument&) {
        continue;  // a travel plane at or below the part: refused, not written
      }
      const gcode::DrillingProgram back = gcode::read_drilling(out);
      if (back.hole_count() != p.hole_count()) std::abort();
    }
  } catch (const gcode::ProgramError&) {
  }
  // A program that also mills (plan --keep-milling): in its own style every
  // line that milled is still there, as written (a program the writer leaves
  // without line numbers: renumbering rewrites every line). Whether a line
  // after a rewritten stretch reads as a cut can change with the new order
  // (a G1 in X/Y is travel at the height the last hole's feed began), so
  // the reading back is not compared.
  try {
    gcode::ReadOptions keeping;
    keeping.keep_milling = true;
    const gcode::DrillingProgram p = gcode::read_drilling(text, keeping);
    gcode::DrillingWriteSettings s;
    s.keep_style = true;
    const std::string out = written(p, s);
    gcode::read_drilling(out, keeping);
    if (!p.uses_line_numbers) {
      std::vector<std::string_view> lines;
      for (std::size_t at = 0; at <= text.size();) {
        std::size_t nl = text.find('\n', at);
        if (nl == std::string_view::npos) nl = text.size();
        lines.push_back(text.substr(at, nl - at));
        at = nl + 1;
      }
      for (std::uint32_t line : p.milling_lines) {
        std::string_view raw = lines.at(line - 1);
        if (!raw.empty() && raw.back() == '\r') raw.remove_suffix(1);
        if (line == 1 && raw.substr(0, 3) == "\xEF\xBB\xBF") raw.remove_prefix(3);  // (a byte-order mark the writer drops)
        if (out.find(raw) == std::string::npos) std::abort();
      }
    }
  } catch (const gcode::ProgramError&) {
  }
  return 0;
}
