#include "cli/output_paths.h"

#include <unistd.h>

#include <filesystem>

#include "core/input_error.h"

namespace rt::cli {

void checkOutputPaths(const std::vector<std::string>& paths) {
  namespace fs = std::filesystem;
  for (const std::string& path : paths) {
    if (path.empty()) continue;
    const fs::path file(path);
    const fs::path folder = file.has_parent_path() ? file.parent_path() : fs::path(".");
    std::error_code error;
    if (!fs::is_directory(folder, error))
      throw InputError({path}, "cannot write here: the folder '" + folder.string() + "' does not exist");
    if (fs::is_directory(file, error)) throw InputError({path}, "cannot write here: it is a folder");
    // access(W_OK) answers for the folder as this user (and root) sees it, without creating a file.
    if (::access(folder.c_str(), W_OK) != 0)
      throw InputError({path}, "cannot write here: the folder '" + folder.string() + "' is not writable");
  }
}

}  // namespace rt::cli
