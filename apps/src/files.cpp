#include "app/files.h"

#include <fcntl.h>
#include <sys/stat.h>
#ifdef _WIN32
#include <windows.h>
#include <shellapi.h>
#include <io.h>
#include <random>
#else
#include <unistd.h>
#endif

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <iterator>
#include <sstream>

#include "app/errors.h"

namespace app {

std::filesystem::path fs_path(const std::string& utf8) { return std::filesystem::u8path(utf8); }

Utf8Argv::Utf8Argv(int argc, char** argv) : args_(argv, argv + argc) {
#ifdef _WIN32
  int count = 0;
  if (LPWSTR* wide = ::CommandLineToArgvW(::GetCommandLineW(), &count)) {
    args_.clear();
    for (int i = 0; i < count; ++i) args_.push_back(std::filesystem::path(wide[i]).u8string());
    ::LocalFree(wide);
    ::SetConsoleOutputCP(CP_UTF8);  // names in messages as the user typed them
  }
#endif
  for (std::string& a : args_) pointers_.push_back(a.data());
  pointers_.push_back(nullptr);
}

namespace {

#ifdef _WIN32
using Stat = struct _stat64;
int stat_of(const std::string& path, Stat* st) { return ::_wstat64(fs_path(path).c_str(), st); }
FILE* open_file(const std::string& path, const wchar_t* mode) { return ::_wfopen(fs_path(path).c_str(), mode); }
int remove_file(const std::string& path) { return ::_wremove(fs_path(path).c_str()); }
#define ACO_MODE(m) L##m
#else
using Stat = struct stat;
int stat_of(const std::string& path, Stat* st) { return ::stat(path.c_str(), st); }
FILE* open_file(const std::string& path, const char* mode) { return std::fopen(path.c_str(), mode); }
#define ACO_MODE(m) m
#endif

}  // namespace

std::string read_file(const std::string& path) {
  if (path == "-") {
    std::ostringstream ss;
    ss << std::cin.rdbuf();
    return ss.str();
  }
  Stat st {};
  if (stat_of(path, &st) != 0) throw UserError(path, 0, std::string("cannot read: ") + std::strerror(errno));
  if (S_ISDIR(st.st_mode)) throw UserError(path, 0, "is a directory, not a file");
  FILE* f = open_file(path, ACO_MODE("rb"));
  if (!f) throw UserError(path, 0, std::string("cannot open: ") + std::strerror(errno));
  std::string data;
  if (S_ISREG(st.st_mode)) data.reserve(static_cast<std::size_t>(st.st_size));
  char buf[1 << 16];
  std::size_t got;
  while ((got = std::fread(buf, 1, sizeof buf, f)) > 0) data.append(buf, got);
  const bool failed = std::ferror(f);
  std::fclose(f);
  if (failed) throw UserError(path, 0, "read error");
  return data;
}

namespace {

// Where an output goes (issue 85). A rename puts a regular file where the
// name was: right for a regular file or a name not taken yet, but done to
// /dev/null it replaced the machine's null device with a file holding the
// program, and done to a FIFO it left the reader with nothing.
enum class Target { replace_atomically, write_in_place };

#ifdef _WIN32
// Windows' reserved device names, in any folder and with any extension
// (NUL, nul.txt, C:\x\CON), and \\.\ paths: devices, never files.
bool is_windows_device(const std::string& path) {
  if (path.rfind("\\\\.\\", 0) == 0 || path.rfind("//./", 0) == 0) return true;
  std::string stem = fs_path(path).filename().u8string();
  stem = stem.substr(0, stem.find('.'));
  while (!stem.empty() && (stem.back() == ' ' || stem.back() == ':')) stem.pop_back();
  for (char& c : stem) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  for (const char* name : {"CON", "PRN", "AUX", "NUL", "CONIN$", "CONOUT$"}) {
    if (stem == name) return true;
  }
  return stem.size() == 4 && (stem.rfind("COM", 0) == 0 || stem.rfind("LPT", 0) == 0) && stem[3] >= '1' && stem[3] <= '9';
}
#else
// /dev/stdout, /dev/stderr and /dev/fd/N name a descriptor this process
// already holds: written through it, as the shell opened it (appending
// after `>>`, a pipe or a socket as well as a file). -1: not such a name.
int descriptor_named(const std::string& path) {
  if (path == "/dev/stdout") return STDOUT_FILENO;
  if (path == "/dev/stderr") return STDERR_FILENO;
  for (const char* prefix : {"/dev/fd/", "/proc/self/fd/"}) {
    const std::string p(prefix);
    if (path.size() > p.size() && path.compare(0, p.size(), p) == 0 &&
        path.find_first_not_of("0123456789", p.size()) == std::string::npos && path.size() - p.size() < 8) {
      return std::stoi(path.substr(p.size()));
    }
  }
  return -1;
}
#endif

// What writing `path` means; a directory or a block device is refused.
// `resolved` is the name to replace: a symbolic link's target, so that the
// link stays a link.
Target target_of(const std::string& path, std::string& resolved) {
  resolved = path;
#ifdef _WIN32
  if (is_windows_device(path)) return Target::write_in_place;
  Stat st {};
  if (stat_of(path, &st) != 0) return Target::replace_atomically;
  if (st.st_mode & _S_IFDIR) throw UserError(path, 0, "is a directory: give the name of a file to write");
  return (st.st_mode & _S_IFREG) ? Target::replace_atomically : Target::write_in_place;
#else
  if (descriptor_named(path) >= 0) return Target::write_in_place;
  Stat st {};
  if (::lstat(path.c_str(), &st) == 0 && S_ISLNK(st.st_mode)) {
    std::error_code ec;
    const std::filesystem::path target = std::filesystem::canonical(path, ec);
    if (!ec) resolved = target.string();
  }
  if (stat_of(resolved, &st) != 0) return Target::replace_atomically;  // not there yet (or a dangling link)
  if (S_ISDIR(st.st_mode)) throw UserError(path, 0, "is a directory: give the name of a file to write");
  if (S_ISBLK(st.st_mode)) throw UserError(path, 0, "is a block device (a disk), not a file: acodrill does not write to it");
  if (S_ISSOCK(st.st_mode)) throw UserError(path, 0, "is a socket, not a file: acodrill cannot write to it");
  return S_ISREG(st.st_mode) ? Target::replace_atomically : Target::write_in_place;
#endif
}

// A device, a FIFO or a terminal, written as it is: nothing renamed, nothing
// created (a name that is not there any more is an error, not a new file).
void write_in_place(const std::string& path, const std::string& content) {
#ifdef _WIN32
  FILE* f = open_file(path, L"wb");
  if (!f) throw UserError(path, 0, std::string("cannot write: ") + std::strerror(errno));
  const bool written = std::fwrite(content.data(), 1, content.size(), f) == content.size();
  const int err = errno;
  if (std::fclose(f) != 0 || !written) throw UserError(path, 0, std::string("cannot write: ") + std::strerror(written ? errno : err));
#else
  const int held = descriptor_named(path);
  const int fd = held >= 0 ? held : ::open(path.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) throw UserError(path, 0, std::string("cannot write: ") + std::strerror(errno));
  const char* p = content.data();
  std::size_t left = content.size();
  int err = 0;
  while (left > 0 && err == 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0) {
      if (errno != EINTR) err = errno;
      continue;
    }
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  if (held < 0 && ::close(fd) != 0 && err == 0) err = errno;
  if (err != 0) throw UserError(path, 0, std::string("cannot write: ") + std::strerror(err));
#endif
}

}  // namespace

void check_output_path(const std::string& path) {
  if (path.empty() || path == "-") return;
  std::string resolved;
  target_of(path, resolved);
}

void write_file_atomic(const std::string& requested, const std::string& content) {
  if (requested == "-") {
    std::cout.write(content.data(), static_cast<std::streamsize>(content.size()));
    std::cout.flush();
    if (!std::cout) throw UserError("-", 0, "cannot write to standard output");
    return;
  }
  std::string path;
  if (target_of(requested, path) == Target::write_in_place) return write_in_place(requested, content);
#ifdef _WIN32
  // Windows: a temporary file beside the target, then MoveFileEx replacing
  // it, written through (rename() will not replace an existing file there).
  std::random_device entropy;
  const std::string tmp = path + ".tmp-" + std::to_string(entropy()) + std::to_string(::GetCurrentProcessId());
  FILE* f = open_file(tmp, L"wbx");
  if (!f) throw UserError(requested, 0, std::string("cannot write: ") + std::strerror(errno));
  const bool written = std::fwrite(content.data(), 1, content.size(), f) == content.size() && std::fflush(f) == 0 &&
                       ::_commit(::_fileno(f)) == 0;
  const int err = errno;
  if (std::fclose(f) != 0 || !written) {
    remove_file(tmp);
    throw UserError(requested, 0, std::string("cannot write: ") + std::strerror(written ? errno : err));
  }
  if (!::MoveFileExW(fs_path(tmp).c_str(), fs_path(path).c_str(), MOVEFILE_REPLACE_EXISTING | MOVEFILE_WRITE_THROUGH)) {
    remove_file(tmp);
    throw UserError(requested, 0, "cannot write (Windows error " + std::to_string(::GetLastError()) + ")");
  }
#else
  // A file replaced keeps its permissions; a new one gets the usual ones
  // (mkstemp creates 0600).
  Stat old {};
  mode_t mode = 0;
  if (stat_of(path, &old) == 0) {
    mode = old.st_mode & 07777;
  } else {
    const mode_t mask = ::umask(0);
    ::umask(mask);
    mode = 0666 & ~mask;
  }
  std::string tmp = path + ".tmp-XXXXXX";
  int fd = ::mkstemp(tmp.data());
  if (fd < 0) throw UserError(requested, 0, std::string("cannot write: ") + std::strerror(errno));
  auto fail = [&](const char* what) {
    const int err = errno;
    ::close(fd);
    ::unlink(tmp.c_str());
    throw UserError(requested, 0, std::string(what) + ": " + std::strerror(err));
  };
  const char* p = content.data();
  std::size_t left = content.size();
  while (left > 0) {
    ssize_t n = ::write(fd, p, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      fail("cannot write");
    }
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0) fail("cannot write");
  ::fchmod(fd, mode);
  if (::close(fd) != 0) {
    const int err = errno;
    ::unlink(tmp.c_str());
    throw UserError(requested, 0, std::string("cannot write: ") + std::strerror(err));
  }
  if (::rename(tmp.c_str(), path.c_str()) != 0) {
    const int err = errno;
    ::unlink(tmp.c_str());
    throw UserError(requested, 0, std::string("cannot write: ") + std::strerror(err));
  }
#endif
}

bool same_file(const std::string& a, const std::string& b) {
  Stat sa {}, sb {};
  if (a == "-" || b == "-") return false;
  if (stat_of(a, &sa) != 0 || stat_of(b, &sb) != 0) return false;
#ifdef _WIN32
  // No inode numbers on Windows: the same file is the same canonical path.
  std::error_code ec;
  return std::filesystem::equivalent(fs_path(a), fs_path(b), ec);
#else
  return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
#endif
}

}  // namespace app
