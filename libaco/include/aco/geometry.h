#pragma once
/**
 * Plain value types shared by every stage (header-only target aco::geometry):
 * readers produce a HoleSet, the solver orders points, the G-code writer
 * drills them. Lengths are millimetres everywhere inside the program; units
 * are converted only at the edges ($INSUNITS in dxf, G20/G21 in gcode).
 *
 * **Example**:
 *   aco::HoleSet holes;
 *   holes.push_back({{10.0, 20.0}, 6.35, "HOLES", 42});
 */
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace aco {

using Length = double;            // millimetres
using HoleIndex = std::uint32_t;  // not uint16_t: PCB panels exceed 65 535 holes

struct Point2 {
  Length x = 0.0;
  Length y = 0.0;
  friend bool operator==(const Point2& a, const Point2& b) { return a.x == b.x && a.y == b.y; }
};

inline Length euclidean(Point2 a, Point2 b) { return std::hypot(a.x - b.x, a.y - b.y); }

struct Hole {
  Point2 center;              // world coordinates, mm
  Length diameter = 0.0;      // mm
  std::string layer;          // DXF layer or Excellon tool name; empty when the format has none
  std::uint32_t source_line = 0;  // 1-based line of the entity in its file; 0 = unknown
  // Nonzero: this hole belongs to a chain (the holes of a drilled slot) that
  // is drilled together and in the order the chain's holes appear in the set.
  std::uint32_t chain = 0;
  // --slots mill: this hole is one end of a slot (its chain holds both ends,
  // in order) that the end mill mills along its length; `diameter` is its width.
  bool slot_end = false;
  // Issue 82: 0, the hole is drilled (through); k > 0, another operation of a
  // hole feature made here (a tap, a counterbore, ...): the job's k-th
  // operation (planning/operations.h), `diameter` its tool's.
  std::uint32_t operation = 0;
};

using HoleSet = std::vector<Hole>;

// An order over a HoleSet: the indices of its holes in drilling order.
using Order = std::vector<HoleIndex>;

}  // namespace aco
