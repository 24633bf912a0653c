#include "app/errors.h"
#include "formats/holes.h"
#include "formats/readers.h"
#include "fuzz_targets.h"

// The Gerber reader, then the slot policy on what it found (a slot's holes are
// made from untrusted sizes too).
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input = ACO_FUZZ_INPUT(data, size);
  formats::InputOptions options;
  options.dxf.max_holes = 100000;
  try {
    formats::LoadedHoles loaded = formats::parse_gerber("fuzz", input, options);
    formats::apply_slot_policy(loaded, options.slots, "fuzz", options.dxf);
  } catch (const app::UserError&) {
  }
  return 0;
}
