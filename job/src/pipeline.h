#pragma once
// The job's private parts, shared by plan.cpp (hole inputs) and
// program_job.cpp (a G-code program reordered).
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "aco/error.h"
#include "formats/error.h"
#include "job/plan.h"

namespace job {

namespace detail {

// Issue 72: the program plan is about to hand back, read back as verify
// reads it, must drill what plan read; one that does not is never given
// (exit 3: the fault is acodrill's, not the input's).
void check_own_program(const std::vector<std::string>& faults, const std::string& program_name);
// The test hook of PlanSettings::break_writer_for_test: drops the last line
// that moves to a hole in a cycle ("X... Y...", "N4 X... Y...").
std::string broken_for_test(std::string text);
// The outputs besides the program that the settings ask for.
void make_outputs(Result& r, const PlanSettings& s, const planning::PlanOptions& o, const ReportContext& ctx,
                  const std::vector<gcode::ToolPass>& passes);

}  // namespace detail

struct PlanJob::Impl {
  using Clock = std::chrono::steady_clock;
  Impl(std::vector<InputFile> files, PlanSettings settings, ProgressFn progress, const std::atomic<bool>* stop)
    : s(std::move(settings)), on_progress(std::move(progress)), stop_flag(stop) {
    guard([&] { prepare(std::move(files)); });
  }

  double seconds() const { return std::chrono::duration<double>(Clock::now() - started).count(); }

  // Runs `step`, and makes any exception the job's one-line error.
  template <class Step>
  void guard(Step&& step) {
    if (failed()) return;
    try {
      step();
    } catch (const formats::InputError& e) {
      fail(e.where_what(), 2);
    } catch (const aco::Error& e) {
      fail(e.what(), e.exit_code());
    } catch (const std::bad_alloc&) {
      fail("out of memory", 2);
    } catch (const std::exception& e) {
      fail(std::string("internal: ") + e.what(), 3);
    }
  }
  void fail(const std::string& message, int code) {
    r = Result{};
    r.error = message;
    r.exit_code = code;
    done = true;
  }
  bool failed() const { return r.exit_code != 0; }

  void prepare(std::vector<InputFile> files);
  void prepare_holes();
  void write_hole_program();
  // SolverSettings::time_limit_covers_outputs: the routing's share of the time limit.
  void budget_routing();
  void report(const aco::Progress& p);
  // A G-code program input (program_job.cpp): its checks, then its holes
  // reordered and written in its own style or a dialect.
  void prepare_program();
  void reorder_and_write();
  // A program input is written back in its own style (--keep-style) unless
  // --dialect names one, or --units asks for other units (a rewrite), issue 83.
  bool keeps_style() const { return s.keep_style || (s.dialect.empty() && s.units.empty()); }

  PlanSettings s;
  ProgressFn on_progress;
  const std::atomic<bool>* stop_flag;
  const Clock::time_point started = Clock::now();
  Result r;
  planning::PlanOptions o;
  planning::Origin origin;
  std::string source;       // the inputs as messages name them
  std::vector<std::string> side_notes;
  std::shared_ptr<const formats::ProcessTable> processes;  // --processes (issue 82)
  std::unique_ptr<planning::GroupRouter> router;
  bool done = false;
  // Progress: the tool whose best is known, and when the last call was.
  std::size_t progress_tool = SIZE_MAX;
  double progress_best = 0.0, progress_at = -1.0;
};


}  // namespace job
