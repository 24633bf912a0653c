// CSV hole lists: x,y[,diameter[,layer]] rows, header optional; a header
// may name feature columns (issue 82): thread, counterbore_mm,
// counterbore_depth_mm, countersink_mm, countersink_angle_deg.
#include <algorithm>
#include <cctype>
#include <cmath>

#include "formats/features.h"
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
  // Feature columns by the header's names (npos: not there).
  enum Column { Thread, Counterbore, CounterboreDepth, Countersink, CountersinkAngle, Columns };
  static const char* const kColumnNames[Columns] = {"thread", "counterbore_mm", "counterbore_depth_mm", "countersink_mm",
                                                    "countersink_angle_deg"};
  std::size_t column[Columns];
  std::fill(std::begin(column), std::end(column), std::string_view::npos);
  bool any_feature_column = false;
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
        for (std::size_t c = 0; c < cells.size(); ++c) {
          std::string name(cells[c]);
          std::transform(name.begin(), name.end(), name.begin(), [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
          for (int k = 0; k < Columns; ++k) {
            if (name == kColumnNames[k]) column[k] = c, any_feature_column = true;
          }
        }
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
    if (any_feature_column) {
      // The row's feature: a thread taps it (drilled at its tap drill), a
      // counterbore or countersink diameter makes one; none, a plain hole.
      auto cell = [&](int k) { return column[k] < cells.size() ? cells[column[k]] : std::string_view(); };
      auto number = [&](int k) {
        double v = 0.0;
        if (cell(k).empty()) return 0.0;
        if (!parse_number(cell(k), v) || !(v > 0)) {
          throw InputError(path, no, std::string(kColumnNames[k]) + " \"" + std::string(cell(k)) + "\" is not a positive number");
        }
        return v;
      };
      ListedFeature given;
      given.thread = std::string(cell(Thread));
      given.counterbore_mm = number(Counterbore) * unit;
      given.counterbore_depth_mm = number(CounterboreDepth) * unit;
      given.countersink_mm = number(Countersink) * unit;
      given.countersink_angle_deg = number(CountersinkAngle);
      HoleFeature f = listed_feature(h, given, unit == 25.4, options.processes.get(), path);
      out.features.push_back(std::move(f));
    }
    out.holes.push_back(std::move(h));
    check_limit(path, no, out.holes.size(), options.dxf);
    return true;
  });
  return out;
}

}  // namespace formats
