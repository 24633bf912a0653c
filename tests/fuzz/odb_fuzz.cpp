// Issue 86: archives (tar, gzip, zip) and the ODB++ jobs in them, as the
// chooser reads them. Its seeds are mostly uncompressed tars, so that the
// fuzzer's changes reach the matrix, step headers and features text.
#include "app/errors.h"
#include "app/inputs.h"
#include "formats/archive.h"
#include "formats/holes.h"
#include "fuzz_targets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input = ACO_FUZZ_INPUT(data, size);
  app::InputOptions options;
  options.dxf.max_holes = 100000;
  try {
    // Little input, little output: a zip bomb is refused, not unpacked.
    formats::unpack_archive("fuzz.tgz", input, std::size_t{64} << 20);
  } catch (const app::UserError&) {
  }
  try {
    formats::parse_sources("fuzz.tgz", input, options);
  } catch (const app::UserError&) {
  }
  return 0;
}
