// TSPLIB .tsp instances (EUC_2D, CEIL_2D, ATT): one node a hole, diameter 0; for benchmarks.
#include <algorithm>
#include <cmath>

#include "formats/readers.h"
#include "text.h"

namespace formats {

aco::Metric tsplib_metric(const LoadedHoles& loaded) {
  if (loaded.edge_weight_type == "CEIL_2D") return aco::Metric::TsplibCeil2d;
  if (loaded.edge_weight_type == "ATT") return aco::Metric::TsplibAtt;
  return aco::Metric::TsplibEuc2d;
}

LoadedHoles parse_tsplib(const std::string& path, std::string_view data) {
  LoadedHoles out;
  out.format = InputFormat::Tsplib;
  out.name = stem(path);
  bool in_coords = false;
  long long dimension = -1;
  for_each_line(data, [&](std::uint32_t no, std::string_view line) {
    std::string_view t = trim(line);
    if (t.empty()) return true;
    if (t == "EOF") return false;
    if (!in_coords) {
      if (t == "NODE_COORD_SECTION") {
        in_coords = true;
        return true;
      }
      auto colon = t.find(':');
      std::string_view key = trim(t.substr(0, colon));
      std::string_view value = colon == std::string_view::npos ? std::string_view{} : trim(t.substr(colon + 1));
      if (key == "NAME") out.name = std::string(value);
      else if (key == "DIMENSION") {
        double d;
        if (!parse_number(value, d) || d < 0) throw InputError(path, no, "DIMENSION is not a count");
        dimension = static_cast<long long>(d);
      } else if (key == "EDGE_WEIGHT_TYPE") {
        if (value != "EUC_2D" && value != "CEIL_2D" && value != "ATT") {
          throw InputError(path, no, "EDGE_WEIGHT_TYPE " + std::string(value) + " is not supported (EUC_2D, CEIL_2D, ATT)");
        }
        out.edge_weight_type = std::string(value);
      } else if (key == "TYPE" && value != "TSP") {
        throw InputError(path, no, "TYPE " + std::string(value) + " is not supported (TSP only)");
      } else if (colon == std::string_view::npos && key != "NODE_COORD_SECTION") {
        throw InputError(path, no, "unexpected line \"" + std::string(t.substr(0, 40)) + "\" in the TSPLIB header");
      }
      return true;
    }
    // "index x y"
    double v[3];
    std::size_t pos = 0;
    for (int i = 0; i < 3; ++i) {
      while (pos < t.size() && std::isspace(static_cast<unsigned char>(t[pos]))) ++pos;
      std::size_t end = pos;
      while (end < t.size() && !std::isspace(static_cast<unsigned char>(t[end]))) ++end;
      if (!parse_number(t.substr(pos, end - pos), v[i])) {
        throw InputError(path, no, "expected \"index x y\", found \"" + std::string(t.substr(0, 60)) + "\"");
      }
      pos = end;
    }
    aco::Hole h;
    h.center = {v[1], v[2]};
    h.source_line = no;
    out.holes.push_back(h);
    if (dimension >= 0 && static_cast<long long>(out.holes.size()) > dimension) {
      throw InputError(path, no, "more nodes than DIMENSION " + std::to_string(dimension));
    }
    return true;
  });
  if (!in_coords) throw InputError(path, 0, "no NODE_COORD_SECTION");
  if (dimension >= 0 && static_cast<long long>(out.holes.size()) != dimension) {
    throw InputError(path, 0, "DIMENSION is " + std::to_string(dimension) + " but " + std::to_string(out.holes.size()) +
                                 " nodes are listed");
  }
  return out;
}

}  // namespace formats
