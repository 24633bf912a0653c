#include "app/inputs.h"

#include <tinyxml2.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>

#include "aco/hole_set.h"
#include "app/errors.h"
#include "app/files.h"
#include "app/excellon.h"
#include "text.h"

namespace app {

namespace {

bool parse_number(std::string_view s, double& out) {
  s = trim(s);
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  if (s.empty()) return false;
  auto r = std::from_chars(s.data(), s.data() + s.size(), out);
  return r.ec == std::errc() && r.ptr == s.data() + s.size() && std::isfinite(out);
}

std::string stem(const std::string& path) {
  std::string base = path.substr(path.find_last_of('/') == std::string::npos ? 0 : path.find_last_of('/') + 1);
  if (auto dot = base.find_last_of('.'); dot != std::string::npos && dot > 0) base.resize(dot);
  return base.empty() || base == "-" ? "stdin" : base;
}

std::string lower_ext(const std::string& path) {
  auto dot = path.find_last_of('.');
  if (dot == std::string::npos) return "";
  std::string e = path.substr(dot + 1);
  for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

// Lines of a text with 1-based numbers.
template <class F>
void for_each_line(std::string_view data, F&& f) {
  std::size_t pos = 0;
  std::uint32_t no = 0;
  while (pos < data.size()) {
    std::size_t nl = data.find('\n', pos);
    if (nl == std::string_view::npos) nl = data.size();
    std::string_view line = data.substr(pos, nl - pos);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    pos = nl + 1;
    if (!f(++no, line)) return;
  }
}

void check_text(const std::string& path, std::string_view data) {
  if (data.empty()) throw UserError(path, 0, "empty file: no holes");
  std::string_view head = data.substr(0, 4096);
  if (head.find('\0') != std::string_view::npos) {
    bool utf16 = head.size() >= 2 && (head[0] == '\0' || head[1] == '\0' ||
                                      static_cast<unsigned char>(head[0]) == 0xFF ||
                                      static_cast<unsigned char>(head[0]) == 0xFE);
    throw UserError(path, 1, utf16 ? "UTF-16 text is not supported; save the file as ASCII or UTF-8"
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

void check_limit(const std::string& path, std::uint32_t line, std::size_t count, const InputOptions& options) {
  if (count > options.dxf.max_holes) {
    throw UserError(path, line, "more than " + std::to_string(options.dxf.max_holes) + " holes (the hole limit, --max-holes)");
  }
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

LoadedHoles parse_csv(const std::string& path, std::string_view data, const InputOptions& options) {
  LoadedHoles out;
  out.format = InputFormat::Csv;
  out.name = stem(path);
  const double unit = options.default_unit_mm;
  bool first_data = true;
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
        return true;
      }
      throw UserError(path, no, "expected x,y[,diameter[,layer]] numbers, found \"" + std::string(t.substr(0, 60)) + "\"");
    }
    first_data = false;
    if (cells.size() >= 3 && !cells[2].empty() && !parse_number(cells[2], d)) {
      throw UserError(path, no, "diameter \"" + std::string(cells[2]) + "\" is not a number");
    }
    if (d < 0.0) throw UserError(path, no, "negative diameter " + std::string(cells[2]));
    aco::Hole h;
    h.center = {x * unit, y * unit};
    h.diameter = d * unit;
    if (cells.size() >= 4) h.layer = std::string(cells[3]);
    h.source_line = no;
    out.holes.push_back(std::move(h));
    check_limit(path, no, out.holes.size(), options);
    return true;
  });
  return out;
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
        if (!parse_number(value, d) || d < 0) throw UserError(path, no, "DIMENSION is not a count");
        dimension = static_cast<long long>(d);
      } else if (key == "EDGE_WEIGHT_TYPE" && value != "EUC_2D" && value != "CEIL_2D" && value != "ATT") {
        throw UserError(path, no, "EDGE_WEIGHT_TYPE " + std::string(value) + " is not supported (EUC_2D only)");
      } else if (key == "TYPE" && value != "TSP") {
        throw UserError(path, no, "TYPE " + std::string(value) + " is not supported (TSP only)");
      } else if (colon == std::string_view::npos && key != "NODE_COORD_SECTION") {
        throw UserError(path, no, "unexpected line \"" + std::string(t.substr(0, 40)) + "\" in the TSPLIB header");
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
        throw UserError(path, no, "expected \"index x y\", found \"" + std::string(t.substr(0, 60)) + "\"");
      }
      pos = end;
    }
    aco::Hole h;
    h.center = {v[1], v[2]};
    h.source_line = no;
    out.holes.push_back(h);
    if (dimension >= 0 && static_cast<long long>(out.holes.size()) > dimension) {
      throw UserError(path, no, "more nodes than DIMENSION " + std::to_string(dimension));
    }
    return true;
  });
  if (!in_coords) throw UserError(path, 0, "no NODE_COORD_SECTION");
  if (dimension >= 0 && static_cast<long long>(out.holes.size()) != dimension) {
    throw UserError(path, 0, "DIMENSION is " + std::to_string(dimension) + " but " + std::to_string(out.holes.size()) +
                                 " nodes are listed");
  }
  return out;
}

LoadedHoles parse_xml_map(const std::string& path, std::string_view data, const InputOptions& options) {
  // The thesis's hole map (documented in README.md, "Input formats"):
  //   <holemap units="inch" name="PLATE70">
  //     <hole x="1.25" y="2.5" diameter="0.25"/> ...
  //   </holemap>
  LoadedHoles out;
  out.format = InputFormat::XmlMap;
  out.name = stem(path);
  tinyxml2::XMLDocument doc;
  if (doc.Parse(data.data(), data.size()) != tinyxml2::XML_SUCCESS) {
    throw UserError(path, static_cast<std::uint32_t>(std::max(0, doc.ErrorLineNum())),
                    std::string("XML: ") + tinyxml2::XMLDocument::ErrorIDToName(doc.ErrorID()));
  }
  const tinyxml2::XMLElement* root = doc.RootElement();
  if (!root || std::strcmp(root->Name(), "holemap") != 0) {
    throw UserError(path, root ? static_cast<std::uint32_t>(root->GetLineNum()) : 1,
                    "expected a <holemap> root element");
  }
  double unit = options.default_unit_mm;
  if (const char* u = root->Attribute("units")) {
    std::string us = u;
    if (us == "mm") unit = 1.0;
    else if (us == "inch" || us == "in") unit = 25.4;
    else throw UserError(path, static_cast<std::uint32_t>(root->GetLineNum()), "units must be \"mm\" or \"inch\", not \"" + us + "\"");
  }
  if (const char* n = root->Attribute("name")) out.name = n;
  for (const tinyxml2::XMLElement* e = root->FirstChildElement(); e; e = e->NextSiblingElement()) {
    const auto line = static_cast<std::uint32_t>(e->GetLineNum());
    if (std::strcmp(e->Name(), "hole") != 0) {
      throw UserError(path, line, std::string("unexpected element <") + e->Name() + ">, expected <hole>");
    }
    auto attr = [&](const char* name, bool required, double fallback) {
      const char* v = e->Attribute(name);
      if (!v) {
        if (required) throw UserError(path, line, std::string("<hole> lacks the ") + name + " attribute");
        return fallback;
      }
      double d;
      if (!parse_number(v, d)) throw UserError(path, line, std::string(name) + "=\"" + v + "\" is not a number");
      return d;
    };
    aco::Hole h;
    h.center = {attr("x", true, 0) * unit, attr("y", true, 0) * unit};
    h.diameter = attr("diameter", false, 0.0) * unit;
    if (h.diameter < 0) throw UserError(path, line, "negative diameter");
    if (const char* layer = e->Attribute("layer")) h.layer = layer;
    h.source_line = line;
    out.holes.push_back(std::move(h));
    check_limit(path, line, out.holes.size(), options);
  }
  return out;
}

LoadedHoles parse_holes(const std::string& path, std::string_view data, const InputOptions& options) {
  const std::string shown = path == "-" ? "<stdin>" : path;
  if (data.empty()) throw UserError(shown, 0, "empty file: no holes");
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
        throw UserError(shown, e.line(), e.what());
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

LoadedHoles load_holes(const std::string& path, const InputOptions& options) {
  return parse_holes(path, read_file(path), options);
}

}  // namespace app
