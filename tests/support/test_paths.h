// Where tests find their inputs: the repository (scenes, lessons, baselines), ../shared (reference data), the
// build.
#pragma once

#include <string>

namespace rt::test {

std::string sourcePath(const std::string& relative);  // <repo>/relative
std::string sharedPath(const std::string& relative);  // <repo>/../shared/relative
std::string binaryPath(const std::string& relative);  // <build>/relative
std::string cliPath();                                // the radiosity executable
bool sharedAvailable();  // false when ../shared is absent (tests then GTEST_SKIP)
// A fresh empty folder under the build tree for one test's outputs (build/<preset>/test-output/<name>-<pid>).
std::string scratchDir(const std::string& name);
// Runs a command through the shell; returns its exit code and captures stdout+stderr.
int runCommand(const std::string& command, std::string* output = nullptr);

}  // namespace rt::test
