// Errors in user input (scene files, lesson files, command-line values). They always name where the problem
// is: the file, and a line (text formats) or a JSON path, so that a user can go straight to it.
#pragma once

#include <stdexcept>
#include <string>

namespace rt {

struct SourceLocation {
  std::string file;      // path as given by the user; empty for in-memory input
  int line = 0;          // 1-based; 0 when unknown or not line-based
  std::string jsonPath;  // e.g. "/surfaces/3/vertices/2"; empty for line-based formats

  // "file:line", "file at /json/path", "file" or "<input>".
  std::string describe() const;
};

class InputError : public std::runtime_error {
 public:
  InputError(SourceLocation where, const std::string& message);
  const SourceLocation& where() const { return where_; }
  const std::string& message() const { return message_; }

 private:
  SourceLocation where_;
  std::string message_;
};

}  // namespace rt
