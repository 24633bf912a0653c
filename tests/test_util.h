#pragma once
// Helpers shared by the tests: paths, files, and running the built programs.
#ifndef _WIN32
#include <sys/wait.h>
#endif
#include <unistd.h>
#ifdef _WIN32
#include <process.h>
#endif

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "aco/geometry.h"

namespace testutil {

inline std::string source_dir() { return ACO_SOURCE_DIR; }
inline std::string data(const std::string& rel) { return source_dir() + "/tests/data/" + rel; }
inline std::string acodrill() { return ACODRILL_BIN; }

inline std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

inline void spit(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

// A fresh directory, removed when the object goes.
class TempDir {
 public:
  TempDir() {
#ifdef _WIN32
    // No mkdtemp on Windows: a name of our own, made once.
    for (unsigned k = 0;; ++k) {
      const auto p = std::filesystem::temp_directory_path() / ("acodrill-test-" + std::to_string(::_getpid()) + "-" + std::to_string(k));
      if (std::filesystem::create_directory(p)) {
        path_ = p.generic_string();
        break;
      }
    }
#else
    std::string tmpl = (std::filesystem::temp_directory_path() / "acodrill-test-XXXXXX").string();
    path_ = ::mkdtemp(tmpl.data());
#endif
  }
  ~TempDir() { std::filesystem::remove_all(path_); }
  std::string operator/(const std::string& name) const { return path_ + "/" + name; }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

struct Run {
  int code = -1;
  std::string out, err;
};

inline std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// Runs a shell command line; captures stdout, stderr and the exit code.
inline Run run(const std::string& command, const std::string& stdin_text = "") {
  TempDir t;
  const std::string in = t / "in", out = t / "out", err = t / "err";
  spit(in, stdin_text);
  const std::string full = command + " <" + shell_quote(in) + " >" + shell_quote(out) + " 2>" + shell_quote(err);
  int status = std::system(full.c_str());
  Run r;
#ifdef _WIN32
  r.code = status;  // Windows' system() gives the exit code itself
#else
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
#endif
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

// LinuxCNC's interpreter rs274, run in `dir` with `dir` as its HOME too
// (issue 85): it keeps state files in its working directory, and LinuxCNC
// 2.9 maps its tool data into $HOME/.tool.mmap, one file for every rs274 of
// the user, so two runs at once with different tool tables read each
// other's ("Requested tool 7 not found in the tool table"). Every test
// starts rs274 through this.
inline Run rs274_in(const std::string& dir, const std::string& args) {
  return run("cd " + shell_quote(dir) + " && HOME=" + shell_quote(dir) + " rs274 " + args);
}

inline Run acodrill_run(const std::string& args, const std::string& stdin_text = "") {
  return run(shell_quote(acodrill()) + " " + args, stdin_text);
}

// Issue 83: a program whose tool changes are comments only (FreeCAD's grbl
// post writes "( M6 T2 )"; GRBL has no T or M6): no T word in its code.
// rs274 sees no tool change in it, where acodrill reads the comments' tools;
// tests/freecad_programs_test.cpp checks those against FreeCAD's own.
inline bool tools_only_in_comments(const std::string& program) {
  std::string code;
  int depth = 0;
  for (std::size_t i = 0; i < program.size(); ++i) {
    const char c = program[i];
    if (c == '(') ++depth;
    else if (c == ')' && depth > 0) --depth;
    else if (c == ';' && depth == 0) {
      while (i < program.size() && program[i] != '\n') ++i;
      code += '\n';
    } else if (depth == 0) code += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  }
  for (std::size_t at = code.find('T'); at != std::string::npos; at = code.find('T', at + 1)) {
    if (at + 1 < code.size() && std::isdigit(static_cast<unsigned char>(code[at + 1])) &&
        (at == 0 || !std::isalpha(static_cast<unsigned char>(code[at - 1])))) {
      return false;
    }
  }
  return true;
}

// Rows of a holes CSV (x_mm,y_mm,diameter_mm[,layer]) with a header.
inline aco::HoleSet read_holes_csv(const std::string& text) {
  aco::HoleSet holes;
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::istringstream row(line);
    std::string x, y, d, layer;
    std::getline(row, x, ',');
    std::getline(row, y, ',');
    std::getline(row, d, ',');
    std::getline(row, layer);
    if (!layer.empty() && layer.back() == '\r') layer.pop_back();
    holes.push_back({{std::stod(x), std::stod(y)}, std::stod(d), layer, 0});
  }
  return holes;
}

// The holes moved so that the lower left of their centres' bounding box is
// (0, 0): where acodrill puts program zero by default. Computed here, not by
// acodrill, so the tests check its placement independently.
inline void move_lower_left_to_zero(aco::HoleSet& holes) {
  if (holes.empty()) return;
  double x0 = holes[0].center.x, y0 = holes[0].center.y;
  for (const aco::Hole& h : holes) {
    x0 = std::min(x0, h.center.x);
    y0 = std::min(y0, h.center.y);
  }
  for (aco::Hole& h : holes) h.center = {h.center.x - x0, h.center.y - y0};
}

// The real drilling programs of tests/data/real-gcode (each beside its
// NAME.holes.csv, what rs274 drills), sorted.
inline std::vector<std::string> real_gcode_programs() {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(data("real-gcode"))) {
    const std::string name = e.path().filename().string();
    const std::string ext = e.path().extension().string();
    if (name.find(".holes.csv") != std::string::npos) continue;
    if (ext == ".nc" || ext == ".ngc" || ext == ".tap" || (ext == ".txt" && name.find("drill") != std::string::npos)) {
      out.push_back(e.path().string());
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

// A file's name as a test parameter's name: letters and digits only.
inline std::string file_param_name(const std::string& path) {
  std::string n = std::filesystem::path(path).filename().string();
  for (char& c : n) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return n;
}

inline int count_lines(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

}  // namespace testutil
