// Reading Matrix Market files back (as `radiosity matrix` writes them) and hostile .npy headers: every
// problem is an InputError naming the file (and the line), never a huge allocation or a crash.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "core/input_error.h"
#include "core/io/matrix_export.h"
#include "core/io/matrix_import.h"
#include "support/test_paths.h"

namespace rt {
namespace {

std::string errorOf(const std::string& text, bool npy = false) {
  try {
    npy ? parseNpyMatrix(text, "m.npy") : parseMatrixMarket(text, "m.mtx");
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError for: " << text;
  return {};
}

TEST(MatrixMarket, RoundTripsWhatTheExporterWrites) {
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> m(2, 3);
  m << 0.1 + 0.2, 0, -1.0 / 7.0, 5e-324, 1e300, 0;
  const std::string path = test::scratchDir("matrix-market") + "/m.mtx";
  writeMatrix(m, path);
  const Eigen::MatrixXd back = readMatrix(path);
  ASSERT_EQ(back.rows(), 2);
  ASSERT_EQ(back.cols(), 3);
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_EQ(back(i, j), m(i, j)) << i << "," << j;
}

TEST(MatrixMarket, ArrayFormatIsColumnByColumn) {
  const Eigen::MatrixXd m =
      parseMatrixMarket("%%MatrixMarket matrix array real general\n% c\n2 2\n1\n2\n3\n4\n", "a");
  EXPECT_EQ(m(1, 0), 2);
  EXPECT_EQ(m(0, 1), 3);
}

TEST(MatrixMarket, ErrorsNameTheLine) {
  const std::string head = "%%MatrixMarket matrix coordinate real general\n";
  EXPECT_NE(errorOf("").find("m.mtx: error: empty file"), std::string::npos);
  EXPECT_NE(errorOf("1 2 3\n").find("m.mtx:1: error: not a Matrix Market file"), std::string::npos);
  EXPECT_NE(errorOf("%%MatrixMarket matrix coordinate complex general\n1 1 1\n1 1 1 0\n").find("only real"),
            std::string::npos);
  EXPECT_NE(
      errorOf(head + "2 2 1\n3 1 0.5\n").find("m.mtx:3: error: entry (3, 1) is outside the 2 x 2 matrix"),
      std::string::npos);
  EXPECT_NE(errorOf(head + "2 2 1\n1 1 nan\n").find("m.mtx:3: error: value 'nan' is not finite"),
            std::string::npos);
  EXPECT_NE(errorOf(head + "2 2 2\n1 1 0.5\n").find("m.mtx:2: error: announces 2 entries but the file has 1"),
            std::string::npos);
  EXPECT_NE(errorOf(head + "2 2 1\n1 1 0.5\n2 2 0.5\n").find("m.mtx:4: error: more entries"),
            std::string::npos);
  EXPECT_NE(errorOf(head + "2 x 1\n").find("m.mtx:2: error: expected the size line"), std::string::npos);
  // Declared far larger than memory: refused before allocating.
  EXPECT_NE(errorOf(head + "100000000 100000000 0\n").find("matrix is too large: it needs"),
            std::string::npos);
  // No memory at all, but a column count no loop should walk (found by fuzzing: a 14 s timeout).
  EXPECT_NE(errorOf("%%MatrixMarket matrix array real general\n0 4444444444444\n")
                .find("m.mtx:2: error: a 0 x 4,444,444,444,444 matrix is too large"),
            std::string::npos);
}

std::string npy(const std::string& header, const std::string& data = "") {
  std::string bytes("\x93NUMPY\x01\x00", 8);
  bytes += static_cast<char>(header.size() & 0xff);
  bytes += static_cast<char>(header.size() >> 8);
  return bytes + header + data;
}

TEST(MatrixMarket, HostileNpyHeadersAreInputErrors) {
  // A shape whose byte count wraps around 64 bits, a shape far beyond the data, a header longer than the
  // file.
  EXPECT_NE(
      errorOf(npy("{'descr': '<f8', 'fortran_order': False, 'shape': (4294967296, 4294967296), }"), true)
          .find("the data is cut short"),
      std::string::npos);
  EXPECT_NE(
      errorOf(npy("{'descr': '<f8', 'fortran_order': False, 'shape': (99999999999999999999, 1), }"), true)
          .find("only 2D arrays"),
      std::string::npos);
  EXPECT_NE(errorOf(npy("{'descr': '<f8', 'fortran_order': False, 'shape': (0, 4444444444444), }"), true)
                .find("matrix is too large"),
            std::string::npos);
  std::string longHeader = npy("{'descr': '<f8', }");
  longHeader[8] = '\xff';
  longHeader[9] = '\xff';
  EXPECT_NE(errorOf(longHeader, true).find("the header is cut short"), std::string::npos);
  EXPECT_NE(
      errorOf(npy("{'descr': '<i4', 'fortran_order': False, 'shape': (1, 1), }", std::string(8, '\0')), true)
          .find("only float64"),
      std::string::npos);
  const Eigen::MatrixXd one = parseNpyMatrix(
      npy("{'descr': '<f8', 'fortran_order': False, 'shape': (1, 1), }", std::string(8, '\0')), "m");
  EXPECT_EQ(one(0, 0), 0.0);
}

}  // namespace
}  // namespace rt
