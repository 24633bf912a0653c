#include "fuzz_targets.h"
#include "gcode/interpreter.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    gcode::interpret(ACO_FUZZ_INPUT(data, size));
  } catch (const gcode::ProgramError&) {
  }
  return 0;
}
