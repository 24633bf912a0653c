#include "app/inputs.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numeric>
#include <tuple>

#include "app/errors.h"
#include "app/files.h"

namespace app {

LoadedHoles load_holes(const std::string& path, const InputOptions& options) {
  // Allegro writes its drill files' number format only in nc_param.txt beside them.
  const std::filesystem::path nc_param = fs_path(path).parent_path() / "nc_param.txt";
  std::error_code ec;
  if (path != "-" && options.nc_param.empty() && std::filesystem::is_regular_file(nc_param, ec)) {
    InputOptions with = options;
    with.nc_param = read_file(nc_param.u8string());
    return formats::parse_holes(path, read_file(path), with);
  }
  return formats::parse_holes(path, read_file(path), options);
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
  Job job;
  if (paths.size() == 1) {
    job.holes = load_holes(paths[0], options);
    job.sources.push_back({paths[0], job.holes.holes.size()});
    job.hole_source.assign(job.holes.holes.size(), 0);
    LoadedHoles summary = job.holes;
    summary.holes.clear();
    job.parts.push_back(std::move(summary));
    return job;
  }
  LoadedHoles& all = job.holes;
  std::vector<std::string> stems;
  std::uint32_t chain_base = 0;  // the highest slot chain number of the files before
  for (std::size_t k = 0; k < paths.size(); ++k) {
    LoadedHoles part = load_holes(paths[k], options);
    const std::string shown = paths[k] == "-" ? "<stdin>" : paths[k];
    if (part.program) {
      throw UserError(shown, 0, "a drilling program is reordered on its own; give it without other inputs");
    }
    if (k == 0) {
      all.format = part.format;
      all.metric = part.metric;
      all.drill_function = part.drill_function;
    } else if (all.drill_function != part.drill_function) {
      all.drill_function.clear();  // plated and non-plated together: no one function
    }
    // Chains (a drilled slot's holes) stay apart from the other files' chains.
    std::uint32_t top = chain_base;
    for (aco::Hole& h : part.holes) {
      if (h.chain != 0) h.chain += chain_base;
      top = std::max(top, h.chain);
      all.holes.push_back(h);
      job.hole_source.push_back(static_cast<std::uint32_t>(k));
    }
    chain_base = top;
    for (const Note& n : part.skipped) all.skipped.push_back({n.line, shown + ": " + n.message});
    for (const Note& n : part.warnings) all.warnings.push_back({n.line, shown + ": " + n.message});
    for (const std::string& a : part.assumptions) all.assumptions.push_back(shown + ": " + a);
    all.round_contours += part.round_contours;
    all.round_contour_holes += part.round_contour_holes;
    if (!part.round_contour_kinds.empty()) {
      all.round_contour_kinds += (all.round_contour_kinds.empty() ? "" : "; ") + shown + ": " + part.round_contour_kinds;
    }
    all.duplicates_removed += part.duplicates_removed;
    all.skipped_by_filter += part.skipped_by_filter;
    all.slots_drilled += part.slots_drilled;
    all.slots_milled += part.slots_milled;
    all.slot_holes += part.slot_holes;
    job.sources.push_back({paths[k], part.holes.size()});
    stems.push_back(part.name);
    part.holes.clear();
    job.parts.push_back(std::move(part));
  }
  all.name = stems.front();
  for (std::size_t k = 1; k < stems.size(); ++k) all.name += "+" + stems[k];
  // A hole in two files is drilled once: the first file's stays.
  std::vector<std::size_t> idx(all.holes.size());
  std::iota(idx.begin(), idx.end(), 0);
  auto key = [&](std::size_t i) {
    const aco::Hole& h = all.holes[i];
    return std::make_tuple(h.center.x, h.center.y, h.diameter);
  };
  std::stable_sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) { return key(a) < key(b); });
  std::vector<char> drop(all.holes.size(), 0);
  for (std::size_t j = 1; j < idx.size(); ++j) {
    const aco::Hole& a = all.holes[idx[j - 1]];
    const aco::Hole& b = all.holes[idx[j]];
    if (std::fabs(a.center.x - b.center.x) <= 1e-6 && std::fabs(a.center.y - b.center.y) <= 1e-6 &&
        std::fabs(a.diameter - b.diameter) <= 1e-6 && job.hole_source[idx[j - 1]] != job.hole_source[idx[j]]) {
      drop[std::max(idx[j - 1], idx[j])] = 1;
    }
  }
  std::size_t kept = 0;
  for (std::size_t i = 0; i < all.holes.size(); ++i) {
    if (drop[i]) {
      ++all.duplicates_removed;
      continue;
    }
    all.holes[kept] = std::move(all.holes[i]);
    job.hole_source[kept] = job.hole_source[i];
    ++kept;
  }
  all.holes.resize(kept);
  job.hole_source.resize(kept);
  for (auto& s : job.sources) s.holes = 0;
  for (std::uint32_t s : job.hole_source) ++job.sources[s].holes;
  return job;
}

double time_left(double limit_s, double spent_s) {
  if (limit_s <= 0.0) return 0.0;
  return std::max(0.01, limit_s - std::max(0.0, spent_s));
}

}  // namespace app
