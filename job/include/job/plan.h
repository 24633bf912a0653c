#pragma once
/**
 * One call plans a job (issue 64): the inputs as bytes with their names,
 * the settings of `acodrill plan` as one value, and back in memory what the
 * command writes (the program, the report, the pictures, the setup sheet,
 * the optimized drill files, the convergence rows), the summary as values,
 * or acodrill's one-line error. No file, terminal or environment is touched
 * here: the command line, the page and a test are front ends of it.
 *
 *   job::PlanSettings settings;
 *   settings.machine = "router";
 *   settings.bench.drills = "0.8,1.0";
 *   settings.wanted.report = true;
 *   job::Result r = job::plan({{"board.drl", bytes}}, settings);
 *   if (r.exit_code != 0) show(r.error); else save(r.files.program);
 *
 * A front end that cannot wait for the whole run (a browser's worker, which
 * handles no message while C++ runs) drives a PlanJob in slices instead:
 *
 *   job::PlanJob run(inputs, settings, on_progress);
 *   while (!run.advance(0, 0.1)) { ...handle messages; maybe break... }
 *   job::Result r = run.finish();  // before the end: the best routes so far
 *
 * With the same inputs, settings and seed and a fixed iteration count the
 * result is byte for byte the same however the run is sliced, on any number
 * of threads.
 */
#include <atomic>
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "job/inputs.h"
#include "job/report.h"
#include "job/settings.h"
#include "planning/plan.h"

namespace job {

// Where a run is: called whenever the tool's best route improves, and at
// least every 200 ms of routing (an iteration allowing); from the thread
// that runs the job or one of its workers, never two at once.
struct Progress {
  std::size_t tool = 0;        // the tool being routed, 0 for the first
  std::size_t tools = 0;       // tools in the job
  int tool_number = 0;         // its T number
  double tool_diameter_mm = 0.0;
  std::size_t holes = 0;       // its holes
  int iteration = 0;           // of its colony
  int iterations = 0;          // its colony's budget (INT_MAX: until the time limit)
  double best_length = 0.0;    // its best route so far: mm (seconds of rapids with objective "time")
  double elapsed_s = 0.0;      // since the job began
  bool improved = false;       // the best route changed since the last call
};
using ProgressFn = std::function<void(const Progress&)>;

// What the command writes, as text; each empty unless asked (Wanted) or made.
struct Files {
  std::string program;      // always, when the job succeeds
  std::string report;       // --report (JSON)
  std::string convergence;  // --convergence (CSV)
  std::string route_svg;    // --svg
  std::string compare_svg;  // --svg-compare
  std::string setup_sheet;  // --setup-sheet (HTML)
  std::string excellon;     // --excellon
  std::string gerber;       // --gerber
};

struct Result {
  int exit_code = 0;   // 0; 2: the inputs or settings are wrong; 3: acodrill's own fault
  std::string error;   // the one line a front end shows after "acodrill: error: "
  bool stopped = false;  // ended early (stop flag or finish()): the best routes found so far
  // SolverSettings::time_limit_covers_outputs left the colony no time: each
  // tool's holes in their nearest-neighbour route.
  bool no_time_for_colony = false;
  Files files;
  // The summary as values.
  aco::HoleSet holes;          // as drilled, in program coordinates
  planning::PlanResult plan;   // tools, drill map, orders, and the travel, time and time split of
                               // input order, nearest neighbour and the plan
  planning::Placement placement;
  Inputs inputs;               // each input as read (format, notes, warnings, assumptions); holes in `holes`
  std::optional<ReportContext::ProgramInput> program_input;  // a G-code program reordered
  std::size_t panel_copies = 1;
  gcode::Dialect dialect = gcode::Dialect::Haas;
};

class PlanJob {
 public:
  // Reads the inputs and checks the settings; an error shows in finish().
  // `stop` (may be null), set from any thread, ends the routing after the
  // iteration under way, with the best routes so far.
  PlanJob(std::vector<InputFile> inputs, PlanSettings settings, ProgressFn progress = {},
          const std::atomic<bool>* stop = nullptr);
  ~PlanJob();
  PlanJob(PlanJob&&) noexcept;
  PlanJob& operator=(PlanJob&&) noexcept;
  // Routes until the job is done (true) or `iterations` more colony
  // iterations (0: no bound) or `seconds` (0: none) have passed. A program
  // input is reordered in one slice.
  bool advance(int iterations = 0, double seconds = 0.0);
  // The outputs; before the routing is done it ends there (stopped). Call once.
  Result finish();
  // What is known before finish(): from construction the holes (in program
  // coordinates), the inputs as read, program zero, the tools and their
  // holes (plan.groups' input orders; a G-code program input's holes are
  // inputs.holes.holes until it is reordered), or the error.
  const Result& state() const;
  // Each tool's route as it stands, before finish(), to draw while the colony works (holes'
  // indices; a tool not yet routed in its input order).
  std::vector<aco::Order> routes_so_far() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The whole job in one call.
Result plan(std::vector<InputFile> inputs, const PlanSettings& settings, ProgressFn progress = {},
            const std::atomic<bool>* stop = nullptr);

// "D0.750 MM, 12 HOLES: T2 0.800 MM DRILL, +0.050 MM": how a designed diameter is made.
std::string drill_map_line(const planning::DrillMapping& d);

}  // namespace job
