#pragma once
// Machine-readable results: the --report JSON (keys per ../shared/interface.md,
// more may be added, none renamed) and the --convergence CSV.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "planning/plan.h"
#include "formats/holes.h"

namespace job {

// What the outputs say about the job besides the plan itself.
struct ReportContext {
  std::string source;   // input file
  std::string program;  // output program
  planning::Placement placement;  // where program zero sits
  std::string name;     // job name: the input's stem or its own name
  const formats::LoadedHoles* input = nullptr;  // slots drilled, features not drilled
  // Each input of the job with its holes (the report's "sources"); empty: `source` alone.
  std::vector<std::pair<std::string, std::size_t>> sources;
  std::size_t panel_copies = 1;  // copies of the board in one program (--panel)
  std::size_t batch = 1;         // programs run one after another (--batch): the report's "batch"
  // A reordered drilling program (issue 14): how it was read and written.
  struct ProgramInput {
    std::size_t runs = 0;
    std::size_t overlapping_holes = 0, overlap_groups = 0;  // kept in input order
    std::string style;                                      // "dialect" or "keep"
    // --keep-milling: the input's lines that mill, copied as written, and the first of them.
    std::size_t milling_lines = 0;
    std::uint32_t first_milling_line = 0;
  };
  std::optional<ProgramInput> program_input;
  gcode::Dialect dialect = gcode::Dialect::Haas;  // the program's: how its tools' holes are made (the "cycle")
};

std::string report_json(const aco::HoleSet& holes, const planning::PlanResult& plan, const ReportContext& context);
std::string convergence_csv(const planning::PlanResult& plan);

// The holes as `acodrill holes --format csv` prints them (../shared/interface.md):
// header x_mm,y_mm,diameter_mm,layer; 6 decimals; a layer with a comma or quote quoted.
std::string holes_csv(const aco::HoleSet& holes);

// `acodrill holes --features` (issue 82): one row a hole feature, header
// x_mm,y_mm,kind,diameter_mm,outer_diameter_mm,thread,layer,evidence; an
// input without features gives each hole as a plain one.
std::string features_csv(const formats::LoadedHoles& loaded);

}  // namespace job
