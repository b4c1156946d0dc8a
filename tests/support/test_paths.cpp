#include "support/test_paths.h"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace rt::test {

std::string sourcePath(const std::string& relative) {
  return std::string(RT_SOURCE_DIR) + "/" + relative;
}
std::string dataPath(const std::string& relative) {
  return std::string(RT_SOURCE_DIR) + "/tests/data/" + relative;
}
std::string binaryPath(const std::string& relative) {
  return std::string(RT_BINARY_DIR) + "/" + relative;
}
std::string cliPath() {
  return RT_CLI_PATH;
}
std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}
std::string scratchDir(const std::string& name) {
  // The process id keeps concurrent test processes (ctest -j runs each test of a binary as its own process)
  // from emptying each other's folders.
  const std::filesystem::path dir =
      std::filesystem::path(RT_BINARY_DIR) / "test-output" / (name + "-" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

int runCommand(const std::string& command, std::string* output) {
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return -1;
  std::array<char, 4096> buffer{};
  std::string text;
  while (std::fgets(buffer.data(), buffer.size(), pipe)) text += buffer.data();
  const int status = pclose(pipe);
  if (output) *output = text;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::vector<std::vector<std::string>> readCsv(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::vector<std::string>> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

int column(const std::vector<std::string>& header, const std::string& name) {
  for (std::size_t k = 0; k < header.size(); ++k)
    if (header[k] == name) return static_cast<int>(k);
  ADD_FAILURE() << "no column " << name;
  return 0;
}

}  // namespace rt::test
