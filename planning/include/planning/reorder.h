#pragma once
/**
 * Another CAM's drilling program made shorter (issue 14): each tool run's
 * holes reordered by the colony — an open path from where the previous run
 * ended, as plan does — while the runs keep their order and every hole keeps
 * how the input made it. Holes that overlap keep their input order.
 */
#include <memory>
#include <string>

#include "planning/plan.h"
#include "gcode/drilling.h"

namespace planning {

struct ReorderOptions {
  // Holes of a run closer than this (mm), or than the run's drill diameter
  // where the program states it, overlap: a drill beside a fresh overlapping
  // hole wanders, so such holes are drilled together in their input order.
  double min_spacing_mm = 0.0;
};

struct ReorderResult {
  gcode::DrillingProgram program;   // the input's runs, each with its holes in the new order
  aco::HoleSet holes;               // every hole in input order (layer "T<n>"), for reports and pictures
  PlanResult plan;                  // one group a run: input order (the program's own) and optimized
  std::size_t overlapping_holes = 0, overlap_groups = 0;  // kept in input order
};

ReorderResult reorder_program(const gcode::DrillingProgram& input, const PlanOptions& options,
                              const ReorderOptions& reorder);

}  // namespace planning
