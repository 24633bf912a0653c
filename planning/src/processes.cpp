// A process table read from JSON (formats/processes.h, issue 82).
#include <algorithm>
#include <set>

#include "formats/threads.h"
#include "json.h"
#include "planning/operations.h"

namespace planning {

namespace {

// The line each rule's object starts on: JSON readers give no positions, and
// a message should name the line a shop engineer opens the file at. The
// rules are the objects of the array under "processes" (or of the root array).
std::vector<std::uint32_t> rule_lines(const std::string& text) {
  std::vector<std::uint32_t> lines;
  std::uint32_t line = 1;
  int depth = 0, array_depth = -1;
  std::string last_key, string_text;
  bool in_string = false, escaped = false;
  for (char c : text) {
    if (c == '\n') ++line;
    if (in_string) {
      if (escaped) escaped = false;
      else if (c == '\\') escaped = true;
      else if (c == '"') in_string = false, last_key = string_text;
      else string_text += c;
      continue;
    }
    if (c == '"') {
      in_string = true;
      string_text.clear();
    } else if (c == '[' || c == '{') {
      if (c == '{' && depth == array_depth) lines.push_back(line);
      if (c == '[' && array_depth < 0 && (depth == 0 || (depth == 1 && last_key == "processes"))) array_depth = depth + 1;
      ++depth;
    } else if (c == ']' || c == '}') {
      --depth;
      if (depth + 1 == array_depth && c == ']') break;
    } else if (c == ',') {
      last_key.clear();
    }
  }
  return lines;
}

std::string text_of(const json& j, const char* key, const std::string& where, std::uint32_t line) {
  if (!j.contains(key)) return "";
  if (!j.at(key).is_string()) throw UserError(where, line, std::string("\"") + key + "\" must be a string");
  return j.at(key).get<std::string>();
}

const char* kOrder = "spot, drill, ream, countersink or counterbore, tap";

}  // namespace

formats::ProcessTable parse_process_table(const std::string& text, const std::string& path) {
  const json j = parse_json_text(text, path);
  const json* list = &j;
  if (j.is_object() && j.contains("processes")) list = &j["processes"];
  if (!list->is_array() || list->empty()) {
    throw UserError(path, 1, "a process table is {\"processes\": [ ... ]} with at least one rule");
  }
  const std::vector<std::uint32_t> lines = rule_lines(text);
  formats::ProcessTable table;
  table.path = path;
  for (std::size_t k = 0; k < list->size(); ++k) {
    const json& e = (*list)[k];
    const std::uint32_t line = k < lines.size() ? lines[k] : 0;
    const std::string rule_name = "process " + std::to_string(k + 1);
    auto fail = [&](const std::string& what) { throw UserError(path, line, rule_name + ": " + what); };
    if (!e.is_object()) fail("each rule is a JSON object");
    for (const auto& [key, value] : e.items()) {
      static const std::set<std::string> known = {"name", "layer", "kind", "diameter_mm", "thread", "operations"};
      if (!known.count(key)) fail("unknown key \"" + key + "\" (a rule has layer, kind, diameter_mm, thread, operations, name)");
    }
    formats::ProcessRule rule;
    const std::string name = text_of(e, "name", path, line);
    rule.where = "process " + std::to_string(k + 1) + (name.empty() ? "" : " (" + name + ")");
    rule.layer = text_of(e, "layer", path, line);
    rule.kind = text_of(e, "kind", path, line);
    static const std::set<std::string> kinds = {"plain", "tapped", "counterbore", "countersink", "undecided"};
    if (!rule.kind.empty() && !kinds.count(rule.kind)) fail("\"kind\" must be plain, tapped, counterbore, countersink or undecided");
    if (e.contains("diameter_mm")) {
      const json& d = e["diameter_mm"];
      if (d.is_number()) {
        const double v = d.get<double>();
        rule.diameter_mm = std::make_pair(v - 0.01, v + 0.01);
      } else if (d.is_array() && d.size() == 2 && d[0].is_number() && d[1].is_number()) {
        rule.diameter_mm = std::make_pair(d[0].get<double>(), d[1].get<double>());
      } else {
        fail("\"diameter_mm\" is a number or [min, max]");
      }
      if (!(rule.diameter_mm->first >= 0 && rule.diameter_mm->first <= rule.diameter_mm->second && rule.diameter_mm->second < 1e4)) {
        fail("\"diameter_mm\" must be [min, max] with 0 <= min <= max");
      }
    }
    rule.thread = text_of(e, "thread", path, line);
    if (!rule.thread.empty() && formats::find_thread(rule.thread) == nullptr) {
      fail("thread \"" + rule.thread + "\" is no standard thread (ISO metric coarse or fine: M6, M10x1.25; UNC, UNF: 1/4-20 UNC, #4-40 UNC)");
    }
    if (!e.contains("operations") || !e["operations"].is_array() || e["operations"].empty()) {
      fail("\"operations\" must list the operations, a drill among them (" + std::string(kOrder) + ")");
    }
    std::set<gcode::Operation> seen;
    std::size_t step_number = 0;
    for (const json& o : e["operations"]) {
      ++step_number;
      const std::string at = "operation " + std::to_string(step_number) + ": ";
      formats::ProcessStep step;
      std::string kind;
      if (o.is_string()) {
        kind = o.get<std::string>();
      } else if (o.is_object()) {
        for (const auto& [key, value] : o.items()) {
          static const std::set<std::string> known = {"operation", "diameter_mm", "depth_mm", "angle_deg", "thread",
                                                      "hand", "rpm", "feed_mm_min", "dwell_s", "name"};
          if (!known.count(key)) fail(at + "unknown key \"" + key + "\"");
        }
        kind = text_of(o, "operation", path, line);
      } else {
        fail(at + "an operation is its name (\"drill\") or an object with \"operation\"");
      }
      const auto op = gcode::operation_from_string(kind);
      if (!op) fail(at + "\"" + kind + "\" is no operation (" + kOrder + ")");
      step.kind = *op;
      if (!seen.insert(step.kind).second) fail(at + "\"" + kind + "\" twice");
      if (o.is_object()) {
        // Numbers checked here, so that a wrong one names the rule's line too.
        auto number = [&](const char* key) -> std::optional<double> {
          if (!o.contains(key)) return std::nullopt;
          if (!o[key].is_number()) fail(at + "\"" + key + "\" must be a number");
          return o[key].get<double>();
        };
        auto positive = [&](const char* key) -> std::optional<double> {
          const std::optional<double> v = number(key);
          if (v && !(*v > 0 && *v < 1e4)) fail(at + "\"" + key + "\" must be positive");
          return v;
        };
        step.diameter_mm = positive("diameter_mm");
        step.depth_mm = positive("depth_mm");
        step.angle_deg = positive("angle_deg");
        if (step.angle_deg && !(*step.angle_deg < 180)) fail(at + "\"angle_deg\" must be below 180");
        if (const auto f = positive("feed_mm_min")) step.feed_mm_min = f;
        if (const auto r = positive("rpm")) step.rpm = static_cast<int>(std::lround(*r));
        step.dwell_s = number("dwell_s");
        if (step.dwell_s && !(*step.dwell_s >= 0 && *step.dwell_s <= 60)) fail(at + "\"dwell_s\" must be 0..60");
        step.thread = text_of(o, "thread", path, line);
        step.name = text_of(o, "name", path, line);
        const std::string hand = text_of(o, "hand", path, line);
        if (!hand.empty() && hand != "right" && hand != "left") fail(at + "\"hand\" must be right or left");
        step.left_hand = hand == "left";
        if ((!step.thread.empty() || !hand.empty()) && step.kind != gcode::Operation::Tap) {
          fail(at + "\"thread\" and \"hand\" are a tap's");
        }
        if (!step.thread.empty() && formats::find_thread(step.thread) == nullptr) {
          fail(at + "thread \"" + step.thread + "\" is no standard thread (ISO metric coarse or fine, UNC, UNF)");
        }
      }
      rule.steps.push_back(step);
    }
    if (!seen.count(gcode::Operation::Drill)) fail("\"operations\" must drill the hole (\"drill\"): " + std::string(kOrder));
    if (seen.count(gcode::Operation::Counterbore) && seen.count(gcode::Operation::Countersink)) {
      fail("a hole is counterbored or countersunk, not both");
    }
    // Made in the order a hole's operations come, whatever order they are listed in.
    std::stable_sort(rule.steps.begin(), rule.steps.end(),
                     [](const formats::ProcessStep& a, const formats::ProcessStep& b) { return a.kind < b.kind; });
    table.rules.push_back(std::move(rule));
  }
  return table;
}

}  // namespace planning
