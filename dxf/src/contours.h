#pragma once
// Holes a CAD drew without a CIRCLE (issue 71): closed contours that are
// circles — SPLINE loops (Fusion 360), polygons of LINEs or closed polylines
// (OpenSCAD, Inkscape), arc pairs and bulged polylines, full-circle ARCs,
// circular ELLIPSEs. Each entity is sampled into a polyline of points on it;
// open pieces are joined end to end into loops; a loop is a hole when every
// point and every chord's middle lies within the tolerance of one circle.
#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "aco/geometry.h"

namespace dxf::contours {

// One drawn piece, sampled: points on the curve in the entity's own
// coordinate system (its OCS, or world for LINE, SPLINE, ELLIPSE).
struct Piece {
  std::string_view kind;            // "LINE", "ARC", "LWPOLYLINE", "POLYLINE", "SPLINE", "ELLIPSE"
  std::vector<std::array<double, 3>> points;
  bool closed = false;              // a loop by itself (first point not repeated at the end)
  std::array<double, 3> extrusion{0, 0, 1};  // the OCS the points are in ((0,0,1): world)
  std::string_view layer;
  std::uint32_t line = 0;
  // An ARC's own circle (in its OCS) and span, kept beside its points: a
  // tapped hole's thread is drawn with one. 0: not an ARC.
  std::array<double, 3> arc_center{0, 0, 0};
  double arc_radius = 0.0, arc_span_deg = 0.0;
};

// A piece placed in the world (drawing units, XY).
struct Placed {
  std::string_view kind;
  std::vector<aco::Point2> points;
  bool closed = false;
  std::string_view layer;
  std::uint32_t line = 0;
};

struct Found {
  aco::Point2 center;
  double diameter = 0.0;            // drawing units
  std::string layer;
  std::uint32_t line = 0;
  std::string kinds;                // what it is drawn with: "SPLINE", "LINE", "ARC+LWPOLYLINE", ...
};

// Joins the pieces into loops and keeps those round within `tolerance`
// (the largest deviation from the fitted circle, as a fraction of its radius).
std::vector<Found> round_loops(const std::vector<Placed>& pieces, double tolerance);

// Sampling of the curves the pieces are made of.
void add_arc(Piece& p, std::array<double, 3> center, double radius, double start_deg, double end_deg);
void add_bulge(Piece& p, std::array<double, 3> from, std::array<double, 3> to, double bulge);
// A NURBS curve of `degree` with its knots, control points and weights (empty: 1).
std::vector<std::array<double, 3>> sample_spline(int degree, const std::vector<double>& knots,
                                                 const std::vector<std::array<double, 3>>& control,
                                                 const std::vector<double>& weights);

}  // namespace dxf::contours
