#include "dxf/reader.h"
#include "formats/features.h"
#include "fuzz_targets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  dxf::ReadOptions options;
  options.max_holes = 100000;  // keep every run fast; the limit itself is under test
  options.max_block_references = 200000;
  options.round_contours = true;  // issue 71: contours read as holes, not only counted
  try {
    const dxf::ReadResult r = dxf::read_holes(ACO_FUZZ_INPUT(data, size), options);
    // Issue 82: the holes' features from the same circles, arcs and callouts.
    formats::recognize_features(r.holes, r.arcs, r.texts, r.unit_mm);
  } catch (const dxf::ReadError&) {
  }
  return 0;
}
