// A process table (--processes, issue 82) from arbitrary bytes: refused with
// one InputError, or read and matched against features of every kind.
#include "formats/error.h"
#include "formats/features.h"
#include "fuzz_targets.h"
#include "planning/operations.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string input(ACO_FUZZ_INPUT(data, size));
  try {
    const formats::ProcessTable table = planning::parse_process_table(input, "fuzz");
    for (const char* kind : {"plain", "tapped", "counterbore", "countersink", "undecided"}) {
      formats::HoleFeature f;
      f.diameter_mm = f.drill_mm = 6.6;
      f.layer = "DOWEL";
      f.thread = "M6";
      const std::uint32_t rule = formats::matching_rule(table, f, kind);
      if (rule > table.rules.size()) __builtin_trap();
      if (rule != 0 && formats::step_of(table.rules[rule - 1], gcode::Operation::Drill) == nullptr) __builtin_trap();
    }
  } catch (const formats::InputError&) {
  }
  return 0;
}
