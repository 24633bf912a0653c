#include "app/inputs.h"

#include "app/files.h"

namespace app {

LoadedHoles load_holes(const std::string& path, const InputOptions& options) {
  return formats::parse_holes(path, read_file(path), options);
}

}  // namespace app
