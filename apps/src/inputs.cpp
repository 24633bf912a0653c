#include "app/inputs.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "app/errors.h"
#include "app/files.h"
#include "formats/archive.h"

namespace app {

namespace {

// An ODB++ job folder (issue 86), as the tar of the files its reader opens:
// the matrix, and each step's header, outline and layers' features.
std::string read_odb_folder(const std::string& path) {
  const std::filesystem::path root = fs_path(path);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(root / "matrix" / "matrix", ec)) {
    throw UserError(path, 0, "is a directory, not an ODB++ job folder (it has no matrix/matrix)");
  }
  std::vector<formats::ArchiveEntry> entries;
  for (auto it = std::filesystem::recursive_directory_iterator(root, ec); !ec && it != std::filesystem::recursive_directory_iterator();
       it.increment(ec)) {
    if (!it->is_regular_file(ec)) continue;
    const std::string rel = it->path().lexically_relative(root).generic_u8string();
    const std::string name = it->path().filename().u8string();
    const bool wanted = rel == "matrix/matrix" ||
                        (rel.rfind("steps/", 0) == 0 && (name == "stephdr" || name == "profile" || name.rfind("features", 0) == 0));
    if (wanted) entries.push_back({rel, read_file(it->path().u8string())});
  }
  if (ec) throw UserError(path, 0, "cannot read the folder: " + ec.message());
  // The archive's order is the folder's listing's, which the system chooses: sorted, the same everywhere.
  std::sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) { return a.path < b.path; });
  return formats::pack_tar(entries);
}

}  // namespace

job::InputFile read_input_file(const std::string& path) {
  std::error_code dir_ec;
  if (path != "-" && std::filesystem::is_directory(fs_path(path), dir_ec)) return {path, read_odb_folder(path), {}};
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
