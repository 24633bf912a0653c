#include "job/inputs.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>

#include "formats/error.h"

namespace job {

formats::LoadedHoles read_input(const InputFile& file, const formats::InputOptions& options) {
  if (file.nc_param.empty() || !options.nc_param.empty()) return formats::parse_holes(file.name, file.bytes, options);
  formats::InputOptions with = options;
  with.nc_param = file.nc_param;
  return formats::parse_holes(file.name, file.bytes, with);
}

namespace {

// A file's drill sources: one, or (IPC-2581, ODB++) its plated and
// non-plated holes and blind spans apart, each named "FILE (plated)".
std::vector<std::pair<std::string, formats::LoadedHoles>> read_sources(const InputFile& file, const formats::InputOptions& options) {
  formats::InputOptions with = options;
  if (!file.nc_param.empty() && options.nc_param.empty()) with.nc_param = file.nc_param;
  std::vector<std::pair<std::string, formats::LoadedHoles>> out;
  for (formats::LoadedHoles& part : formats::parse_sources(file.name, file.bytes, with)) {
    const std::string shown = file.name == "-" ? "<stdin>" : file.name;
    const std::string name = part.source_label.empty() ? file.name : shown + " (" + part.source_label + ")";
    out.emplace_back(name, std::move(part));
  }
  return out;
}

}  // namespace

Inputs read_inputs(const std::vector<InputFile>& files, const formats::InputOptions& options) {
  Inputs job;
  std::vector<std::pair<std::string, formats::LoadedHoles>> read;
  std::vector<bool> first_of_file;  // per source: the first of its file (the job's name has each file once)
  for (const InputFile& file : files) {
    bool first = true;
    for (auto& source : read_sources(file, options)) {
      first_of_file.push_back(first);
      first = false;
      read.push_back(std::move(source));
    }
  }
  if (read.size() == 1) {
    job.holes = std::move(read.front().second);
    job.sources.push_back({read.front().first, job.holes.holes.size()});
    job.hole_source.assign(job.holes.holes.size(), 0);
    formats::LoadedHoles summary = job.holes;
    summary.holes.clear();
    job.parts.push_back(std::move(summary));
    // The file's own feature warnings are its part's; the job's (issue 82: what
    // it makes of the features) are added to the whole, each said once.
    job.holes.feature_warnings.clear();
    return job;
  }
  formats::LoadedHoles& all = job.holes;
  std::vector<std::string> stems;
  std::uint32_t chain_base = 0;  // the highest slot chain number of the files before
  for (std::size_t k = 0; k < read.size(); ++k) {
    formats::LoadedHoles& part = read[k].second;
    const std::string& name = read[k].first;
    const std::string shown = name == "-" ? "<stdin>" : name;
    if (part.program) {
      throw formats::InputError(shown, 0, "a drilling program is reordered on its own; give it without other inputs");
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
    for (const formats::Note& n : part.skipped) all.skipped.push_back({n.line, shown + ": " + n.message});
    all.features.insert(all.features.end(), part.features.begin(), part.features.end());
    for (const formats::Note& n : part.warnings) all.warnings.push_back({n.line, shown + ": " + n.message});
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
    job.sources.push_back({name, part.holes.size()});
    if (first_of_file[k]) stems.push_back(part.name);
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

}  // namespace job
