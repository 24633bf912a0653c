// The standard threads' tables (formats/threads.h names the sources).
#include "formats/threads.h"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace formats {

namespace {

struct Metric {
  double major, pitch, tap_drill;
};

// ISO 261 coarse pitches with the ISO 2306 / DIN 336 tap drills.
constexpr Metric kCoarse[] = {
    {1, 0.25, 0.75},  {1.2, 0.25, 0.95}, {1.4, 0.3, 1.1},   {1.6, 0.35, 1.25}, {1.8, 0.35, 1.45}, {2, 0.4, 1.6},
    {2.2, 0.45, 1.75}, {2.5, 0.45, 2.05}, {3, 0.5, 2.5},    {3.5, 0.6, 2.9},   {4, 0.7, 3.3},     {4.5, 0.75, 3.7},
    {5, 0.8, 4.2},    {6, 1.0, 5.0},     {7, 1.0, 6.0},     {8, 1.25, 6.8},    {9, 1.25, 7.8},    {10, 1.5, 8.5},
    {11, 1.5, 9.5},   {12, 1.75, 10.2},  {14, 2.0, 12.0},   {16, 2.0, 14.0},   {18, 2.5, 15.5},   {20, 2.5, 17.5},
    {22, 2.5, 19.5},  {24, 3.0, 21.0},   {27, 3.0, 24.0},   {30, 3.5, 26.5},   {33, 3.5, 29.5},   {36, 4.0, 32.0},
    {39, 4.0, 35.0},  {42, 4.5, 37.5},   {45, 4.5, 40.5},   {48, 5.0, 43.0},   {52, 5.0, 47.0},   {56, 5.5, 50.5},
    {60, 5.5, 54.5},  {64, 6.0, 58.0},
};

// ISO 261 fine pitches (the usual ones), tap drills per DIN 336 (D - P where it lists none).
constexpr Metric kFine[] = {
    {1, 0.2, 0.8},      {1.2, 0.2, 1.0},     {1.4, 0.2, 1.2},    {1.6, 0.2, 1.4},    {1.8, 0.2, 1.6},
    {2, 0.25, 1.75},    {2.2, 0.25, 1.95},   {2.5, 0.35, 2.15},  {3, 0.35, 2.65},    {3.5, 0.35, 3.15},
    {4, 0.5, 3.5},      {4.5, 0.5, 4.0},     {5, 0.5, 4.5},      {6, 0.75, 5.2},     {7, 0.75, 6.2},
    {8, 1.0, 7.0},      {8, 0.75, 7.2},      {9, 1.0, 8.0},      {9, 0.75, 8.2},     {10, 1.25, 8.8},
    {10, 1.0, 9.0},     {10, 0.75, 9.2},     {11, 1.0, 10.0},    {12, 1.5, 10.5},    {12, 1.25, 10.8},
    {12, 1.0, 11.0},    {14, 1.5, 12.5},     {14, 1.25, 12.8},   {14, 1.0, 13.0},    {16, 1.5, 14.5},
    {16, 1.0, 15.0},    {18, 2.0, 16.0},     {18, 1.5, 16.5},    {18, 1.0, 17.0},    {20, 2.0, 18.0},
    {20, 1.5, 18.5},    {20, 1.0, 19.0},     {22, 2.0, 20.0},    {22, 1.5, 20.5},    {24, 2.0, 22.0},
    {24, 1.5, 22.5},    {27, 2.0, 25.0},     {27, 1.5, 25.5},    {30, 2.0, 28.0},    {30, 1.5, 28.5},
    {33, 2.0, 31.0},    {36, 3.0, 33.0},     {36, 2.0, 34.0},    {36, 1.5, 34.5},
};

struct Unified {
  const char* size;  // "#4", "1/4"
  double major_in;
  int tpi;
  double tap_drill_in;
};

// ASME B1.1 UNC, tap drills for about 75 % thread.
constexpr Unified kUnc[] = {
    {"#1", 0.073, 64, 0.0595}, {"#2", 0.086, 56, 0.0700},  {"#3", 0.099, 48, 0.0785},   {"#4", 0.112, 40, 0.0890},
    {"#5", 0.125, 40, 0.1015}, {"#6", 0.138, 32, 0.1065},  {"#8", 0.164, 32, 0.1360},   {"#10", 0.190, 24, 0.1495},
    {"#12", 0.216, 24, 0.1770}, {"1/4", 0.250, 20, 0.2010}, {"5/16", 0.3125, 18, 0.2570}, {"3/8", 0.375, 16, 0.3125},
    {"7/16", 0.4375, 14, 0.3680}, {"1/2", 0.500, 13, 0.4219}, {"9/16", 0.5625, 12, 0.4844}, {"5/8", 0.625, 11, 0.5312},
    {"3/4", 0.750, 10, 0.6562}, {"7/8", 0.875, 9, 0.7656},  {"1", 1.000, 8, 0.8750},
};

// ASME B1.1 UNF.
constexpr Unified kUnf[] = {
    {"#0", 0.060, 80, 0.0469},  {"#1", 0.073, 72, 0.0595},  {"#2", 0.086, 64, 0.0700},   {"#3", 0.099, 56, 0.0820},
    {"#4", 0.112, 48, 0.0935},  {"#5", 0.125, 44, 0.1040},  {"#6", 0.138, 40, 0.1130},   {"#8", 0.164, 36, 0.1360},
    {"#10", 0.190, 32, 0.1590}, {"#12", 0.216, 28, 0.1820}, {"1/4", 0.250, 28, 0.2130},  {"5/16", 0.3125, 24, 0.2720},
    {"3/8", 0.375, 24, 0.3320}, {"7/16", 0.4375, 20, 0.3906}, {"1/2", 0.500, 20, 0.4531}, {"9/16", 0.5625, 18, 0.5156},
    {"5/8", 0.625, 18, 0.5781}, {"3/4", 0.750, 16, 0.6875}, {"7/8", 0.875, 14, 0.8125},  {"1", 1.000, 12, 0.9219},
};

std::string number(double v) {
  std::string s = std::to_string(v);
  s.erase(s.find_last_not_of('0') + 1);
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}

std::vector<Thread> make_tables() {
  std::vector<Thread> t;
  for (const Metric& m : kCoarse) t.push_back({"M" + number(m.major), "ISO metric coarse", m.major, m.pitch, m.tap_drill, false});
  for (const Metric& m : kFine) {
    t.push_back({"M" + number(m.major) + "x" + number(m.pitch), "ISO metric fine", m.major, m.pitch, m.tap_drill, false});
  }
  auto unified = [&t](const char* series, const Unified* begin, const Unified* end) {
    for (const Unified* u = begin; u != end; ++u) {
      t.push_back({std::string(u->size) + "-" + std::to_string(u->tpi) + " " + series, series, u->major_in * 25.4,
                   25.4 / u->tpi, u->tap_drill_in * 25.4, true});
    }
  };
  unified("UNC", std::begin(kUnc), std::end(kUnc));
  unified("UNF", std::begin(kUnf), std::end(kUnf));
  return t;
}

std::string upper_without_spaces(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (!std::isspace(static_cast<unsigned char>(c))) out += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  }
  return out;
}

}  // namespace

const std::vector<Thread>& standard_threads() {
  static const std::vector<Thread> tables = make_tables();
  return tables;
}

double major_tolerance_mm(double major_mm) { return std::max(0.03, 0.01 * major_mm); }

double tap_drill_allowance_mm(double tap_drill_mm) { return std::max(0.05, 0.015 * tap_drill_mm); }

const Thread* match_thread(double arc_mm, double hole_mm, bool inch_drawing) {
  // Two tiers: the hole between the minor diameter and the tap drill (as
  // drawings show them, rounded), then up to the allowance over the tap drill;
  // within a tier the table's order, coarse before fine.
  for (int pass = 0; pass < 2; ++pass) {
    const bool inch = pass == 0 ? inch_drawing : !inch_drawing;
    for (double over : {kMinorRoundingMm, -1.0}) {
      for (const Thread& t : standard_threads()) {
        if (t.inch != inch || std::fabs(arc_mm - t.major_mm) > major_tolerance_mm(t.major_mm)) continue;
        const double top = t.tap_drill_mm + (over >= 0 ? over : tap_drill_allowance_mm(t.tap_drill_mm));
        if (hole_mm >= t.minor_mm() - kMinorRoundingMm - 1e-9 && hole_mm <= top + 1e-9) return &t;
      }
    }
  }
  return nullptr;
}

const Thread* find_thread(const std::string& name) {
  const std::string wanted = upper_without_spaces(name);
  for (const Thread& t : standard_threads()) {
    const std::string full = upper_without_spaces(t.name);
    if (wanted == full) return &t;
    if (t.inch && wanted + t.series == full) return &t;  // "1/4-20" is the UNC or UNF of that count
    if (!t.inch && t.series == "ISO metric coarse" && wanted == full + "X" + number(t.pitch_mm)) return &t;  // "M3x0.5"
  }
  return nullptr;
}

}  // namespace formats
