#pragma once
// An input or usage error (exit 2) with the file and line it concerns, printed
// as `acodrill: error: FILE:LINE: what`. Every reader throws it; the command
// line knows it as app::UserError.
#include <cstdint>
#include <stdexcept>
#include <string>

namespace formats {

class InputError : public std::runtime_error {
 public:
  InputError(std::string file, std::uint32_t line, const std::string& message)
      : std::runtime_error(message), file_(std::move(file)), line_(line) {}
  explicit InputError(const std::string& message) : std::runtime_error(message), line_(0) {}
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

}  // namespace formats
