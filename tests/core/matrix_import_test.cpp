#include "core/io/matrix_import.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <string>

#include "core/input_error.h"
#include "core/io/matrix_export.h"
#include "support/test_paths.h"

namespace rt {
namespace {

using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// A v1.0 .npy file with the given header dictionary and raw data bytes.
void writeRawNpy(const std::string& path, std::string header, const std::string& data) {
  const std::size_t total = ((10 + header.size() + 1 + 63) / 64) * 64;
  header.append(total - 10 - header.size() - 1, ' ');
  header.push_back('\n');
  std::ofstream out(path, std::ios::binary);
  out.write("\x93NUMPY\x01\x00", 8);
  const char length[2] = {static_cast<char>(header.size() & 0xff), static_cast<char>(header.size() >> 8)};
  out.write(length, 2);
  out << header << data;
}

std::string bytesOf(std::initializer_list<double> values, bool bigEndian) {
  std::string data;
  for (double v : values) {
    char b[8];
    std::memcpy(b, &v, 8);
    if (bigEndian) std::reverse(b, b + 8);  // the test machines are little-endian
    data.append(b, 8);
  }
  return data;
}

TEST(MatrixImport, NpyRoundTripsBitExact) {
  RowMatrix m(2, 3);
  m << 0.1 + 0.2, 1.0 / 3.0, -0.0, 5e-324, 1e300, -1.0 / 7.0;
  const std::string path = test::scratchDir("matrix-import") + "/m.npy";
  writeMatrix(m, path);
  const Eigen::MatrixXd back = readNpyMatrix(path);
  ASSERT_EQ(back.rows(), 2);
  ASSERT_EQ(back.cols(), 3);
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_EQ(std::memcmp(&back(i, j), &m(i, j), 8), 0) << i << "," << j;
}

TEST(MatrixImport, FortranOrderAndBigEndianAsNumpyWritesThem) {
  const std::string dir = test::scratchDir("matrix-import-orders");
  writeRawNpy(dir + "/f.npy", "{'descr': '<f8', 'fortran_order': True, 'shape': (2, 3), }",
              bytesOf({1, 4, 2, 5, 3, 6}, false));
  writeRawNpy(dir + "/b.npy", "{'descr': '>f8', 'fortran_order': False, 'shape': (2, 3), }",
              bytesOf({1, 2, 3, 4, 5, 6}, true));
  for (const char* name : {"/f.npy", "/b.npy"}) {
    const Eigen::MatrixXd m = readNpyMatrix(dir + name);
    ASSERT_EQ(m.rows(), 2) << name;
    EXPECT_EQ(m(0, 0), 1) << name;
    EXPECT_EQ(m(0, 2), 3) << name;
    EXPECT_EQ(m(1, 0), 4) << name;
    EXPECT_EQ(m(1, 2), 6) << name;
  }
}

void expectInputError(const std::string& path, const std::string& expected) {
  try {
    readNpyMatrix(path);
    ADD_FAILURE() << "no error for " << path;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
  }
}

TEST(MatrixImport, AnythingElseIsAnErrorNamingTheFile) {
  const std::string dir = test::scratchDir("matrix-import-errors");
  expectInputError(dir + "/missing.npy", "cannot open");
  std::ofstream(dir + "/text.npy") << "1,2\n3,4\n";
  expectInputError(dir + "/text.npy", "not a NumPy .npy file");
  writeRawNpy(dir + "/int.npy", "{'descr': '<i8', 'fortran_order': False, 'shape': (1, 1), }",
              std::string(8, '\0'));
  expectInputError(dir + "/int.npy", "only float64");
  writeRawNpy(dir + "/vector.npy", "{'descr': '<f8', 'fortran_order': False, 'shape': (3,), }",
              bytesOf({1, 2, 3}, false));
  expectInputError(dir + "/vector.npy", "only 2D arrays");
  writeRawNpy(dir + "/short.npy", "{'descr': '<f8', 'fortran_order': False, 'shape': (2, 2), }",
              bytesOf({1, 2, 3}, false));
  expectInputError(dir + "/short.npy", "cut short: 2 x 2 doubles need 32 bytes");
}

}  // namespace
}  // namespace rt
