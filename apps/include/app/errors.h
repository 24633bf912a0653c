#pragma once
// What the command line reports: an input or usage error (exit 2) with the
// file and line it concerns, printed as `acodrill: error: FILE:LINE: what`.
// The readers in formats/ throw the same type.
#include "formats/error.h"

namespace app {

using UserError = formats::InputError;

}  // namespace app
