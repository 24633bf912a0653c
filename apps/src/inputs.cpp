#include "app/inputs.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "app/errors.h"
#include "app/files.h"

namespace app {

job::InputFile read_input_file(const std::string& path) {
  job::InputFile file{path, read_file(path), {}};
  // Allegro writes its drill files' number format only in nc_param.txt beside them.
  const std::filesystem::path nc_param = fs_path(path).parent_path() / "nc_param.txt";
  std::error_code ec;
  if (path != "-" && std::filesystem::is_regular_file(nc_param, ec)) file.nc_param = read_file(nc_param.u8string());
  return file;
}

LoadedHoles load_holes(const std::string& path, const InputOptions& options) {
  return job::read_input(read_input_file(path), options);
}

std::vector<std::string> distinct_inputs(const std::vector<std::string>& paths, std::vector<std::string>& repeated) {
  std::vector<std::string> kept;
  for (const std::string& p : paths) {
    const bool again = std::any_of(kept.begin(), kept.end(), [&](const std::string& k) { return k == p || same_file(k, p); });
    if (again) repeated.push_back(p);
    else kept.push_back(p);
  }
  return kept;
}

Job load_job(const std::vector<std::string>& paths, const InputOptions& options) {
  std::vector<job::InputFile> files;
  for (const std::string& p : paths) files.push_back(read_input_file(p));
  return job::read_inputs(files, options);
}

}  // namespace app
