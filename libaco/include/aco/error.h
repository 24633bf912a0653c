#pragma once
// Errors split by audience (after VROOM): an InputError is the caller's to fix
// (bad parameters, an empty problem) and maps to exit code 2; an InternalError
// is ours. apps/ prints the message and exits with exit_code().
#include <stdexcept>
#include <string>

namespace aco {

class Error : public std::runtime_error {
 public:
  Error(const std::string& message, int exit_code) : std::runtime_error(message), exit_code_(exit_code) {}
  int exit_code() const { return exit_code_; }

 private:
  int exit_code_;
};

class InputError : public Error {
 public:
  explicit InputError(const std::string& message) : Error(message, 2) {}
};

class InternalError : public Error {
 public:
  explicit InternalError(const std::string& message) : Error(message, 3) {}
};

}  // namespace aco
