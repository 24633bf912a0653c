#include "app/files.h"

#include <fcntl.h>
#include <sys/stat.h>
#ifdef _WIN32
#include <windows.h>
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

std::string read_file(const std::string& path) {
  if (path == "-") {
    std::ostringstream ss;
    ss << std::cin.rdbuf();
    return ss.str();
  }
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) throw UserError(path, 0, std::string("cannot read: ") + std::strerror(errno));
  if (S_ISDIR(st.st_mode)) throw UserError(path, 0, "is a directory, not a file");
  FILE* f = std::fopen(path.c_str(), "rb");
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
  FILE* f = std::fopen(tmp.c_str(), "wbx");
  if (!f) throw UserError(path, 0, std::string("cannot write: ") + std::strerror(errno));
  const bool written = std::fwrite(content.data(), 1, content.size(), f) == content.size() && std::fflush(f) == 0 &&
                       ::_commit(::_fileno(f)) == 0;
  const int err = errno;
  if (std::fclose(f) != 0 || !written) {
    std::remove(tmp.c_str());
    throw UserError(path, 0, std::string("cannot write: ") + std::strerror(written ? errno : err));
  }
  if (!::MoveFileExA(tmp.c_str(), path.c_str(), MOVEFILE_REPLACE_EXISTING | MOVEFILE_WRITE_THROUGH)) {
    std::remove(tmp.c_str());
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
  struct stat sa {}, sb {};
  if (a == "-" || b == "-") return false;
  if (::stat(a.c_str(), &sa) != 0 || ::stat(b.c_str(), &sb) != 0) return false;
#ifdef _WIN32
  // No inode numbers on Windows: the same file is the same canonical path.
  std::error_code ec;
  return std::filesystem::equivalent(a, b, ec);
#else
  return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
#endif
}

}  // namespace app
