// Issue 86: IPC-2581 (XML) as the chooser reads it: its drill sources.
#include "app/errors.h"
#include "app/inputs.h"
#include "formats/holes.h"
#include "fuzz_targets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input = ACO_FUZZ_INPUT(data, size);
  app::InputOptions options;
  options.dxf.max_holes = 100000;
  try {
    formats::parse_sources("fuzz.xml", input, options);
  } catch (const app::UserError&) {
  }
  return 0;
}
