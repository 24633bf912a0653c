// The time a program takes as a control runs it (motion_time.h): a reader of
// the words our dialects write, turning each line into straight moves (arcs
// cut into chords, canned cycles expanded), and a planner that times them
// as GRBL 1.1h's does (planner.c, motion_control.c).
#include "gcode/motion_time.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <optional>
#include <string>

#include "aco/charconv.h"
#include "gcode/interpreter.h"

namespace gcode {

namespace {

using Vec = std::array<double, 3>;
enum class Share { Moves, Drilling };

struct Block {
  double length = 0.0, nominal = 0.0, accel = 0.0;  // mm, mm/s, mm/s^2
  double max_entry_sqr = 0.0;                       // (mm/s)^2: junction and nominal speeds
  Share share = Share::Moves;
};

// The largest value along `unit` that no axis's limit exceeds (GRBL's limit_value_by_axis_maximum).
double along(const double* limit, const Vec& unit) {
  double v = 1e300;
  for (int i = 0; i < 3; ++i) {
    if (std::fabs(unit[i]) > 1e-12) v = std::min(v, limit[i] / std::fabs(unit[i]));
  }
  return v;
}

// Time of a move of `length` entered at v0, left at v1, cruising at most at vn, accelerating at a.
double trapezoid_s(double length, double v0, double v1, double vn, double a) {
  const double accel_d = (vn * vn - v0 * v0) / (2 * a), decel_d = (vn * vn - v1 * v1) / (2 * a);
  if (accel_d + decel_d <= length) return (vn - v0) / a + (vn - v1) / a + (length - accel_d - decel_d) / vn;
  const double peak = std::sqrt(std::max(0.0, (2 * a * length + v0 * v0 + v1 * v1) / 2));
  return (peak - v0) / a + (peak - v1) / a;
}

class Planner {
 public:
  Planner(const Kinematics& k, ProgramTime& out) : k_(k), out_(out) {
    for (int i = 0; i < 3; ++i) {
      rate_[i] = k.rate_mm_min[i] / 60.0;
      accel_[i] = k.accel_mm_s2[i];
    }
  }

  // A straight move from `from` to `to`: rapid (feed_mm_min <= 0) or at a feed.
  void line(const Vec& from, const Vec& to, double feed_mm_min, Share share) {
    Vec d{to[0] - from[0], to[1] - from[1], to[2] - from[2]};
    const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (length < 1e-9) return;
    const bool rapid = feed_mm_min <= 0;
    if (rapid && !k_.linear_rapids) {
      // A dogleg: each axis on its own, the move ends when the slowest does, at rest.
      stop();
      double t = 0.0;
      for (int i = 0; i < 3; ++i) {
        if (std::fabs(d[i]) > 1e-12) t = std::max(t, trapezoid_s(std::fabs(d[i]), 0, 0, rate_[i], accel_[i]));
      }
      spend(share, t);
      prev_ = {0, 0, 0};
      return;
    }
    Vec unit{d[0] / length, d[1] / length, d[2] / length};
    Block b;
    b.length = length;
    b.accel = along(accel_, unit);
    const double rapid_rate = along(rate_, unit);
    b.nominal = rapid ? rapid_rate : std::max(1.0 / 60.0, std::min(feed_mm_min / 60.0, rapid_rate));
    b.share = share;
    if (blocks_.empty() && !moving_) {
      b.max_entry_sqr = 0.0;  // from rest
    } else {
      double junction_sqr = 1e300;
      const double cos_theta = -(prev_[0] * unit[0] + prev_[1] * unit[1] + prev_[2] * unit[2]);
      if (cos_theta > 0.999999) {
        junction_sqr = 0.0;
      } else if (cos_theta >= -0.999999) {
        Vec j{unit[0] - prev_[0], unit[1] - prev_[1], unit[2] - prev_[2]};
        const double jl = std::sqrt(j[0] * j[0] + j[1] * j[1] + j[2] * j[2]);
        for (double& c : j) c /= jl;
        const double sin_half = std::sqrt(0.5 * (1.0 - cos_theta));
        junction_sqr = along(accel_, j) * k_.junction_deviation_mm * sin_half / (1.0 - sin_half);
      }
      b.max_entry_sqr = std::min({junction_sqr, b.nominal * b.nominal, prev_nominal_ * prev_nominal_});
    }
    prev_ = unit;
    prev_nominal_ = b.nominal;
    blocks_.push_back(b);
    moving_ = true;
    if (blocks_.size() >= kFlushAt) run(blocks_.size() - kBuffer);
  }

  // The control waits here for every move to end.
  void stop() {
    run(blocks_.size());
    moving_ = false;
    prev_ = {0, 0, 0};
  }

  void dwell(double seconds, bool spindle_wait) {
    stop();
    if (spindle_wait) out_.spindle_wait_s += seconds;
    else {
      out_.dwell_s += seconds;
      out_.drilling_s += seconds;
    }
    tool_s_ += seconds;
  }

  void probe(double distance, double feed_mm_min) {
    stop();
    if (feed_mm_min > 0) {
      out_.probe_s += distance / feed_mm_min * 60.0;
      tool_s_ += distance / feed_mm_min * 60.0;
    }
  }

  void next_tool() {
    stop();
    out_.per_tool_s.push_back(tool_s_);
    tool_s_ = 0.0;
  }
  void finish() {
    stop();
    out_.per_tool_s.push_back(tool_s_);
  }

 private:
  // GRBL's buffer holds 15 blocks (16 slots, one kept free), the block under
  // way among them, the last ending at rest: a block may not leave faster
  // than the next 14 let the machine stop.
  static constexpr std::size_t kBuffer = 15;
  static constexpr std::size_t kFlushAt = 4096;

  // Times the first `count` blocks (all, at a stop), keeping the rest with their entry.
  void run(std::size_t count) {
    const std::size_t n = blocks_.size();
    for (std::size_t i = 0; i < count; ++i) {
      Block& b = blocks_[i];
      // The fastest the next block may be entered so that the window can stop by its end.
      double exit_sqr = 0.0;
      for (std::size_t j = std::min(n, i + kBuffer); j-- > i + 1;) {
        exit_sqr = std::min(blocks_[j].max_entry_sqr, exit_sqr + 2 * blocks_[j].accel * blocks_[j].length);
      }
      const double entry_sqr = std::min(entry_sqr_, b.max_entry_sqr);
      exit_sqr = std::min(exit_sqr, entry_sqr + 2 * b.accel * b.length);
      const double t = trapezoid_s(b.length, std::sqrt(entry_sqr), std::sqrt(exit_sqr), b.nominal, b.accel);
      spend(b.share, t);
      entry_sqr_ = exit_sqr;
    }
    blocks_.erase(blocks_.begin(), blocks_.begin() + static_cast<long>(count));
    if (blocks_.empty()) entry_sqr_ = 0.0;
  }

  void spend(Share share, double t) {
    (share == Share::Moves ? out_.moves_s : out_.drilling_s) += t;
    tool_s_ += t;
  }

  const Kinematics& k_;
  ProgramTime& out_;
  double rate_[3], accel_[3];
  std::vector<Block> blocks_;
  Vec prev_{0, 0, 0};
  double prev_nominal_ = 0.0;
  double entry_sqr_ = 0.0;
  bool moving_ = false;
  double tool_s_ = 0.0;
};

struct Word {
  char letter;
  double value;
  bool integer = false;  // written without a decimal point (a canned cycle's P: milliseconds)
};

// The words of a line, comments left out; a word GRBL or LinuxCNC would refuse is ProgramError.
std::vector<Word> words_of(std::string_view line, std::uint32_t number) {
  std::vector<Word> out;
  std::size_t i = 0;
  while (i < line.size()) {
    const char c = static_cast<char>(std::toupper(static_cast<unsigned char>(line[i])));
    if (c == '(') {
      const std::size_t close = line.find(')', i);
      i = close == std::string_view::npos ? line.size() : close + 1;
      continue;
    }
    if (c == ';') break;
    if (c == ' ' || c == '\t' || c == '\r' || c == '%') {
      ++i;
      continue;
    }
    if (!std::isalpha(static_cast<unsigned char>(c))) throw ProgramError(number, "unexpected '" + std::string(1, c) + "'");
    ++i;
    std::string num;
    while (i < line.size() && (std::isdigit(static_cast<unsigned char>(line[i])) || line[i] == '.' || line[i] == '-' ||
                               line[i] == '+' || line[i] == ' ')) {
      if (line[i] != ' ' && line[i] != '+') num += line[i];
      ++i;
    }
    double v = 0.0;
    auto r = aco::from_chars(num.data(), num.data() + num.size(), v);
    if (num.empty() || r.ec != std::errc() || r.ptr != num.data() + num.size()) {
      throw ProgramError(number, std::string("a number after ") + c);
    }
    out.push_back({c, v, num.find('.') == std::string::npos});
    // M0, M1 and M117 (Marlin) take the rest of the line as their message.
    if (c == 'M' && (v == 0 || v == 1 || v == 117)) break;
  }
  return out;
}

bool is_g(const Word& w, double code) { return w.letter == 'G' && std::fabs(w.value - code) < 1e-6; }

}  // namespace

ProgramTime time_program(std::string_view program, const Kinematics& k) {
  ProgramTime out;
  Planner planner(k, out);
  Vec pos{0, 0, 0};
  bool absolute = true, inch = false, r_retract = false;
  int motion = 0;  // 0, 1, 2, 3, 38, 73, 81, 82, 83; -1: none (G80)
  double feed = 0.0, rpm = 0.0, cycle_r = 0.0, cycle_z = 0.0, cycle_q = 0.0, cycle_p = 0.0, initial_z = 0.0;
  bool cycle_active = false, spindle_just_started = false;
  double probe_from_z = 0.0;
  bool probing = false;
  std::uint32_t number = 0;
  std::size_t start = 0;
  auto share_of_rapid = [](const Vec& from, const Vec& to) {
    const bool xy = std::fabs(to[0] - from[0]) > 1e-9 || std::fabs(to[1] - from[1]) > 1e-9;
    return xy || from[2] >= -1e-9 ? Share::Moves : Share::Drilling;
  };
  auto rapid = [&](const Vec& to) {
    planner.line(pos, to, 0.0, share_of_rapid(pos, to));
    pos = to;
  };
  auto feed_to = [&](const Vec& to) {
    planner.line(pos, to, feed, Share::Drilling);
    pos = to;
  };
  while (start <= program.size()) {
    std::size_t end = program.find('\n', start);
    if (end == std::string_view::npos) end = program.size();
    const std::string_view line = program.substr(start, end - start);
    start = end + 1;
    ++number;
    std::vector<Word> words = words_of(line, number);
    if (words.empty()) {
      if (end == program.size()) break;
      continue;
    }
    const double scale = inch ? 25.4 : 1.0;
    bool machine_coords = false, home = false, dwell = false, set_coords = false, new_cycle = false;
    std::optional<double> x, y, z, i_off, j_off, r, q, p, f, k_word, s_word;
    bool p_integer = false;
    int new_motion = motion;
    for (const Word& w : words) {
      switch (w.letter) {
        case 'G':
          if (is_g(w, 0) || is_g(w, 1) || is_g(w, 2) || is_g(w, 3)) new_motion = static_cast<int>(w.value);
          else if (is_g(w, 38.2) || is_g(w, 38.3) || is_g(w, 38.4) || is_g(w, 38.5)) new_motion = 38;
          else if (is_g(w, 33.1)) new_motion = 331;
          else if (is_g(w, 73) || is_g(w, 81) || is_g(w, 82) || is_g(w, 83) || is_g(w, 84) || is_g(w, 74) || is_g(w, 85)) {
            new_motion = static_cast<int>(w.value);
            new_cycle = true;
          } else if (is_g(w, 80)) new_motion = -1;
          else if (is_g(w, 90)) absolute = true;
          else if (is_g(w, 91)) absolute = false;
          else if (is_g(w, 20)) inch = true;
          else if (is_g(w, 21)) inch = false;
          else if (is_g(w, 98)) r_retract = false;
          else if (is_g(w, 99)) r_retract = true;
          else if (is_g(w, 53)) machine_coords = true;
          else if (is_g(w, 28)) home = true;
          else if (is_g(w, 4)) dwell = true;
          else if (is_g(w, 10)) set_coords = true;
          break;
        case 'M': {
          const int m = static_cast<int>(w.value);
          if (m == 0 || m == 1) {
            planner.stop();
            ++out.pauses;
          } else if (m == 6) {
            planner.next_tool();
            ++out.tool_changes;
          } else if (m == 3 || m == 4) {
            planner.stop();
            spindle_just_started = true;
          } else if (m == 5 || m == 7 || m == 8 || m == 9 || m == 2 || m == 30) {
            planner.stop();
          }
          break;
        }
        case 'T':
          // A tool named without M6 (GRBL, Marlin: the change is at a pause): a change all the same.
          if (std::none_of(words.begin(), words.end(), [](const Word& v) { return v.letter == 'M' && static_cast<int>(v.value) == 6; })) {
            planner.next_tool();
            ++out.tool_changes;
          }
          break;
        case 'X': x = w.value; break;
        case 'Y': y = w.value; break;
        case 'Z': z = w.value; break;
        case 'I': i_off = w.value; break;
        case 'J': j_off = w.value; break;
        case 'R': r = w.value; break;
        case 'Q': q = w.value; break;
        case 'P': p = w.value, p_integer = w.integer; break;
        case 'F': f = w.value; break;
        case 'K': k_word = w.value; break;
        case 'S': s_word = w.value; break;
        default: break;  // N, H, O, L, D: no motion
      }
    }
    if (f) feed = *f * scale;
    if (s_word && !dwell) rpm = *s_word;  // (Marlin's "G4 S3" is seconds)
    if (dwell) {
      planner.dwell(p.value_or(0.0) / (k.dwell_p_in_ms ? 1000.0 : 1.0), spindle_just_started);
      spindle_just_started = false;
      continue;
    }
    if (set_coords) {
      // G10 L20 P0 Z.. after a probe: the plate's top is where the probe stopped.
      if (probing && z) planner.probe(std::max(0.0, probe_from_z - *z * scale), feed);
      if (probing && z) pos[2] = *z * scale;
      probing = false;
      planner.stop();
      continue;
    }
    const bool axis = x || y || z;
    Vec target = pos;
    auto coordinate = [&](std::optional<double> v, int a) {
      if (!v) return;
      target[a] = absolute ? *v * scale : pos[a] + *v * scale;
    };
    if (machine_coords) {
      // G53: only Z to machine zero is written (the tool change height).
      if (z) target[2] = k.machine_z0_mm + *z * scale;
      coordinate(x, 0);
      coordinate(y, 1);
      rapid(target);
      continue;
    }
    if (home) {
      planner.stop();
      if (z) rapid({pos[0], pos[1], k.machine_z0_mm});
      planner.stop();
      continue;
    }
    coordinate(x, 0);
    coordinate(y, 1);
    coordinate(z, 2);
    motion = new_motion;
    if (motion == -1) cycle_active = false;
    if (!axis && !new_cycle) {
      if (end == program.size()) break;
      continue;
    }
    if (motion == 0) rapid(target);
    else if (motion == 1) feed_to(target);
    else if (motion == 38) {
      planner.stop();
      ++out.probes;
      probing = true;
      probe_from_z = pos[2];
    } else if (motion == 2 || motion == 3) {
      // GRBL's chords (motion_control.c, mc_arc), the helix's Z shared among them.
      const Vec center{pos[0] + i_off.value_or(0.0) * scale, pos[1] + j_off.value_or(0.0) * scale, 0.0};
      const double r0x = pos[0] - center[0], r0y = pos[1] - center[1];
      const double r1x = target[0] - center[0], r1y = target[1] - center[1];
      const double radius = std::hypot(r0x, r0y);
      double angle = std::atan2(r0x * r1y - r0y * r1x, r0x * r1x + r0y * r1y);
      if (motion == 2) {
        if (angle >= -5e-7) angle -= 2 * M_PI;
      } else if (angle <= 5e-7) {
        angle += 2 * M_PI;
      }
      const double tol = k.arc_tolerance_mm;
      const auto segments = radius > tol ? static_cast<long>(std::floor(std::fabs(0.5 * angle * radius) /
                                                                         std::sqrt(tol * (2 * radius - tol))))
                                         : 0L;
      const double start_angle = std::atan2(r0y, r0x);
      const Vec from = pos;
      for (long s = 1; s < segments; ++s) {
        const double a = start_angle + angle * static_cast<double>(s) / static_cast<double>(segments);
        feed_to({center[0] + radius * std::cos(a), center[1] + radius * std::sin(a),
                 from[2] + (target[2] - from[2]) * static_cast<double>(s) / static_cast<double>(segments)});
      }
      feed_to(target);
    } else if (motion == 331) {
      // LinuxCNC's rigid tapping (issue 82): over X Y at this height, down to
      // Z at K a turn of the spindle, which reverses there, and back up to
      // where it began at the same rate.
      const double start_z = pos[2];
      const double rate = k_word.value_or(0.0) * scale * rpm;
      rapid({target[0], target[1], start_z});
      planner.line(pos, {pos[0], pos[1], target[2]}, rate, Share::Drilling);
      pos[2] = target[2];
      planner.dwell(k.tap_reverse_s, false);
      planner.line(pos, {pos[0], pos[1], start_z}, rate, Share::Drilling);
      pos[2] = start_z;
    } else if (motion == 73 || motion == 81 || motion == 82 || motion == 83 || motion == 84 || motion == 74 || motion == 85) {
      if (r) cycle_r = absolute ? *r * scale : pos[2] + *r * scale;
      if (z) cycle_z = target[2];
      if (q) cycle_q = *q * scale;
      if (p) cycle_p = p_integer && k.cycle_p_integer_ms ? *p / 1000.0 : *p;
      if (!cycle_active) initial_z = pos[2];
      cycle_active = true;
      // Up to R first if below it, then over the hole at that height, down to R.
      if (pos[2] < cycle_r) rapid({pos[0], pos[1], cycle_r});
      rapid({target[0], target[1], pos[2]});
      rapid({pos[0], pos[1], cycle_r});
      const double bottom = cycle_z;
      if ((motion == 83 || motion == 73) && cycle_q > 0) {
        double reached = cycle_r;
        while (reached > bottom + 1e-9) {
          const double next = std::max(bottom, reached - cycle_q);
          feed_to({pos[0], pos[1], next});
          reached = next;
          if (reached <= bottom + 1e-9) break;
          if (motion == 83) {
            rapid({pos[0], pos[1], cycle_r});
            rapid({pos[0], pos[1], reached + k.peck_clearance_mm});
          } else {
            rapid({pos[0], pos[1], reached + k.peck_clearance_mm});
          }
        }
      } else {
        feed_to({pos[0], pos[1], bottom});
      }
      if (motion == 82 && cycle_p > 0) planner.dwell(cycle_p, false);
      if (motion == 84 || motion == 74 || motion == 85) {
        // Tapping: the spindle reverses at the bottom and the tap feeds out at
        // the same pitch; reaming: fed out to R. Then as any cycle.
        if (motion != 85) planner.dwell(k.tap_reverse_s, false);
        feed_to({pos[0], pos[1], cycle_r});
      }
      rapid({pos[0], pos[1], r_retract ? cycle_r : std::max(cycle_r, initial_z)});
    }
    if (end == program.size()) break;
  }
  planner.finish();
  return out;
}

}  // namespace gcode
