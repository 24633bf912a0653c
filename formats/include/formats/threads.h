#pragma once
/**
 * Standard screw threads, as the hole features of a drawing need them
 * (issue 82): a tapped hole drawn with its thread's major diameter is that
 * thread, drilled at its standard tap drill.
 *
 * Sources, tabled in src/threads.cpp:
 *  - ISO metric, coarse and fine pitches: ISO 261 (sizes and pitches), basic
 *    minor diameter of the nut D1 = D - 1.082532 P (ISO 724); tap drills as
 *    ISO 2306 / DIN 336 give them (D - P, rounded to the drills sold).
 *  - Unified inch, UNC and UNF: ASME B1.1 (sizes, threads per inch), the
 *    same D1 formula with P = 1/n inch; tap drills for about 75 % thread, the
 *    usual table (Machinery's Handbook).
 *
 * **Example**:
 *   if (const formats::Thread* t = formats::match_thread(3.0, 2.459, false))
 *     drill(t->tap_drill_mm);   // M3: 2.5
 */
#include <string>
#include <vector>

namespace formats {

struct Thread {
  std::string name;     // "M3", "M10x1.25", "1/4-20 UNC", "#4-40 UNC"
  std::string series;   // "ISO metric coarse", "ISO metric fine", "UNC", "UNF"
  double major_mm = 0.0;
  double pitch_mm = 0.0;
  double tap_drill_mm = 0.0;
  bool inch = false;
  // The nut's basic minor diameter: the smallest the drawn tap-drill circle can be.
  double minor_mm() const { return major_mm - 1.082532 * pitch_mm; }
};

// Every thread of the tables, metric coarse first, then fine, UNC, UNF.
const std::vector<Thread>& standard_threads();

// How close a drawn arc must be to a thread's major diameter: within 1 % or
// 0.03 mm, whichever is larger.
double major_tolerance_mm(double major_mm);

// How far over its tap drill a drawn hole may be and still be that thread's:
// 1.5 % or 0.05 mm, whichever is larger (drawings show the minor diameter, the
// tap drill or a little more; never the major). Small enough that no coarse
// thread's reaches its fine threads' minor diameters.
double tap_drill_allowance_mm(double tap_drill_mm);

// A drawing's minor diameter rounded to its printed digits (M1.6's 1.22114
// drawn as 1.22): how far under the minor diameter a drawn hole may be.
constexpr double kMinorRoundingMm = 0.01;

// The thread of a tapped hole drawn as a circle of `hole_mm` inside an arc of
// `arc_mm`, or nullptr: the arc is a standard major diameter (within
// major_tolerance_mm) and the circle lies between that thread's minor diameter
// (less kMinorRoundingMm) and its tap drill plus tap_drill_allowance_mm.
// Where several threads fit (M10 coarse and fine share the major) the drawn
// hole decides: first a thread whose minor diameter to tap drill holds it,
// then one whose allowance does; then coarse before fine (#8-32 UNC and
// #8-36 UNF share their tap drill: a drawing cannot tell them apart, and
// reads as UNC; so do #1 and #2; #5-44 and #12-28 UNF drawn at their minor
// diameter lie inside #5-40's and #12-24's range and read as those). An inch drawing tries inch threads first, a metric one metric.
const Thread* match_thread(double arc_mm, double hole_mm, bool inch_drawing);

// The thread named as a drawing or a table writes it ("M6", "M10x1.25",
// "1/4-20", "1/4-20 UNC", "#10-32"), or nullptr.
const Thread* find_thread(const std::string& name);

}  // namespace formats
