#pragma once
/**
 * Every input format acodrill reads, chosen by content (the extension only
 * breaks ties): DXF, Excellon, the thesis's XML hole map, CSV and TSPLIB.
 * Each reader returns holes in mm; errors are UserError with file and line.
 */
#include <optional>
#include <string>
#include <vector>

#include "aco/geometry.h"
#include "dxf/reader.h"

namespace app {

enum class InputFormat { Dxf, Excellon, XmlMap, Csv, Tsplib };
const char* to_string(InputFormat f);

struct InputOptions {
  dxf::ReadOptions dxf;        // layer and diameter filters, limits, default unit
  double default_unit_mm = 1.0;  // --input-units, for files that do not say
  bool input_units_given = false;
};

struct Note {
  std::uint32_t line = 0;
  std::string message;
};

struct LoadedHoles {
  aco::HoleSet holes;
  InputFormat format = InputFormat::Csv;
  std::vector<Note> warnings;
  std::size_t duplicates_removed = 0;
  std::size_t skipped_by_filter = 0;
  std::string name;  // TSPLIB NAME or the file's stem
  std::optional<bool> metric;  // the units the file itself is written in, where it says (Excellon)
};

InputFormat detect_format(const std::string& path, std::string_view data);

LoadedHoles load_holes(const std::string& path, const InputOptions& options);
LoadedHoles parse_holes(const std::string& path, std::string_view data, const InputOptions& options);

// The individual readers, for tests and the fuzzers.
LoadedHoles parse_csv(const std::string& path, std::string_view data, const InputOptions& options);
LoadedHoles parse_tsplib(const std::string& path, std::string_view data);
LoadedHoles parse_xml_map(const std::string& path, std::string_view data, const InputOptions& options);

}  // namespace app
