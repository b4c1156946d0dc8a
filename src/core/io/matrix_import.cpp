#include "core/io/matrix_import.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <sstream>
#include <vector>

#include "core/input_error.h"
#include "core/io/scene_assembly.h"
#include "core/memory_budget.h"

namespace rt {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& message, int line = 0) {
  throw InputError({path, line, {}}, message);
}

bool hostIsLittleEndian() {
  const std::uint16_t one = 1;
  unsigned char first;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

// Refuses a rows x cols matrix of doubles that cannot fit in memory, before it is allocated.
void checkFits(double rows, double cols, const std::string& path) {
  // Each dimension alone must fit too: a 0 x 10^13 matrix needs no memory, but every loop over its columns
  // would run for hours.
  const double bytes = 8 * std::max({rows * cols, rows, cols}), budget = memoryBudgetBytes();
  if (bytes > budget)
    fail(path, "a " + formatCount(rows) + " x " + formatCount(cols) + " matrix is too large: it needs " +
                   formatBytes(bytes) + "; this machine has " + formatBytes(budget));
}

// The value of `key` in the .npy header's Python dict literal: the text after "'key':" up to the next ',' at
// nesting depth 0 (or the closing brace). A hand parser: the header is untrusted, and std::regex recurses
// per character.
std::optional<std::string> headerValue(const std::string& header, const std::string& key) {
  const std::size_t at = header.find("'" + key + "'");
  if (at == std::string::npos) return std::nullopt;
  std::size_t i = header.find(':', at + key.size() + 2);
  if (i == std::string::npos) return std::nullopt;
  int depth = 0;
  std::string value;
  for (++i; i < header.size(); ++i) {
    const char c = header[i];
    if (c == '(') ++depth;
    if (c == ')') --depth;
    if (depth < 0 || (depth == 0 && (c == ',' || c == '}'))) break;
    value += c;
  }
  value.erase(std::remove_if(value.begin(), value.end(), [](unsigned char c) { return std::isspace(c); }),
              value.end());
  return value;
}

// "(12,34)" -> {12, 34}; nullopt for any other shape.
std::optional<std::pair<long long, long long>> shape2d(const std::string& text) {
  long long rows = 0, cols = 0;
  char open = 0, comma = 0, close = 0;
  std::istringstream in(text);
  if (!(in >> open >> rows >> comma >> cols >> close) || open != '(' || comma != ',' || close != ')')
    return std::nullopt;
  if (in.peek() != EOF || rows < 0 || cols < 0) return std::nullopt;
  return std::make_pair(rows, cols);
}

std::string headerForMessage(const std::string& header) {
  return header.substr(0, std::min<std::size_t>(header.find('}') + 1, 200));
}

}  // namespace

Eigen::MatrixXd parseNpyMatrix(const std::string& bytes, const std::string& path) {
  if (bytes.size() < 8 || std::memcmp(bytes.data(), "\x93NUMPY", 6) != 0)
    fail(path, "not a NumPy .npy file (the magic string \\x93NUMPY is missing)");
  const int major = static_cast<unsigned char>(bytes[6]);
  if (major < 1 || major > 3)
    fail(path, ".npy format version " + std::to_string(major) + " is not supported");
  const std::size_t lengthSize = major == 1 ? 2 : 4;
  if (bytes.size() < 8 + lengthSize) fail(path, "the header is cut short");
  std::size_t headerLength = 0;
  for (std::size_t k = lengthSize; k-- > 0;)
    headerLength = headerLength * 256 + static_cast<unsigned char>(bytes[8 + k]);
  const std::size_t dataStart = 8 + lengthSize + headerLength;
  if (headerLength > bytes.size() || dataStart > bytes.size()) fail(path, "the header is cut short");
  const std::string header = bytes.substr(8 + lengthSize, headerLength);

  const std::optional<std::string> descr = headerValue(header, "descr");
  if (!descr || descr->size() < 4 || (*descr)[0] != '\'' || descr->substr(descr->size() - 3) != "f8'" ||
      (descr->size() == 5 && std::string("<>|=").find((*descr)[1]) == std::string::npos) || descr->size() > 5)
    fail(path, "only float64 arrays are supported (header: " + headerForMessage(header) + ")");
  const char order = descr->size() == 5 ? (*descr)[1] : '=';
  const bool bigEndian = order == '>' || (order == '=' && !hostIsLittleEndian());
  const std::optional<std::string> fortranText = headerValue(header, "fortran_order");
  if (!fortranText || (*fortranText != "True" && *fortranText != "False"))
    fail(path, "the header has no fortran_order");
  const bool fortran = *fortranText == "True";
  const std::optional<std::string> shapeText = headerValue(header, "shape");
  const auto shape = shapeText ? shape2d(*shapeText) : std::nullopt;
  if (!shape) fail(path, "only 2D arrays are supported (header: " + headerForMessage(header) + ")");
  const auto [rows, cols] = *shape;

  // Counted in double first: a shape of 10^12 x 10^12 must not wrap around to a small byte count.
  const double needed = 8.0 * static_cast<double>(rows) * static_cast<double>(cols);
  const std::size_t available = bytes.size() - dataStart;
  if (needed > static_cast<double>(available))
    fail(path, "the data is cut short: " + std::to_string(rows) + " x " + std::to_string(cols) +
                   " doubles need " + formatCount(needed) + " bytes, the file has " +
                   std::to_string(available));
  checkFits(static_cast<double>(rows), static_cast<double>(cols), path);
  const std::size_t count = static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols);
  Eigen::MatrixXd m(rows, cols);
  for (std::size_t k = 0; k < count; ++k) {
    char b[8];
    std::memcpy(b, bytes.data() + dataStart + 8 * k, 8);
    if (bigEndian == hostIsLittleEndian()) std::reverse(b, b + 8);
    double v;
    std::memcpy(&v, b, 8);
    const auto i = static_cast<Eigen::Index>(fortran ? k % rows : k / cols);
    const auto j = static_cast<Eigen::Index>(fortran ? k / rows : k % cols);
    m(i, j) = v;
  }
  return m;
}

Eigen::MatrixXd readNpyMatrix(const std::string& path) {
  return parseNpyMatrix(io_detail::readTextFile(path), path);
}

Eigen::MatrixXd readMatrixMarket(const std::string& path) {
  return parseMatrixMarket(io_detail::readTextFile(path), path);
}

Eigen::MatrixXd readMatrix(const std::string& path) {
  const std::size_t dot = path.rfind('.');
  const std::string extension = dot == std::string::npos ? "" : path.substr(dot);
  if (extension == ".npy") return readNpyMatrix(path);
  if (extension == ".mtx") return readMatrixMarket(path);
  fail(path, "unknown matrix format '" + extension + "': expected .npy or .mtx");
}

}  // namespace rt
