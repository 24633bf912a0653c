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

void write_file_atomic(const std::string& path, const std::string& content) {
  if (path == "-") {
    std::cout.write(content.data(), static_cast<std::streamsize>(content.size()));
    std::cout.flush();
    if (!std::cout) throw UserError("-", 0, "cannot write to standard output");
    return;
  }
#ifdef _WIN32
  // Windows: a temporary file beside the target, then MoveFileEx replacing
  // it, written through (rename() will not replace an existing file there).
  std::random_device entropy;
  const std::string tmp = path + ".tmp-" + std::to_string(entropy()) + std::to_string(::GetCurrentProcessId());
  FILE* f = open_file(tmp, L"wbx");
  if (!f) throw UserError(path, 0, std::string("cannot write: ") + std::strerror(errno));
  const bool written = std::fwrite(content.data(), 1, content.size(), f) == content.size() && std::fflush(f) == 0 &&
                       ::_commit(::_fileno(f)) == 0;
  const int err = errno;
  if (std::fclose(f) != 0 || !written) {
    remove_file(tmp);
    throw UserError(path, 0, std::string("cannot write: ") + std::strerror(written ? errno : err));
  }
  if (!::MoveFileExW(fs_path(tmp).c_str(), fs_path(path).c_str(), MOVEFILE_REPLACE_EXISTING | MOVEFILE_WRITE_THROUGH)) {
    remove_file(tmp);
    throw UserError(path, 0, "cannot write (Windows error " + std::to_string(::GetLastError()) + ")");
  }
#else
  std::string tmp_template = path + ".tmp-XXXXXX";
  std::string tmp = tmp_template;
  int fd = ::mkstemp(tmp.data());
  if (fd < 0) throw UserError(path, 0, std::string("cannot write: ") + std::strerror(errno));
  auto fail = [&](const char* what) {
    const int err = errno;
    ::close(fd);
    ::unlink(tmp.c_str());
    throw UserError(path, 0, std::string(what) + ": " + std::strerror(err));
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
  // mkstemp creates 0600; give the file the usual permissions.
  mode_t mask = ::umask(0);
  ::umask(mask);
  ::fchmod(fd, 0666 & ~mask);
  if (::close(fd) != 0) {
    const int err = errno;
    ::unlink(tmp.c_str());
    throw UserError(path, 0, std::string("cannot write: ") + std::strerror(err));
  }
  if (::rename(tmp.c_str(), path.c_str()) != 0) {
    const int err = errno;
    ::unlink(tmp.c_str());
    throw UserError(path, 0, std::string("cannot write: ") + std::strerror(err));
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
