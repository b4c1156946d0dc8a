// Output files are checked before any computation: a path whose folder does not exist or cannot be written
// fails at once, naming the path, instead of after a long solve.
#pragma once

#include <string>
#include <vector>

namespace rt::cli {

// Throws InputError naming the first path (empty ones are skipped) whose file cannot be created.
void checkOutputPaths(const std::vector<std::string>& paths);

}  // namespace rt::cli
