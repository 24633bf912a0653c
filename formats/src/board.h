#pragma once
// Issue 86: what the IPC-2581 and ODB++ readers share: a placement (a panel's
// step-and-repeat copy), the choice of step, a slot fitted to its outline,
// and the drill sources a board job holds — plated and non-plated holes, a
// blind or buried span — each a LoadedHoles of its own, as PTH and NPTH
// drill files are.
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "formats/holes.h"

namespace formats::board {

// x' = origin + R(angle) · M · (x − datum): a step placed in its parent,
// composed with the parent's own placement. Angles counter-clockwise, degrees.
struct Placement {
  double a = 1, b = 0, c = 0, d = 1;  // the linear part, row-major
  double tx = 0, ty = 0;
  aco::Point2 apply(aco::Point2 p) const { return {a * p.x + b * p.y + tx, c * p.x + d * p.y + ty}; }
  // This placement after `inner`: p ↦ this(inner(p)).
  Placement after(const Placement& inner) const {
    Placement r;
    r.a = a * inner.a + b * inner.c;
    r.b = a * inner.b + b * inner.d;
    r.c = c * inner.a + d * inner.c;
    r.d = c * inner.b + d * inner.d;
    r.tx = a * inner.tx + b * inner.ty + tx;
    r.ty = c * inner.tx + d * inner.ty + ty;
    return r;
  }
  // A child placed with its `datum` at `at`, rotated and, first, mirrored in X.
  static Placement of(aco::Point2 at, double angle_deg, bool mirror, aco::Point2 datum) {
    const double rad = angle_deg * 3.14159265358979323846 / 180.0;
    const double co = std::cos(rad), si = std::sin(rad);
    const double m = mirror ? -1.0 : 1.0;
    Placement r;
    r.a = co * m;
    r.b = -si;
    r.c = si * m;
    r.d = co;
    r.tx = at.x - (r.a * datum.x + r.b * datum.y);
    r.ty = at.y - (r.c * datum.x + r.d * datum.y);
    return r;
  }
};

// The step to read: `wanted` (--step) if given; else the one top step (no
// other step places it) that places others — the panel —; else the only
// step. `steps` lists every step with the steps it places; several
// candidates or a name that is not there: InputError naming them.
std::string choose_step(const std::string& path, const std::vector<std::pair<std::string, std::vector<std::string>>>& steps,
                        const std::string& wanted);

// A slot from the points of its outline (a stadium, convex): the narrowest
// rectangle around the points with a side along one of its edges — a
// stadium's straight sides are edges — is the slot's width and length.
// False: fewer than 3 points, or round (then `hole` holds the circle's
// centre and diameter).
bool fit_slot(const std::vector<aco::Point2>& outline, Slot& slot, aco::Hole& hole);

// Where a drill layer goes through the board: conductor layers `from` and
// `to` (1-based, top first) of `conductors`; 0, 0: through (not said).
struct Span {
  int from = 0, to = 0, conductors = 0;
  bool back_drill = false;  // IPC-2581 BACKDRILL: drilled from one side to remove a via's stub (not plated)
  bool through() const {
    return !back_drill && (from == 0 || (std::min(from, to) == 1 && std::max(from, to) == conductors));
  }
};

// The drill sources of a board file: each hole goes to the source of its
// plating and span, made on first use; sources() orders through-holes plated
// first, then non-plated, then the blind and buried spans as first met.
class Sources {
 public:
  explicit Sources(InputFormat format) : format_(format) {}
  LoadedHoles& of(bool plated, const Span& span);
  std::vector<LoadedHoles> take(const std::string& description, std::vector<Note> warnings, std::vector<Note> skipped);

 private:
  InputFormat format_;
  std::vector<std::pair<std::string, LoadedHoles>> made_;  // label, holes
};

// "160.02 x 99.06 mm" for a bounding box of points; empty for none.
std::string size_text(const std::vector<aco::Point2>& points);

}  // namespace formats::board
