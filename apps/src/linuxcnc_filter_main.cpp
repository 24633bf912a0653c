// acodrill-linuxcnc-filter: LinuxCNC's [FILTER] program for drill files and
// DXF. AXIS runs it as `sh -c "acodrill-linuxcnc-filter 'FILE'"` with no
// standard input, loads what it prints as the program, moves its progress bar
// by the "FILTER_PROGRESS=N" lines on stderr and shows stderr when it fails.
//
// It only turns the machine's INI into `acodrill plan` options and runs the
// acodrill installed beside it (or on PATH) in its place: the program, the
// progress, the one error line and the exit code are acodrill's own, and
// nothing reaches stdout unless the whole program does (plan -o - writes it
// only when complete).
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace {

constexpr const char* kUsage =
    "Usage: acodrill-linuxcnc-filter FILE\n"
    "LinuxCNC's filter for drill files and DXF: plans FILE with acodrill and prints the LinuxCNC program.\n\n"
    "In the machine's INI:\n"
    "  [FILTER]\n"
    "  PROGRAM_EXTENSION = .drl,.xln,.txt,.dxf,.gbr Drill files and drawings (acodrill)\n"
    "  drl = acodrill-linuxcnc-filter\n"
    "  xln = acodrill-linuxcnc-filter\n"
    "  txt = acodrill-linuxcnc-filter\n"
    "  dxf = acodrill-linuxcnc-filter\n"
    "  gbr = acodrill-linuxcnc-filter\n"
    "  [ACODRILL]                  (every key optional)\n"
    "  MACHINE = router            a class (acodrill machines) or a profile file; default router\n"
    "  DRILLS = 0.6,0.8,1.0,1.2    the drills you own (acodrill plan --drills)\n"
    "  END_MILL = 1.0              an end mill for what no drill fits\n"
    "  ORIGIN = lower-left         program zero: lower-left, center, upper-left, drawing or X,Y\n"
    "  TIME_LIMIT = 5              seconds the colony may take (default 5)\n"
    "  UNITS = mm                  program units (default: [TRAJ] LINEAR_UNITS)\n"
    "  also PROBE_PLATE, SLOTS, MATERIAL, THICKNESS, INPUT_UNITS, TOOLS, SIDE, MIRROR_AXIS, ALIGNMENT_PINS,\n"
    "  APERTURES, SEED, THREADS, EXCELLON_FORMAT, DXF_UNITS, ROUND_TOLERANCE, CONCENTRIC, PROCESSES: the\n"
    "  acodrill plan options of the same names; ROUND_CONTOURS = YES reads DXF holes drawn without a CIRCLE\n"
    "  (--round-contours); SPOT = YES spots every hole first (--spot).\n"
    "LinuxCNC sets INI_FILE_NAME to the INI it runs; without it the defaults apply.\n";

// The [ACODRILL] keys and the `acodrill plan` options they become.
const std::map<std::string, std::string>& settings() {
  static const std::map<std::string, std::string> keys = {
      {"MACHINE", "--machine"},         {"DRILLS", "--drills"},       {"END_MILL", "--end-mill"},
      {"ORIGIN", "--origin"},           {"TIME_LIMIT", "--time-limit"}, {"UNITS", "--units"},
      {"PROBE_PLATE", "--probe-plate"}, {"SLOTS", "--slots"},         {"MATERIAL", "--material"},
      {"THICKNESS", "--thickness"},     {"INPUT_UNITS", "--input-units"}, {"TOOLS", "--tools"},
      {"SIDE", "--side"},               {"MIRROR_AXIS", "--mirror-axis"}, {"ALIGNMENT_PINS", "--alignment-pins"},
      {"APERTURES", "--apertures"},     {"SEED", "--seed"},           {"THREADS", "--threads"},
      {"EXCELLON_FORMAT", "--excellon-format"}, {"DXF_UNITS", "--dxf-units"}, {"ROUND_TOLERANCE", "--round-tolerance"},
      {"ROUND_CONTOURS", "--round-contours"}, {"CONCENTRIC", "--concentric"}, {"PROCESSES", "--processes"},
      {"SPOT", "--spot"}};
  return keys;
}

// Keys that switch an option on or off (YES/NO, TRUE/FALSE, 1/0) rather than give it a value.
bool is_switch(const std::string& key) { return key == "ROUND_CONTOURS" || key == "SPOT"; }

[[noreturn]] void fail(const std::string& where, const std::string& what) {
  std::fprintf(stderr, "acodrill: error: %s%s%s\n", where.c_str(), where.empty() ? "" : ": ", what.c_str());
  std::exit(2);
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

struct Setting {
  std::string value;
  std::size_t line = 0;
};

// The keys of two sections of a LinuxCNC INI ("[SECTION]", "KEY = VALUE",
// comments on lines of their own after '#' or ';'); a key given twice: the first.
void read_ini(const std::string& path, std::map<std::string, Setting>& acodrill, std::map<std::string, Setting>& traj) {
  std::ifstream in(path);
  if (!in) fail(path, std::string("cannot read the INI file named by INI_FILE_NAME: ") + std::strerror(errno));
  std::string line, section;
  for (std::size_t n = 1; std::getline(in, line); ++n) {
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#' || t[0] == ';') continue;
    if (t[0] == '[') {
      const auto close = t.find(']');
      section = upper(trim(t.substr(1, close == std::string::npos ? std::string::npos : close - 1)));
      continue;
    }
    const auto eq = t.find('=');
    if (eq == std::string::npos) continue;
    std::map<std::string, Setting>* into = section == "ACODRILL" ? &acodrill : section == "TRAJ" ? &traj : nullptr;
    if (into) into->emplace(upper(trim(t.substr(0, eq))), Setting{trim(t.substr(eq + 1)), n});
  }
}

// acodrill beside this program (the build folder, /usr/bin), else on PATH.
std::string acodrill_binary() {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const std::filesystem::path beside = self.parent_path() / "acodrill";
    if (::access(beside.c_str(), X_OK) == 0) return beside.string();
  }
  return "acodrill";
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 2 && (std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0)) {
    std::fputs(kUsage, stdout);
    return 0;
  }
  if (argc == 2 && std::strcmp(argv[1], "--version") == 0) {
    std::printf("acodrill-linuxcnc-filter " ACO_VERSION "\n");
    return 0;
  }
  if (argc != 2 || argv[1][0] == '\0') {
    std::fputs(kUsage, stderr);
    return 2;
  }
  const std::string file = argv[1];
  std::map<std::string, Setting> acodrill, traj;
  const char* ini = std::getenv("INI_FILE_NAME");
  if (ini && *ini) read_ini(ini, acodrill, traj);

  std::vector<std::string> args = {acodrill_binary(), "plan", file, "-o", "-", "--dialect", "linuxcnc", "--quiet",
                                   "--filter-progress"};
  for (const auto& [key, s] : acodrill) {
    auto option = settings().find(key);
    if (option == settings().end()) {
      std::string known;
      for (const auto& [k, o] : settings()) known += (known.empty() ? "" : ", ") + k;
      fail(std::string(ini) + ":" + std::to_string(s.line), "[ACODRILL] " + key + " is not an acodrill setting (" + known + ")");
    }
    if (s.value.empty()) fail(std::string(ini) + ":" + std::to_string(s.line), "[ACODRILL] " + key + " has no value");
  }
  // A desktop router without a tool changer unless the INI names the machine,
  // the program in the machine's own units, and a budget AXIS waits for.
  const auto given = [&](const char* key) { return acodrill.count(key) > 0; };
  if (!given("MACHINE")) args.insert(args.end(), {"--machine", "router"});
  if (!given("TIME_LIMIT")) args.insert(args.end(), {"--time-limit", "5"});
  if (!given("UNITS") && traj.count("LINEAR_UNITS")) {
    const std::string u = upper(traj.at("LINEAR_UNITS").value);
    args.insert(args.end(), {"--units", u == "INCH" || u == "IN" || u == "IMPERIAL" ? "inch" : "mm"});
  }
  for (const auto& [key, s] : acodrill) {
    if (!is_switch(key)) {
      args.insert(args.end(), {settings().at(key), s.value});
      continue;
    }
    const std::string v = upper(s.value);
    if (v == "YES" || v == "TRUE" || v == "1" || v == "ON") args.push_back(settings().at(key));
    else if (v != "NO" && v != "FALSE" && v != "0" && v != "OFF") {
      fail(std::string(ini) + ":" + std::to_string(s.line), "[ACODRILL] " + key + " is YES or NO (got \"" + s.value + "\")");
    }
  }

  std::vector<char*> argv_out;
  for (std::string& a : args) argv_out.push_back(a.data());
  argv_out.push_back(nullptr);
  ::execvp(argv_out[0], argv_out.data());
  fail("", "cannot run " + args[0] + " (" + std::strerror(errno) + "); install acodrill beside this filter or on PATH");
}
