#include "core/input_error.h"

namespace rt {

std::string SourceLocation::describe() const {
  std::string out = file.empty() ? std::string("<input>") : file;
  if (line > 0) out += ":" + std::to_string(line);
  if (!jsonPath.empty()) out += " at " + jsonPath;
  return out;
}

InputError::InputError(SourceLocation where, const std::string& message)
    : std::runtime_error(where.describe() + ": error: " + message),
      where_(std::move(where)),
      message_(message) {}

}  // namespace rt
