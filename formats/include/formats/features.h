#pragma once
/**
 * Hole features (issue 82): what a drawing's circles, arcs and callouts say
 * each hole is, by the top-view conventions a machinist reads.
 *
 *  - Concentric circles (centres within kConcentricMm) are one feature: the
 *    smallest is the hole, drilled through; each larger one is a counterbore
 *    or a countersink, never a hole of its own. Which, is decided by the larger
 *    circle's layer name (a whole word CBORE, C'BORE, COUNTERBORE, SPOTFACE;
 *    CSK, COUNTERSINK), else by a hole callout beside the feature that names it
 *    with its diameter (⌴ / CBORE, ⌵ / CSK, Ø, ↧; or the GD&T font's v, w, n,
 *    x); a callout decides every feature of the same two diameters, unless
 *    another callout says otherwise. Undecided, the larger circle is not
 *    machined and says so.
 *  - A circle with a concentric ARC of kThreadSpanMin..kThreadSpanMax degrees
 *    and a larger diameter is a tapped hole (ISO 6410-1, ASME Y14.6) when the
 *    arc is a standard thread's major diameter and the circle that thread's
 *    minor diameter up to a little over its tap drill (formats/threads.h): it
 *    is drilled at the thread's tap drill.
 *
 * Readers that know no features (Excellon, Gerber, ...) have none; the DXF
 * reader's result goes through recognize_features unless
 * `--concentric separate` asks for every circle drilled through.
 */
#include <cstdint>
#include <string>
#include <vector>

#include "aco/geometry.h"
#include "dxf/reader.h"
#include "formats/processes.h"

namespace formats {

// Centres this close (mm) are one centre.
constexpr double kConcentricMm = 0.01;
// The span of a thread's arc, degrees: about three quarters of a turn, open anywhere.
constexpr double kThreadSpanMin = 240.0, kThreadSpanMax = 300.0;
// A callout is beside a feature when one of its points (where the text
// stands, where its leader or dimension points) lies within this many mm of
// the feature's outer circle.
constexpr double kCalloutReachMm = 30.0;

enum class FeatureKind { Plain, Tapped, Counterbore, Countersink, Undecided };
const char* to_string(FeatureKind kind);  // "plain", "tapped", ...

struct HoleFeature {
  aco::Point2 center;
  FeatureKind kind = FeatureKind::Plain;
  double diameter_mm = 0.0;        // the hole as drawn: the smallest circle
  double drill_mm = 0.0;           // what drills it through: the drawn diameter, or the thread's tap drill
  double outer_diameter_mm = 0.0;  // counterbore, countersink: its circle; tapped: the thread's major; undecided: the larger circle
  std::vector<double> undecided_mm;  // larger circles nothing decided: not machined
  std::string thread;              // tapped: "M3", "1/4-20 UNC"
  double pitch_mm = 0.0;           // tapped
  double depth_mm = 0.0;           // counterbore depth from a callout (0: not given)
  double angle_deg = 0.0;          // countersink angle from a callout (0: not given)
  std::string layer;               // the hole's
  bool inch = false;               // drawn in inches: inch standards first (threads, an 82 degree countersink)
  std::string evidence;            // why: "arc 270 deg, line 812", "layer CBORE", "callout, line 90"
  std::uint32_t line = 0;          // the hole's CIRCLE
  std::uint32_t rule = 0;          // the process table's rule that gives its operations (1-based; 0: the defaults)
};

struct FeatureNote {
  std::uint32_t line = 0;
  std::string message;
};

struct RecognizedFeatures {
  aco::HoleSet holes;                 // one a feature, in file order, at the diameter that drills it through
  std::vector<HoleFeature> features;  // the same order
  std::vector<FeatureNote> warnings;  // one line each, for stderr
  std::vector<FeatureNote> not_made;  // each undecided circle, never machined (header, report, setup sheet)
};

// `circles`: the drawing's holes as read (duplicates removed, filters
// applied); `unit_mm`: millimetres per drawing unit (callouts' numbers are
// in it; 25.4 makes an inch drawing, whose threads are matched inch first).
// `processes`: a process table (--processes), whose first rule that selects
// a feature decides before the layer and the callout (HoleFeature::rule).
RecognizedFeatures recognize_features(const aco::HoleSet& circles, const std::vector<dxf::DrawnArc>& arcs,
                                      const std::vector<dxf::DrawnText>& texts, double unit_mm,
                                      const ProcessTable* processes = nullptr);

// A hole list's feature (issue 82): CSV columns, XML map attributes, in mm
// (0 or empty: not given).
struct ListedFeature {
  std::string thread;  // "M6", "1/4-20 UNC"
  double counterbore_mm = 0.0, counterbore_depth_mm = 0.0, countersink_mm = 0.0, countersink_angle_deg = 0.0;
};
// The feature of `hole` as listed: a thread taps it (`hole` then drilled at
// its tap drill), a counterbore or countersink diameter makes one, nothing a
// plain hole; matched to the process table's rules. Throws InputError (file
// `path`, the hole's line) for what contradicts or names no standard thread.
HoleFeature listed_feature(aco::Hole& hole, const ListedFeature& given, bool inch, const ProcessTable* processes,
                           const std::string& path);

// A hole callout's text as read: a DXF's MTEXT codes, %%c, the GD&T font's
// letters and the Unicode symbols made one plain form ("Ø3.4 THRU ⌴ Ø6.5 ↧ 3.0"
// as "D3.4 THRU CBORE D6.5 DEPTH 3.0"). For the tests and for the evidence.
std::string plain_callout(const std::string& text, bool gdt_font);

// One line a summary shows: "2 tapped (M3), 4 counterbored, 4 undecided"; empty
// when every feature is plain.
std::string features_summary(const std::vector<HoleFeature>& features);

}  // namespace formats
