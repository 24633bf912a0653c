// The seed thesis's XML hole map, read with tinyxml2.
#include <tinyxml2.h>

#include <cstring>
#include <algorithm>
#include <cmath>

#include "formats/features.h"
#include "formats/readers.h"
#include "text.h"

namespace formats {

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
    throw InputError(path, static_cast<std::uint32_t>(std::max(0, doc.ErrorLineNum())),
                    std::string("XML: ") + tinyxml2::XMLDocument::ErrorIDToName(doc.ErrorID()));
  }
  const tinyxml2::XMLElement* root = doc.RootElement();
  if (!root || std::strcmp(root->Name(), "holemap") != 0) {
    throw InputError(path, root ? static_cast<std::uint32_t>(root->GetLineNum()) : 1,
                    "expected a <holemap> root element");
  }
  double unit = options.default_unit_mm;
  if (const char* u = root->Attribute("units")) {
    std::string us = u;
    if (us == "mm") unit = 1.0;
    else if (us == "inch" || us == "in") unit = 25.4;
    else throw InputError(path, static_cast<std::uint32_t>(root->GetLineNum()), "units must be \"mm\" or \"inch\", not \"" + us + "\"");
  }
  if (const char* n = root->Attribute("name")) out.name = n;
  std::vector<HoleFeature> listed;
  bool any_feature = false;
  for (const tinyxml2::XMLElement* e = root->FirstChildElement(); e; e = e->NextSiblingElement()) {
    const auto line = static_cast<std::uint32_t>(e->GetLineNum());
    if (std::strcmp(e->Name(), "hole") != 0) {
      throw InputError(path, line, std::string("unexpected element <") + e->Name() + ">, expected <hole>");
    }
    auto attr = [&](const char* name, bool required, double fallback) {
      const char* v = e->Attribute(name);
      if (!v) {
        if (required) throw InputError(path, line, std::string("<hole> lacks the ") + name + " attribute");
        return fallback;
      }
      double d;
      if (!parse_number(v, d)) throw InputError(path, line, std::string(name) + "=\"" + v + "\" is not a number");
      return d;
    };
    aco::Hole h;
    h.center = {attr("x", true, 0) * unit, attr("y", true, 0) * unit};
    h.diameter = attr("diameter", false, 0.0) * unit;
    if (h.diameter < 0) throw InputError(path, line, "negative diameter");
    if (const char* layer = e->Attribute("layer")) h.layer = layer;
    h.source_line = line;
    // Issue 82: a hole's feature, as attributes (README, "Holes as drawn").
    ListedFeature given;
    if (const char* thread = e->Attribute("thread")) given.thread = thread;
    given.counterbore_mm = attr("counterbore_mm", false, 0.0);
    given.counterbore_depth_mm = attr("counterbore_depth_mm", false, 0.0);
    given.countersink_mm = attr("countersink_mm", false, 0.0);
    given.countersink_angle_deg = attr("countersink_angle_deg", false, 0.0);
    if (!given.thread.empty() || given.counterbore_mm != 0 || given.countersink_mm != 0) any_feature = true;
    given.counterbore_mm *= unit, given.counterbore_depth_mm *= unit, given.countersink_mm *= unit;
    listed.push_back(listed_feature(h, given, unit == 25.4, options.processes.get(), path));
    out.holes.push_back(std::move(h));
    check_limit(path, line, out.holes.size(), options.dxf);
  }
  // Features only where the map gives one: a plain map stays the thesis's.
  if (any_feature) out.features = std::move(listed);
  return out;
}

}  // namespace formats
