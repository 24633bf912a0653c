// The readings of a program (verify's lenient one, plan's drilling-only one, with its milling kept)
// and, for what reads as drilling, both writers: the reordered program must
// read back to as many holes as the input has. A mismatch aborts (a finding).
#include <cstdlib>
#include <sstream>
#include <string>
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
  // A program that also mills (plan --keep-milling): in its own style, read
  // back the same way, every line that milled is still there.
  try {
    gcode::ReadOptions keeping;
    keeping.keep_milling = true;
    const gcode::DrillingProgram p = gcode::read_drilling(text, keeping);
    gcode::DrillingWriteSettings s;
    s.keep_style = true;
    const gcode::DrillingProgram back = gcode::read_drilling(written(p, s), keeping);
    if (!p.milling_lines.empty() && back.milling_lines.size() != p.milling_lines.size()) std::abort();
  } catch (const gcode::ProgramError&) {
  }
  return 0;
}
