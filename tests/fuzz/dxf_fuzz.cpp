#include "dxf/reader.h"
#include "fuzz_targets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  dxf::ReadOptions options;
  options.max_holes = 100000;  // keep every run fast; the limit itself is under test
  options.max_block_references = 200000;
  options.round_contours = true;  // issue 71: contours read as holes, not only counted
  try {
    dxf::read_holes(ACO_FUZZ_INPUT(data, size), options);
  } catch (const dxf::ReadError&) {
  }
  return 0;
}
