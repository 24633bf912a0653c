#include "app/excellon.h"

#include "app/errors.h"

namespace app {

bool looks_like_excellon(std::string_view head) {
  return head.rfind("M48", 0) == 0 || head.find("\nM48") != std::string_view::npos;
}

LoadedHoles parse_excellon(const std::string& path, std::string_view, const InputOptions&) {
  throw UserError(path, 1, "Excellon input is not supported by this build yet");
}

}  // namespace app
