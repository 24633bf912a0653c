// Issue 86: IPC-2581 (revisions B and C), read with tinyxml2. The holes are
// the <Hole> and <SlotCavity> elements of the LayerFeatures whose layer is a
// drill layer (layerFunction DRILL, BACKDRILL, ROUT, ROUTE), in the chosen step,
// with its StepRepeat copies; units from CadHeader.
#include <tinyxml2.h>

#include <algorithm>
#include <cstring>
#include <map>

#include "board.h"
#include "formats/readers.h"
#include "text.h"

namespace formats {

namespace {

using tinyxml2::XMLElement;

// An element's name without its namespace prefix ("ipc:Hole" is a Hole).
bool named(const XMLElement* e, const char* name) {
  const char* n = e->Name();
  const char* colon = std::strrchr(n, ':');
  return std::strcmp(colon ? colon + 1 : n, name) == 0;
}

const XMLElement* child(const XMLElement* e, const char* name) {
  for (const XMLElement* c = e ? e->FirstChildElement() : nullptr; c; c = c->NextSiblingElement()) {
    if (named(c, name)) return c;
  }
  return nullptr;
}

template <class F>
void each_child(const XMLElement* e, const char* name, F&& f) {
  for (const XMLElement* c = e ? e->FirstChildElement() : nullptr; c; c = c->NextSiblingElement()) {
    if (named(c, name)) f(c);
  }
}

std::uint32_t line_of(const XMLElement* e) { return static_cast<std::uint32_t>(std::max(0, e->GetLineNum())); }

std::string text_attr(const XMLElement* e, const char* name) {
  const char* v = e->Attribute(name);
  return v ? v : "";
}

struct DrillLayer {
  std::string name;
  board::Span span;
};

class Ipc2581Reader {
 public:
  Ipc2581Reader(const std::string& path, const InputOptions& options) : path_(path), options_(options) {}

  std::vector<LoadedHoles> read(std::string_view data) {
    tinyxml2::XMLDocument doc;
    if (doc.Parse(data.data(), data.size()) != tinyxml2::XML_SUCCESS) {
      throw InputError(path_, static_cast<std::uint32_t>(std::max(0, doc.ErrorLineNum())),
                       std::string("IPC-2581: XML: ") + tinyxml2::XMLDocument::ErrorIDToName(doc.ErrorID()));
    }
    const XMLElement* root = doc.RootElement();
    if (!root || !named(root, "IPC-2581")) throw InputError(path_, root ? line_of(root) : 1, "expected an <IPC-2581> root element");
    const std::string revision = text_attr(root, "revision");
    const XMLElement* cad = child(child(root, "Ecad"), "CadData");
    if (!cad) throw InputError(path_, line_of(root), "IPC-2581 without <Ecad><CadData>: no board (a bill of materials only?)");
    read_units(child(child(root, "Ecad"), "CadHeader"), root);
    read_layers(cad);
    if (drill_layers_.empty()) {
      throw InputError(path_, line_of(cad), "no drill layer: no <Layer> with layerFunction DRILL, so no holes to drill");
    }
    std::vector<std::pair<std::string, std::vector<std::string>>> steps;
    each_child(cad, "Step", [&](const XMLElement* s) {
      const std::string name = text_attr(s, "name");
      std::vector<std::string> placed;
      each_child(s, "StepRepeat", [&](const XMLElement* r) { placed.push_back(text_attr(r, "stepRef")); });
      steps.push_back({name, placed});
      steps_[name] = s;
    });
    const std::string step = board::choose_step(path_, steps, options_.step);
    visit(steps_.at(step), board::Placement{}, 0);
    std::string description = "IPC-2581" + (revision.empty() ? "" : " rev " + revision) + ", step " + step + "; drill layers";
    for (const auto& [name, count] : per_layer_) description += " " + name + " (" + std::to_string(count) + ")";
    if (per_layer_.empty()) description += " none with holes";
    const std::string size = board::size_text(outline_);
    if (!size.empty()) description += "; board " + size;
    return sources_.take(description, std::move(warnings_), std::move(skipped_));
  }

 private:
  void read_units(const XMLElement* header, const XMLElement* root) {
    const std::string units = header ? text_attr(header, "units") : "";
    if (units == "MILLIMETER" || units.empty()) unit_ = 1.0;
    else if (units == "MICRON") unit_ = 0.001;
    else if (units == "INCH") unit_ = 25.4;
    else throw InputError(path_, line_of(header ? header : root), "CadHeader units \"" + units + "\": expected MILLIMETER, MICRON or INCH");
  }

  void read_layers(const XMLElement* cad) {
    std::vector<std::string> conductors;
    each_child(cad, "Layer", [&](const XMLElement* l) {
      const std::string function = text_attr(l, "layerFunction");
      if (function == "CONDUCTOR" || function == "SIGNAL" || function == "PLANE" || function == "MIXED" ||
          function == "CONDFILM" || function == "CONDFOIL") {
        conductors.push_back(text_attr(l, "name"));
      }
    });
    each_child(cad, "Layer", [&](const XMLElement* l) {
      const std::string function = text_attr(l, "layerFunction");
      if (function.find("DRILL") == std::string::npos && function != "ROUT" && function != "ROUTE") return;
      DrillLayer d;
      d.name = text_attr(l, "name");
      d.span.conductors = static_cast<int>(conductors.size());
      if (const XMLElement* s = child(l, "Span")) {
        auto index = [&](const std::string& name) {
          const auto it = std::find(conductors.begin(), conductors.end(), name);
          return it == conductors.end() ? 0 : static_cast<int>(it - conductors.begin()) + 1;
        };
        d.span.from = index(text_attr(s, "fromLayer"));
        d.span.to = index(text_attr(s, "toLayer"));
        if (d.span.from == 0 || d.span.to == 0) d.span = board::Span{0, 0, d.span.conductors};
      }
      const bool spans_all = d.span.through();
      d.span.back_drill = function.find("BACK") != std::string::npos;
      if (!d.span.through()) {
        warnings_.push_back({line_of(l), "drill layer " + d.name + (d.span.back_drill ? " is a back-drill" : "") +
                                             (spans_all ? "" : " spans conductor layers " + std::to_string(d.span.from) + "-" +
                                                                   std::to_string(d.span.to) + " of " +
                                                                   std::to_string(d.span.conductors)) +
                                             ": its holes are a source of their own, not merged with the through-holes"});
      }
      drill_layers_[d.name] = d;
    });
  }

  double number(const XMLElement* e, const char* name, bool required) {
    const char* v = e->Attribute(name);
    double out = 0;
    if (!v) {
      if (required) throw InputError(path_, line_of(e), std::string("<") + e->Name() + "> without " + name);
      return 0;
    }
    if (!parse_number(v, out)) throw InputError(path_, line_of(e), std::string(name) + "=\"" + v + "\" is not a number");
    return out;
  }

  void visit(const XMLElement* step, const board::Placement& place, int depth) {
    if (depth > 16) throw InputError(path_, line_of(step), "step-and-repeat nested more than 16 deep (a step placing itself?)");
    if (++copies_ > 1'000'000) throw InputError(path_, line_of(step), "step-and-repeat makes more than a million copies");
    const XMLElement* profile = child(step, "Profile");
    if (depth == 0 && profile) collect_outline(child(profile, "Polygon"), place);
    each_child(step, "LayerFeature", [&](const XMLElement* lf) {
      const auto layer = drill_layers_.find(text_attr(lf, "layerRef"));
      if (layer == drill_layers_.end()) return;
      each_child(lf, "Set", [&](const XMLElement* set) { read_set(set, layer->second, place); });
    });
    each_child(step, "StepRepeat", [&](const XMLElement* r) {
      const std::string ref = text_attr(r, "stepRef");
      const auto it = steps_.find(ref);
      if (it == steps_.end()) throw InputError(path_, line_of(r), "StepRepeat of step \"" + ref + "\", which the file does not have");
      aco::Point2 datum{0, 0};
      if (const XMLElement* d = child(it->second, "Datum")) datum = {number(d, "x", false) * unit_, number(d, "y", false) * unit_};
      const double x = number(r, "x", false) * unit_, y = number(r, "y", false) * unit_;
      const double dx = number(r, "dx", false) * unit_, dy = number(r, "dy", false) * unit_;
      const double nx = std::max(1.0, number(r, "nx", false)), ny = std::max(1.0, number(r, "ny", false));
      if (nx * ny > 1e6) throw InputError(path_, line_of(r), "StepRepeat of " + ref + " makes more than a million copies");
      const double angle = number(r, "angle", false);
      const std::string m = text_attr(r, "mirror");
      const bool mirror = m == "true" || m == "TRUE" || m == "1";
      for (int i = 0; i < static_cast<int>(nx); ++i) {
        for (int j = 0; j < static_cast<int>(ny); ++j) {
          visit(it->second, place.after(board::Placement::of({x + i * dx, y + j * dy}, angle, mirror, datum)), depth + 1);
        }
      }
    });
  }

  // The points of an outline's <Polygon>, an arc's points every 10 degrees.
  std::vector<aco::Point2> polygon_points(const XMLElement* polygon, aco::Point2 offset) {
    std::vector<aco::Point2> points;
    if (!polygon) return points;
    aco::Point2 at{0, 0};
    for (const XMLElement* e = polygon->FirstChildElement(); e; e = e->NextSiblingElement()) {
      const aco::Point2 p{number(e, "x", true) * unit_ + offset.x, number(e, "y", true) * unit_ + offset.y};
      if (named(e, "PolyStepCurve") && !points.empty()) {
        const aco::Point2 c{number(e, "centerX", true) * unit_ + offset.x, number(e, "centerY", true) * unit_ + offset.y};
        const bool clockwise = text_attr(e, "clockwise") == "true";
        const double r = aco::euclidean(c, at);
        double a0 = std::atan2(at.y - c.y, at.x - c.x), a1 = std::atan2(p.y - c.y, p.x - c.x);
        const double two_pi = 2 * 3.14159265358979323846;
        double sweep = a1 - a0;
        if (clockwise) {
          while (sweep >= 0) sweep -= two_pi;
        } else {
          while (sweep <= 0) sweep += two_pi;
        }
        const int n = std::max(2, static_cast<int>(std::ceil(std::fabs(sweep) / (two_pi / 36))));
        for (int k = 1; k < n; ++k) {
          const double a = a0 + sweep * k / n;
          points.push_back({c.x + r * std::cos(a), c.y + r * std::sin(a)});
        }
      }
      if (named(e, "PolyBegin") || named(e, "PolyStepSegment") || named(e, "PolyStepCurve")) {
        points.push_back(p);
        at = p;
      }
    }
    return points;
  }

  void collect_outline(const XMLElement* polygon, const board::Placement& place) {
    for (const aco::Point2& p : polygon_points(polygon, {0, 0})) outline_.push_back(place.apply(p));
  }

  // A Set's holes and slots, wherever under it they are written.
  void read_set(const XMLElement* e, const DrillLayer& layer, const board::Placement& place) {
    for (const XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
      if (named(c, "Hole")) {
        aco::Hole h;
        h.center = place.apply({number(c, "x", true) * unit_, number(c, "y", true) * unit_});
        h.diameter = number(c, "diameter", true) * unit_;
        if (!(h.diameter >= 0)) throw InputError(path_, line_of(c), "a hole's diameter is negative");
        h.layer = layer.name;
        h.source_line = line_of(c);
        LoadedHoles& to = sources_.of(text_attr(c, "platingStatus") != "NONPLATED" && !layer.span.back_drill, layer.span);
        to.holes.push_back(std::move(h));
        check_limit(path_, line_of(c), ++holes_, options_.dxf);
        ++per_layer_[layer.name];
      } else if (named(c, "SlotCavity")) {
        aco::Point2 offset{0, 0};
        if (const XMLElement* at = child(c, "Location")) offset = {number(at, "x", false) * unit_, number(at, "y", false) * unit_};
        std::vector<aco::Point2> points = polygon_points(child(child(c, "Outline"), "Polygon"), offset);
        if (const XMLElement* oval = child(c, "Oval"); oval && points.empty()) {
          // A primitive at the Location, turned by its Xform (counter-clockwise): the stadium's points.
          const double w = number(oval, "width", true) * unit_, h = number(oval, "height", true) * unit_;
          double turn = 0;
          if (const XMLElement* x = child(c, "Xform")) turn = number(x, "rotation", false);
          const board::Placement at = board::Placement::of(offset, turn, false, {0, 0});
          for (double sx : {-1.0, 1.0}) {
            for (double sy : {-1.0, 1.0}) points.push_back(at.apply({sx * w / 2, sy * h / 2}));
          }
          std::swap(points[2], points[3]);  // around the rectangle, not across it
        } else if (const XMLElement* circle = child(c, "Circle"); circle && points.empty()) {
          const double r = number(circle, "diameter", true) * unit_ / 2;
          // Its square: as wide as long, so fit_slot takes it for the round hole it is.
          points = {{offset.x - r, offset.y - r}, {offset.x + r, offset.y - r}, {offset.x + r, offset.y + r}, {offset.x - r, offset.y + r}};
        }
        for (aco::Point2& p : points) p = place.apply(p);
        Slot slot;
        aco::Hole round;
        LoadedHoles& to = sources_.of(text_attr(c, "platingStatus") != "NONPLATED", layer.span);
        if (board::fit_slot(points, slot, round)) {
          slot.layer = layer.name;
          slot.source_line = line_of(c);
          to.slots.push_back(slot);
        } else if (round.diameter > 0) {
          round.layer = layer.name;
          round.source_line = line_of(c);
          to.holes.push_back(round);
          ++holes_;
        } else {
          skipped_.push_back({line_of(c), "slot " + text_attr(c, "name") + ": its outline is not a polygon acodrill reads"});
          continue;
        }
        ++per_layer_[layer.name];
      } else {
        read_set(c, layer, place);
      }
    }
  }

  const std::string& path_;
  const InputOptions& options_;
  double unit_ = 1.0;
  std::map<std::string, DrillLayer> drill_layers_;
  std::map<std::string, const XMLElement*> steps_;
  board::Sources sources_{InputFormat::Ipc2581};
  std::vector<Note> warnings_, skipped_;
  std::vector<aco::Point2> outline_;
  std::map<std::string, std::size_t> per_layer_;
  std::size_t holes_ = 0, copies_ = 0;
};

}  // namespace

std::vector<LoadedHoles> parse_ipc2581(const std::string& path, std::string_view data, const InputOptions& options) {
  return Ipc2581Reader(path, options).read(data);
}

bool looks_like_ipc2581(std::string_view head) {
  // The root element: the first "<" that opens no declaration, comment or DOCTYPE.
  for (std::size_t at = head.find('<'); at != std::string_view::npos; at = head.find('<', at + 1)) {
    if (at + 1 < head.size() && (head[at + 1] == '?' || head[at + 1] == '!')) continue;
    std::string_view name = head.substr(at + 1);
    if (const std::size_t colon = name.find(':'); colon != std::string_view::npos && colon < name.find_first_of(" \t\r\n>/")) {
      name.remove_prefix(colon + 1);  // a namespace prefix
    }
    return name.size() > 8 && name.substr(0, 8) == "IPC-2581" &&
           (name[8] == ' ' || name[8] == '>' || name[8] == '\t' || name[8] == '\r' || name[8] == '\n' || name[8] == '/');
  }
  return false;
}

}  // namespace formats
