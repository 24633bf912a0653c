// The chooser: which reader a file's bytes are for, then the filters and the
// duplicate removal every format shares.
#include "formats/holes.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "aco/hole_set.h"
#include "formats/archive.h"
#include "formats/readers.h"
#include "gcode/program.h"
#include "text.h"

namespace formats {

namespace {

// What acodrill reads, for the messages that say a file is none of it.
constexpr const char* kFormatsRead =
    "acodrill reads DXF, Excellon, Gerber, IPC-2581, ODB++, another CAM's G-code drilling program, an XML hole map, CSV "
    "and TSPLIB";

// Files people open by mistake, known by their first bytes: named, with what to do.
void refuse_known_binary(const std::string& path, std::string_view data) {
  struct Kind {
    std::string_view magic;
    const char* what;
  };
  static const Kind kinds[] = {
      {"\x89PNG\r\n\x1A\n", "a PNG image"},
      {"\xFF\xD8\xFF", "a JPEG image"},
      {"GIF87a", "a GIF image"},
      {"GIF89a", "a GIF image"},
      {"%PDF-", "a PDF document"},
      {"AC10", "an AutoCAD DWG drawing (save it as DXF)"},
      {"\xD0\xCF\x11\xE0\xA1\xB1\x1A\xE1", "an OLE compound file (an old Office document or a SolidWorks part)"},
      {"\x7F" "ELF", "a program (ELF)"},
      {"Rar!\x1A\x07", "a RAR archive (unpack it; acodrill reads zip and tar archives of ODB++ and IPC-2581)"},
      {"7z\xBC\xAF\x27\x1C", "a 7-Zip archive (unpack it; acodrill reads zip and tar archives of ODB++ and IPC-2581)"},
      {"ISO-10303-21;", "a STEP model (export the holes from CAD as DXF)"},
  };
  for (const Kind& k : kinds) {
    if (data.substr(0, k.magic.size()) == k.magic) {
      throw InputError(path, 0, std::string(k.what) + ", not a hole file: " + kFormatsRead);
    }
  }
  if (data.size() > 64 && data.substr(0, 2) == "MZ" && data.substr(0, 64).find('\0') != std::string_view::npos) {
    throw InputError(path, 0, std::string("a Windows program, not a hole file: ") + kFormatsRead);
  }
}

void check_text(const std::string& path, std::string_view data) {
  if (data.empty()) throw InputError(path, 0, "empty file: no holes");
  std::string_view head = data.substr(0, 4096);
  if (head.find('\0') != std::string_view::npos) {
    bool utf16 = head.size() >= 2 && (head[0] == '\0' || head[1] == '\0' ||
                                      static_cast<unsigned char>(head[0]) == 0xFF ||
                                      static_cast<unsigned char>(head[0]) == 0xFE);
    throw InputError(path, 1, utf16 ? "UTF-16 text is not supported; save the file as ASCII or UTF-8"
                                   : std::string("binary data, not a hole file: ") + kFormatsRead);
  }
}

void filter(LoadedHoles& out, const InputOptions& options) {
  aco::HoleSet kept;
  kept.reserve(out.holes.size());
  for (aco::Hole& h : out.holes) {
    if (!dxf::selected(h, options.dxf)) {
      ++out.skipped_by_filter;
      continue;
    }
    kept.push_back(std::move(h));
  }
  out.holes = std::move(kept);
  if (out.program) {
    // A program drills what it drills: a position drilled twice stays twice
    // (plan keeps every hole as the program makes it); it is only counted,
    // within each work offset (program_holes' layer "T1 G55").
    std::map<std::string, aco::HoleSet> by_offset;
    for (const aco::Hole& h : out.holes) {
      const std::size_t space = h.layer.find(' ');
      by_offset[space == std::string::npos ? std::string() : h.layer.substr(space)].push_back(h);
    }
    out.drilled_again = 0;
    for (auto& [offset, holes] : by_offset) out.drilled_again += aco::remove_duplicate_holes(holes);
    return;
  }
  out.duplicates_removed += aco::remove_duplicate_holes(out.holes);
}

}  // namespace

std::vector<aco::Point2> slot_holes(const Slot& slot, double pitch_mm) {
  const double length = aco::euclidean(slot.from, slot.to);
  const double pitch = pitch_mm > 0 ? pitch_mm : slot.width_mm / 4;
  if (!(length > 1e-9) || !(pitch > 0)) return {slot.from};
  const auto intervals = static_cast<std::size_t>(std::min(1e6, std::ceil(length / pitch - 1e-9)));
  auto at = [&](std::size_t i) {
    const double t = static_cast<double>(i) / static_cast<double>(intervals);
    return aco::Point2{slot.from.x + t * (slot.to.x - slot.from.x), slot.from.y + t * (slot.to.y - slot.from.y)};
  };
  std::vector<aco::Point2> out{at(0), at(intervals)};
  // Breadth-first bisection: each new hole lies midway between two drilled ones.
  std::vector<std::pair<std::size_t, std::size_t>> level{{0, intervals}}, next;
  while (!level.empty()) {
    next.clear();
    for (auto [lo, hi] : level) {
      if (hi - lo < 2) continue;
      const std::size_t mid = lo + (hi - lo) / 2;
      out.push_back(at(mid));
      next.push_back({lo, mid});
      next.push_back({mid, hi});
    }
    level.swap(next);
  }
  return out;
}

void apply_slot_policy(LoadedHoles& loaded, const SlotOptions& options, const std::string& path, const dxf::ReadOptions& limit) {
  const std::size_t max_holes = limit.max_holes;
  if (loaded.slots.empty()) return;
  std::uint32_t chain = 0;
  for (const aco::Hole& h : loaded.holes) chain = std::max(chain, h.chain);
  for (const Slot& slot : loaded.slots) {
    if (options.policy == SlotPolicy::Skip) {
      auto mm = [](double v) { return gcode::format_number(v, 3); };
      // No parentheses: the text goes into G-code comments as it is.
      loaded.skipped.push_back({slot.source_line, "slot " + mm(slot.width_mm) + " mm wide from X" + mm(slot.from.x) + " Y" +
                                                      mm(slot.from.y) + " to X" + mm(slot.to.x) + " Y" + mm(slot.to.y) +
                                                      " mm, --slots skip"});
      continue;
    }
    ++chain;
    // A hole of the slot's width, one of its chain.
    auto add = [&](aco::Point2 p, bool slot_end) {
      aco::Hole h;
      h.center = p;
      h.diameter = slot.width_mm;
      h.layer = slot.layer;
      h.source_line = slot.source_line;
      h.chain = chain;
      h.slot_end = slot_end;
      loaded.holes.push_back(std::move(h));
    };
    if (options.policy == SlotPolicy::Mill && aco::euclidean(slot.from, slot.to) > 1e-6) {
      // Its two ends, in order: the plan mills the slot between them.
      ++loaded.slots_milled;
      add(slot.from, true);
      add(slot.to, true);
      continue;
    }
    ++loaded.slots_drilled;
    // Count before making them: a long slot at a fine pitch must not exhaust memory.
    const double pitch = options.pitch_mm > 0 ? options.pitch_mm : slot.width_mm / 4;
    const double count = pitch > 0 ? aco::euclidean(slot.from, slot.to) / pitch + 1 : 1;
    if (!(count <= static_cast<double>(max_holes - std::min(max_holes, loaded.holes.size())))) {
      throw InputError(path, slot.source_line, "drilling the slots makes more than " + std::to_string(max_holes) +
                                                   " holes (" + limit.max_holes_named + "); a coarser --slot-pitch or --slots skip");
    }
    for (aco::Point2 p : slot_holes(slot, options.pitch_mm)) {
      add(p, false);
      ++loaded.slot_holes;
    }
  }
}

const char* to_string(InputFormat f) {
  switch (f) {
    case InputFormat::Dxf: return "dxf";
    case InputFormat::Excellon: return "excellon";
    case InputFormat::Gerber: return "gerber";
    case InputFormat::XmlMap: return "xml";
    case InputFormat::Csv: return "csv";
    case InputFormat::Tsplib: return "tsplib";
    case InputFormat::Program: return "g-code program";
    case InputFormat::Ipc2581: return "ipc-2581";
    case InputFormat::Odb: return "odb++";
  }
  return "?";
}

namespace {

// The format the file's content shows, if any.
std::optional<InputFormat> format_by_content(std::string_view data) {
  if (dxf::looks_like_dxf(data.substr(0, 65536))) return InputFormat::Dxf;
  // An archive (an ODB++ job, or KiCad's zipped IPC-2581): what is inside decides, in parse_sources.
  if (archive_kind(data) != ArchiveKind::None) return InputFormat::Odb;
  std::string_view head = trim(data.substr(0, 4096));
  if (head.substr(0, 3) == "\xEF\xBB\xBF") head = trim(head.substr(3));  // a UTF-8 byte order mark (Windows tools write one)
  if (!head.empty() && head.front() == '<') return looks_like_ipc2581(head) ? InputFormat::Ipc2581 : InputFormat::XmlMap;
  if (gcode::looks_like_gcode(data.substr(0, 65536))) return InputFormat::Program;
  if (looks_like_gerber(data.substr(0, 65536))) return InputFormat::Gerber;
  if (looks_like_excellon(data.substr(0, 65536))) return InputFormat::Excellon;
  // TSPLIB: a "NAME" / "TYPE" / "DIMENSION" keyword header.
  for (const char* key : {"NAME", "TYPE", "DIMENSION", "COMMENT", "EDGE_WEIGHT_TYPE"}) {
    if (head.rfind(key, 0) == 0) return InputFormat::Tsplib;
  }
  return std::nullopt;
}

// The format a file's name says (CSV when it says none).
InputFormat format_by_name(const std::string& path) {
  const std::string ext = lower_ext(path);
  if (ext == "dxf") return InputFormat::Dxf;
  if (ext == "tsp") return InputFormat::Tsplib;
  if (ext == "xml") return InputFormat::XmlMap;
  if (ext == "gbr" || ext == "ger" || ext == "pho" || ext == "gtl") return InputFormat::Gerber;
  if (ext == "drl" || ext == "drd" || ext == "xln" || ext == "exc" || ext == "ncd") return InputFormat::Excellon;
  return InputFormat::Csv;
}

}  // namespace

InputFormat detect_format(const std::string& path, std::string_view data) {
  if (const auto by_content = format_by_content(data)) return *by_content;
  return format_by_name(path);
}

namespace {

// A board job's sources (IPC-2581, ODB++), each with the slot policy and the
// filters applied; sources the filters leave empty are dropped (one stays).
std::vector<LoadedHoles> board_sources(const std::string& path, std::string_view data, const InputOptions& options) {
  const std::string shown = path == "-" ? "<stdin>" : path;
  std::vector<LoadedHoles> sources;
  if (archive_kind(data) == ArchiveKind::None) {
    sources = parse_ipc2581(shown, data, options);
  } else {
    const std::vector<ArchiveEntry> entries = unpack_archive(shown, data);
    const bool odb = std::any_of(entries.begin(), entries.end(), [](const ArchiveEntry& e) {
      const std::string p = e.path.size() >= 13 ? e.path.substr(e.path.size() - 13) : e.path;
      return p == "matrix/matrix" || p == "MATRIX/MATRIX";
    });
    std::vector<const ArchiveEntry*> ipc;
    for (const ArchiveEntry& e : entries) {
      if (looks_like_ipc2581(trim(std::string_view(e.bytes).substr(0, 4096)))) ipc.push_back(&e);
    }
    if (odb || ipc.size() != 1) {
      if (!odb) {
        std::string names;
        for (std::size_t k = 0; k < entries.size() && k < 5; ++k) names += (k ? ", " : "") + entries[k].path;
        if (entries.size() > 5) names += ", ...";
        throw InputError(shown, 0, "an archive with neither an ODB++ job (no matrix/matrix) nor one IPC-2581 file" +
                                       (entries.empty() ? std::string(" (it is empty)") : "; it holds " + names));
      }
      sources = parse_odb(shown, entries, options);
    } else {
      sources = parse_ipc2581(shown + ":" + ipc.front()->path, ipc.front()->bytes, options);
    }
  }
  for (LoadedHoles& s : sources) {
    // Numbers too large for the board (1e308 mm, or turned into infinity by a unit): refused where they are written.
    auto finite = [](aco::Point2 p) { return std::isfinite(p.x) && std::isfinite(p.y); };
    for (const aco::Hole& h : s.holes) {
      if (!finite(h.center) || !std::isfinite(h.diameter)) throw InputError(shown, h.source_line, "a hole's numbers are too large to be a board's");
    }
    for (const Slot& slot : s.slots) {
      if (!finite(slot.from) || !finite(slot.to) || !std::isfinite(slot.width_mm)) {
        throw InputError(shown, slot.source_line, "a slot's numbers are too large to be a board's");
      }
    }
    apply_slot_policy(s, options.slots, shown, options.dxf);
    filter(s, options);
    s.name = stem(path);
  }
  // A source the filters emptied is dropped (one stays); its counts, and what
  // the file says as a whole (the first source's), go to the first kept.
  std::vector<bool> keep(sources.size());
  for (std::size_t k = 0; k < sources.size(); ++k) keep[k] = !sources[k].holes.empty() || !sources[k].skipped.empty();
  if (std::find(keep.begin(), keep.end(), true) == keep.end()) keep[0] = true;
  std::vector<LoadedHoles> kept;
  for (std::size_t k = 0; k < sources.size(); ++k) {
    if (keep[k]) kept.push_back(std::move(sources[k]));
  }
  for (std::size_t k = 0; k < sources.size(); ++k) {
    if (keep[k]) continue;
    LoadedHoles& s = sources[k];
    LoadedHoles& to = kept.front();
    to.skipped_by_filter += s.skipped_by_filter;
    to.duplicates_removed += s.duplicates_removed;
    if (!s.description.empty()) to.description = std::move(s.description);
    to.warnings.insert(to.warnings.begin(), s.warnings.begin(), s.warnings.end());
  }
  if (kept.size() == 1) kept.front().source_label.clear();
  return kept;
}

}  // namespace

std::vector<LoadedHoles> parse_sources(const std::string& path, std::string_view data, const InputOptions& options) {
  const InputFormat format = data.empty() ? InputFormat::Csv : detect_format(path, data);
  if (format != InputFormat::Ipc2581 && format != InputFormat::Odb) return {parse_holes(path, data, options)};
  return board_sources(path, data, options);
}

namespace {

// Other CAMs' machine files that are not G-code (issue 83: FreeCAD's opensbp,
// rml and heidenhain posts): named in one line, not read as CSV.
void refuse_other_machine_files(const std::string& path, std::string_view data) {
  std::uint32_t line_no = 0;
  std::string_view first;
  for_each_line(data.substr(0, 65536), [&](std::uint32_t no, std::string_view line) {
    line = trim(line);
    if (line.empty()) return true;
    line_no = no;
    first = line;
    return false;
  });
  auto starts = [&](std::string_view p) { return first.substr(0, p.size()) == p; };
  // OpenSBP: ' comments and two-letter commands with commas ("JZ,16.0", "MX,10").
  static const char* const kSbpCommands[] = {"JZ,", "J2,", "J3,", "JX,", "JY,", "JS,", "MZ,", "M2,", "M3,", "MX,", "MY,", "MS,", "VS,", "TR,", "SA,", "SR,", "SO,"};
  const bool sbp_command = std::any_of(std::begin(kSbpCommands), std::end(kSbpCommands), [&](const char* c) { return first.substr(0, 3) == c; });
  if (starts("'") || sbp_command) throw InputError(path, line_no, "an OpenSBP (ShopBot) part file, not G-code; post the job for a G-code control");
  // Roland RML-1: HP-GL-like instructions ended by ';' ("PA;", ";IN;", "!MC1;").
  if (starts("PA;") || starts(";IN;") || starts("IN;") || starts("!MC")) {
    throw InputError(path, line_no, "a Roland RML file, not G-code; post the job for a G-code control");
  }
  if (starts("BEGIN PGM") || (first.size() > 2 && std::isdigit(static_cast<unsigned char>(first[0])) &&
                              first.find(" BEGIN PGM ") != std::string_view::npos)) {
    throw InputError(path, line_no, "HEIDENHAIN conversational (Klartext), not G-code; post the job for a G-code control");
  }
}

LoadedHoles parse_holes_as(InputFormat format, const std::string& path, const std::string& shown, std::string_view data,
                           const InputOptions& options) {
  LoadedHoles out;
  switch (format) {
    case InputFormat::Ipc2581:
    case InputFormat::Odb: {
      // One list of every source's holes (`acodrill holes`); plan reads them apart (parse_sources).
      std::vector<LoadedHoles> sources = board_sources(path, data, options);
      out = std::move(sources.front());
      std::uint32_t chain_base = 0;
      for (const aco::Hole& h : out.holes) chain_base = std::max(chain_base, h.chain);
      for (std::size_t k = 1; k < sources.size(); ++k) {
        LoadedHoles& s = sources[k];
        std::uint32_t top = chain_base;
        for (aco::Hole& h : s.holes) {
          if (h.chain != 0) h.chain += chain_base;
          top = std::max(top, h.chain);
          out.holes.push_back(std::move(h));
        }
        chain_base = top;
        out.slots.insert(out.slots.end(), s.slots.begin(), s.slots.end());
        out.skipped.insert(out.skipped.end(), s.skipped.begin(), s.skipped.end());
        out.warnings.insert(out.warnings.end(), s.warnings.begin(), s.warnings.end());
        out.duplicates_removed += s.duplicates_removed;
        out.skipped_by_filter += s.skipped_by_filter;
        out.slots_drilled += s.slots_drilled;
        out.slots_milled += s.slots_milled;
        out.slot_holes += s.slot_holes;
      }
      if (sources.size() > 1) out.drill_function.clear();  // plated and non-plated together: no one function
      out.source_label.clear();
      return out;
    }
    case InputFormat::Dxf: {
      dxf::ReadOptions o = options.dxf;
      o.default_unit_mm = options.default_unit_mm;
      try {
        dxf::ReadResult r = dxf::read_holes(data, o);
        out.format = InputFormat::Dxf;
        out.holes = std::move(r.holes);
        for (const auto& d : r.diagnostics) out.warnings.push_back({d.line, d.message});
        if (!options.concentric_separate) {
          RecognizedFeatures f = recognize_features(out.holes, r.arcs, r.texts, r.unit_mm, options.processes.get());
          out.holes = std::move(f.holes);
          out.features = std::move(f.features);
          for (const FeatureNote& n : f.warnings) out.feature_warnings.push_back({n.line, n.message});
          for (const FeatureNote& n : f.not_made) out.skipped.push_back({n.line, n.message});
        }
        out.duplicates_removed = r.duplicates_removed;
        out.skipped_by_filter = r.skipped_by_filter;
        out.round_contours = r.round_contours;
        out.round_contour_holes = r.round_contour_holes;
        out.round_contour_kinds = r.round_contour_kinds;
      } catch (const dxf::ReadError& e) {
        throw InputError(shown, e.line(), e.what());
      }
      out.name = stem(path);
      return out;
    }
    case InputFormat::Excellon:
      out = parse_excellon(shown, data, options);
      break;
    case InputFormat::Gerber:
      out = parse_gerber(shown, data, options);
      break;
    case InputFormat::XmlMap:
      check_text(shown, data);
      out = parse_xml_map(shown, data, options);
      break;
    case InputFormat::Tsplib:
      check_text(shown, data);
      out = parse_tsplib(shown, data);
      break;
    case InputFormat::Csv:  // (nothing in it shows a format: parse_holes refused other machines' files)
      check_text(shown, data);
      out = parse_csv(shown, data, options);
      break;
    case InputFormat::Program:
      check_text(shown, data);
      refuse_other_machine_files(shown, data);
      out = parse_program(shown, data, options.keep_milling);
      break;
  }
  apply_slot_policy(out, options.slots, shown, options.dxf);
  filter(out, options);
  if (path != "-") out.name = out.format == InputFormat::Tsplib ? out.name : stem(path);
  return out;
}

// The number of the first line with something on it.
std::uint32_t first_code_line(std::string_view data) {
  std::uint32_t first = 0;
  for_each_line(data.substr(0, 65536), [&](std::uint32_t no, std::string_view line) {
    if (trim(line).empty()) return true;
    first = no;
    return false;
  });
  return first;
}

}  // namespace

LoadedHoles parse_holes(const std::string& path, std::string_view data, const InputOptions& options) {
  const std::string shown = path == "-" ? "<stdin>" : path;
  if (data.empty()) throw InputError(shown, 0, "empty file: no holes");
  refuse_known_binary(shown, data);
  // Taken for Excellon or CSV by its name alone (nothing in it looked like
  // any format): a file that fails at once is most likely none of them.
  if (const auto by_content = format_by_content(data)) return parse_holes_as(*by_content, path, shown, data, options);
  refuse_other_machine_files(shown, data);
  const InputFormat by_name = format_by_name(path);
  if (lower_ext(path) != "csv") {
    try {
      return parse_holes_as(by_name, path, shown, data, options);
    } catch (const InputError& e) {
      if (e.line() == 0 || e.line() > first_code_line(data)) throw;
      throw InputError(e.file(), e.line(), std::string(e.what()) + ": not a hole file acodrill recognises (" + kFormatsRead + ")");
    }
  }
  return parse_holes_as(by_name, path, shown, data, options);
}

}  // namespace formats
