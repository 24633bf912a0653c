#pragma once
// File input and output the way a CAM pipeline needs it: inputs read whole
// (or from stdin for "-"), outputs written to a temporary name beside the
// target and renamed into place only when complete, so a failed run never
// leaves a truncated program behind and never touches an existing file;
// devices and FIFOs are written in place.
#include <filesystem>
#include <string>
#include <vector>

namespace app {

// acodrill holds every file name as UTF-8, whatever the system (issue 68):
// this is the name for the file system (on Windows its UTF-16 form, so a
// name outside the ANSI code page opens).
std::filesystem::path fs_path(const std::string& utf8);

// The command line as UTF-8: on Windows the arguments as the system holds
// them (UTF-16), not as the ANSI code page mangles them, and the console
// told to show UTF-8; elsewhere argv as it is. Holds the strings for as
// long as `argv()` is used.
class Utf8Argv {
 public:
  Utf8Argv(int argc, char** argv);
  int argc() const { return static_cast<int>(args_.size()); }
  char** argv() { return pointers_.data(); }

 private:
  std::vector<std::string> args_;
  std::vector<char*> pointers_;
};

// Reads a whole file, or standard input for "-". Throws UserError.
std::string read_file(const std::string& path);

// Writes `content` to `path` ("-" = standard output). A regular file, or a
// name not taken yet, is written atomically: a temporary file beside it,
// renamed into place when complete (through a symbolic link, to its target).
// A device, a FIFO or a terminal (/dev/null, /dev/stdout, a named pipe; NUL
// and CON on Windows) is opened and written in place, never renamed over.
// A directory, a block device or a socket: UserError, as every failure.
void write_file_atomic(const std::string& path, const std::string& content);

// Throws the UserError write_file_atomic would for a path that can never be
// written (a directory, ...): checked before a long job, not after it.
void check_output_path(const std::string& path);

// True when two paths name the same existing file.
bool same_file(const std::string& a, const std::string& b);

}  // namespace app
