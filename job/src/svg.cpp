#include "job/svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <sstream>

#include "gcode/program.h"
#include "text.h"

namespace job {

// The planning model's values (planning/) are what these pages and reports show.
using namespace planning;

namespace {

// Colour-blind-safe palette (Okabe & Ito 2008) for the first eight tools;
// past eight (panels, sister tools: a job can have dozens) each tool gets a
// hue of its own, 137.5 degrees (the golden angle) from the last, so no two
// tools ever share a colour and neighbours in the list look far apart.
const char* kPalette[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#F0E442", "#000000"};

std::string tool_colour(std::size_t g) {
  if (g < 8) return kPalette[g];
  const double hue = std::fmod(static_cast<double>(g - 8) * 137.508, 360.0);
  // Lightness alternates in three steps, so that hues close on the wheel still differ.
  const double light = 0.35 + 0.12 * static_cast<double>((g - 8) % 3);
  const double sat = 0.75;
  auto f = [&](double n) {
    const double k = std::fmod(n + hue / 30.0, 12.0);
    const double a = sat * std::min(light, 1.0 - light);
    return light - a * std::max(-1.0, std::min({k - 3.0, 9.0 - k, 1.0}));
  };
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02X%02X%02X", static_cast<int>(std::lround(f(0) * 255)),
                static_cast<int>(std::lround(f(8) * 255)), static_cast<int>(std::lround(f(4) * 255)));
  return buf;
}

std::string num(double v) { return gcode::format_number(v, 3); }

struct Box {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  void add(double x, double y, double r = 0) {
    x0 = std::min(x0, x - r);
    y0 = std::min(y0, y - r);
    x1 = std::max(x1, x + r);
    y1 = std::max(y1, y + r);
  }
};

// One panel: the route of `orders` (one per tool group) in drawing units,
// placed with its lower-left drawing corner at (ox, oy) of the page.
void panel(std::ostringstream& out, const aco::HoleSet& holes, const PlanResult& plan, const PlanOptions& options,
           const std::vector<const aco::Order*>& orders, const Box& box, double scale, double ox, double oy,
           const std::string& heading, double travel_mm, double time_s, const Placement& placement) {
  const double h = (box.y1 - box.y0) * scale;
  auto X = [&](double x) { return ox + (x - box.x0) * scale; };
  auto Y = [&](double y) { return oy + h - (y - box.y0) * scale; };  // CAD Y points up, SVG Y down
  out << "<g>\n<text x=\"" << num(ox) << "\" y=\"" << num(oy - 8) << "\" font-size=\"14\" font-weight=\"bold\">"
      << xml_escape(heading) << " — " << num(travel_mm / 1000.0) << " m travel, " << gcode::format_number(time_s / 60.0, 2)
      << " min</text>\n";
  out << "<rect x=\"" << num(ox) << "\" y=\"" << num(oy) << "\" width=\"" << num((box.x1 - box.x0) * scale)
      << "\" height=\"" << num(h) << "\" fill=\"#fafafa\" stroke=\"#cccccc\"/>\n";
  // Path, tool by tool, from the start and back to it.
  aco::Point2 at = options.machine.start;
  for (std::size_t g = 0; g < plan.groups.size(); ++g) {
    const std::string colour = tool_colour(g);
    out << "<polyline fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"1.2\" stroke-opacity=\"0.8\" "
        << "marker-mid=\"url(#arrow" << g << ")\" points=\"" << num(X(at.x)) << "," << num(Y(at.y));
    // Appended to one string, not streamed number by number: at 10^6 holes
    // these are 4 x 10^6 numbers (issue 84).
    std::string points;
    auto point = [&](double x, double y) {
      points += ' ';
      gcode::append_number(points, X(x), 3);
      points += ',';
      gcode::append_number(points, Y(y), 3);
    };
    for (aco::HoleIndex i : *orders[g]) {
      const aco::Point2 p = holes[i].center;
      // A midpoint vertex carries the direction arrow in the middle of each leg.
      point((at.x + p.x) / 2, (at.y + p.y) / 2);
      point(p.x, p.y);
      at = p;
    }
    out << points << "\"/>\n";
  }
  const aco::Point2 home = options.machine.start;
  out << "<polyline fill=\"none\" stroke=\"#888888\" stroke-width=\"1\" stroke-dasharray=\"4 3\" points=\"" << num(X(at.x))
      << "," << num(Y(at.y)) << " " << num(X(home.x)) << "," << num(Y(home.y)) << "\"/>\n";
  // Holes to scale (at least a visible dot), coloured by tool. A hole
  // feature's other operations (issue 82) as a drawing shows them, over the
  // drilled holes: a counterbore or a reamer a ring, a countersink a dashed
  // ring, a tap three quarters of a ring, a spot a small cross.
  for (std::size_t g = 0; g < plan.groups.size(); ++g) {
    const gcode::Operation op = plan.groups[g].tool.operation;
    if (op == gcode::Operation::Drill) {
      out << "<g fill=\"" << tool_colour(g) << "\" fill-opacity=\"0.55\" stroke=\"" << tool_colour(g) << "\">\n";
    } else {
      out << "<g fill=\"none\" stroke=\"" << tool_colour(g) << "\" stroke-width=\"1.5\""
          << (op == gcode::Operation::Countersink ? " stroke-dasharray=\"3 2\"" : "") << ">\n";
    }
    std::string shapes;
    // Text and numbers in turn, appended: as fast as the route above.
    auto put = [&shapes](std::initializer_list<std::pair<const char*, double>> parts, const char* end) {
      for (const auto& [text, value] : parts) {
        shapes += text;
        gcode::append_number(shapes, value, 3);
      }
      shapes += end;
    };
    for (aco::HoleIndex i : *orders[g]) {
      const aco::Hole& hole = holes[i];
      const double cx = X(hole.center.x), cy = Y(hole.center.y), r = std::max(hole.diameter / 2 * scale, 1.5);
      if (op == gcode::Operation::Spot) {
        put({{"<path d=\"M", cx - 3}, {" ", cy}, {"H", cx + 3}, {"M", cx}, {" ", cy - 3}, {"V", cy + 3}}, "\"/>\n");
      } else if (op == gcode::Operation::Tap) {
        put({{"<path d=\"M", cx + r}, {" ", cy}, {"A", r}, {" ", r}, {" 0 1 1 ", cx}, {" ", cy - r}}, "\"/>\n");
      } else {
        put({{"<circle cx=\"", cx}, {"\" cy=\"", cy}, {"\" r=\"", r}}, "\"/>\n");
      }
    }
    out << shapes << "</g>\n";
  }
  // Program zero, where the machinist sets the work offset: a crosshair.
  const double zx = X(0.0), zy = Y(0.0);
  out << "<g stroke=\"#C00000\" stroke-width=\"1.5\" fill=\"none\"><rect x=\"" << num(zx - 6) << "\" y=\"" << num(zy - 6)
      << "\" width=\"12\" height=\"12\" transform=\"rotate(45 " << num(zx) << " " << num(zy) << ")\"/><line x1=\"" << num(zx - 12) << "\" y1=\"" << num(zy) << "\" x2=\"" << num(zx + 12) << "\" y2=\""
      << num(zy) << "\"/><line x1=\"" << num(zx) << "\" y1=\"" << num(zy - 12) << "\" x2=\"" << num(zx) << "\" y2=\""
      << num(zy + 12) << "\"/></g>\n<text x=\"" << num(zx + 10) << "\" y=\"" << num(zy + 16)
      << "\" font-size=\"11\" fill=\"#C00000\">X0 Y0 (" << xml_escape(to_string(placement.origin)) << ")</text>\n";
  out << "<rect x=\"" << num(X(home.x) - 5) << "\" y=\"" << num(Y(home.y) - 5)
      << "\" width=\"10\" height=\"10\" fill=\"#000000\"/>\n<text x=\"" << num(X(home.x) + 8) << "\" y=\""
      << num(Y(home.y) + 4) << "\" font-size=\"11\">start</text>\n</g>\n";
}

std::string document(const aco::HoleSet& holes, const PlanResult& plan, const PlanOptions& options,
                     const Placement& placement, const std::string& title, bool compare) {
  Box box;
  box.add(options.machine.start.x, options.machine.start.y);
  box.add(0.0, 0.0);  // program zero
  for (const aco::Hole& h : holes) box.add(h.center.x, h.center.y, h.diameter / 2);
  const double pad = std::max({(box.x1 - box.x0) * 0.03, (box.y1 - box.y0) * 0.03, 1.0});
  box.x0 -= pad;
  box.y0 -= pad;
  box.x1 += pad;
  box.y1 += pad;
  // Each panel about 700 px on its longer side.
  const double scale = 700.0 / std::max(box.x1 - box.x0, box.y1 - box.y0);
  const double pw = (box.x1 - box.x0) * scale, ph = (box.y1 - box.y0) * scale;
  const double margin = 30, legend_h = 40 + 18.0 * static_cast<double>(plan.groups.size() + 3);
  const double width = margin * 2 + (compare ? pw * 2 + margin : pw);
  const double height = margin * 2 + ph + legend_h + 20;
  std::ostringstream out;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << num(width) << "\" height=\"" << num(height)
      << "\" viewBox=\"0 0 " << num(width) << " " << num(height) << "\" font-family=\"sans-serif\">\n"
      << "<title>" << xml_escape(title) << "</title>\n<defs>\n";
  for (std::size_t c = 0; c < plan.groups.size(); ++c) {
    out << "<marker id=\"arrow" << c << "\" viewBox=\"0 0 10 10\" refX=\"5\" refY=\"5\" markerWidth=\"5\" "
        << "markerHeight=\"5\" orient=\"auto\"><path d=\"M0,1 L10,5 L0,9 z\" fill=\"" << tool_colour(c) << "\"/></marker>\n";
  }
  out << "</defs>\n<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
  std::vector<const aco::Order*> input, optimized;
  for (const ToolGroup& g : plan.groups) {
    input.push_back(&g.input_order);
    optimized.push_back(&g.optimized);
  }
  const double top = margin + 10;
  if (compare) {
    panel(out, holes, plan, options, input, box, scale, margin, top, "input order", plan.input_order.travel_mm,
          plan.input_order.time_s, placement);
    panel(out, holes, plan, options, optimized, box, scale, margin * 2 + pw, top, "optimized",
          plan.optimized.travel_mm, plan.optimized.time_s, placement);
  } else {
    panel(out, holes, plan, options, optimized, box, scale, margin, top, title, plan.optimized.travel_mm,
          plan.optimized.time_s, placement);
  }
  // Legend.
  double y = top + ph + 30;
  out << "<g font-size=\"12\">\n";
  for (std::size_t g = 0; g < plan.groups.size(); ++g) {
    const ToolGroup& group = plan.groups[g];
    out << "<rect x=\"" << num(margin) << "\" y=\"" << num(y - 10) << "\" width=\"12\" height=\"12\" fill=\""
        << tool_colour(g) << "\"/><text x=\"" << num(margin + 18) << "\" y=\"" << num(y) << "\">T"
        << group.tool.number << "  Ø " << gcode::format_number(group.tool.diameter_mm, 3) << " mm  "
        << group.optimized.size() << " holes  " << gcode::to_string(group.tool.cycle) << "</text>\n";
    y += 18;
  }
  const double saved_min = (plan.input_order.time_s - plan.optimized.time_s) / 60.0;
  const double saved_pct = plan.input_order.travel_mm > 0
                               ? 100.0 * (plan.input_order.travel_mm - plan.optimized.travel_mm) / plan.input_order.travel_mm
                               : 0.0;
  out << "<text x=\"" << num(margin) << "\" y=\"" << num(y + 4) << "\">travel: input order "
      << gcode::format_number(plan.input_order.travel_mm, 1) << " mm, nearest neighbour "
      << gcode::format_number(plan.nearest_neighbor.travel_mm, 1) << " mm, optimized "
      << gcode::format_number(plan.optimized.travel_mm, 1) << " mm (" << gcode::format_number(saved_pct, 1)
      << " % less than input order)</text>\n";
  out << "<text x=\"" << num(margin) << "\" y=\"" << num(y + 22) << "\">machining time: "
      << gcode::format_number(plan.optimized.time_s / 60.0, 2) << " min, " << gcode::format_number(saved_min, 2)
      << " min saved against the input order</text>\n";
  const Extent& e = placement.extent;
  out << "<text x=\"" << num(margin) << "\" y=\"" << num(y + 40) << "\">program zero: "
      << xml_escape(describe(placement.origin)) << " (drawing X" << num(placement.zero.x) << " Y" << num(placement.zero.y)
      << " mm); holes X" << num(e.x_min) << ".." << num(e.x_max) << " Y" << num(e.y_min) << ".." << num(e.y_max)
      << " mm</text>\n</g>\n</svg>\n";
  return out.str();
}

}  // namespace

std::string route_svg(const aco::HoleSet& holes, const PlanResult& plan, const PlanOptions& options,
                      const Placement& placement, const std::string& title) {
  return document(holes, plan, options, placement, title, false);
}

std::string compare_svg(const aco::HoleSet& holes, const PlanResult& plan, const PlanOptions& options,
                        const Placement& placement, const std::string& title) {
  return document(holes, plan, options, placement, title, true);
}

}  // namespace job
