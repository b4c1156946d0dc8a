#include "core/io/matrix_import.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <regex>
#include <vector>

#include "core/input_error.h"

namespace rt {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& message) {
  throw InputError({path, 0, {}}, message);
}

bool hostIsLittleEndian() {
  const std::uint16_t one = 1;
  unsigned char first;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

}  // namespace

Eigen::MatrixXd readNpyMatrix(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot open the file");
  char magic[8];
  if (!in.read(magic, 8) || std::memcmp(magic, "\x93NUMPY", 6) != 0)
    fail(path, "not a NumPy .npy file (the magic string \\x93NUMPY is missing)");
  const int major = static_cast<unsigned char>(magic[6]);
  std::size_t headerLength = 0;
  unsigned char lengthBytes[4] = {0, 0, 0, 0};
  const int lengthSize = major == 1 ? 2 : 4;
  if (major < 1 || major > 3)
    fail(path, ".npy format version " + std::to_string(major) + " is not supported");
  if (!in.read(reinterpret_cast<char*>(lengthBytes), lengthSize)) fail(path, "the header is cut short");
  for (int k = lengthSize - 1; k >= 0; --k) headerLength = headerLength * 256 + lengthBytes[k];
  std::string header(headerLength, '\0');
  if (!in.read(header.data(), static_cast<std::streamsize>(headerLength)))
    fail(path, "the header is cut short");

  std::smatch match;
  if (!std::regex_search(header, match, std::regex(R"('descr'\s*:\s*'([<>|=]?)f8')")))
    fail(path, "only float64 arrays are supported (header: " + header.substr(0, header.find('}') + 1) + ")");
  const bool bigEndian = match[1] == ">" || (match[1] == "=" && !hostIsLittleEndian());
  if (!std::regex_search(header, match, std::regex(R"('fortran_order'\s*:\s*(True|False))")))
    fail(path, "the header has no fortran_order");
  const bool fortran = match[1] == "True";
  if (!std::regex_search(header, match, std::regex(R"('shape'\s*:\s*\(\s*(\d+)\s*,\s*(\d+)\s*\))")))
    fail(path, "only 2D arrays are supported (header: " + header.substr(0, header.find('}') + 1) + ")");
  const long long rows = std::stoll(match[1]), cols = std::stoll(match[2]);
  const std::size_t count = static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols);

  std::vector<char> bytes(count * 8);
  if (!in.read(bytes.data(), static_cast<std::streamsize>(bytes.size())))
    fail(path, "the data is cut short: " + std::to_string(rows) + " x " + std::to_string(cols) +
                   " doubles need " + std::to_string(bytes.size()) + " bytes");
  if (bigEndian == hostIsLittleEndian())
    for (std::size_t k = 0; k < count; ++k) std::reverse(bytes.begin() + 8 * k, bytes.begin() + 8 * k + 8);
  Eigen::MatrixXd m(rows, cols);
  for (std::size_t k = 0; k < count; ++k) {
    double v;
    std::memcpy(&v, bytes.data() + 8 * k, 8);
    const auto i = static_cast<Eigen::Index>(fortran ? k % rows : k / cols);
    const auto j = static_cast<Eigen::Index>(fortran ? k / rows : k % cols);
    m(i, j) = v;
  }
  return m;
}

}  // namespace rt
