#pragma once
/**
 * Every input format acodrill reads, in one place and one shape: a file's
 * bytes → records carrying their line numbers → holes in mm (diameter, layer
 * or tool, source line), with the reader's warnings. The format is chosen by
 * content; the extension only breaks ties. Errors are formats::InputError
 * with file and line.
 *
 * **Example**:
 *   formats::LoadedHoles in = formats::parse_holes("board.drl", bytes, {});
 *   for (const aco::Hole& h : in.holes) use(h.center, h.diameter);
 */
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "aco/geometry.h"
#include "dxf/reader.h"

namespace formats {

enum class InputFormat { Dxf, Excellon, XmlMap, Csv, Tsplib };
const char* to_string(InputFormat f);

struct InputOptions {
  dxf::ReadOptions dxf;          // layer and diameter filters, limits, default unit
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
  std::string name;            // TSPLIB NAME or the file's stem
  std::optional<bool> metric;  // the units the file itself is written in, where it says (Excellon)
};

InputFormat detect_format(const std::string& path, std::string_view data);

// Chooses the reader by content, reads, applies the layer and diameter
// filters and drops exact duplicates. `path` names the file in messages ("-": standard input).
LoadedHoles parse_holes(const std::string& path, std::string_view data, const InputOptions& options);

}  // namespace formats
