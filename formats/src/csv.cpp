// CSV hole lists: x,y[,diameter[,layer]] rows, header optional.
#include <algorithm>
#include <cmath>

#include "formats/readers.h"
#include "text.h"

namespace formats {

LoadedHoles parse_csv(const std::string& path, std::string_view data, const InputOptions& options) {
  LoadedHoles out;
  out.format = InputFormat::Csv;
  out.name = stem(path);
  const double unit = options.default_unit_mm;
  bool first_data = true;
  std::size_t header_fields = 0;  // 0: no header
  for_each_line(data, [&](std::uint32_t no, std::string_view line) {
    std::string_view t = trim(line);
    if (t.empty() || t.front() == '#') return true;
    std::vector<std::string_view> cells;
    std::size_t start = 0;
    const char sep = t.find(',') != std::string_view::npos ? ',' : (t.find(';') != std::string_view::npos ? ';' : '\t');
    for (;;) {
      std::size_t comma = t.find(sep, start);
      cells.push_back(trim(t.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start)));
      if (comma == std::string_view::npos) break;
      start = comma + 1;
    }
    double x = 0, y = 0, d = 0.0;
    const bool x_ok = parse_number(cells[0], x);
    const bool y_ok = cells.size() >= 2 && parse_number(cells[1], y);
    if (!x_ok || !y_ok) {
      // A header is a first line whose first two cells are both words, not numbers.
      if (first_data && out.holes.empty() && !x_ok && cells.size() >= 2 && !parse_number(cells[1], y)) {
        first_data = false;
        header_fields = cells.size();
        return true;
      }
      throw InputError(path, no, "expected x,y[,diameter[,layer]] numbers, found \"" + std::string(t.substr(0, 60)) + "\"");
    }
    first_data = false;
    // A row shorter than its header has lost a field (most often the diameter).
    if (cells.size() < header_fields) {
      throw InputError(path, no, "the row has " + std::to_string(cells.size()) + " fields but the header names " +
                                     std::to_string(header_fields));
    }
    if (cells.size() >= 3 && !cells[2].empty() && !parse_number(cells[2], d)) {
      throw InputError(path, no, "diameter \"" + std::string(cells[2]) + "\" is not a number");
    }
    if (d < 0.0) throw InputError(path, no, "negative diameter " + std::string(cells[2]));
    aco::Hole h;
    h.center = {x * unit, y * unit};
    h.diameter = d * unit;
    if (cells.size() >= 4) h.layer = std::string(cells[3]);
    h.source_line = no;
    out.holes.push_back(std::move(h));
    check_limit(path, no, out.holes.size(), options.dxf.max_holes);
    return true;
  });
  return out;
}

}  // namespace formats
