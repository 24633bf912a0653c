// The chooser: which reader a file's bytes are for, then the filters and the
// duplicate removal every format shares.
#include "formats/holes.h"

#include <algorithm>

#include "aco/hole_set.h"
#include "formats/readers.h"
#include "text.h"

namespace formats {

namespace {

void check_text(const std::string& path, std::string_view data) {
  if (data.empty()) throw InputError(path, 0, "empty file: no holes");
  std::string_view head = data.substr(0, 4096);
  if (head.find('\0') != std::string_view::npos) {
    bool utf16 = head.size() >= 2 && (head[0] == '\0' || head[1] == '\0' ||
                                      static_cast<unsigned char>(head[0]) == 0xFF ||
                                      static_cast<unsigned char>(head[0]) == 0xFE);
    throw InputError(path, 1, utf16 ? "UTF-16 text is not supported; save the file as ASCII or UTF-8"
                                   : "binary data: not a hole file acodrill reads (DXF, Excellon, XML, CSV, TSPLIB)");
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
  out.duplicates_removed += aco::remove_duplicate_holes(out.holes);
}

}  // namespace

const char* to_string(InputFormat f) {
  switch (f) {
    case InputFormat::Dxf: return "dxf";
    case InputFormat::Excellon: return "excellon";
    case InputFormat::XmlMap: return "xml";
    case InputFormat::Csv: return "csv";
    case InputFormat::Tsplib: return "tsplib";
  }
  return "?";
}

InputFormat detect_format(const std::string& path, std::string_view data) {
  if (dxf::looks_like_dxf(data.substr(0, 65536))) return InputFormat::Dxf;
  std::string_view head = trim(data.substr(0, 4096));
  if (!head.empty() && head.front() == '<') return InputFormat::XmlMap;
  if (looks_like_excellon(data.substr(0, 65536))) return InputFormat::Excellon;
  // TSPLIB: a "NAME" / "TYPE" / "DIMENSION" keyword header.
  for (const char* key : {"NAME", "TYPE", "DIMENSION", "COMMENT", "EDGE_WEIGHT_TYPE"}) {
    if (head.rfind(key, 0) == 0) return InputFormat::Tsplib;
  }
  const std::string ext = lower_ext(path);
  if (ext == "dxf") return InputFormat::Dxf;
  if (ext == "tsp") return InputFormat::Tsplib;
  if (ext == "xml") return InputFormat::XmlMap;
  if (ext == "drl" || ext == "drd" || ext == "xln" || ext == "exc" || ext == "ncd") return InputFormat::Excellon;
  return InputFormat::Csv;
}

LoadedHoles parse_holes(const std::string& path, std::string_view data, const InputOptions& options) {
  const std::string shown = path == "-" ? "<stdin>" : path;
  if (data.empty()) throw InputError(shown, 0, "empty file: no holes");
  LoadedHoles out;
  switch (detect_format(path, data)) {
    case InputFormat::Dxf: {
      dxf::ReadOptions o = options.dxf;
      o.default_unit_mm = options.default_unit_mm;
      try {
        dxf::ReadResult r = dxf::read_holes(data, o);
        out.format = InputFormat::Dxf;
        out.holes = std::move(r.holes);
        out.duplicates_removed = r.duplicates_removed;
        out.skipped_by_filter = r.skipped_by_filter;
        for (const auto& d : r.diagnostics) out.warnings.push_back({d.line, d.message});
      } catch (const dxf::ReadError& e) {
        throw InputError(shown, e.line(), e.what());
      }
      out.name = stem(path);
      return out;
    }
    case InputFormat::Excellon:
      out = parse_excellon(shown, data, options);
      break;
    case InputFormat::XmlMap:
      check_text(shown, data);
      out = parse_xml_map(shown, data, options);
      break;
    case InputFormat::Tsplib:
      check_text(shown, data);
      out = parse_tsplib(shown, data);
      break;
    case InputFormat::Csv:
      check_text(shown, data);
      out = parse_csv(shown, data, options);
      break;
  }
  filter(out, options);
  if (path != "-") out.name = out.format == InputFormat::Tsplib ? out.name : stem(path);
  return out;
}

}  // namespace formats
