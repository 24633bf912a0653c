#pragma once
// What the command line reports: an input or usage error (exit 2) with the
// file and line it concerns, printed as `acodrill: error: FILE:LINE: what`.
#include <cstdint>
#include <stdexcept>
#include <string>

namespace app {

class UserError : public std::runtime_error {
 public:
  UserError(std::string file, std::uint32_t line, const std::string& message)
      : std::runtime_error(message), file_(std::move(file)), line_(line) {}
  explicit UserError(const std::string& message) : std::runtime_error(message), line_(0) {}
  const std::string& file() const { return file_; }
  std::uint32_t line() const { return line_; }
  // "FILE:LINE: message", "FILE: message" or "message".
  std::string where_what() const {
    std::string s;
    if (!file_.empty()) s += file_ + ":";
    if (!file_.empty() && line_ > 0) s += std::to_string(line_) + ":";
    if (!s.empty()) s += " ";
    return s + what();
  }

 private:
  std::string file_;
  std::uint32_t line_;
};

}  // namespace app
