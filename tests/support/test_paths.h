// Where tests find their inputs: the repository (scenes, lessons, baselines), the tests' own data (reference
// form factors and the Cornell box measurements in tests/data/refdata, small OBJ/MTL files), the build.
#pragma once

#include <string>
#include <vector>

namespace rt::test {

std::string sourcePath(const std::string& relative);  // <repo>/relative
std::string dataPath(const std::string& relative);    // <repo>/tests/data/relative
std::string binaryPath(const std::string& relative);  // <build>/relative
std::string cliPath();                                // the radiosity executable
// The whole of a file as bytes ("" when it cannot be read).
std::string readFile(const std::string& path);
// A fresh empty folder under the build tree for one test's outputs (build/<preset>/test-output/<name>-<pid>).
std::string scratchDir(const std::string& name);
// Runs a command through the shell; returns its exit code and captures stdout+stderr.
int runCommand(const std::string& command, std::string* output = nullptr);
// The cells of a comma-separated file, row by row, as text (no quoting: the program's own CSV files).
std::vector<std::vector<std::string>> readCsv(const std::string& path);
// The index of the column called `name` in a CSV header row (a test failure, and 0, when there is none).
int column(const std::vector<std::string>& header, const std::string& name);

}  // namespace rt::test
