// Issue 86: ODB++ (a job folder, .tgz or .zip). The drill layers are the
// matrix's LAYERs of TYPE=DRILL; each one's holes are the pads (P records) of
// steps/STEP/layers/LAYER/features: a round symbol r<d> a hole of diameter d,
// an oval<w>x<h> a slot; symbols are in microns in a metric file and in mils
// in an inch one. A panel step's stephdr STEP-REPEAT places its child steps.
// ODB++ turns clockwise: its angles are negated into board::Placement.
#include <algorithm>
#include <map>

#include "board.h"
#include "formats/archive.h"
#include "formats/readers.h"
#include "text.h"

namespace formats {

namespace {

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}
std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::vector<std::string_view> words(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    const std::size_t start = i;
    while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

// A structured text file (matrix, stephdr): KEY=VALUE lines, and blocks
// "NAME {" ... "}" of them.
struct Block {
  std::string name;  // "" for the file's top level
  std::uint32_t line = 0;
  std::map<std::string, std::string> values;
};

std::vector<Block> read_blocks(std::string_view text) {
  std::vector<Block> out(1);
  bool inside = false;
  for_each_line(text, [&](std::uint32_t no, std::string_view raw) {
    std::string_view line = trim(raw);
    if (line.empty() || line.front() == '#') return true;
    if (line.back() == '{') {
      out.push_back({upper(std::string(trim(line.substr(0, line.size() - 1)))), no, {}});
      inside = true;
      return true;
    }
    if (line == "}") {
      inside = false;
      return true;
    }
    const std::size_t eq = line.find('=');
    if (eq == std::string_view::npos) return true;
    Block& b = inside ? out.back() : out.front();
    b.values[upper(std::string(trim(line.substr(0, eq))))] = std::string(trim(line.substr(eq + 1)));
    return true;
  });
  return out;
}

std::string value(const Block& b, const char* key) {
  const auto it = b.values.find(key);
  return it == b.values.end() ? "" : it->second;
}

struct DrillLayer {
  std::string name;  // as the matrix writes it
  board::Span span;
};

class OdbReader {
 public:
  OdbReader(const std::string& path, const std::vector<ArchiveEntry>& entries, const InputOptions& options)
      : path_(path), options_(options) {
    // The job's root: the folder holding matrix/matrix (KiCad's .tgz puts the job in "odb/").
    std::string root;
    bool found = false;
    for (const ArchiveEntry& e : entries) {
      const std::string p = lower(e.path);
      if (p == "matrix/matrix" || (p.size() > 14 && p.compare(p.size() - 14, 14, "/matrix/matrix") == 0)) {
        const std::string r = e.path.substr(0, e.path.size() - 13);
        if (!found || r.size() < root.size()) root = r;
        found = true;
      }
    }
    if (!found) throw InputError(path, 0, "no matrix/matrix: not an ODB++ job (nor an archive of one)");
    root_ = root;
    for (const ArchiveEntry& e : entries) {
      if (e.path.size() > root.size() && e.path.compare(0, root.size(), root) == 0) files_[lower(e.path.substr(root.size()))] = &e;
    }
  }

  std::vector<LoadedHoles> read() {
    read_matrix();
    std::vector<std::pair<std::string, std::vector<std::string>>> steps;
    for (const std::string& s : step_names_) {
      std::vector<std::string> placed;
      for (const Block& b : header(s)) {
        if (b.name == "STEP-REPEAT") placed.push_back(value(b, "NAME"));
      }
      steps.push_back({s, placed});
    }
    const std::string step = board::choose_step(path_, steps, options_.step);
    visit(step, board::Placement{}, 0);
    std::string description = "ODB++, step " + step + "; drill layers";
    for (const DrillLayer& d : drill_layers_) description += " " + d.name + " (" + std::to_string(per_layer_[d.name]) + ")";
    const std::string size = board::size_text(outline_);
    if (!size.empty()) description += "; board " + size;
    return sources_.take(description, std::move(warnings_), std::move(skipped_));
  }

 private:
  const std::string* file(const std::string& name) const {
    const auto it = files_.find(lower(name));
    return it == files_.end() ? nullptr : &it->second->bytes;
  }
  // FILE:ENTRY, the entry as the archive names it (with the job's folder).
  std::string where(const std::string& name) const {
    const auto it = files_.find(lower(name));
    return path_ + ":" + (it == files_.end() ? root_ + name : it->second->path);
  }

  void read_matrix() {
    const std::string* matrix = file("matrix/matrix");
    std::vector<std::string> conductors;
    std::vector<std::pair<int, const Block*>> rows;
    matrix_ = read_blocks(*matrix);
    for (const Block& b : matrix_) {
      if (b.name == "STEP") step_names_.push_back(value(b, "NAME"));
      if (b.name == "LAYER") rows.push_back({std::atoi(value(b, "ROW").c_str()), &b});
    }
    std::stable_sort(rows.begin(), rows.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    for (const auto& [row, b] : rows) {
      const std::string type = upper(value(*b, "TYPE"));
      if (upper(value(*b, "CONTEXT")) == "BOARD" && (type == "SIGNAL" || type == "POWER_GROUND" || type == "MIXED")) {
        conductors.push_back(upper(value(*b, "NAME")));
      }
    }
    for (const auto& [row, b] : rows) {
      if (upper(value(*b, "TYPE")) != "DRILL" || upper(value(*b, "CONTEXT")) == "MISC") continue;
      DrillLayer d;
      d.name = value(*b, "NAME");
      d.span.conductors = static_cast<int>(conductors.size());
      auto index = [&](const std::string& name) {
        const auto it = std::find(conductors.begin(), conductors.end(), upper(name));
        return it == conductors.end() ? 0 : static_cast<int>(it - conductors.begin()) + 1;
      };
      d.span.from = index(value(*b, "START_NAME"));
      d.span.to = index(value(*b, "END_NAME"));
      if (d.span.from == 0 || d.span.to == 0) d.span = board::Span{0, 0, d.span.conductors};
      if (!d.span.through()) {
        warnings_.push_back({b->line, "drill layer " + d.name + " spans conductor layers " + std::to_string(d.span.from) + "-" +
                                          std::to_string(d.span.to) + " of " + std::to_string(d.span.conductors) +
                                          ": its holes are a source of their own, not merged with the through-holes"});
      }
      drill_layers_.push_back(d);
    }
    if (drill_layers_.empty()) throw InputError(where("matrix/matrix"), 0, "no drill layer (no LAYER with TYPE=DRILL): no holes to drill");
    if (step_names_.empty()) throw InputError(where("matrix/matrix"), 0, "no STEP: the job holds no board");
  }

  const std::vector<Block>& header(const std::string& step) {
    auto [it, fresh] = headers_.try_emplace(lower(step));
    if (fresh) {
      const std::string* h = file("steps/" + step + "/stephdr");
      it->second = h ? read_blocks(*h) : std::vector<Block>(1);
    }
    return it->second;
  }

  void visit(const std::string& step, const board::Placement& place, int depth) {
    if (depth > 16) throw InputError(where("steps/" + lower(step) + "/stephdr"), 0, "step-and-repeat nested more than 16 deep (a step placing itself?)");
    if (++copies_ > 1'000'000) throw InputError(where("steps/" + lower(step) + "/stephdr"), 0, "step-and-repeat makes more than a million copies");
    const std::vector<Block>& hdr = header(step);
    if (depth == 0) read_outline(step, place);
    for (const DrillLayer& d : drill_layers_) {
      for (const Feature& f : features(step, d)) {
        LoadedHoles& to = sources_.of(f.plated, d.span);
        ++per_layer_[d.name];
        if (f.is_slot) {
          to.slots.push_back(Slot{place.apply(f.slot.from), place.apply(f.slot.to), f.slot.width_mm, d.name, f.slot.source_line});
          continue;
        }
        aco::Hole h = f.hole;
        h.center = place.apply(h.center);
        to.holes.push_back(std::move(h));
        check_limit(path_, f.hole.source_line, ++holes_, options_.dxf);
      }
    }
    for (const Block& b : hdr) {
      if (b.name != "STEP-REPEAT") continue;
      const std::string name = "steps/" + lower(step) + "/stephdr";
      auto num = [&](const char* key, double fallback) {
        const std::string v = value(b, key);
        double out = fallback;
        if (!v.empty() && !parse_number(v, out)) throw InputError(where(name), b.line, std::string(key) + "=" + v + " is not a number");
        return out;
      };
      const std::string child = value(b, "NAME");
      if (std::find_if(step_names_.begin(), step_names_.end(), [&](const std::string& s) { return lower(s) == lower(child); }) ==
          step_names_.end()) {
        throw InputError(where(name), b.line, "STEP-REPEAT of step \"" + child + "\", which the job does not have");
      }
      const double unit = unit_of(hdr);
      const std::vector<Block>& child_hdr = header(child);
      const double child_unit = unit_of(child_hdr);
      const aco::Point2 datum{num_of(child_hdr.front(), "X_DATUM") * child_unit, num_of(child_hdr.front(), "Y_DATUM") * child_unit};
      const double nx = std::max(1.0, num("NX", 1)), ny = std::max(1.0, num("NY", 1));
      if (nx * ny > 1e6) throw InputError(where(name), b.line, "STEP-REPEAT of " + child + " makes more than a million copies");
      const double x = num("X", 0) * unit, y = num("Y", 0) * unit, dx = num("DX", 0) * unit, dy = num("DY", 0) * unit;
      const double angle = -num("ANGLE", 0);  // ODB++ turns clockwise
      const bool mirror = upper(value(b, "MIRROR")) == "YES";
      for (int i = 0; i < static_cast<int>(nx); ++i) {
        for (int j = 0; j < static_cast<int>(ny); ++j) {
          visit(child, place.after(board::Placement::of({x + i * dx, y + j * dy}, angle, mirror, datum)), depth + 1);
        }
      }
    }
  }

  static double unit_of(const std::vector<Block>& hdr) { return upper(value(hdr.front(), "UNITS")) == "MM" ? 1.0 : 25.4; }
  static double num_of(const Block& b, const char* key) {
    double out = 0;
    return parse_number(value(b, key), out) ? out : 0.0;
  }

  // The board's outline: the points of the profile's surface.
  void read_outline(const std::string& step, const board::Placement& place) {
    const std::string* profile = file("steps/" + step + "/profile");
    if (!profile) return;
    double unit = 25.4;
    for_each_line(*profile, [&](std::uint32_t, std::string_view line) {
      const std::vector<std::string_view> w = words(line);
      if (w.empty()) return true;
      if (w[0].rfind("UNITS=", 0) == 0) unit = upper(std::string(w[0].substr(6))) == "MM" ? 1.0 : 25.4;
      if (w.size() == 2 && w[0] == "U") unit = upper(std::string(w[1])) == "MM" ? 1.0 : 25.4;
      double x = 0, y = 0;
      if ((w[0] == "OB" || w[0] == "OS") && w.size() >= 3 && parse_number(w[1], x) && parse_number(w[2], y)) {
        outline_.push_back(place.apply({x * unit, y * unit}));
      }
      return true;
    });
  }

  // A hole or slot of a drill layer, in its step's coordinates.
  struct Feature {
    bool plated = true, is_slot = false;
    aco::Hole hole;
    Slot slot;
  };

  // A step's layer's features, read once however many copies of the step a panel places.
  const std::vector<Feature>& features(const std::string& step, const DrillLayer& layer) {
    const std::string name = "steps/" + lower(step) + "/layers/" + lower(layer.name) + "/features";
    auto [it, fresh] = features_.try_emplace(name);
    if (fresh) it->second = read_features(name, layer);
    return it->second;
  }

  std::vector<Feature> read_features(const std::string& name, const DrillLayer& layer) {
    std::vector<Feature> out;
    const std::string* text = file(name);
    if (!text) {
      if (file(name + ".z")) throw InputError(where(name + ".Z"), 0, "compressed with Unix compress; uncompress it (uncompress or gzip -d) first");
      return out;  // a layer with nothing on it in this step
    }
    const std::string shown = where(name);
    double unit = 25.4;        // coordinates: mm or inch
    bool metric = false;
    std::map<long, std::pair<std::string, bool>> symbols;  // $n: name, metric
    int drill_attribute = -1;  // @n of ".drill"
    for_each_line(*text, [&](std::uint32_t no, std::string_view raw) {
      std::string_view line = trim(raw);
      if (line.empty() || line.front() == '#') return true;
      const std::size_t semi = line.find(';');
      const std::string_view attrs = semi == std::string_view::npos ? std::string_view() : line.substr(semi + 1);
      const std::vector<std::string_view> w = words(line.substr(0, semi));
      if (w.empty()) return true;
      if (w[0].rfind("UNITS=", 0) == 0 || (w[0] == "U" && w.size() == 2)) {
        metric = upper(std::string(w[0] == "U" ? w[1] : w[0].substr(6))) == "MM";
        unit = metric ? 1.0 : 25.4;
        return true;
      }
      if (w[0].front() == '$') {
        if (w.size() < 2) throw InputError(shown, no, "a symbol line without its symbol");
        const bool sym_metric = w.size() >= 3 ? upper(std::string(w[2])) == "M" : metric;
        symbols[std::atol(std::string(w[0].substr(1)).c_str())] = {lower(std::string(w[1])), sym_metric};
        return true;
      }
      if (w[0].front() == '@') {
        if (w.size() >= 2 && w[1] == ".drill") drill_attribute = std::atoi(std::string(w[0].substr(1)).c_str());
        return true;
      }
      if (w[0] != "P" && w[0] != "L") return true;  // arcs, surfaces, text: not holes
      const bool pad = w[0] == "P";
      if (w.size() < (pad ? 4u : 6u)) throw InputError(shown, no, std::string(pad ? "a pad" : "a line") + " record with too few fields");
      double v[4] = {};
      for (int k = 0; k < (pad ? 2 : 4); ++k) {
        if (!parse_number(w[1 + k], v[k])) throw InputError(shown, no, "\"" + std::string(w[1 + k]) + "\" is not a number");
      }
      const std::string_view sym_field = w[pad ? 3 : 5];
      const auto sym = symbols.find(std::atol(std::string(sym_field).c_str()));
      if (sym == symbols.end()) throw InputError(shown, no, "symbol " + std::string(sym_field) + " is not defined (no $" + std::string(sym_field) + " line)");
      const double sym_unit = sym->second.second ? 0.001 : 0.0254;  // microns or mils
      // Plated unless its .drill attribute says non_plated (option 1), or the layer's name does.
      bool plated = lower(layer.name).find("non") == std::string::npos && lower(layer.name).find("npth") == std::string::npos;
      if (drill_attribute >= 0) {
        const std::string key = std::to_string(drill_attribute) + "=";
        std::string all(attrs);
        std::replace(all.begin(), all.end(), ',', ' ');
        for (std::string_view a : words(all)) {
          if (a.substr(0, key.size()) == key) plated = a.substr(key.size()) != "1";
        }
      }
      Feature f;
      f.plated = plated;
      const std::string& symbol = sym->second.first;
      double d = 0, w2 = 0;
      aco::Hole h;
      h.layer = layer.name;
      h.source_line = no;
      if (symbol.size() > 1 && symbol[0] == 'r' && parse_number(symbol.substr(1), d)) {
        h.diameter = d * sym_unit;
        if (pad) {
          h.center = {v[0] * unit, v[1] * unit};
          f.hole = std::move(h);
          out.push_back(std::move(f));
          check_limit(shown, no, out.size(), options_.dxf);
          return true;
        }
        f.is_slot = true;
        f.slot = Slot{{v[0] * unit, v[1] * unit}, {v[2] * unit, v[3] * unit}, h.diameter, layer.name, no};
        out.push_back(std::move(f));
        check_limit(shown, no, out.size(), options_.dxf);
        return true;
      }
      const std::size_t x = symbol.find('x');
      if (pad && symbol.rfind("oval", 0) == 0 && x != std::string::npos && parse_number(symbol.substr(4, x - 4), d) &&
          parse_number(symbol.substr(x + 1), w2)) {
        // An oval pad: a slot along its longer side, turned as the pad is.
        double angle = 0;
        bool mirror = false;
        if (w.size() >= 7) {
          const int orient = std::atoi(std::string(w[6]).c_str());
          mirror = orient == 9 || (orient >= 4 && orient <= 7);
          if (orient >= 8 && w.size() >= 8) parse_number(w[7], angle);
          else angle = 90.0 * (orient % 4);
        }
        const double width = std::min(d, w2) * sym_unit, half = (std::max(d, w2) - std::min(d, w2)) * sym_unit / 2;
        const aco::Point2 along = d > w2 ? aco::Point2{half, 0} : aco::Point2{0, half};
        const board::Placement turn = board::Placement::of({v[0] * unit, v[1] * unit}, -angle, mirror, {0, 0});
        f.is_slot = true;
        f.slot = Slot{turn.apply({-along.x, -along.y}), turn.apply(along), width, layer.name, no};
        out.push_back(std::move(f));
        check_limit(shown, no, out.size(), options_.dxf);
        return true;
      }
      skipped_.push_back({no, name + ": a " + std::string(pad ? "pad" : "line") + " of symbol " + symbol +
                                  " on drill layer " + layer.name + " (not round or oval): not drilled"});
      return true;
    });
    return out;
  }

  const std::string& path_;
  const InputOptions& options_;
  std::string root_;                                   // the job's folder in the archive ("odb/"), or ""
  std::map<std::string, const ArchiveEntry*> files_;  // by path from the job's root, lower case
  std::vector<Block> matrix_;
  std::map<std::string, std::vector<Block>> headers_;     // each step's stephdr, by lower-case name
  std::map<std::string, std::vector<Feature>> features_;  // each step's layer's features, by entry
  std::vector<std::string> step_names_;
  std::vector<DrillLayer> drill_layers_;
  board::Sources sources_{InputFormat::Odb};
  std::vector<Note> warnings_, skipped_;
  std::vector<aco::Point2> outline_;
  std::map<std::string, std::size_t> per_layer_;
  std::size_t holes_ = 0, copies_ = 0;
};

}  // namespace

std::vector<LoadedHoles> parse_odb(const std::string& path, const std::vector<ArchiveEntry>& entries, const InputOptions& options) {
  return OdbReader(path, entries, options).read();
}

}  // namespace formats
